// SPDX-License-Identifier: Apache-2.0
// One walk of a text for one variant: the branches the preprocessor takes and, in order, the
// keywords it looks up on the way.
#pragma once

#include <optional>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "BlockTracker.h"
#include "ConditionEvaluator.h"
#include "ConditionalText.h"
#include "Reachability.h"

namespace varc::driver::projection {

// When a stage's preprocessed text is pruned to what |entry| reaches before anything else reads
// it (StagePruner), the lookups that can change only what pruning removes may be left out.
struct ReachableCode {
    const MacroIndex& macros;  // of the text and the base preamble
    std::string_view entry;
};

class ProjectionWalk final : public MacroScope {
public:
    // |keywords| names the keyword bits (the pass's text); |key| is the variant; |reachable|,
    // when given, leaves out the lookups that cannot change the pruned program (Reachability.h):
    // in clean groups (BraceShape.h) and text runs inside the bodies of functions the entry
    // point cannot reach, and in definesOnly groups (DefineGroups.h) defining only macros
    // nothing kept uses.
    ProjectionWalk(const ConditionalText& keywords, const variants::VariantKey& key,
                   const ReachableCode* reachable = nullptr)
        : mKeywords(keywords), mKey(key), mReachable(reachable) {}

    // Walks |base| (the preamble's macros) and then |text|, first asking about |formable|.
    // False when the text holds what the walk does not model: its answers are then unusable.
    bool run(const ConditionalText& base, const ConditionalText& text, const KeywordBits& formable);

    // (keyword, on in the variant) for each keyword asked about, in the order first asked.
    const std::vector<std::pair<int, bool>>& answers() const { return mAnswers; }
    const KeywordBits& asked() const { return mAsked; }

    const PpLine* macro(std::string_view name) override;

private:
    void walk(const ConditionalText& text);
    // From the branch directive at |i|: the index of the first line of the taken branch.
    size_t enterGroup(const std::vector<PpLine>& lines, size_t i);
    void ask(int keyword);
    void askAlways(int keyword);  // a lookup that counts wherever it is made
    void askAll(const KeywordBits& keywords);
    // Keeps the asks that can matter, in order (answers() and asked()).
    void settleAsks();

    const ConditionalText& mKeywords;
    const variants::VariantKey& mKey;
    const ReachableCode* mReachable;
    std::optional<BlockTracker> mTracker;  // of the text, with |mReachable|
    // What #define/#undef of the text set so far (nullptr: undefined).
    std::unordered_map<std::string_view, const PpLine*> mTable;
    // Where an ask was made: the function body whose clean group or text run it was in, the
    // innermost definesOnly group it was in (-1: none). With neither, it always counts.
    struct Ask {
        int keyword;
        int body;
        int group;
    };
    static bool leavable(const Ask& ask, const Liveness& liveness);
    std::vector<Ask> mAsks;                       // each keyword's first ask per place, in order
    std::unordered_set<uint64_t> mPlaceAsks;      // (keyword, body, group) of mAsks, packed
    KeywordBits mAskedOutside;                    // keywords asked where they always count
    int mBody = -1;                               // the body asks are made in now, or -1
    size_t mBodyUntil = 0;                        // the #endif of the clean group that set mBody
    std::vector<uint32_t> mDefineGroups;          // the definesOnly groups open now (#if lines)
    std::vector<EnteredGroup> mEntered;           // WalkTrace::groups
    std::vector<std::string_view> mLooseDefines;  // WalkTrace::looseDefines
    const std::vector<PpLine>* mTextLines = nullptr;
    std::vector<std::pair<int, bool>> mAnswers;
    KeywordBits mAsked;
    bool mFailed = false;
};

}  // namespace varc::driver::projection
