// SPDX-License-Identifier: Apache-2.0
// The pack file's fixed layout: magic, version, header, chunk table and chunk identifiers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace varc::pack {

// File layout (docs/PACK_FORMAT.md has the full description):
//
//   +--------------------+  offset 0
//   | header (64 bytes)  |  magic, version, file size, chunk count, inputs hash, checksum
//   +--------------------+  offset 64
//   | chunk table        |  chunkCount entries of 32 bytes: id, flags, offset, size, checksum
//   +--------------------+  aligned to 8
//   | chunk 0 | pad | chunk 1 | pad | ... | chunk n-1 |   = fileSize
//   +--------------------+
//
// Every byte is covered: the header checksum covers the header and chunk table, each chunk has
// its own checksum, and padding must be zero.
inline constexpr std::array<char, 8> kMagic = {'V', 'A', 'R', 'C', 'P', 'A', 'C', 'K'};

// Versioning: readers accept any minor version of their major. A minor bump may only add
// chunks (unknown chunk ids are skipped) or append fields to table records (readers ignore
// fields past the ones they know). Anything else bumps the major version.
inline constexpr uint16_t kVersionMajor = 1;
inline constexpr uint16_t kVersionMinor = 1;  // 1.1: the optional PROP chunk

inline constexpr size_t kHeaderSize = 64;
inline constexpr size_t kChunkEntrySize = 32;
inline constexpr size_t kChunkAlignment = 8;

// Byte offsets inside the header.
inline constexpr size_t kHeaderMagic = 0;        // 8 bytes
inline constexpr size_t kHeaderMajor = 8;        // u16
inline constexpr size_t kHeaderMinor = 10;       // u16
inline constexpr size_t kHeaderSizeField = 12;   // u32, = kHeaderSize
inline constexpr size_t kHeaderFileSize = 16;    // u64, the whole file
inline constexpr size_t kHeaderChunkCount = 24;  // u32
inline constexpr size_t kHeaderFlags = 28;       // u32, 0 (reserved)
inline constexpr size_t kHeaderInputsHash = 32;  // u64, hash of every compiler input
inline constexpr size_t kHeaderReserved = 40;    // 16 bytes, 0
inline constexpr size_t kHeaderChecksum = 56;    // u64, see headerChecksumSeed()

// Byte offsets inside one chunk table entry.
inline constexpr size_t kEntryId = 0;         // u32 fourcc
inline constexpr size_t kEntryFlags = 4;      // u32, 0 (reserved)
inline constexpr size_t kEntryOffset = 8;     // u64, from the start of the file
inline constexpr size_t kEntrySize = 16;      // u64, bytes, excluding padding
inline constexpr size_t kEntryChecksum = 24;  // u64, XXH3-64 of the chunk's bytes

// The header checksum is XXH3_64bits_withSeed(chunk table bytes, seed), where seed is
// XXH3_64bits(header bytes [0, kHeaderChecksum)). Chaining two calls keeps the checksum field
// itself out of the hashed bytes without a streaming state.

// The chunks of format 1.0, in the order the writer emits them. Table chunks hold fixed-size
// records of u32 fields (PackTables.h); raw chunks hold bytes.
enum class Chunk : uint8_t {
    Strings,          // table: offset, length into StringBytes
    StringBytes,      // raw: UTF-8 string bytes, no terminators
    Tools,            // table: toolchain name/version pairs
    Shaders,          // table
    ShaderNames,      // table: shader indices sorted by name
    Passes,           // table
    Tags,             // table: key/value string pairs
    StringLists,      // table: one string per record; ranges of it form lists
    KeywordSets,      // table: declared sets
    RenderStates,     // table
    VariantKeys,      // raw: per pass, the sorted keys (keyWords u64 words each)
    VariantPrograms,  // table: per sorted variant, the stage programs and enumeration index
    VariantOrder,     // table: per enumeration index, the sorted position
    Programs,         // table
    Reflections,      // table
    UniformBlocks,    // table (uniform blocks and push-constant blocks)
    BlockMembers,     // table
    Resources,        // table
    VertexInputs,     // table
    StageVariables,   // table (stage inputs and outputs)
    Blobs,            // table: codec, offset, size, raw size of each SPIR-V blob
    BlobData,         // raw: the (compressed) blobs
    Dictionary,       // raw, optional: the zstd dictionary shared by ZstdDictionary blobs
    Properties,       // table, optional (format 1.1): the shaders' Properties defaults
};
inline constexpr size_t kChunkCount = static_cast<size_t>(Chunk::Properties) + 1;

