// SPDX-License-Identifier: Apache-2.0
// PackWriter: round trips through the reader, determinism, program merging, compression.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>

#include "PackTestData.h"
#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PackDecoder.h"

namespace varc {
namespace {

using packwriter::PackDictionary;
using packwriter::PackWriteOptions;
using packwriter::PackWriteStats;
using packwriter::serializePack;

pack::PackContents roundTrip(const std::string& bytes) {
    Result<reader::Pack> pack = reader::Pack::fromBytes(bytes);
    EXPECT_TRUE(pack.ok()) << (pack.ok() ? "" : pack.error().detail);
    if (!pack.ok()) return {};
    Result<pack::PackContents> contents = reader::decodePack(*pack);
    EXPECT_TRUE(contents.ok());
    return contents.ok() ? *contents : pack::PackContents{};
}

TEST(PackWriter, RoundTripGivesEqualContents) {
    pack::PackContents contents = packtest::makeSampleContents();
    EXPECT_EQ(roundTrip(serializePack(contents)), contents);
}

TEST(PackWriter, PropertiesRoundTripAndAPackWithoutAnyLacksThePropChunk) {
    pack::PackContents contents = packtest::makeSampleContents();
    Result<reader::Pack> pack = reader::Pack::fromBytes(serializePack(contents));
    ASSERT_TRUE(pack.ok());
    std::optional<reader::ShaderView> lit = pack->findShader("Custom/Lit");
    ASSERT_TRUE(lit);
    EXPECT_EQ(lit->properties(), contents.shaders[0].properties);
    EXPECT_TRUE(pack->findShader("Custom/Empty")->properties().empty());

    for (pack::PackShader& shader : contents.shaders) shader.properties.clear();
    std::string bytes = serializePack(contents);
    EXPECT_EQ(bytes.find("PROP"), std::string::npos) << "an empty optional table is left out";
    EXPECT_EQ(roundTrip(bytes), contents);
}

TEST(PackWriter, RoundTripWithAndWithoutDictionary) {
    pack::PackContents contents = packtest::makeSampleContents();
    for (PackDictionary mode : {PackDictionary::Never, PackDictionary::Always}) {
        PackWriteStats stats;
        std::string bytes = serializePack(contents, {.dictionary = mode}, &stats);
        EXPECT_EQ(stats.dictionaryBytes > 0, mode == PackDictionary::Always);
        EXPECT_EQ(roundTrip(bytes), contents);
    }
}

TEST(PackWriter, WritePackThenOpenFromDisk) {
    auto path = std::filesystem::temp_directory_path() / "varc_pack_writer_test.vpk";
    pack::PackContents contents = packtest::makeSampleContents();
    ASSERT_TRUE(packwriter::writePack(path.string(), contents).ok());
    Result<reader::Pack> pack = reader::Pack::open(path.string());
    ASSERT_TRUE(pack.ok()) << pack.error().detail;
    Result<pack::PackContents> decoded = reader::decodePack(*pack);
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(*decoded, contents);
    std::filesystem::remove(path);
}

TEST(PackWriter, SerializingTwiceGivesIdenticalBytes) {
    pack::PackContents contents = packtest::makeSampleContents();
    EXPECT_EQ(serializePack(contents), serializePack(contents));
    PackWriteOptions always{.dictionary = PackDictionary::Always};
    EXPECT_EQ(serializePack(contents, always), serializePack(contents, always));
}

// Reversing contents.programs (and remapping the variants) changes nothing on disk.
TEST(PackWriter, ProgramInsertionOrderDoesNotChangeBytes) {
    pack::PackContents contents = packtest::makeSampleContents();
    pack::PackContents reversed = contents;
    std::reverse(reversed.programs.begin(), reversed.programs.end());
    auto last = static_cast<uint32_t>(contents.programs.size() - 1);
    for (auto& shader : reversed.shaders) {
        for (auto& pass : shader.passes) {
            for (auto& variant : pass.variants) {
                for (uint32_t& program : variant.programs) {
                    if (program != pack::kNoProgram) program = last - program;
                }
            }
        }
    }
    EXPECT_EQ(serializePack(reversed), serializePack(contents));
}

TEST(PackWriter, EqualProgramsAreStoredOnce) {
    pack::PackContents contents = packtest::makeSampleContents();
    PackWriteStats before;
    serializePack(contents, {}, &before);
    // A copy of program 0 with different source info, used by one variant.
    pack::PackProgram copy = contents.programs[0];
    copy.source.file = "Other.shader";
    contents.programs.push_back(copy);
    contents.shaders[0].passes[0].variants[5].programs[0] =
        static_cast<uint32_t>(contents.programs.size() - 1);
    PackWriteStats after;
    std::string bytes = serializePack(contents, {}, &after);
    EXPECT_EQ(after.programs, before.programs);
    EXPECT_EQ(after.blobs, before.blobs);
    pack::PackContents decoded = roundTrip(bytes);
    EXPECT_EQ(decoded.programs.size(), before.programs);
    EXPECT_EQ(decoded.shaders[0].passes[0].variants[5].programs[0], 0u);
    EXPECT_EQ(decoded.programs[0].source.file, contents.programs[0].source.file);
}

TEST(PackWriter, UnusedProgramsAreDropped) {
    pack::PackContents contents = packtest::makeSampleContents();
    pack::PackContents extra = contents;
    extra.programs.push_back({Stage::Vertex, "unused", packtest::fakeSpirv(999), {}, {}});
    EXPECT_EQ(serializePack(extra), serializePack(contents));
}

TEST(PackWriter, ProgramsWithSameSpirvButOtherEntryShareTheBlob) {
    pack::PackContents contents = packtest::makeSampleContents();
    pack::PackProgram renamed = contents.programs[0];
    renamed.entryPoint = "vert2";
    contents.programs.push_back(renamed);
    contents.shaders[0].passes[0].variants[3].programs[0] =
        static_cast<uint32_t>(contents.programs.size() - 1);
    PackWriteStats stats;
    std::string bytes = serializePack(contents, {}, &stats);
    EXPECT_EQ(stats.programs, contents.programs.size());
    EXPECT_EQ(stats.blobs, contents.programs.size() - 1);
    EXPECT_EQ(roundTrip(bytes).programs.size(), contents.programs.size());
}

TEST(PackWriter, CompressesSimilarBlobs) {
    PackWriteStats stats;
    serializePack(packtest::makeSampleContents(), {}, &stats);
    EXPECT_GT(stats.rawSpirvBytes, 0u);
    EXPECT_LT(stats.storedBlobBytes + stats.dictionaryBytes, stats.rawSpirvBytes / 2);
    EXPECT_EQ(stats.packBytes, serializePack(packtest::makeSampleContents()).size());
}

TEST(PackWriter, EmptyContentsRoundTrip) {
    pack::PackContents empty;
    EXPECT_EQ(roundTrip(serializePack(empty)), empty);
}

TEST(PackWriter, KeysBeyond64KeywordsRoundTrip) {
    pack::PackContents contents;
    contents.programs.push_back({Stage::Vertex, "vert", packtest::fakeSpirv(1), {}, {}});
    pack::PackPass pass;
    for (int i = 0; i < 130; ++i) pass.keywordTable.push_back("K" + std::to_string(1000 + i));
    for (int v : {0, 63, 64, 65, 127, 128, 129}) {
        pack::PackVariant variant;
        variant.key = packtest::keyOf(pass.keywordTable, {pass.keywordTable[v]});
        variant.programs[0] = 0;
        pass.variants.push_back(variant);
    }
    contents.shaders.push_back({"Wide", {pass}, {}});
    EXPECT_EQ(roundTrip(serializePack(contents)), contents);
}

TEST(PackWriterDeathTest, DuplicateKeysAreAProgrammerError) {
    pack::PackContents contents = packtest::makeSampleContents();
    auto& variants = contents.shaders[0].passes[0].variants;
    variants[1].key = variants[0].key;
    EXPECT_DEATH(serializePack(contents), "same key");
}

TEST(PackWriterDeathTest, UnsortedKeywordTableIsAProgrammerError) {
    pack::PackContents contents = packtest::makeSampleContents();
    std::swap(contents.shaders[0].passes[0].keywordTable[0],
              contents.shaders[0].passes[0].keywordTable[1]);
    EXPECT_DEATH(serializePack(contents), "not sorted");
}

}  // namespace
}  // namespace varc
