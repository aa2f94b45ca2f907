// SPDX-License-Identifier: Apache-2.0
// Lays out header, chunk table and chunks into the final file, with checksums and padding.
#include "ChunkAssembler.h"

#include <xxhash.h>

#include <cstring>

#include "varc/core/Check.h"
#include "varc/pack/LittleEndian.h"

namespace varc::packwriter {

namespace {

void padTo(std::string& out, size_t alignment) {
    out.append((alignment - out.size() % alignment) % alignment, '\0');
}

void writeHeader(std::string& out, size_t chunkCount, uint64_t inputsHash) {
    std::memcpy(out.data() + pack::kHeaderMagic, pack::kMagic.data(), pack::kMagic.size());
    pack::storeLittle<uint16_t>(out, pack::kHeaderMajor, pack::kVersionMajor);
    pack::storeLittle<uint16_t>(out, pack::kHeaderMinor, pack::kVersionMinor);
    pack::storeLittle<uint32_t>(out, pack::kHeaderSizeField, uint32_t{pack::kHeaderSize});
    pack::storeLittle<uint64_t>(out, pack::kHeaderFileSize, out.size());
    pack::storeLittle<uint32_t>(out, pack::kHeaderChunkCount, static_cast<uint32_t>(chunkCount));
    pack::storeLittle<uint64_t>(out, pack::kHeaderInputsHash, inputsHash);
    // Flags and reserved bytes stay zero.
    size_t tableBytes = chunkCount * pack::kChunkEntrySize;
    uint64_t seed = XXH3_64bits(out.data(), pack::kHeaderChecksum);
    uint64_t checksum = XXH3_64bits_withSeed(out.data() + pack::kHeaderSize, tableBytes, seed);
    pack::storeLittle<uint64_t>(out, pack::kHeaderChecksum, checksum);
}

}  // namespace

std::string assembleChunks(const std::vector<std::pair<pack::Chunk, std::string>>& chunks,
                           uint64_t inputsHash) {
    std::string out(pack::kHeaderSize + chunks.size() * pack::kChunkEntrySize, '\0');
    for (size_t i = 0; i < chunks.size(); ++i) {
        const auto& [chunk, bytes] = chunks[i];
        padTo(out, pack::kChunkAlignment);
        size_t entry = pack::kHeaderSize + i * pack::kChunkEntrySize;
        pack::storeLittle<uint32_t>(out, entry + pack::kEntryId, pack::chunkInfo(chunk).fourcc);
        pack::storeLittle<uint64_t>(out, entry + pack::kEntryOffset, out.size());
        pack::storeLittle<uint64_t>(out, entry + pack::kEntrySize, bytes.size());
        pack::storeLittle<uint64_t>(out, entry + pack::kEntryChecksum,
                                    XXH3_64bits(bytes.data(), bytes.size()));
        out.append(bytes);
    }
    writeHeader(out, chunks.size(), inputsHash);
    return out;
}

}  // namespace varc::packwriter
