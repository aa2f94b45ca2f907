// SPDX-License-Identifier: Apache-2.0
// Property test: for many random pragma blocks (user sets, shortcuts with options and rules,
// skips), VariantSpace agrees with a naive full-product-then-filter reference, in order.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "VariantsTestSupport.h"
#include "varc/variants/Shortcuts.h"

namespace varc::variants {
namespace {

using Names = std::vector<std::string>;

// The obvious model: nested loops over every set (first slowest), then drop variants with a
// skipped keyword or breaking a rule. Each variant is its sorted keyword list.
class ReferenceEnumerator {
public:
    explicit ReferenceEnumerator(const PassKeywords& keywords) : mKeywords(keywords) {}

    std::vector<Names> run() {
        Names chosen;
        recurse(0, chosen);
        return mVariants;
    }

    uint64_t fullProduct() const {
        uint64_t product = 1;
        for (const KeywordSetDecl& set : mKeywords.sets) product *= set.keywords.size();
        return product;
    }

private:
    void recurse(size_t set, Names& chosen) {
        if (set == mKeywords.sets.size()) {
            if (keep(chosen)) {
                Names sorted = chosen;
                std::sort(sorted.begin(), sorted.end());
                mVariants.push_back(sorted);
            }
            return;
        }
        for (const std::string& keyword : mKeywords.sets[set].keywords) {
            if (!keyword.empty()) chosen.push_back(keyword);
            recurse(set + 1, chosen);
            if (!keyword.empty()) chosen.pop_back();
        }
    }

    bool keep(const Names& on) const {
        auto has = [&](const std::string& k) {
            return std::find(on.begin(), on.end(), k) != on.end();
        };
        if (std::any_of(mKeywords.skipped.begin(), mKeywords.skipped.end(), has)) return false;
        for (const ValidityRule& rule : mKeywords.rules) {
            if (!has(rule.keyword)) continue;
            auto& needs = rule.requiresAnyOf;
            if (!needs.empty() && std::none_of(needs.begin(), needs.end(), has)) return false;
            if (std::any_of(rule.forbids.begin(), rule.forbids.end(), has)) return false;
        }
        return true;
    }

    const PassKeywords& mKeywords;
    std::vector<Names> mVariants;
};

// Random pragma blocks mixing user sets, shortcuts (with options) and skip_variants.
class BlockGenerator {
public:
    explicit BlockGenerator(uint32_t seed) : mRandom(seed) {}

    std::vector<std::string> next() {
        std::vector<std::string> pragmas;
        for (int i = pick(3); i > 0; --i) pragmas.push_back(userSet());
        for (int i = pick(2); i > 0; --i) pragmas.push_back(shortcut());
        std::shuffle(pragmas.begin(), pragmas.end(), mRandom);
        if (pick(2) == 1) pragmas.push_back(skip());
        if (pick(4) == 0) pragmas.push_back("instancing_options procedural:setup");
        return pragmas;
    }

private:
    int pick(int maxInclusive) {
        return std::uniform_int_distribution<int>(0, maxInclusive)(mRandom);
    }

    std::string userSet() {
        static const char* kDirectives[] = {"multi_compile", "shader_feature",
                                            "multi_compile_local_fragment", "shader_feature_local"};
        std::string line = kDirectives[pick(3)];
        int keywordCount = 1 + pick(3);
        int underscoreAt = pick(keywordCount + 1);
        for (int i = 0; i <= keywordCount; ++i) {
            if (i == underscoreAt) line += " _";
            if (i < keywordCount) line += " U" + std::to_string(mNextUser++);
        }
        return line;
    }

    std::string shortcut() {
        const auto& shortcuts = builtinShortcuts();
        std::string line =
            shortcuts[static_cast<size_t>(pick(static_cast<int>(shortcuts.size()) - 1))]
                .directive();
        for (const ShortcutOption& option : shortcutOptions()) {
            if (pick(5) == 0) line += " " + option.name;
        }
        return line;
    }

    std::string skip() {
        static const char* kPool[] = {"SPOT",
                                      "POINT",
                                      "SHADOWS_SOFT",
                                      "SHADOWS_CUBE",
                                      "LIGHTMAP_ON",
                                      "VERTEXLIGHT_ON",
                                      "FOG_EXP",
                                      "U0",
                                      "U1",
                                      "U3",
                                      "U5",
                                      "DYNAMICLIGHTMAP_ON",
                                      "SHADOWS_SHADOWMASK",
                                      "INSTANCING_ON"};
        std::string line = "skip_variants";
        for (int i = 0; i <= pick(2); ++i) line += std::string(" ") + kPool[pick(13)];
        return line;
    }

    std::mt19937 mRandom;
    int mNextUser = 0;
};

std::vector<Names> spaceVariants(const VariantSpace& space) {
    std::vector<Names> variants;
    space.forEach([&](const VariantKey& key) {
        variants.push_back(space.table().namesOf(key));
        return true;
    });
    return variants;
}

TEST(VariantSpaceProperty, CountOrderAndContentsMatchTheNaiveModel) {
    BlockGenerator generator(20261122);
    int checked = 0;
    int withRules = 0;
    int withSkips = 0;
    for (int round = 0; round < 600; ++round) {
        std::vector<std::string> pragmas = generator.next();
        DiagnosticList sink;
        std::optional<PassKeywords> keywords = testing::parse(pragmas, sink);
        if (!keywords) continue;  // two shortcuts sharing keywords: a legitimate error
        std::optional<VariantSpace> space = VariantSpace::build(*keywords, sink);
        ASSERT_TRUE(space);
        ReferenceEnumerator reference(*keywords);
        std::vector<Names> expected = reference.run();
        std::string context = ::testing::PrintToString(pragmas);
        ASSERT_EQ(space->count(), expected.size()) << context;
        ASSERT_EQ(spaceVariants(*space), expected) << context;
        ASSERT_EQ(space->fullCount(), reference.fullProduct()) << context;
        std::vector<VariantKey> keys = space->enumerate();
        ASSERT_EQ(std::set<VariantKey>(keys.begin(), keys.end()).size(), keys.size()) << context;
        ++checked;
        withRules += keywords->rules.empty() ? 0 : 1;
        withSkips += keywords->skipped.empty() ? 0 : 1;
    }
    EXPECT_GT(checked, 300);
    EXPECT_GT(withRules, 100);
    EXPECT_GT(withSkips, 100);
    RecordProperty("checked_blocks", checked);
}

}  // namespace
}  // namespace varc::variants
