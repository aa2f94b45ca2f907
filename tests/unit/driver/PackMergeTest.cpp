// SPDX-License-Identifier: Apache-2.0
// mergePartialPacks: programs taken from the part that compiled them (merged by SPIR-V bytes
// when several did), parts checked for being one sharded build, stage interfaces checked across.
#include <gtest/gtest.h>

#include "varc/driver/PackMerge.h"
#include "varc/pack/PartialPack.h"

namespace varc::driver {
namespace {

pack::PackProgram program(Stage stage, std::vector<uint32_t> spirv,
                          std::vector<pack::StageVariable> inputs = {},
                          std::vector<pack::StageVariable> outputs = {}) {
    pack::PackProgram result;
    result.stage = stage;
    result.entryPoint = stage == Stage::Vertex ? "vert" : "frag";
    result.spirv = std::move(spirv);
    result.reflection.inputs = std::move(inputs);
    result.reflection.outputs = std::move(outputs);
    result.source = {"a.shader", 12, {}};
    return result;
}

// A shard of a one-pass build with two variants: {} uses programs 0 (vertex) and 1 (fragment),
// {FOO} uses 0 and 2. |real| says which of the three this shard compiled.
PartialPackInput part(const std::string& path, const std::string& shard, std::array<bool, 3> real,
                      const std::string& fooInputType = "vec4") {
    PartialPackInput input;
    input.path = path;
    pack::PackContents& contents = input.contents;
    contents.toolchain = {{"varc", "0.1.0"}, {std::string(pack::kShardTool), shard + " level=7"}};
    contents.inputsHash = 42;
    pack::PackPass pass;
    pass.keywordTable = {"FOO"};
    pack::PackVariant plain, foo;
    foo.key.set(0);
    plain.programs[stageIndex(Stage::Vertex)] = foo.programs[stageIndex(Stage::Vertex)] = 0;
    plain.programs[stageIndex(Stage::Fragment)] = 1;
    foo.programs[stageIndex(Stage::Fragment)] = 2;
    pass.variants = {plain, foo};
    contents.shaders = {{"S", {pass}, {}}};
    std::vector<pack::PackProgram> programs = {
        program(Stage::Vertex, {0x07230203, 1}, {}, {{"uv", 0, "vec4"}}),
        program(Stage::Fragment, {0x07230203, 2}, {{"uv", 0, "vec4"}}),
        program(Stage::Fragment, {0x07230203, 3}, {{"uv", 0, fooInputType}})};
    for (uint32_t i = 0; i < 3; ++i) {
        contents.programs.push_back(
            real[i] ? programs[i] : program(programs[i].stage, pack::placeholderSpirv(i)));
    }
    return input;
}

TEST(PackMerge, TakesEachProgramFromThePartThatCompiledIt) {
    Result<MergedPack> merged = mergePartialPacks(
        {part("b", "2/2", {false, true, false}), part("a", "1/2", {true, false, true})});
    ASSERT_TRUE(merged.ok()) << merged.error().detail;
    EXPECT_TRUE(merged->errors.empty());
    EXPECT_EQ(merged->compressionLevel, 7);
    const pack::PackContents& contents = merged->contents;
    EXPECT_EQ(contents.toolchain, (std::vector<pack::ToolVersion>{{"varc", "0.1.0"}}));
    EXPECT_EQ(contents.inputsHash, 42u);
    for (const pack::PackProgram& p : contents.programs) {
        EXPECT_FALSE(pack::isPlaceholderSpirv(p.spirv));
    }
    const auto& variants = contents.shaders[0].passes[0].variants;
    EXPECT_EQ(contents.programs[variants[0].programs[stageIndex(Stage::Fragment)]].spirv,
              (std::vector<uint32_t>{0x07230203, 2}));
    EXPECT_EQ(contents.programs[variants[1].programs[stageIndex(Stage::Fragment)]].spirv,
              (std::vector<uint32_t>{0x07230203, 3}));
}

// A shard of the same build that built whole variants: |mine| says which of {} and {FOO}; the
// other variant's stages name placeholders. Every real program comes from line |line|.
PartialPackInput variantPart(const std::string& path, const std::string& shard,
                             std::array<bool, 2> mine, uint32_t line) {
    PartialPackInput input = part(path, shard, {true, true, true});
    pack::PackContents& contents = input.contents;
    contents.programs.clear();
    for (pack::PackVariant& variant : contents.shaders[0].passes[0].variants) {
        const bool built = mine[variant.key.test(0) ? 1 : 0];
        for (Stage stage : {Stage::Vertex, Stage::Fragment}) {
            uint32_t tag = stage == Stage::Vertex ? 1 : (variant.key.test(0) ? 3 : 2);
            pack::PackProgram program_ = program(
                stage, built ? std::vector<uint32_t>{0x07230203, tag}
                             : pack::placeholderSpirv(static_cast<uint32_t>(stageIndex(stage))));
            program_.source.line = line;
            variant.programs[stageIndex(stage)] = static_cast<uint32_t>(contents.programs.size());
            contents.programs.push_back(program_);
        }
    }
    return input;
}

TEST(PackMerge, MergesAProgramSeveralPartsCompiledByItsBytes) {
    // Both parts compiled the vertex program {0x07230203, 1}: the merged pack holds it once, as
    // the whole build does, with the source of its first use (part a's, variant {}).
    Result<MergedPack> merged = mergePartialPacks(
        {variantPart("b", "2/2", {false, true}, 30), variantPart("a", "1/2", {true, false}, 12)});
    ASSERT_TRUE(merged.ok()) << merged.error().detail;
    EXPECT_TRUE(merged->errors.empty());
    const pack::PackContents& contents = merged->contents;
    ASSERT_EQ(contents.programs.size(), 3u);
    const auto& variants = contents.shaders[0].passes[0].variants;
    const size_t vertex = stageIndex(Stage::Vertex), fragment = stageIndex(Stage::Fragment);
    EXPECT_EQ(variants[0].programs[vertex], variants[1].programs[vertex]);
    EXPECT_NE(variants[0].programs[fragment], variants[1].programs[fragment]);
    EXPECT_EQ(contents.programs[variants[0].programs[vertex]].source.line, 12u);
    EXPECT_EQ(contents.programs[variants[1].programs[fragment]].source.line, 30u);
    EXPECT_EQ(contents.programs[variants[1].programs[fragment]].spirv,
              (std::vector<uint32_t>{0x07230203, 3}));
    for (const pack::PackProgram& p : contents.programs) {
        EXPECT_FALSE(pack::isPlaceholderSpirv(p.spirv));
    }
}

TEST(PackMerge, RefusesAVariantNoPartBuilt) {
    Result<MergedPack> merged = mergePartialPacks(
        {variantPart("a", "1/2", {true, false}, 12), variantPart("b", "2/2", {true, false}, 12)});
    ASSERT_FALSE(merged.ok());
    EXPECT_EQ(merged.error().detail,
              "no part holds the vertex program of shader \"S\" pass 0, keywords: FOO");
}

TEST(PackMerge, RefusesPartsThatAreNotOneBuild) {
    auto errorOf = [](std::vector<PartialPackInput> parts) {
        Result<MergedPack> merged = mergePartialPacks(std::move(parts));
        EXPECT_FALSE(merged.ok());
        return merged.ok() ? std::string() : merged.error().detail;
    };
    EXPECT_EQ(
        errorOf({part("a", "1/3", {true, true, true}), part("c", "3/3", {false, false, false})}),
        "shard 2/3 is missing: give all 3 parts");
    EXPECT_EQ(errorOf({part("a", "1/2", {true, true, true}), part("b", "1/2", {true, true, true})}),
              "a and b are both shard 1/2");
    PartialPackInput other = part("b", "2/2", {false, false, false});
    other.contents.inputsHash = 43;
    EXPECT_EQ(errorOf({part("a", "1/2", {true, true, true}), other})
                  .rfind("b: built from other inputs or options than a (inputs hash", 0),
              0u);
    PartialPackInput whole = part("w", "1/1", {true, true, true});
    whole.contents.toolchain.pop_back();
    EXPECT_EQ(errorOf({whole}), "w: not a partial pack (built without --shard)");
    EXPECT_EQ(errorOf({part("a", "1/2", {true, true, true}), part("b", "2/3", {true, true, true})}),
              "b: shard 2/3 (level 7) is not of the same sharded build as a, shard 1/2 (level 7)");
}

TEST(PackMerge, ChecksStageInterfacesAcrossParts) {
    // {FOO}'s fragment program reads a vec2 the vertex program (another part's) never writes.
    Result<MergedPack> merged = mergePartialPacks({part("a", "1/2", {true, true, false}, "vec2"),
                                                   part("b", "2/2", {false, false, true}, "vec2")});
    ASSERT_TRUE(merged.ok()) << merged.error().detail;
    ASSERT_EQ(merged->errors.size(), 1u);
    EXPECT_EQ(merged->errors[0],
              "a.shader:12:1: error: fragment input 'uv' (location 0, vec2) is not written by the "
              "vertex program in shader \"S\" pass 0, keywords: FOO");
}

}  // namespace
}  // namespace varc::driver
