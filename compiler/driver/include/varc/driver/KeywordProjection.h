// SPDX-License-Identifier: Apache-2.0
// Which keywords can change one stage's preprocessed text in a given variant. The preprocessor
// reads a keyword macro only where it looks the name up: in a `#if`/`#elif` (expanded, with
// `defined`), an `#ifdef`/`#ifndef`, a `#define`/`#undef` of that name, or a line it
// macro-expands, all in the branches the variant takes. Variants that agree on the keywords
// so looked up preprocess to the same text, so the compile driver preprocesses once per
// distinct projection (the looked-up keywords that are on) instead of once per variant.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "varc/variants/VariantKey.h"

namespace varc::driver {

namespace projection {
class ConditionalText;
class MacroIndex;
}  // namespace projection

// A pass's text parsed for the analysis, shared by the projections of its stages.
class ProjectionText {
public:
    // |keywords|: the pass's keyword table (index = VariantKey bit). |formable|: keywords token
    // pasting can form (`##`): taken as looked up in every variant.
    ProjectionText(std::string_view text, const std::vector<std::string>& keywords,
                   variants::VariantKey formable);
    ~ProjectionText();
    const projection::ConditionalText& text() const { return *mText; }
    const variants::VariantKey& formable() const { return mFormable; }

private:
    std::unique_ptr<projection::ConditionalText> mText;
    variants::VariantKey mFormable;
};

// The projections of one stage of a pass: a decision tree over the keywords the walk of the
// text asks about, in the order it asks; each leaf is one distinct projection. With an entry
// point, the leaves are kept per set of keywords a walk kept instead (knownLeaf). Not
// thread-safe.
class KeywordProjection {
public:
    // |basePreamble|: the macros glslang sees before the text in every variant of the stage
    // (varc's predefined macros without the keywords), as `#define`/`#undef` lines. |entry|:
    // the stage's entry point when its preprocessed text is pruned to what the entry point
    // reaches before anything else reads it; lookups made only in the bodies of functions it
    // cannot reach are then left out (docs/ARCHITECTURE.md, "Keyword projection"). Empty: none.
    KeywordProjection(std::shared_ptr<const ProjectionText> text, std::string_view basePreamble,
                      std::string entry = {});
    ~KeywordProjection();

    // The keywords of |key| the stage's preprocessing can observe (a subset of |key|), or
    // nullopt when the analysis cannot decide for this text: the caller then keeps them all.
    // |kept|, when given, receives the keywords that decide the projection (a superset of it).
    std::optional<variants::VariantKey> observedOf(const variants::VariantKey& key,
                                                   variants::VariantKey* kept = nullptr);

    // Counts every lookup from now on (the pruner could not prune a text this projection
    // chose, so unreachable bodies stay in it): the tree starts again.
    void keepUnreachableLookups();
    bool leavesOutUnreachable() const { return !mEntry.empty(); }

    bool usable() const { return mUsable; }              // false: the analysis gave up
    size_t walks() const { return mWalks; }              // walks of the text so far
    size_t projections() const { return mProjections; }  // distinct projections found

private:
    struct Node {
        int keyword = -1;   // asked at this node; -1: a leaf, or a node being built
        bool leaf = false;  // a walk ended here
        int child[2] = {-1, -1};
        variants::VariantKey asked;  // at a leaf: every keyword the walk asked about
    };
    bool insertWalk(const std::vector<std::pair<int, bool>>& answers,
                    const variants::VariantKey& asked);
    // With an entry point: the leaves, per set of keywords a walk kept.
    struct Leaves {
        variants::VariantKey asked;
        std::unordered_set<variants::VariantKey> projections;  // key & asked of each leaf
    };
    std::optional<variants::VariantKey> knownLeaf(const variants::VariantKey& key,
                                                  variants::VariantKey& kept);
    void insertLeaf(const variants::VariantKey& asked, const variants::VariantKey& projected);

    std::shared_ptr<const ProjectionText> mText;
    std::unique_ptr<projection::ConditionalText> mBase;
    std::string mEntry;
    std::unique_ptr<projection::MacroIndex> mMacros;  // with |mEntry|
    std::vector<Node> mNodes;                         // mNodes[0] is the root once a walk ran
    std::vector<Leaves> mLeaves;
    bool mUsable = true;
    size_t mWalks = 0, mProjections = 0;
};

}  // namespace varc::driver
