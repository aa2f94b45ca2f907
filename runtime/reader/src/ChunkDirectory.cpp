// SPDX-License-Identifier: Apache-2.0
// Parses and checks a pack's header and chunk table, yielding each known chunk's bytes.
#include "ChunkDirectory.h"

#include <xxhash.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "Unflattener.h"
#include "varc/pack/LittleEndian.h"

namespace varc::reader::detail {

namespace {

Error invalid(std::string detail) { return makeError(ErrorCode::InvalidInput, std::move(detail)); }

Error truncated(size_t have, uint64_t need, const char* what) {
    return invalid("truncated pack: " + std::to_string(have) + " bytes, but " + what + " needs " +
                   std::to_string(need));
}

// Magic first: a file that is not a pack at all should say so, whatever its size.
Status checkMagic(std::span<const std::byte> bytes) {
    size_t compared = std::min(bytes.size(), pack::kMagic.size());
    if (compared > 0 && std::memcmp(bytes.data(), pack::kMagic.data(), compared) != 0) {
        return invalid("bad magic: not a varc pack (expected \"VARCPACK\")");
    }
    if (bytes.size() < pack::kHeaderSize) {
        return truncated(bytes.size(), pack::kHeaderSize, "the header");
    }
    return Ok{};
}

Result<PackHeader> readHeader(std::span<const std::byte> bytes) {
    Unflattener in(bytes);
    PackHeader header;
    uint32_t headerSize = 0, flags = 0;
    uint64_t reserved0 = 0, reserved1 = 0;
    bool ok = in.seek(pack::kHeaderMajor) && in.readU16(header.major) && in.readU16(header.minor) &&
              in.readU32(headerSize) && in.readU64(header.fileSize) &&
              in.readU32(header.chunkCount) && in.readU32(flags) && in.readU64(header.inputsHash) &&
              in.readU64(reserved0) && in.readU64(reserved1);
    if (!ok) return truncated(bytes.size(), pack::kHeaderSize, "the header");
    if (header.major != pack::kVersionMajor) {
        return makeError(ErrorCode::Unsupported,
                         "unsupported pack version " + std::to_string(header.major) + "." +
                             std::to_string(header.minor) + " (this reader reads " +
                             std::to_string(pack::kVersionMajor) + ".x)");
    }
    if (header.fileSize > bytes.size()) {
        return truncated(bytes.size(), header.fileSize, "the header's file size");
    }
    if (header.fileSize < bytes.size()) {
        return invalid("pack has " + std::to_string(bytes.size() - header.fileSize) +
                       " trailing bytes after its " + std::to_string(header.fileSize));
    }
    if (headerSize != pack::kHeaderSize || flags != 0 || reserved0 != 0 || reserved1 != 0) {
        return invalid("corrupt pack header: unexpected header size, flags or reserved bytes");
    }
    return header;
}

Status checkHeaderChecksum(std::span<const std::byte> bytes, size_t tableBytes) {
    uint64_t seed = XXH3_64bits(bytes.data(), pack::kHeaderChecksum);
    uint64_t actual = XXH3_64bits_withSeed(bytes.data() + pack::kHeaderSize, tableBytes, seed);
    if (actual != pack::loadU64(bytes.data() + pack::kHeaderChecksum)) {
        return invalid("checksum mismatch in the pack header or chunk table");
    }
    return Ok{};
}

bool allZero(std::span<const std::byte> bytes) {
    return std::all_of(bytes.begin(), bytes.end(), [](std::byte b) { return b == std::byte{0}; });
}

std::string fourccText(uint32_t fourcc) {
    std::string text;
    for (int i = 0; i < 4; ++i) {
        auto c = static_cast<char>((fourcc >> (8 * i)) & 0xff);
        text += (c >= 0x20 && c < 0x7f) ? c : '?';
    }
    return text;
}

}  // namespace

Result<ChunkDirectory> ChunkDirectory::parse(std::span<const std::byte> bytes,
                                             bool verifyChecksums) {
    if (Status magic = checkMagic(bytes); !magic) return magic.error();
    Result<PackHeader> header = readHeader(bytes);
    if (!header) return header.error();
    ChunkDirectory directory;
    directory.mHeader = *header;
    uint64_t tableEnd = pack::kHeaderSize + uint64_t{header->chunkCount} * pack::kChunkEntrySize;
    if (tableEnd > bytes.size()) return truncated(bytes.size(), tableEnd, "the chunk table");
    if (verifyChecksums) {
        Status checksum = checkHeaderChecksum(bytes, tableEnd - pack::kHeaderSize);
        if (!checksum) return checksum.error();
    }
    if (Status entries = directory.readEntries(bytes, verifyChecksums); !entries) {
        return entries.error();
    }
    for (size_t i = 0; i < pack::kChunkCount; ++i) {
        if (pack::kChunkInfo[i].required && !directory.mChunks[i]) {
            return invalid(std::string("pack lacks the required chunk ") +
                           pack::kChunkInfo[i].name);
        }
    }
    return directory;
}

// Walks the chunk table: chunk i starts at the first 8-aligned offset after chunk i-1 (after
// the table for chunk 0), the bytes between are zero, and the last chunk ends the file.
Status ChunkDirectory::readEntries(std::span<const std::byte> bytes, bool verifyChecksums) {
    Unflattener table(bytes);
    table.seek(pack::kHeaderSize);
    uint64_t end = pack::kHeaderSize + uint64_t{mHeader.chunkCount} * pack::kChunkEntrySize;
    for (uint32_t i = 0; i < mHeader.chunkCount; ++i) {
        uint32_t fourcc = 0, flags = 0;
        uint64_t offset = 0, size = 0, checksum = 0;
        if (!(table.readU32(fourcc) && table.readU32(flags) && table.readU64(offset) &&
              table.readU64(size) && table.readU64(checksum))) {
            return truncated(bytes.size(), end, "the chunk table");
        }
        uint64_t expected =
            (end + pack::kChunkAlignment - 1) / pack::kChunkAlignment * pack::kChunkAlignment;
        if (flags != 0 || offset != expected || offset > bytes.size() ||
            size > bytes.size() - offset) {
            return invalid("corrupt chunk table: chunk " + fourccText(fourcc) + " at offset " +
                           std::to_string(offset) + " with " + std::to_string(size) + " bytes");
        }
        if (!allZero(bytes.subspan(end, offset - end))) {
            return invalid("non-zero padding before chunk " + fourccText(fourcc));
        }
        std::span<const std::byte> data = bytes.subspan(offset, size);
        if (verifyChecksums && XXH3_64bits(data.data(), data.size()) != checksum) {
            return invalid("checksum mismatch in chunk " + fourccText(fourcc));
        }
        if (Status added = addChunk(fourcc, data); !added) return added.error();
        end = offset + size;
    }
    if (end != bytes.size()) {
        return invalid("corrupt chunk table: chunks end at " + std::to_string(end) +
                       ", the file at " + std::to_string(bytes.size()));
    }
    return Ok{};
}

// Unknown chunks (from a newer minor version) are skipped; duplicates are rejected.
Status ChunkDirectory::addChunk(uint32_t fourcc, std::span<const std::byte> data) {
    for (size_t i = 0; i < pack::kChunkCount; ++i) {
        if (pack::kChunkInfo[i].fourcc != fourcc) continue;
        if (mChunks[i]) return invalid("duplicate chunk " + fourccText(fourcc));
        mChunks[i] = data;
    }
    return Ok{};
}

}  // namespace varc::reader::detail
