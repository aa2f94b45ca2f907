// SPDX-License-Identifier: Apache-2.0
// pack::kMaxBlobBytes (docs/SECURITY.md): a blob of exactly the limit is written and read back; a
// pack that records one byte-word more is refused by the reader before it allocates anything.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "PackTestData.h"
#include "varc/pack/PackFormat.h"
#include "varc/pack/PackTables.h"
#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PackDecoder.h"

namespace varc {
namespace {

constexpr size_t kWordsAtTheLimit = pack::kMaxBlobBytes / 4;

uint32_t readU32(const std::string& bytes, size_t at) {
    uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
}

uint64_t readU64(const std::string& bytes, size_t at) {
    uint64_t value = 0;
    std::memcpy(&value, bytes.data() + at, 8);
    return value;
}

// The byte offset of table chunk |id| (PACK_FORMAT.md: a 64-byte header, then 32-byte chunk
// entries; a table chunk is u32 fieldCount, u32 recordCount, then the records).
size_t tableOffset(const std::string& bytes, const char* id) {
    uint32_t chunks = readU32(bytes, 24);
    for (uint32_t c = 0; c < chunks; ++c) {
        size_t entry = 64 + size_t{c} * 32;
        if (std::memcmp(bytes.data() + entry, id, 4) == 0) return readU64(bytes, entry + 8);
    }
    ADD_FAILURE() << "no chunk " << id;
    return 0;
}

size_t fieldOffset(const std::string& bytes, size_t table, uint32_t record, uint32_t field) {
    uint32_t fields = readU32(bytes, table);
    return table + pack::kTableHeaderSize + (size_t{record} * fields + field) * 4;
}

// The sample contents with program 0 grown to |words| words.
pack::PackContents contentsWithProgramOf(size_t words) {
    pack::PackContents contents = packtest::makeSampleContents();
    contents.programs[0].spirv = packtest::fakeSpirv(7, words);
    return contents;
}

const std::string& packAtTheLimit() {
    static const std::string bytes = packwriter::serializePack(
        contentsWithProgramOf(kWordsAtTheLimit),
        {.compressionLevel = 1, .dictionary = packwriter::PackDictionary::Never});
    return bytes;
}

TEST(PackLimits, ABlobOfExactlyTheLimitIsWrittenAndReadBack) {
    Result<reader::Pack> pack = reader::Pack::fromBytes(packAtTheLimit());
    ASSERT_TRUE(pack.ok()) << pack.error().detail;
    Result<pack::PackContents> decoded = reader::decodePack(*pack);
    ASSERT_TRUE(decoded.ok()) << decoded.error().detail;
    bool found = false;
    for (const pack::PackProgram& program : decoded->programs) {
        if (program.spirv.size() == kWordsAtTheLimit) {
            found = true;
            EXPECT_EQ(program.spirv, packtest::fakeSpirv(7, kWordsAtTheLimit));
        }
    }
    EXPECT_TRUE(found);
}

TEST(PackLimits, ABlobRecordedOneWordPastTheLimitIsRefused) {
    std::string bytes = packAtTheLimit();
    Result<reader::Pack> original = reader::Pack::fromBytes(bytes);
    ASSERT_TRUE(original.ok());
    size_t table = tableOffset(bytes, "BLOB");
    uint32_t blobs = readU32(bytes, table + 4);
    bool patched = false;
    for (uint32_t blob = 0; blob < blobs; ++blob) {
        size_t at = fieldOffset(bytes, table, blob, pack::kBlobRawSize);
        if (readU32(bytes, at) != pack::kMaxBlobBytes) continue;
        uint32_t past = pack::kMaxBlobBytes + 4;
        std::memcpy(bytes.data() + at, &past, 4);
        patched = true;
    }
    ASSERT_TRUE(patched);
    // Checksums off, so the size check itself (not the checksum) must refuse it.
    Result<reader::Pack> pack = reader::Pack::fromBytes(bytes, {.verifyChecksums = false});
    ASSERT_FALSE(pack.ok());
    EXPECT_NE(pack.error().detail.find("has a bad size"), std::string::npos) << pack.error().detail;
}

TEST(PackLimits, TheWriterRefusesAProgramPastTheLimit) {
    EXPECT_DEATH(packwriter::serializePack(
                     contentsWithProgramOf(kWordsAtTheLimit + 1),
                     {.compressionLevel = 1, .dictionary = packwriter::PackDictionary::Never}),
                 "check failed");
}

}  // namespace
}  // namespace varc
