// SPDX-License-Identifier: Apache-2.0
// Compresses the distinct SPIR-V blobs with zstd, with a trained dictionary when it pays off.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "varc/pack/PackFormat.h"
#include "varc/packwriter/PackWriter.h"

namespace varc::packwriter {

struct StoredBlob {
    pack::BlobCodec codec = pack::BlobCodec::Stored;
    uint32_t offset = 0;   // in data, aligned to pack::kBlobAlignment
    uint32_t size = 0;     // stored bytes
    uint32_t rawSize = 0;  // SPIR-V bytes
};

struct CompressedBlobs {
    std::vector<StoredBlob> blobs;  // parallel to the input
    std::string data;               // the BlobData chunk
    std::string dictionary;         // the Dictionary chunk; empty = none
};

// Compresses each of |blobs| (little-endian SPIR-V bytes) at |options.compressionLevel|. With
// PackDictionary::Auto a dictionary is trained (ZDICT_trainFromBuffer) across all blobs and kept
// only if blobs plus dictionary come out smaller. A blob that does not shrink is stored raw.
// Deterministic for equal inputs.
CompressedBlobs compressBlobs(const std::vector<std::string>& blobs,
                              const PackWriteOptions& options);

}  // namespace varc::packwriter
