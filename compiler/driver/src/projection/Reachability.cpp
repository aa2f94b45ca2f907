// SPDX-License-Identifier: Apache-2.0
// Function bodies, macros and definition groups a stage's entry point can reach, by name.
#include "Reachability.h"

#include <algorithm>
#include <unordered_set>

namespace varc::driver::projection {

void MacroIndex::add(const ConditionalText& text) {
    for (const PpLine& line : text.lines()) {
        if (line.kind != PpLine::Kind::Define) continue;
        Macro& macro = mMacros[line.name];
        const std::vector<std::string_view>& body = line.tokens;
        auto isParameter = [&](std::string_view token) {
            return token == "__VA_ARGS__" ||
                   std::find(line.params.begin(), line.params.end(), token) != line.params.end();
        };
        for (size_t i = 0; i < body.size(); ++i) {
            if (isIdentifierToken(body[i])) macro.identifiers.push_back(body[i]);
            if (body[i] != "##") continue;
            const bool leftKnown = i > 0 && !isParameter(body[i - 1]);
            const bool rightKnown = i + 1 < body.size() && !isParameter(body[i + 1]);
            if (leftKnown) macro.fragments.push_back(body[i - 1]);
            if (rightKnown) macro.fragments.push_back(body[i + 1]);
            if (!leftKnown && !rightKnown) macro.pastesUnknown = true;
        }
    }
}

// The breadth-first search over names; friend of MacroIndex.
class LivenessWalk {
public:
    LivenessWalk(const WalkTrace& trace, const MacroIndex& macros)
        : mTrace(trace), mBlocks(trace.tracker.blocks()), mMacros(macros.mMacros) {
        mLiveness.deadBodies.assign(mBlocks.size(), 1);
        mLiveness.liveGroups.assign(trace.lines.size(), 0);
        std::unordered_map<std::string_view, int> outermostDefiners;
        for (const EnteredGroup& entered : trace.groups) {
            const PpLine& group = trace.lines[entered.line];
            if (entered.body >= 0) {
                mBodyGroups[static_cast<size_t>(entered.body)].push_back(entered.line);
                continue;
            }
            if (!group.definesOnly) {
                liven(entered.line);
                continue;
            }
            for (std::string_view name : group.defines) {
                mDefiners[name].push_back(entered.line);
                if (entered.outermost) ++outermostDefiners[name];
            }
        }
        for (const auto& [name, count] : outermostDefiners)
            if (count > 1) push(name);
        for (std::string_view name : trace.looseDefines)
            if (mDefiners.count(name)) push(name);
        for (size_t b = 0; b < mBlocks.size(); ++b) {
            std::string_view name = mBlocks[b].function;
            if (!name.empty() && !macros.defines(name)) {
                mBodies[name].push_back(b);
                continue;
            }
            // Not a function body, or one whose name a macro makes: always used.
            reach(b);
            if (!name.empty()) push(name);
        }
    }

    Liveness run(std::string_view entry) {
        push(entry);
        for (std::string_view name : mTrace.tracker.outside()) push(name);
        for (std::string_view name : mTrace.tracker.braceMacroUses()) push(name);
        while (!mPending.empty()) {
            std::string_view name = mPending.back();
            mPending.pop_back();
            if (auto bodies = mBodies.find(name); bodies != mBodies.end())
                for (size_t b : bodies->second) reach(b);
            if (auto groups = mDefiners.find(name); groups != mDefiners.end())
                for (uint32_t g : groups->second) liven(g);
            auto macro = mMacros.find(name);
            if (macro == mMacros.end()) continue;
            if (macro->second.pastesUnknown) return {};
            for (std::string_view token : macro->second.identifiers) push(token);
            for (std::string_view fragment : macro->second.fragments) pushContaining(fragment);
        }
        for (size_t b = 0; b < mBlocks.size(); ++b)
            if (mBlocks[b].function.empty()) mLiveness.deadBodies[b] = 0;
        mLiveness.decided = true;
        return std::move(mLiveness);
    }

private:
    void push(std::string_view name) {
        if (mSeen.insert(name).second) mPending.push_back(name);
    }
    // Pasting may form any name holding |fragment|: every such function, group name or macro.
    void pushContaining(std::string_view fragment) {
        if (!mFragments.insert(fragment).second) return;
        auto contains = [&](std::string_view name) {
            return name.find(fragment) != std::string_view::npos;
        };
        for (const auto& [name, bodies] : mBodies)
            if (contains(name)) push(name);
        for (const auto& [name, groups] : mDefiners)
            if (contains(name)) push(name);
        for (const auto& [name, macro] : mMacros)
            if (contains(name)) push(name);
    }
    void reach(size_t block) {
        if (!mLiveness.deadBodies[block]) return;
        mLiveness.deadBodies[block] = 0;
        for (std::string_view name : mBlocks[block].identifiers) push(name);
        if (auto groups = mBodyGroups.find(block); groups != mBodyGroups.end())
            for (uint32_t g : groups->second) liven(g);
    }
    // A group whose branch matters: what its conditions name matters too.
    void liven(uint32_t g) {
        if (mLiveness.liveGroups[g]) return;
        mLiveness.liveGroups[g] = 1;
        for (uint32_t branch = g;; branch = mTrace.lines[branch].next) {
            const PpLine& line = mTrace.lines[branch];
            if (line.kind == PpLine::Kind::Endif) break;
            if (!line.name.empty()) push(line.name);
            for (std::string_view token : line.tokens)
                if (isIdentifierToken(token)) push(token);
        }
    }

    const WalkTrace& mTrace;
    const std::vector<BlockTracker::Block>& mBlocks;
    const std::unordered_map<std::string_view, MacroIndex::Macro>& mMacros;
    std::unordered_map<std::string_view, std::vector<size_t>> mBodies;      // by function name
    std::unordered_map<std::string_view, std::vector<uint32_t>> mDefiners;  // definesOnly groups
    std::unordered_map<size_t, std::vector<uint32_t>> mBodyGroups;          // clean groups per body
    Liveness mLiveness;
    std::unordered_set<std::string_view> mSeen;
    std::unordered_set<std::string_view> mFragments;  // pasted fragments already followed
    std::vector<std::string_view> mPending;
};

Liveness livenessOf(const WalkTrace& trace, const MacroIndex& macros, std::string_view entry) {
    if (!trace.tracker.consistent()) return {};
    return LivenessWalk(trace, macros).run(entry);
}

}  // namespace varc::driver::projection
