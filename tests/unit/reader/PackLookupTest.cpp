// SPDX-License-Identifier: Apache-2.0
// Pack lookups: shaders by name, passes by index and LightMode, variants under every policy.
#include <gtest/gtest.h>

#include <thread>

#include "PackTestData.h"
#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"

namespace varc {
namespace {

using reader::Pack;
using reader::PassView;
using reader::VariantView;
using varc::Stage;
using variants::SelectionPolicy;

class PackLookup : public ::testing::Test {
protected:
    void SetUp() override {
        mContents = packtest::makeSampleContents();
        Result<Pack> pack = Pack::fromBytes(packwriter::serializePack(mContents));
        ASSERT_TRUE(pack.ok()) << pack.error().detail;
        mPack.emplace(std::move(*pack));
    }
    PassView litPass(std::string_view lightMode) {
        return *mPack->findShader("Custom/Lit")->pass(lightMode);
    }

    pack::PackContents mContents;
    std::optional<Pack> mPack;
};

TEST_F(PackLookup, FindsShadersByName) {
    ASSERT_TRUE(mPack->findShader("Custom/Lit"));
    EXPECT_EQ(mPack->findShader("Custom/Lit")->name(), "Custom/Lit");
    EXPECT_EQ(mPack->findShader("Custom/Unlit")->index(), 1u);
    EXPECT_EQ(mPack->findShader("Custom/Empty")->index(), 2u);
    EXPECT_FALSE(mPack->findShader("Custom/Missing"));
    EXPECT_FALSE(mPack->findShader(""));
    EXPECT_EQ(mPack->shaderCount(), 3u);
    EXPECT_EQ(mPack->inputsHash(), 0x0123456789abcdefull);
    EXPECT_EQ(mPack->toolchain(), mContents.toolchain);
}

TEST_F(PackLookup, FindsPassesByIndexAndLightMode) {
    reader::ShaderView lit = *mPack->findShader("Custom/Lit");
    ASSERT_EQ(lit.passCount(), 3u);
    EXPECT_EQ(lit.pass(1)->name(), "FORWARD_DELTA");
    EXPECT_FALSE(lit.pass(3));
    EXPECT_EQ(lit.pass("ForwardAdd")->index(), 1u);
    EXPECT_EQ(lit.pass("forwardbase")->name(), "FORWARD");  // tags compare case-insensitively
    EXPECT_FALSE(lit.pass("Deferred"));
    EXPECT_EQ(lit.pass(0)->tagValue("rendertype"), "Opaque");
}

TEST_F(PackLookup, ExactLookupFindsEachVariant) {
    PassView base = litPass("ForwardBase");
    const pack::PackPass& source = mContents.shaders[0].passes[0];
    ASSERT_EQ(base.variantCount(), source.variants.size());
    for (size_t e = 0; e < source.variants.size(); ++e) {
        Result<VariantView> found = base.lookup(source.variants[e].key, SelectionPolicy::Exact);
        ASSERT_TRUE(found.ok()) << found.error().detail;
        EXPECT_TRUE(found->exact());
        EXPECT_EQ(found->enumerationIndex(), e);
        EXPECT_EQ(found->program(Stage::Vertex)->index(), source.variants[e].programs[0]);
        EXPECT_FALSE(found->hasStage(Stage::Geometry));
    }
}

TEST_F(PackLookup, LookupByNamesIgnoresUndeclaredKeywords) {
    Result<VariantView> found =
        litPass("ForwardBase")
            .lookup(std::vector<std::string>{"SHADOWS_SCREEN", "DIRECTIONAL", "NOT_DECLARED"},
                    SelectionPolicy::Exact);
    ASSERT_TRUE(found.ok()) << found.error().detail;
    EXPECT_EQ(found->keywords(), (std::vector<std::string>{"DIRECTIONAL", "SHADOWS_SCREEN"}));
    std::vector<std::string_view> views = {"DIRECTIONAL", "FOG_EXP"};
    EXPECT_EQ(litPass("ForwardBase").lookup(views, SelectionPolicy::Exact)->enumerationIndex(), 1u);
}

TEST_F(PackLookup, DynamicBranchSetsListTheirKeywordsAndSelectNoVariant) {
    EXPECT_TRUE(litPass("ForwardBase").dynamicKeywords().empty());  // no dynamic_branch set
    pack::PackContents contents = packtest::makeSampleContents();
    auto& passes = contents.shaders[0].passes;
    passes[0].sets.push_back({"dynamic_branch_local", {"", "RED", "GREEN"}});
    passes[0].sets.push_back({"dynamic_branch", {"BLUE", "RED"}});
    passes[1].sets.push_back({"dynamic_branch", {"WAVE"}});
    Result<Pack> pack = Pack::fromBytes(packwriter::serializePack(contents));
    ASSERT_TRUE(pack.ok()) << pack.error().detail;
    reader::ShaderView lit = *pack->findShader("Custom/Lit");
    PassView base = *lit.pass(size_t{0});
    EXPECT_EQ(base.dynamicKeywords(), (std::vector<std::string>{"BLUE", "GREEN", "RED"}));
    EXPECT_EQ(lit.dynamicKeywords(), (std::vector<std::string>{"BLUE", "GREEN", "RED", "WAVE"}));
    Result<VariantView> found = base.lookup(
        std::vector<std::string>{"RED", "SHADOWS_SCREEN", "DIRECTIONAL"}, SelectionPolicy::Strict);
    ASSERT_TRUE(found.ok()) << found.error().detail;
    EXPECT_EQ(found->keywords(), (std::vector<std::string>{"DIRECTIONAL", "SHADOWS_SCREEN"}));
}

TEST_F(PackLookup, ExactAndStrictMissesNameTheProblem) {
    PassView base = litPass("ForwardBase");
    variants::VariantKey none;  // every ForwardBase variant has DIRECTIONAL
    Result<VariantView> exact = base.lookup(none, SelectionPolicy::Exact);
    ASSERT_FALSE(exact.ok());
    EXPECT_EQ(exact.error().code, ErrorCode::NotFound);
    EXPECT_NE(exact.error().detail.find("shader 'Custom/Lit' pass 0"), std::string::npos);
    Result<VariantView> strict =
        base.lookup(std::vector<std::string>{"FOG_EXP"}, SelectionPolicy::Strict);
    ASSERT_FALSE(strict.ok());
    EXPECT_NE(strict.error().detail.find("{FOG_EXP}"), std::string::npos) << strict.error().detail;
}

TEST_F(PackLookup, ClosestAndFirstFallBack) {
    PassView base = litPass("ForwardBase");
    Result<VariantView> closest =
        base.lookup(std::vector<std::string>{"FOG_EXP"}, SelectionPolicy::Closest);
    ASSERT_TRUE(closest.ok()) << closest.error().detail;
    EXPECT_FALSE(closest->exact());
    EXPECT_EQ(closest->keywords(), (std::vector<std::string>{"DIRECTIONAL", "FOG_EXP"}));
    Result<VariantView> first =
        base.lookup(std::vector<std::string>{"FOG_EXP"}, SelectionPolicy::First);
    ASSERT_TRUE(first.ok());
    EXPECT_EQ(first->enumerationIndex(), 0u);
}

TEST_F(PackLookup, PassWithoutVariantsFindsNothing) {
    PassView empty = *mPack->findShader("Custom/Empty")->pass(0);
    for (auto policy : {SelectionPolicy::Exact, SelectionPolicy::Closest, SelectionPolicy::First,
                        SelectionPolicy::Strict}) {
        EXPECT_FALSE(empty.lookup(variants::VariantKey{}, policy).ok());
    }
}

TEST_F(PackLookup, LookupFromLightDescription) {
    variants::LightDescription spot;
    spot.type = variants::LightType::Spot;
    Result<VariantView> add = litPass("ForwardAdd").lookup(spot, SelectionPolicy::Exact);
    ASSERT_TRUE(add.ok()) << add.error().detail;
    EXPECT_EQ(add->keywords(), std::vector<std::string>{"SPOT"});

    variants::LightDescription sun;
    sun.shadows = variants::ShadowMode::Hard;
    PassView base = litPass("ForwardBase");
    Result<VariantView> lit =
        base.lookup(sun, SelectionPolicy::Closest, base.keyOf(std::vector<std::string>{"FOG_EXP"}));
    ASSERT_TRUE(lit.ok()) << lit.error().detail;
    EXPECT_EQ(lit->keywords(),
              (std::vector<std::string>{"DIRECTIONAL", "FOG_EXP", "SHADOWS_SCREEN"}));

    Result<VariantView> shadow = litPass("ShadowCaster").lookup(sun, SelectionPolicy::Closest);
    ASSERT_FALSE(shadow.ok());
    EXPECT_EQ(shadow.error().code, ErrorCode::InvalidInput);
}

TEST_F(PackLookup, VariantGivesSpirvReflectionStateAndSource) {
    VariantView variant =
        *litPass("ForwardAdd").lookup(std::vector<std::string>{"POINT"}, SelectionPolicy::Exact);
    const pack::PackVariant& source = mContents.shaders[0].passes[1].variants[0];
    const pack::PackProgram& fragment = mContents.programs[source.programs[1]];
    Result<std::span<const uint32_t>> words = variant.spirv(Stage::Fragment);
    ASSERT_TRUE(words.ok());
    EXPECT_EQ(std::vector<uint32_t>(words->begin(), words->end()), fragment.spirv);
    EXPECT_EQ(variant.program(Stage::Fragment)->reflection(), fragment.reflection);
    EXPECT_EQ(variant.program(Stage::Fragment)->source(), fragment.source);
    EXPECT_EQ(variant.renderState(), mContents.shaders[0].passes[1].state);
    EXPECT_EQ(variant.renderState().srcColor.property, "_SrcBlend");
    EXPECT_FALSE(variant.spirv(Stage::Hull).ok());
    EXPECT_NE(variant.describe().find("{POINT}"), std::string::npos);
    EXPECT_NE(variant.program(Stage::Vertex)->describe().find(".shader:"), std::string::npos);
}

TEST_F(PackLookup, ConcurrentLookupsAndDecompressionAgree) {
    std::vector<std::vector<uint32_t>> expected;
    for (const pack::PackProgram& program : mContents.programs) expected.push_back(program.spirv);
    std::vector<std::thread> threads;
    std::atomic<int> failures{0};
    for (int t = 0; t < 8; ++t) {
        threads.emplace_back([&, t] {
            for (size_t i = 0; i < expected.size(); ++i) {
                size_t p = (i + static_cast<size_t>(t)) % expected.size();
                Result<std::span<const uint32_t>> words = mPack->program(p).spirv();
                if (!words.ok() || !std::equal(words->begin(), words->end(), expected[p].begin(),
                                               expected[p].end())) {
                    ++failures;
                }
                if (!litPass("ForwardBase")
                         .lookup(std::vector<std::string>{"FOG_EXP"}, SelectionPolicy::Closest)
                         .ok()) {
                    ++failures;
                }
            }
        });
    }
    for (std::thread& thread : threads) thread.join();
    EXPECT_EQ(failures.load(), 0);
}

TEST_F(PackLookup, SpirvSpansAreStableAcrossCalls) {
    Result<std::span<const uint32_t>> a = mPack->program(0).spirv();
    Result<std::span<const uint32_t>> b = mPack->program(0).spirv();
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->data(), b->data());
    Pack moved = std::move(*mPack);  // views into the image survive a move of the Pack
    EXPECT_EQ(moved.program(0).spirv()->data(), a->data());
    mPack.reset();
}

}  // namespace
}  // namespace varc
