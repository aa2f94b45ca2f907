// SPDX-License-Identifier: Apache-2.0
// One walk of a text for one variant: the branches the preprocessor takes and, in order, the
// keywords it looks up on the way.
#pragma once

#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ConditionEvaluator.h"
#include "ConditionalText.h"

namespace varc::driver::projection {

class ProjectionWalk final : public MacroScope {
public:
    // |keywords| names the keyword bits (the pass's text); |key| is the variant.
    ProjectionWalk(const ConditionalText& keywords, const variants::VariantKey& key)
        : mKeywords(keywords), mKey(key) {}

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
    void askAll(const KeywordBits& keywords);

    const ConditionalText& mKeywords;
    const variants::VariantKey& mKey;
    // What #define/#undef of the text set so far (nullptr: undefined).
    std::unordered_map<std::string_view, const PpLine*> mTable;
    std::vector<std::pair<int, bool>> mAnswers;
    KeywordBits mAsked;
    bool mFailed = false;
};

}  // namespace varc::driver::projection
