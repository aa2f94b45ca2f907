// SPDX-License-Identifier: Apache-2.0
// Property validation on lavapipe (issue #16): every lit shader of the library pack (varc's
// library and the seed fixtures) holds every relation, and each deliberately broken copy of
// varc/Forward (tests/properties/mutants) is caught by the relation meant to catch it.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include "VulkanTestSupport.h"
#include "varc/properties/PropertyRunner.h"
#include "varc/render/SceneRenderer.h"

namespace varc::render {
namespace {

using properties::Verdict;

class PropertyRelationsTest : public testing::VulkanTest {
protected:
    // The report of every lit shader in |packName| (in VARC_TEST_PACK_DIR), by shader name.
    std::map<std::string, properties::ShaderReport> check(const std::string& packName) {
        std::map<std::string, properties::ShaderReport> reports;
        auto pack = reader::Pack::open(std::string(VARC_TEST_PACK_DIR) + "/" + packName);
        EXPECT_TRUE(pack) << pack.error().detail;
        if (!pack) return reports;
        auto renderer = SceneRenderer::create(context(), {&*pack});
        EXPECT_TRUE(renderer) << renderer.error().detail;
        if (!renderer) return reports;
        properties::PropertyOptions options;
        options.outDir = (std::filesystem::temp_directory_path() / "varc-properties-test").string();
        properties::PropertyRunner runner(*renderer, options);
        for (const reader::ShaderView& shader : properties::lightingShaders({&*pack}))
            reports.emplace(std::string(shader.name()), runner.check(shader));
        return reports;
    }
};

// The relations that fail for |report|.
std::set<std::string> failing(const properties::ShaderReport& report) {
    std::set<std::string> names;
    for (const properties::RelationOutcome& outcome : report.relations)
        if (outcome.verdict == Verdict::Fail) names.insert(outcome.relation);
    return names;
}

Verdict verdictOf(const properties::ShaderReport& report, const std::string& relation) {
    for (const properties::RelationOutcome& outcome : report.relations)
        if (outcome.relation == relation) return outcome.verdict;
    ADD_FAILURE() << "no relation " << relation;
    return Verdict::NotApplicable;
}

const properties::RelationOutcome* outcomeOf(const properties::ShaderReport& report,
                                             const std::string& relation) {
    for (const properties::RelationOutcome& outcome : report.relations)
        if (outcome.relation == relation) return &outcome;
    return nullptr;
}

std::string detailOf(const properties::ShaderReport& report, const std::string& relation) {
    for (const properties::RelationOutcome& outcome : report.relations)
        if (outcome.relation == relation) return outcome.detail;
    return "";
}

TEST_F(PropertyRelationsTest, EveryLibraryAndSeedShaderHoldsEveryRelation) {
    auto reports = check("library.svpack");
    for (const char* name : {"varc/Forward", "varc/SimpleDiffuse", "varc/GlslVertexLights",
                             "Custom/My First Lighting Shader"}) {
        ASSERT_TRUE(reports.count(name)) << name << " is not checked";
    }
    for (const auto& [name, report] : reports) {
        EXPECT_TRUE(report.error.empty()) << name << ": " << report.error;
        EXPECT_EQ(report.model, properties::LightingModel::Lit)
            << name << ": " << report.modelReason;
        for (const properties::RelationOutcome& outcome : report.relations)
            EXPECT_NE(outcome.verdict, Verdict::Fail) << name << " " << outcome.relation << ":\n"
                                                      << outcome.detail;
        EXPECT_GE(report.renders, 16u) << name;
    }
    // varc/Forward takes every light type: every relation applies and passes (but
    // forward_deferred: no Deferred pass), and the checks draw each of its 15 lit variants
    // (every_variant).
    for (const properties::RelationOutcome& outcome : reports.at("varc/Forward").relations)
        EXPECT_EQ(outcome.verdict,
                  outcome.relation == "forward_deferred" ? Verdict::NotApplicable : Verdict::Pass)
            << outcome.relation;
    EXPECT_EQ(reports.at("varc/Forward").litVariantsDrawn(), 15u);
    EXPECT_EQ(reports.at("varc/Forward").litVariants, 15u);
    // The GLSL shader's ForwardAdd pass has no light keywords: no spots, no cookies.
    const properties::ShaderReport& glsl = reports.at("varc/GlslVertexLights");
    EXPECT_EQ(verdictOf(glsl, "black_cookie"), Verdict::NotApplicable);
    EXPECT_EQ(verdictOf(glsl, "white_cookie"), Verdict::NotApplicable);
    EXPECT_EQ(verdictOf(glsl, "out_of_range"), Verdict::Pass);
    EXPECT_EQ(glsl.lights, "directional point");
}

TEST_F(PropertyRelationsTest, EveryMutantIsCaughtByItsRelation) {
    auto reports = check("mutants.svpack");
    // Each mutant and the relations that must catch it (docs/PROPERTIES.md).
    const std::map<std::string, std::set<std::string>> expected{
        {"varc-mutants/NoAttenuation", {"out_of_range", "black_cookie"}},
        {"varc-mutants/WrongBlend", {"additivity", "additivity_ldr"}},
        {"varc-mutants/CookieIgnored", {"black_cookie"}},
        {"varc-mutants/UnnormalisedNormal", {"scale"}},
        {"varc-mutants/NanSpot", {"finite"}},
        {"varc-mutants/IntensityIgnored", {"intensity"}},
        {"varc-mutants/WorldXLight", {"rotation", "mirror", "light_axis"}},
        {"varc-mutants/FixedDirection", {"behind"}},
        {"varc-mutants/PointCookieNoFalloff", {"white_cookie"}},
        {"varc-mutants/LambertForward", {"forward_deferred"}},
        {"varc-mutants/LightTimesZero", {"lit"}},
    };
    ASSERT_EQ(reports.size(), expected.size() + 5)
        << "the mutants, the control, the two classification fixtures, the unlit shader with a "
           "ForwardAdd pass and the shader with both paths";
    const properties::ShaderReport& control = reports.at("varc-mutants/Control");
    EXPECT_TRUE(control.passed()) << "the unmodified copy must hold every relation";
    for (const properties::RelationOutcome& outcome : control.relations) {
        // A forward-only shader: forward_deferred does not apply, and says why.
        if (outcome.relation == "forward_deferred") {
            EXPECT_EQ(outcome.verdict, Verdict::NotApplicable);
            EXPECT_EQ(outcome.detail, "no Deferred pass");
            continue;
        }
        EXPECT_EQ(outcome.verdict, Verdict::Pass) << outcome.relation << ":\n" << outcome.detail;
    }
    // The shader with both paths holds every relation, forward_deferred included: its forward
    // passes shade with the BRDF the deferred light pass applies to its G-buffer.
    ASSERT_TRUE(reports.count("varc-tests/ForwardDeferred"));
    const properties::ShaderReport& bothPaths = reports.at("varc-tests/ForwardDeferred");
    EXPECT_TRUE(bothPaths.error.empty()) << bothPaths.error;
    EXPECT_EQ(bothPaths.model, properties::LightingModel::Lit) << bothPaths.modelReason;
    for (const properties::RelationOutcome& outcome : bothPaths.relations)
        EXPECT_EQ(outcome.verdict, Verdict::Pass) << outcome.relation << ":\n" << outcome.detail;
    for (const auto& [name, catchers] : expected) {
        ASSERT_TRUE(reports.count(name)) << name;
        const properties::ShaderReport& report = reports.at(name);
        EXPECT_TRUE(report.error.empty()) << name << ": " << report.error;
        std::set<std::string> failed = failing(report);
        for (const std::string& relation : catchers)
            EXPECT_TRUE(failed.count(relation)) << name << " is not caught by " << relation;
        // A bug is never excused as a model: every mutant stays "lit".
        EXPECT_EQ(report.model, properties::LightingModel::Lit)
            << name << ": " << report.modelReason;
    }
    // A shader that reads the light and draws black is lit by its reflection: it FAILs `lit`
    // (each key light, and why that is not excused), not n/a; nothing else fails.
    const properties::ShaderReport& black = reports.at("varc-mutants/LightTimesZero");
    EXPECT_EQ(failing(black), (std::set<std::string>{"lit"}));
    const std::string blackLit = detailOf(black, "lit");
    for (const char* label : {"directional:", "point:", "spot:", "_LightColor0",
                              "yet no key light changes the image (directional 0, point 0, "
                              "spot 0 of 4096)"})
        EXPECT_NE(blackLit.find(label), std::string::npos) << blackLit;
    EXPECT_FALSE(black.passed());
    // A light whose intensity is ignored does not brighten when doubled: a bug, not a model.
    EXPECT_EQ(failing(reports.at("varc-mutants/IntensityIgnored")),
              (std::set<std::string>{"intensity"}));
    // A fixed light direction holds every relation that moves, turns or mirrors the scene about
    // the y axis (the direction is symmetric about it): only a light behind the surface shows it.
    EXPECT_EQ(failing(reports.at("varc-mutants/FixedDirection")),
              (std::set<std::string>{"behind"}));
    // The narrow mutants break nothing else: the relations are specific, not noisy.
    EXPECT_EQ(failing(reports.at("varc-mutants/CookieIgnored")),
              (std::set<std::string>{"black_cookie"}));
    EXPECT_EQ(failing(reports.at("varc-mutants/UnnormalisedNormal")),
              (std::set<std::string>{"scale"}));
    // Each path alone is a correct light: only the comparison of the two sees the Lambert
    // forward passes, in every case (each key light alone and all together, HDR and LDR), with
    // the deferred light pass's variant named.
    const properties::ShaderReport& lambert = reports.at("varc-mutants/LambertForward");
    EXPECT_EQ(failing(lambert), (std::set<std::string>{"forward_deferred"}));
    const std::string paths = detailOf(lambert, "forward_deferred");
    for (const char* label :
         {"directional:", "point:", "spot:", "all lights:", "ldr directional:", "ldr all lights:"})
        EXPECT_NE(paths.find(label), std::string::npos) << paths;
    EXPECT_NE(paths.find("'varc/DeferredLight' pass 0 {SPOT UNITY_HDR_ON}"), std::string::npos)
        << paths;
    // The white cube cookie on a point light: only POINT_COOKIE is broken.
    EXPECT_EQ(failing(reports.at("varc-mutants/PointCookieNoFalloff")),
              (std::set<std::string>{"white_cookie"}));
    EXPECT_NE(detailOf(reports.at("varc-mutants/PointCookieNoFalloff"), "white_cookie")
                  .find("{POINT_COOKIE}"),
              std::string::npos);
    // The failure names the case, the variant and the worst pixels.
    const std::string detail = detailOf(reports.at("varc-mutants/CookieIgnored"), "black_cookie");
    EXPECT_NE(detail.find("directional:"), std::string::npos) << detail;
    EXPECT_NE(detail.find("{DIRECTIONAL_COOKIE}"), std::string::npos) << detail;
    EXPECT_NE(detail.find("expected 0 got"), std::string::npos) << detail;
    // The same failure in fields, for the HTML report: each failing case with its finding, the
    // variants drawn and the three PNGs written (actual, expected, diff).
    const properties::RelationOutcome* cookie =
        outcomeOf(reports.at("varc-mutants/CookieIgnored"), "black_cookie");
    ASSERT_NE(cookie, nullptr);
    ASSERT_FALSE(cookie->cases.empty());
    const properties::FailedCase& first = cookie->cases.front();
    EXPECT_EQ(first.label, "directional");
    EXPECT_NE(first.finding.find("expected 0 got"), std::string::npos) << first.finding;
    EXPECT_EQ(first.variants.size(), 2u);
    EXPECT_NE(first.variants.back().find("{DIRECTIONAL_COOKIE}"), std::string::npos);
    ASSERT_EQ(first.images.size(), 3u);
    const char* kinds[] = {".actual.png", ".expected.png", ".diff.png"};
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_NE(first.images[i].find(std::string("black_cookie.directional") + kinds[i]),
                  std::string::npos)
            << first.images[i];
        EXPECT_TRUE(std::filesystem::is_regular_file(first.images[i])) << first.images[i];
    }
    // A relation that is n/a by the shader's model lists no failing cases.
    const properties::RelationOutcome* sqrtIntensity =
        outcomeOf(reports.at("varc-mutants/SqrtColour"), "intensity");
    ASSERT_NE(sqrtIntensity, nullptr);
    EXPECT_EQ(sqrtIntensity->verdict, Verdict::NotApplicable);
    EXPECT_TRUE(sqrtIntensity->cases.empty());
}

// Relations that do not apply are n/a with the reason, never failures: a shader whose programs
// read no light input and that draws the same whatever its lights is not lit; one whose light
// colour goes through sqrt is a non-linear model. A ForwardAdd pass that reads no light input
// fails `lit` even in a shader that is not lit.
TEST_F(PropertyRelationsTest, ModelsThatTheRelationsDoNotDescribeAreNotApplicable) {
    auto reports = check("mutants.svpack");
    ASSERT_TRUE(reports.count("varc-mutants/Unlit") && reports.count("varc-mutants/SqrtColour") &&
                reports.count("varc-mutants/UnlitAddPass"));
    const properties::ShaderReport& unlit = reports.at("varc-mutants/Unlit");
    EXPECT_EQ(unlit.model, properties::LightingModel::NotLit);
    EXPECT_TRUE(unlit.passed()) << unlit.modelReason;
    EXPECT_NE(unlit.modelReason.find("read no light input"), std::string::npos)
        << unlit.modelReason;
    EXPECT_NE(unlit.modelReason.find("(directional 0 of 4096)"), std::string::npos)
        << unlit.modelReason;
    for (const std::string& relation : properties::notLitRelations()) {
        EXPECT_EQ(verdictOf(unlit, relation), Verdict::NotApplicable) << relation;
        EXPECT_EQ(detailOf(unlit, relation), unlit.modelReason) << relation;
    }
    for (const char* relation : {"finite", "translation", "rotation", "scale"})
        EXPECT_EQ(verdictOf(unlit, relation), Verdict::Pass) << relation;

    const properties::ShaderReport& addPass = reports.at("varc-mutants/UnlitAddPass");
    EXPECT_EQ(addPass.model, properties::LightingModel::NotLit) << addPass.modelReason;
    EXPECT_FALSE(addPass.passed());
    EXPECT_EQ(failing(addPass), (std::set<std::string>{"lit"}));
    const properties::RelationOutcome* addLit = outcomeOf(addPass, "lit");
    ASSERT_NE(addLit, nullptr);
    ASSERT_EQ(addLit->cases.size(), 1u) << addLit->detail;
    EXPECT_EQ(addLit->cases[0].label, "reflection");
    EXPECT_NE(addLit->cases[0].finding.find("ForwardAdd variant"), std::string::npos)
        << addLit->cases[0].finding;
    EXPECT_NE(addLit->cases[0].finding.find("reads no light input, yet Unity draws it once per "
                                            "light"),
              std::string::npos)
        << addLit->cases[0].finding;

    const properties::ShaderReport& sqrtColour = reports.at("varc-mutants/SqrtColour");
    EXPECT_EQ(sqrtColour.model, properties::LightingModel::NonLinear) << sqrtColour.modelReason;
    EXPECT_EQ(verdictOf(sqrtColour, "intensity"), Verdict::NotApplicable);
    for (const properties::RelationOutcome& outcome : sqrtColour.relations) {
        if (outcome.relation == "intensity" || outcome.relation == "forward_deferred") continue;
        EXPECT_EQ(outcome.verdict, Verdict::Pass) << outcome.relation << ":\n" << outcome.detail;
    }
}

}  // namespace
}  // namespace varc::render
