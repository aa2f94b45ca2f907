// SPDX-License-Identifier: Apache-2.0
// The decision tree of a stage's keyword projections, grown by one walk per new projection.
#include "varc/driver/KeywordProjection.h"

#include <algorithm>

#include "projection/ConditionalText.h"
#include "projection/ProjectionWalk.h"
#include "projection/Reachability.h"

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
                                     std::string_view basePreamble, std::string entry)
    : mText(std::move(text)),
      mBase(
          std::make_unique<projection::ConditionalText>(basePreamble, std::vector<std::string>{})),
      mEntry(std::move(entry)) {
    if (mEntry.empty()) return;
    mMacros = std::make_unique<projection::MacroIndex>();
    mMacros->add(mText->text());
    mMacros->add(*mBase);
}

void KeywordProjection::keepUnreachableLookups() {
    mEntry.clear();
    mMacros.reset();
    mNodes.clear();
    mLeaves.clear();
    mProjections = 0;
}

// A walk that leaves lookups out sees which of them count only once it has seen the whole text
// (a macro used further down makes an earlier group count), so its answers in order are no path
// of a decision tree. But any variant agreeing with a walked one on the keywords that walk kept
// preprocesses and prunes to the same program (docs/ARCHITECTURE.md): leaves are kept per kept
// set, the most recently matched set tried first.
std::optional<variants::VariantKey> KeywordProjection::knownLeaf(const variants::VariantKey& key,
                                                                 variants::VariantKey& kept) {
    for (size_t i = 0; i < mLeaves.size(); ++i) {
        variants::VariantKey projected = key & mLeaves[i].asked;
        if (!mLeaves[i].projections.count(projected)) continue;
        if (i > 0) std::swap(mLeaves[i], mLeaves[0]);
        kept = mLeaves[0].asked;
        return projected;
    }
    return std::nullopt;
}

void KeywordProjection::insertLeaf(const variants::VariantKey& asked,
                                   const variants::VariantKey& projected) {
    auto same = std::find_if(mLeaves.begin(), mLeaves.end(),
                             [&](const Leaves& leaves) { return leaves.asked == asked; });
    if (same == mLeaves.end()) same = mLeaves.insert(mLeaves.end(), Leaves{asked, {}});
    if (same->projections.insert(projected).second) ++mProjections;
}

KeywordProjection::~KeywordProjection() = default;

std::optional<variants::VariantKey> KeywordProjection::observedOf(const variants::VariantKey& key,
                                                                  variants::VariantKey* kept) {
    variants::VariantKey ignored;
    variants::VariantKey& mask = kept ? *kept : ignored;
    if (!mUsable) return std::nullopt;
    if (mMacros) {
        if (std::optional<variants::VariantKey> known = knownLeaf(key, mask)) return known;
    }
    int node = mNodes.empty() ? -1 : 0;
    while (node >= 0 && !mNodes[static_cast<size_t>(node)].leaf) {
        const Node& inner = mNodes[static_cast<size_t>(node)];
        node = inner.child[key.test(static_cast<size_t>(inner.keyword)) ? 1 : 0];
    }
    if (node >= 0) {
        mask = mNodes[static_cast<size_t>(node)].asked;
        return key & mask;
    }
    ++mWalks;
    std::optional<projection::ReachableCode> reachable;
    if (mMacros) reachable.emplace(projection::ReachableCode{*mMacros, mEntry});
    projection::ProjectionWalk walk(mText->text(), key, reachable ? &*reachable : nullptr);
    if (!walk.run(*mBase, mText->text(), bitsOf(mText->formable()))) {
        mUsable = false;
        return std::nullopt;
    }
    variants::VariantKey asked = keyOf(walk.asked());
    mask = asked;
    if (mMacros) {
        insertLeaf(asked, key & asked);
        return key & asked;
    }
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
