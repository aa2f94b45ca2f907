// SPDX-License-Identifier: Apache-2.0
// The validated, in-place view of a pack's bytes that every runtime view reads from.
#pragma once

#include "KeyHashIndex.h"

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string_view>
#include <vector>

#include "BlobCache.h"
#include "ChunkDirectory.h"
#include "MappedFile.h"
#include "TableView.h"
#include "varc/core/Result.h"
#include "varc/pack/PackFormat.h"
#include "varc/reader/Pack.h"
#include "varc/variants/VariantKey.h"

namespace varc::reader::detail {

// Owns the pack's storage (a mapping, or an aligned copy) and the lazily built caches. After
// load() succeeded every record index, range and string id reachable from the tables is known
// to be in range, so accessors index without checks. Thread-safe after load(): the tables are
// read-only and the caches are built under std::call_once.
class PackImage {
public:
    explicit PackImage(MappedFile mapping);
    explicit PackImage(std::span<const std::byte> copyOf);
    PackImage(const PackImage&) = delete;
    PackImage& operator=(const PackImage&) = delete;
    ~PackImage();

    // Parses and validates the whole pack (see Pack::open). Call once, before any accessor.
    Status load(const OpenOptions& options);

    std::span<const std::byte> bytes() const { return mBytes; }
    const PackHeader& header() const { return mHeader; }
    const TableView& table(pack::Chunk chunk) const { return mTables[index(chunk)]; }
    std::span<const std::byte> raw(pack::Chunk chunk) const { return mRaw[index(chunk)]; }
    uint32_t get(pack::Chunk chunk, uint32_t record, uint32_t field) const {
        return table(chunk).get(record, field);
    }
    uint32_t count(pack::Chunk chunk) const { return table(chunk).count; }

    std::string_view string(uint32_t id) const;
    // The string of StringLists record |record|.
    std::string_view listString(uint32_t record) const;

    // The words of blob |blob|, decompressed on first use (see BlobCache).
    Result<std::span<const uint32_t>> blobWords(uint32_t blob) const;

    // The hash index of pass record |pass|'s sorted keys; empty for small or multi-word passes.
    const KeyHashIndex& keyIndex(uint32_t pass) const { return mKeyIndexes[pass]; }
    // The keys of pass |pass| in enumeration order, decoded on first use (for selectVariant).
    const std::vector<variants::VariantKey>& enumerationKeys(uint32_t pass) const;

private:
    static size_t index(pack::Chunk chunk) { return static_cast<size_t>(chunk); }
    Status loadTables(const ChunkDirectory& directory);

    MappedFile mMapping;
    std::vector<uint64_t> mOwned;  // 8-aligned copy for fromBytes()
    std::span<const std::byte> mBytes;
    PackHeader mHeader;
    std::array<TableView, pack::kChunkCount> mTables{};
    std::array<std::span<const std::byte>, pack::kChunkCount> mRaw{};
    std::unique_ptr<BlobCache> mBlobs;

    struct PassKeys {
        std::once_flag once;
        std::vector<variants::VariantKey> keys;
    };
    std::unique_ptr<PassKeys[]> mPassKeys;
    std::vector<KeyHashIndex> mKeyIndexes;  // per Passes record, built by load()
};

}  // namespace varc::reader::detail
