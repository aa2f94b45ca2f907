// SPDX-License-Identifier: Apache-2.0
// Which predefined macros a program text can observe. A `#define NAME ...` whose NAME the text
// can never spell cannot change what the text preprocesses to, so the compile driver drops such
// lines before comparing variants: variants (and stages) that differ only in unobserved keywords
// or stage macros share one preprocessing instead of repeating it.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "varc/driver/PredefinedMacro.h"

namespace varc::driver {

class ObservedNames {
public:
    // Collects every identifier-like token of |text| outside `#pragma` lines (which glslang does
    // not macro-expand; comments and strings count, which only makes the answer more
    // conservative) and the names token pasting (`##`) can form: a chain
    // `A ## ... ## Z` in a macro body forms names starting with A unless A is a macro parameter,
    // and ending with Z unless Z is one. A chain with parameters at both ends forms the
    // concatenations of the tokens its arguments can hold: a name is formable when it splits
    // into pieces each of which is a token of the text, a number, or a formed name itself.
    explicit ObservedNames(std::string_view text);

    // Thread-safe (the answers for formed names are kept, shared by copies).
    bool mayObserve(std::string_view name) const;
    // Whether token pasting (`##`) may form |name|: such a name can be looked up wherever a
    // paste happens, which the keyword projection does not follow.
    bool mayPaste(std::string_view name) const;

private:
    struct StringHash {
        using is_transparent = void;
        size_t operator()(std::string_view text) const {
            return std::hash<std::string_view>{}(text);
        }
    };
    using NameSet = std::unordered_set<std::string, StringHash, std::equal_to<>>;
    struct FormedCache {
        std::mutex mutex;
        std::unordered_map<std::string, bool, StringHash, std::equal_to<>> answers;
    };

    void addPastes(std::string_view directive);
    bool isPastedEnd(std::string_view name) const;
    bool isFormable(std::string_view name) const;

    bool mObservesAll = false;
    bool mPastesTokens = false;  // some chain has parameters at both ends
    NameSet mNames;
    std::vector<std::string> mPastedPrefixes, mPastedSuffixes;
    std::shared_ptr<FormedCache> mFormed = std::make_shared<FormedCache>();
};

// Removes from |macros| the definitions whose name |names| cannot observe; `#undef`s stay.
// Example: with a text that only mentions POINT, the definitions of SHADER_STAGE_VERTEX, POINT
// and SPOT become the one of POINT.
void dropUnobservedMacros(std::vector<PredefinedMacro>& macros, const ObservedNames& names);

}  // namespace varc::driver
