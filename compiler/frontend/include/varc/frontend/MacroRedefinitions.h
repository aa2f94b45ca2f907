// SPDX-License-Identifier: Apache-2.0
// Macro redefinitions as Unity's HLSL compilers take them: a warning, and the later definition
// wins. glslang's preprocessor stops instead ("Macro redefined; different substitutions").
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace varc::frontend {

// The names glslang's |log| reports as redefined with different substitutions.
// Example: "ERROR: 9:9: '#define' : Macro redefined; different substitutions: PI\n" -> {"PI"}.
std::vector<std::string> redefinedMacros(std::string_view log);

// |text| (expanded source in the front end's convention: `#line N F` names the next line) with
// `#undef NAME` before every `#define NAME` but the first, for each of |names|, followed by a
// `#line` that puts the `#define` back at its own file and line, so every later line still maps
// to its origin. Example, names {"PI"}:
//   "#line 1 0\n#define PI 3.14\n#line 9 2\n#define PI 3.1416\nx\n" ->
//   "#line 1 0\n#define PI 3.14\n#line 9 2\n#undef PI\n#line 9 2\n#define PI 3.1416\nx\n".
std::string undefineBeforeRedefinitions(std::string_view text,
                                        const std::vector<std::string>& names);

}  // namespace varc::frontend
