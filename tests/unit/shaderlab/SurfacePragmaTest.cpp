// SPDX-License-Identifier: Apache-2.0
// parseSurfaceOptions: the words of `#pragma surface FUNC MODEL [options]`.
#include <gtest/gtest.h>

#include "SurfacePragma.h"

namespace varc::shaderlab {
namespace {

using Alpha = SurfaceOptions::Alpha;

struct Parsed {
    bool ok = false;
    SurfaceProgram program;
    DiagnosticList diagnostics;
};

Parsed parseWords(std::string_view text) {
    Parsed parsed;
    parsed.ok =
        parseSurfaceOptions(text, SourceLocation{3, 10, 20}, parsed.program, parsed.diagnostics);
    return parsed;
}

TEST(SurfacePragma, ReadsFunctionModelAndValueOptions) {
    Parsed parsed = parseWords(" surf StandardSpecular vertex:vert finalcolor:tint alphatest:_Cut");
    ASSERT_TRUE(parsed.ok);
    EXPECT_EQ(parsed.program.function, "surf");
    EXPECT_EQ(parsed.program.lightingModel, "StandardSpecular");
    EXPECT_EQ(parsed.program.options.vertexFunction, "vert");
    EXPECT_EQ(parsed.program.options.finalColorFunction, "tint");
    EXPECT_EQ(parsed.program.options.alphaTestProperty, "_Cut");
    EXPECT_TRUE(parsed.diagnostics.diagnostics().empty());
}

TEST(SurfacePragma, ReadsFlagsAndIgnoresACommentAfterThem) {
    Parsed parsed = parseWords(
        " surf Lambert keepalpha addshadow fullforwardshadows noforwardadd noambient "
        "novertexlights nofog noshadow nolightmap nometa dithercrossfade exclude_path:deferred "
        "// alpha:blend");
    ASSERT_TRUE(parsed.ok) << parsed.diagnostics.diagnostics().at(0).message;
    const SurfaceOptions& options = parsed.program.options;
    EXPECT_TRUE(options.keepAlpha && options.addShadow && options.fullForwardShadows &&
                options.noForwardAdd && options.noAmbient && options.noVertexLights &&
                options.noFog && options.noShadow && options.ditherCrossFade);
    EXPECT_EQ(options.shortcutOptions,
              (std::vector<std::string>{"novertexlights", "noshadow", "nolightmap"}));
    EXPECT_FALSE(options.excludeForward);
    EXPECT_EQ(options.alpha, Alpha::Off);  // written after `//`
}

TEST(SurfacePragma, ReadsTheAlphaAndDecalModes) {
    EXPECT_EQ(parseWords(" s Lambert alpha").program.options.alpha, Alpha::Blend);
    EXPECT_EQ(parseWords(" s Lambert alpha:fade").program.options.alpha, Alpha::Fade);
    EXPECT_EQ(parseWords(" s Lambert alpha:premul").program.options.alpha, Alpha::Premultiply);
    EXPECT_EQ(parseWords(" s Lambert decal:add").program.options.decal, SurfaceOptions::Decal::Add);
    EXPECT_TRUE(parseWords(" s Lambert exclude_path:forward").program.options.excludeForward);
}

TEST(SurfacePragma, ReportsAnUnknownOptionAtItsColumn) {
    Parsed parsed = parseWords(" surf Lambert  glossy");
    EXPECT_FALSE(parsed.ok);
    ASSERT_EQ(parsed.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(parsed.diagnostics.diagnostics()[0].message,
              "unknown surface shader option 'glossy'");
    EXPECT_EQ(parsed.diagnostics.diagnostics()[0].location, (SourceLocation{3, 10, 35}));
}

TEST(SurfacePragma, ReportsBadValuesAndMissingWords) {
    Parsed badAlpha = parseWords(" surf Lambert alpha:opaque");
    EXPECT_FALSE(badAlpha.ok);
    EXPECT_EQ(badAlpha.diagnostics.diagnostics().at(0).message,
              "unknown value 'opaque' of 'alpha' (blend, fade, premul)");
    Parsed noValue = parseWords(" surf Lambert vertex:");
    EXPECT_FALSE(noValue.ok);
    EXPECT_EQ(noValue.diagnostics.diagnostics().at(0).message,
              "surface shader option 'vertex:' has no value");
    Parsed noModel = parseWords(" surf");
    EXPECT_FALSE(noModel.ok);
    EXPECT_EQ(noModel.diagnostics.diagnostics().at(0).location, (SourceLocation{3, 10, 20}));
}

TEST(SurfacePragma, WarnsThatTessellationIsNotGenerated) {
    Parsed parsed = parseWords(" surf Lambert tessellate:tess");
    EXPECT_TRUE(parsed.ok);
    ASSERT_EQ(parsed.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(parsed.diagnostics.diagnostics()[0].severity, Severity::Warning);
}

}  // namespace
}  // namespace varc::shaderlab
