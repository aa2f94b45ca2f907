// SPDX-License-Identifier: Apache-2.0
// Unity's built-in `multi_compile_*` shortcuts: their keyword sets, validity rules and options.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "varc/core/SourceLocation.h"
#include "varc/variants/PassKeywords.h"

namespace varc::variants {

// One shortcut as varc models it (docs/KEYWORDS.md §4).
struct Shortcut {
    std::string name;                            // "fwdadd"; the directive is multi_compile_<name>
    std::vector<std::vector<std::string>> sets;  // declared order; "" = the no-keyword entry
    std::vector<ValidityRule> rules;             // origin = directive()
    std::string source;                          // where the model comes from, for reports

    std::string directive() const { return "multi_compile_" + name; }
};

// An option written after a shortcut, e.g. `multi_compile_fwdbase nolightmap`.
struct ShortcutOption {
    std::string name;                  // "nolightmap"
    std::vector<std::string> removes;  // keywords it removes from the shortcut's sets
};

// The result of expanding one shortcut line.
struct ShortcutExpansion {
    std::vector<KeywordSetDecl> sets;
    std::vector<ValidityRule> rules;
};

// Every built-in shortcut, in docs/KEYWORDS.md order.
const std::vector<Shortcut>& builtinShortcuts();
// The shortcut called |name| ("fwdadd", without "multi_compile_"), or nullptr.
const Shortcut* findShortcut(std::string_view name);

// Every option accepted after a shortcut.
const std::vector<ShortcutOption>& shortcutOptions();
// The option called |name| ("noshadow"), or nullptr.
const ShortcutOption* findShortcutOption(std::string_view name);

// The sets and rules of |shortcut| with the keywords of |options| removed. A set left without
// any keyword (nothing, or only the no-keyword entry) is dropped: it no longer varies. Each set
// gets kind MultiCompile, all stages, directive = shortcut.directive() and |location|.
// Example: fwdadd_fullshadows + noshadow -> the single fwdadd light-type set.
ShortcutExpansion expandShortcut(const Shortcut& shortcut,
                                 const std::vector<const ShortcutOption*>& options,
                                 SourceLocation location);

}  // namespace varc::variants
