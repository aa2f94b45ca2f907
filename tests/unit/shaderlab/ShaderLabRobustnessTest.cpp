// SPDX-License-Identifier: Apache-2.0
// parseShaderLab never crashes or hangs: every prefix of the fixtures, random garbage, mutations.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "ShaderLabTestSupport.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab {
namespace {

const std::string kFixtures[] = {
    VARC_SHARED_DIR "/fixtures/seed000-multiple-lights/My First Lighting Shader.shader",
    VARC_SHARED_DIR "/fixtures/seed002-deferred-lights/DeferredShading.shader",
};

// A parse either succeeds without errors or fails with at least one, each with a location.
void expectConsistent(const testing::ParseOutcome& outcome, std::string_view input) {
    EXPECT_EQ(outcome.shader.has_value(), !outcome.diagnostics.hasErrors()) << input;
    for (const Diagnostic& diagnostic : outcome.diagnostics.diagnostics()) {
        EXPECT_EQ(diagnostic.location.file, testing::kTestFile) << input;
        EXPECT_GE(diagnostic.location.line, 1u) << input;
        EXPECT_GE(diagnostic.location.column, 1u) << input;
    }
}

TEST(ShaderLabRobustness, EveryPrefixOfTheFixturesParsesOrReportsAnError) {
    for (const std::string& path : kFixtures) {
        std::string text = testing::readFile(path);
        ASSERT_FALSE(text.empty()) << "cannot read " << path;
        size_t closing = text.rfind('}');
        for (size_t length = 0; length <= text.size(); ++length) {
            std::string_view prefix = std::string_view(text).substr(0, length);
            auto outcome = testing::parse(prefix);
            expectConsistent(outcome, prefix);
            // Only prefixes that include the shader's closing brace are complete shaders.
            EXPECT_EQ(outcome.shader.has_value(), length > closing) << "prefix length " << length;
        }
    }
}

// Random token soup from ShaderLab's vocabulary, plus raw bytes.
std::string randomShaderLabish(std::mt19937& random) {
    static const char* const kPieces[] = {
        "Shader",     "\"A\"",       "{",         "}",      "SubShader", "Pass",     "Category",
        "Properties", "Tags",        "\"k\"",     "=",      "(",         ")",        ",",
        "[",          "]",           "_X",        "Color",  "Range",     "2D",       "1",
        "-.5",        "Blend",       "One",       "Off",    "Stencil",   "Ref",      "CGPROGRAM",
        "ENDCG",      "HLSLINCLUDE", "ENDHLSL",   "//",     "/*",        "*/",       "\"",
        "\n",         " ",           "\t",        "LOD",    "UsePass",   "GrabPass", "SetTexture",
        "Material",   "Fallback",    "ColorMask", "Offset", "#",         "\x01",     "\xff"};
    std::uniform_int_distribution<size_t> count(0, 60);
    std::uniform_int_distribution<size_t> pick(0, std::size(kPieces) - 1);
    std::string text;
    for (size_t n = count(random); n > 0; --n) text += std::string(kPieces[pick(random)]) + " ";
    return text;
}

TEST(ShaderLabRobustness, RandomTokenSoupNeverCrashes) {
    std::mt19937 random(1234);
    size_t parsed = 0;
    for (int i = 0; i < 3000; ++i) {
        std::string text = "Shader \"A\" { " + randomShaderLabish(random);
        auto outcome = testing::parse(text);
        expectConsistent(outcome, text);
        parsed += outcome.shader.has_value();
    }
    EXPECT_LT(parsed, 3000u);  // random soup is essentially never a valid shader
}

TEST(ShaderLabRobustness, SingleByteMutationsOfFixturesNeverCrash) {
    std::mt19937 random(99);
    for (const std::string& path : kFixtures) {
        std::string text = testing::readFile(path);
        ASSERT_FALSE(text.empty()) << "cannot read " << path;
        std::uniform_int_distribution<size_t> position(0, text.size() - 1);
        std::uniform_int_distribution<int> byte(0, 255);
        for (int i = 0; i < 1000; ++i) {
            std::string mutated = text;
            mutated[position(random)] = static_cast<char>(byte(random));
            expectConsistent(testing::parse(mutated), mutated);
        }
    }
}

TEST(ShaderLabRobustness, DeeplyNestedBracesInSkippedBlocksDoNotExhaustTheStack) {
    std::string text = "Shader \"A\" { SubShader { Pass { Material " + std::string(200000, '{');
    auto outcome = testing::parse(text);
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(), "'{' opened here is never closed");
}

}  // namespace
}  // namespace varc::shaderlab