constexpr uint32_t makeFourcc(const char (&text)[5]) {
    return static_cast<uint32_t>(static_cast<unsigned char>(text[0])) |
           static_cast<uint32_t>(static_cast<unsigned char>(text[1])) << 8 |
           static_cast<uint32_t>(static_cast<unsigned char>(text[2])) << 16 |
           static_cast<uint32_t>(static_cast<unsigned char>(text[3])) << 24;
}

struct ChunkInfo {
    uint32_t fourcc;
    const char* name;
    bool table;     // records of u32 fields; otherwise raw bytes
    bool required;  // a pack without it is rejected
};

inline constexpr std::array<ChunkInfo, kChunkCount> kChunkInfo = {{
    {makeFourcc("STRS"), "STRS", true, true},   {makeFourcc("STRB"), "STRB", false, true},
    {makeFourcc("TOOL"), "TOOL", true, true},   {makeFourcc("SHDR"), "SHDR", true, true},
    {makeFourcc("SHNM"), "SHNM", true, true},   {makeFourcc("PASS"), "PASS", true, true},
    {makeFourcc("TAGS"), "TAGS", true, true},   {makeFourcc("SLST"), "SLST", true, true},
    {makeFourcc("KSET"), "KSET", true, true},   {makeFourcc("RSTA"), "RSTA", true, true},
    {makeFourcc("VKEY"), "VKEY", false, true},  {makeFourcc("VPRG"), "VPRG", true, true},
    {makeFourcc("VORD"), "VORD", true, true},   {makeFourcc("PROG"), "PROG", true, true},
    {makeFourcc("REFL"), "REFL", true, true},   {makeFourcc("UBLK"), "UBLK", true, true},
    {makeFourcc("UMEM"), "UMEM", true, true},   {makeFourcc("RRES"), "RRES", true, true},
    {makeFourcc("VINP"), "VINP", true, true},   {makeFourcc("SVAR"), "SVAR", true, true},
    {makeFourcc("BLOB"), "BLOB", true, true},   {makeFourcc("BDAT"), "BDAT", false, true},
    {makeFourcc("DICT"), "DICT", false, false}, {makeFourcc("PROP"), "PROP", true, false},
}};

constexpr const ChunkInfo& chunkInfo(Chunk chunk) { return kChunkInfo[static_cast<size_t>(chunk)]; }

// A table chunk starts with u32 fieldCount and u32 recordCount, then recordCount records of
// fieldCount little-endian u32 fields: size = 8 + 4 * fieldCount * recordCount.
inline constexpr size_t kTableHeaderSize = 8;

// How one SPIR-V blob is stored in BlobData.
enum class BlobCodec : uint32_t {
    Stored = 0,          // the raw little-endian words
    Zstd = 1,            // one zstd frame with its content size
    ZstdDictionary = 2,  // one zstd frame compressed with the Dictionary chunk
};
inline constexpr uint32_t kBlobCodecCount = 3;

// "No value" for optional indices (e.g. a variant without a geometry program).
inline constexpr uint32_t kNone = 0xffffffffu;

// Largest decompressed blob a reader accepts (guards allocations against corrupt packs).
inline constexpr uint32_t kMaxBlobBytes = 64u << 20;

// Blobs start at offsets aligned to 4 inside BlobData, so stored blobs can be used in place.
inline constexpr size_t kBlobAlignment = 4;

}  // namespace varc::pack
