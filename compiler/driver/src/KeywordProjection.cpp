// SPDX-License-Identifier: Apache-2.0
// The decision tree of a stage's keyword projections, grown by one walk per new projection.
#include "varc/driver/KeywordProjection.h"

#include "projection/ConditionalText.h"
#include "projection/ProjectionWalk.h"

namespace varc::driver {

namespace {

projection::KeywordBits bitsOf(const variants::VariantKey& key) {
    projection::KeywordBits bits;
    for (size_t k = 0; k < variants::VariantKey::kMaxKeywords; ++k)
        if (key.test(k)) bits.set(k);
    return bits;
}

variants::VariantKey keyOf(const projection::KeywordBits& bits) {
    variants::VariantKey key;
    for (size_t k = 0; k < bits.size(); ++k)
        if (bits.test(k)) key.set(k);
    return key;
}

}  // namespace

ProjectionText::ProjectionText(std::string_view text, const std::vector<std::string>& keywords,
                               variants::VariantKey formable)
    : mText(std::make_unique<projection::ConditionalText>(text, keywords)), mFormable(formable) {}

ProjectionText::~ProjectionText() = default;

KeywordProjection::KeywordProjection(std::shared_ptr<const ProjectionText> text,
                                     std::string_view basePreamble)
    : mText(std::move(text)),
      mBase(std::make_unique<projection::ConditionalText>(basePreamble,
                                                          std::vector<std::string>{})) {}

KeywordProjection::~KeywordProjection() = default;

std::optional<variants::VariantKey> KeywordProjection::observedOf(const variants::VariantKey& key) {
    if (!mUsable) return std::nullopt;
    int node = mNodes.empty() ? -1 : 0;
    while (node >= 0 && !mNodes[static_cast<size_t>(node)].leaf) {
        const Node& inner = mNodes[static_cast<size_t>(node)];
        node = inner.child[key.test(static_cast<size_t>(inner.keyword)) ? 1 : 0];
    }
    if (node >= 0) return key & mNodes[static_cast<size_t>(node)].asked;
    ++mWalks;
    projection::ProjectionWalk walk(mText->text(), key);
    if (!walk.run(*mBase, mText->text(), bitsOf(mText->formable()))) {
        mUsable = false;
        return std::nullopt;
    }
    variants::VariantKey asked = keyOf(walk.asked());
    if (!insertWalk(walk.answers(), asked)) {
        mUsable = false;  // the walk was not a function of its answers: a bug, stay safe
        return std::nullopt;
    }
    return key & asked;
}

bool KeywordProjection::insertWalk(const std::vector<std::pair<int, bool>>& answers,
                                   const variants::VariantKey& asked) {
    if (mNodes.empty()) mNodes.emplace_back();
    size_t node = 0;
    for (const auto& [keyword, on] : answers) {
        if (mNodes[node].leaf) return false;
        if (mNodes[node].keyword < 0) mNodes[node].keyword = keyword;
        if (mNodes[node].keyword != keyword) return false;
        if (mNodes[node].child[on ? 1 : 0] < 0) {
            mNodes[node].child[on ? 1 : 0] = static_cast<int>(mNodes.size());
            mNodes.emplace_back();
        }
        node = static_cast<size_t>(mNodes[node].child[on ? 1 : 0]);
    }
    if (mNodes[node].leaf || mNodes[node].keyword >= 0) return false;
    mNodes[node].leaf = true;
    mNodes[node].asked = asked;
    ++mProjections;
    return true;
}

}  // namespace varc::driver
