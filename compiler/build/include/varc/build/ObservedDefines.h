// SPDX-License-Identifier: Apache-2.0
// Which predefined macros a program text can observe. A `#define NAME ...` whose NAME the text
// can never spell cannot change what the text preprocesses to, so the compile driver drops such
// lines before comparing variants: variants (and stages) that differ only in unobserved keywords
// or stage macros share one preprocessing instead of repeating it.
#pragma once

#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace varc::compiler {

class ObservedNames {
public:
    // Collects every identifier-like token of |text| outside `#pragma` lines (which glslang does
    // not macro-expand; comments and strings count, which only makes the answer more
    // conservative) and the names token pasting (`##`) can form: a chain
    // `A ## ... ## Z` in a macro body forms names starting with A unless A is a macro parameter,
    // and ending with Z unless Z is one; a chain with parameters at both ends forms any name.
    explicit ObservedNames(std::string_view text);

    bool mayObserve(std::string_view name) const;

private:
    void addPastes(std::string_view directive);

    bool mObservesAll = false;
    std::unordered_set<std::string> mNames;
    std::vector<std::string> mPastedPrefixes, mPastedSuffixes;
};

// |preamble| without the `#define NAME ...` lines whose NAME |names| cannot observe; every other
// line is kept as is. Example: with a text that only mentions POINT,
//   "#define SHADER_STAGE_VERTEX 1\n#define POINT 1\n#define SPOT 1\n" -> "#define POINT 1\n".
std::string dropUnobservedDefines(std::string_view preamble, const ObservedNames& names);

}  // namespace varc::compiler
