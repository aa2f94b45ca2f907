// SPDX-License-Identifier: Apache-2.0
// Property test: on random small passes and materials, MaterialSelection ships exactly the
// variants a brute-force filter of the full enumeration keeps, in the same order.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "VariantsTestSupport.h"
#include "varc/variants/MaterialSelection.h"

namespace varc::variants {
namespace {

using Names = std::vector<std::string>;

class PassGenerator {
public:
    explicit PassGenerator(uint32_t seed) : mRandom(seed) {}

    std::vector<std::string> pragmas() {
        std::vector<std::string> lines;
        for (int i = 1 + pick(3); i > 0; --i) lines.push_back(userSet());
        if (pick(1) == 1) {
            static const char* kShortcuts[] = {"multi_compile_fwdadd_fullshadows",
                                               "multi_compile_fog", "multi_compile_shadowcaster",
                                               "multi_compile_prepassfinal"};
            lines.push_back(kShortcuts[pick(3)]);
        }
        std::shuffle(lines.begin(), lines.end(), mRandom);
        if (pick(2) == 0) {
            static const char* kPool[] = {"U0", "U1", "U2", "U4", "SPOT", "FOG_EXP", "LIGHTMAP_ON"};
            lines.push_back(std::string("skip_variants ") + kPool[pick(6)] + " " + kPool[pick(6)]);
        }
        return lines;
    }

    // Random requests over the pass's declared keywords (skipped ones included) and a stray.
    std::vector<KeywordRequest> requests(const PassKeywords& keywords) {
        Names pool = {"JUNK"};
        for (const KeywordSetDecl& set : keywords.sets) {
            for (const std::string& keyword : set.keywords) {
                if (!keyword.empty()) pool.push_back(keyword);
            }
        }
        std::vector<KeywordRequest> result;
        for (int i = pick(4); i > 0; --i) {
            KeywordRequest request;
            request.kind = pick(4) == 0 ? RequestKind::CollectionVariant : RequestKind::Material;
            request.name = "R" + std::to_string(result.size());
            for (const std::string& keyword : pool) {
                if (pick(3) == 0) request.keywords.push_back(keyword);
            }
            std::shuffle(request.keywords.begin(), request.keywords.end(), mRandom);
            result.push_back(std::move(request));
        }
        return result;
    }

    // Turns a random multi_compile set into a shader_feature set, so that shortcut rules
    // also constrain pinned sets (the parser never produces that from text).
    void maybeFlipASet(PassKeywords& keywords) {
        if (pick(2) != 0 || keywords.sets.empty()) return;
        const int last = static_cast<int>(keywords.sets.size()) - 1;
        keywords.sets[static_cast<size_t>(pick(last))].kind = DirectiveKind::ShaderFeature;
    }

    int pick(int maxInclusive) {
        return std::uniform_int_distribution<int>(0, maxInclusive)(mRandom);
    }

private:
    std::string userSet() {
        static const char* kDirectives[] = {"multi_compile", "shader_feature",
                                            "shader_feature_local_fragment", "shader_feature"};
        std::string line = kDirectives[pick(3)];
        const int keywordCount = 1 + pick(2);
        const int underscoreAt = pick(keywordCount + 1);  // == keywordCount + 1: none
        for (int i = 0; i <= keywordCount; ++i) {
            if (i == underscoreAt) line += " _";
            if (i < keywordCount) line += " U" + std::to_string(mNextUser++);
        }
        return line;
    }

    std::mt19937 mRandom;
    int mNextUser = 0;
};

// The reference's §2.2 pick, by names: the first declared enabled keyword; none on -> `_`
// when the set has it, else its first keyword. Skipped keywords count as undeclared.
std::string pickByName(const Names& remaining, const Names& enabled) {
    for (const std::string& keyword : remaining) {
        if (!keyword.empty() &&
            std::find(enabled.begin(), enabled.end(), keyword) != enabled.end()) {
            return keyword;
        }
    }
    bool hasOff = std::find(remaining.begin(), remaining.end(), "") != remaining.end();
    return hasOff ? "" : remaining.front();
}

// Brute force: enumerate the full space and keep variants whose shader_feature names form a
// requested combination (the all-off one too when no material exists).
std::vector<VariantKey> bruteForce(const PassKeywords& keywords, const VariantSpace& space,
                                   const std::vector<KeywordRequest>& requests, bool always) {
    std::vector<Names> featureSets;
    for (const KeywordSetDecl& set : keywords.sets) {
        if (set.kind != DirectiveKind::ShaderFeature) continue;
        Names remaining;
        for (const std::string& keyword : set.keywords) {
            const Names& skipped = keywords.skipped;
            if (std::find(skipped.begin(), skipped.end(), keyword) == skipped.end()) {
                remaining.push_back(keyword);
            }
        }
        if (remaining.empty()) return {};
        featureSets.push_back(remaining);
    }
    auto combinationOf = [&](const Names& enabled) {
        Names combination;
        for (const Names& set : featureSets) combination.push_back(pickByName(set, enabled));
        return combination;
    };
    std::set<Names> used;
    bool anyMaterial = false;
    for (const KeywordRequest& request : requests) {
        used.insert(combinationOf(request.keywords));
        anyMaterial = anyMaterial || request.kind == RequestKind::Material;
    }
    if (!anyMaterial) used.insert(combinationOf({}));
    std::vector<VariantKey> kept;
    for (const VariantKey& key : space.enumerate()) {
        Names on = space.table().namesOf(key);
        Names combination;
        for (const Names& set : featureSets) {
            std::string chosen;
            for (const std::string& keyword : set) {
                if (std::find(on.begin(), on.end(), keyword) != on.end()) chosen = keyword;
            }
            combination.push_back(chosen);
        }
        if (always || used.count(combination) != 0) kept.push_back(key);
    }
    return kept;
}

TEST(MaterialSelectionProperty, ShipsExactlyTheBruteForceFilterInOrder) {
    PassGenerator generator(20261127);
    int checked = 0, withRules = 0, withSkips = 0, partial = 0;
    for (int round = 0; round < 500; ++round) {
        std::vector<std::string> pragmas = generator.pragmas();
        DiagnosticList sink;
        std::optional<PassKeywords> keywords = testing::parse(pragmas, sink);
        ASSERT_TRUE(keywords) << ::testing::PrintToString(pragmas);
        generator.maybeFlipASet(*keywords);
        std::optional<VariantSpace> space = VariantSpace::build(*keywords, sink);
        ASSERT_TRUE(space);
        std::vector<KeywordRequest> requests = generator.requests(*keywords);
        const bool always = generator.pick(9) == 0;
        MaterialSelection selection =
            MaterialSelection::select(*keywords, *space, requests, always);
        std::vector<VariantKey> expected = bruteForce(*keywords, *space, requests, always);
        const std::string context = ::testing::PrintToString(pragmas);
        ASSERT_EQ(selection.count(), expected.size()) << context;
        ASSERT_EQ(selection.enumerate(), expected) << context;
        std::set<VariantKey> shipped(expected.begin(), expected.end());
        for (const VariantKey& key : space->enumerate()) {
            ASSERT_EQ(selection.explain(key).ships, shipped.count(key) != 0) << context;
        }
        ++checked;
        withRules += keywords->rules.empty() ? 0 : 1;
        withSkips += keywords->skipped.empty() ? 0 : 1;
        partial += expected.size() < space->count() ? 1 : 0;
    }
    EXPECT_EQ(checked, 500);
    EXPECT_GT(withRules, 100);
    EXPECT_GT(withSkips, 100);
    EXPECT_GT(partial, 150);
}

}  // namespace
}  // namespace varc::variants
