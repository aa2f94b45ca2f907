// SPDX-License-Identifier: Apache-2.0
// Parses and checks a pack's header and chunk table, yielding each known chunk's bytes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "varc/core/Result.h"
#include "varc/pack/PackFormat.h"

namespace varc::reader::detail {

struct PackHeader {
    uint16_t major = 0;
    uint16_t minor = 0;
    uint64_t fileSize = 0;
    uint32_t chunkCount = 0;
    uint64_t inputsHash = 0;
};

class ChunkDirectory {
public:
    // Checks, in order: magic ("bad magic"), major version ("unsupported pack version"), size
    // against the header's file size ("truncated"), the header checksum, then that chunks are
    // laid out back to back at 8-aligned offsets with zero padding up to the end of the file,
    // each chunk's checksum, no duplicate chunk ids, and that every required chunk is present.
    // Checksums are skipped when |verifyChecksums| is false (fuzzing only). Errors are
    // InvalidInput, or Unsupported for a different major version.
    static Result<ChunkDirectory> parse(std::span<const std::byte> bytes, bool verifyChecksums);

    const PackHeader& header() const { return mHeader; }
    bool has(pack::Chunk chunk) const { return mChunks[index(chunk)].has_value(); }
    // The chunk's bytes (empty for an absent optional chunk).
    std::span<const std::byte> chunk(pack::Chunk chunk) const {
        return mChunks[index(chunk)].value_or(std::span<const std::byte>{});
    }

private:
    static size_t index(pack::Chunk chunk) { return static_cast<size_t>(chunk); }
    Status readEntries(std::span<const std::byte> bytes, bool verifyChecksums);
    Status addChunk(uint32_t fourcc, std::span<const std::byte> data);

    PackHeader mHeader;
    std::array<std::optional<std::span<const std::byte>>, pack::kChunkCount> mChunks;
};

}  // namespace varc::reader::detail
