// SPDX-License-Identifier: Apache-2.0
// What of a walk's emitted text can reach the stage's pruned program: the function bodies its
// entry point can reach, and the macros and definition-only groups those (and everything outside
// function bodies) can name. Lookups made only elsewhere do not change the pruned program.
#pragma once

#include <cstdint>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "BlockTracker.h"
#include "ConditionalText.h"

namespace varc::driver::projection {

// The macros of a text and its preamble as the analysis reads them: every definition of a name
// at once (a superset of the one in force where a line expands it).
class MacroIndex {
public:
    void add(const ConditionalText& text);
    bool defines(std::string_view name) const { return mMacros.count(name) != 0; }

private:
    friend class LivenessWalk;
    struct Macro {
        std::vector<std::string_view> identifiers;  // of every definition's body
        // What `##` in a body pastes to a parameter: a name holding one of these may be formed.
        std::vector<std::string_view> fragments;
        bool pastesUnknown = false;  // `a ## b` of two parameters: any name may be formed
    };
    std::unordered_map<std::string_view, Macro> mMacros;
};

// A conditional group one walk entered.
struct EnteredGroup {
    uint32_t line;  // its #if/#ifdef/#ifndef
    // The function body block whose clean group it is (BraceShape.h; its conditions count only
    // if that body is reached), or -1.
    int body;
    bool outermost;  // a definesOnly group inside no other definesOnly group
};

// What one walk emitted, entered and defined.
struct WalkTrace {
    const BlockTracker& tracker;              // finished
    const std::vector<PpLine>& lines;         // of the text
    const std::vector<EnteredGroup>& groups;  // every group entered, in order
    // The names a #define outside every definesOnly group gave a body.
    const std::vector<std::string_view>& looseDefines;
};

struct Liveness {
    bool decided = false;  // false: nothing may be left out (token pasting of unknown names...)
    std::vector<char> deadBodies;  // per tracker block: a function body nothing reaches
    std::vector<char> liveGroups;  // per line: an entered definesOnly group defining a used name
};

// Starts from |entry|, the identifiers outside function bodies, the macros whose braces the
// tracker followed, the conditions of every entered group that is not definesOnly, and the
// names whose definition a variant's choice could make a redefinition (a diagnostic): those two
// outermost definesOnly groups define, or one defines and a loose #define gives a body; follows
// names into function bodies, macro bodies, and the definesOnly groups defining them (and then
// their conditions), to the fixed point.
Liveness livenessOf(const WalkTrace& trace, const MacroIndex& macros, std::string_view entry);

}  // namespace varc::driver::projection
