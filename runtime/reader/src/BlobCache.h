// SPDX-License-Identifier: Apache-2.0
// Lazily decompressed SPIR-V blobs: each blob is decoded once, on first use, by any thread.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>

#include "TableView.h"
#include "varc/core/Result.h"

struct ZSTD_DDict_s;

namespace varc::reader::detail {

// Thread-safe: each blob's slot is filled under its own std::once_flag, the shared dictionary
// under another, and a filled slot is never changed again, so the returned spans stay valid
// for the cache's lifetime. Stored (uncompressed) blobs that are 4-aligned in the pack are
// returned in place on little-endian hosts, without a copy.
class BlobCache {
public:
    // |blobs| is the validated Blobs table; |data| and |dictionary| the BlobData and Dictionary
    // chunks (the dictionary may be empty). The cache keeps views, not copies.
    BlobCache(TableView blobs, std::span<const std::byte> data,
              std::span<const std::byte> dictionary);
    BlobCache(const BlobCache&) = delete;
    BlobCache& operator=(const BlobCache&) = delete;
    ~BlobCache();

    // The words of blob |blob| (< the Blobs count). Fails with InvalidInput when the stored
    // frame does not decompress to its recorded size; the failure is remembered.
    Result<std::span<const uint32_t>> words(uint32_t blob) const;

private:
    struct Slot {
        std::once_flag once;
        std::unique_ptr<uint32_t[]> owned;
        std::span<const uint32_t> words;
        std::string error;  // set when decoding failed
    };
    void fill(uint32_t blob, Slot& slot) const;
    void decompress(uint32_t blob, std::span<const std::byte> frame, bool withDictionary,
                    Slot& slot) const;
    const ZSTD_DDict_s* dictionary() const;

    TableView mBlobs;
    std::span<const std::byte> mData;
    std::span<const std::byte> mDictionaryBytes;
    std::unique_ptr<Slot[]> mSlots;
    mutable std::once_flag mDictionaryOnce;
    mutable ZSTD_DDict_s* mDictionary = nullptr;
};

}  // namespace varc::reader::detail
