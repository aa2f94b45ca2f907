// SPDX-License-Identifier: Apache-2.0
// The validated, in-place view of a pack's bytes that every runtime view reads from.
#include "PackImage.h"

#include <cstring>
#include <string>

#include "PackValidator.h"
#include "varc/pack/KeyEncoding.h"
#include "varc/pack/PackTables.h"

namespace varc::reader::detail {

PackImage::PackImage(MappedFile mapping) : mMapping(std::move(mapping)) {
    mBytes = mMapping.bytes();
}

// The copy lives in u64 storage so that the 8-aligned chunks are 8-aligned in memory too.
PackImage::PackImage(std::span<const std::byte> copyOf) : mOwned((copyOf.size() + 7) / 8) {
    if (!copyOf.empty()) std::memcpy(mOwned.data(), copyOf.data(), copyOf.size());
    mBytes = {reinterpret_cast<const std::byte*>(mOwned.data()), copyOf.size()};
}

PackImage::~PackImage() = default;

Status PackImage::load(const OpenOptions& options) {
    Result<ChunkDirectory> directory = ChunkDirectory::parse(mBytes, options.verifyChecksums);
    if (!directory) return directory.error();
    mHeader = directory->header();
    if (Status tables = loadTables(*directory); !tables) return tables;
    if (Status schemas = validateSchemas(*this); !schemas) return schemas;
    if (Status references = validateReferences(*this); !references) return references;
    mBlobs = std::make_unique<BlobCache>(table(pack::Chunk::Blobs), raw(pack::Chunk::BlobData),
                                         raw(pack::Chunk::Dictionary));
    mPassKeys = std::make_unique<PassKeys[]>(count(pack::Chunk::Passes));
    mKeyIndexes.resize(count(pack::Chunk::Passes));
    for (uint32_t pass = 0; options.indexKeys && pass < count(pack::Chunk::Passes); ++pass) {
        uint32_t variants = get(pack::Chunk::Passes, pass, pack::kPassVariantCount);
        if (get(pack::Chunk::Passes, pass, pack::kPassKeyWords) != 1 ||
            variants < KeyHashIndex::kMinKeys)
            continue;
        const std::byte* keys = raw(pack::Chunk::VariantKeys).data() +
                                8 * size_t{get(pack::Chunk::Passes, pass, pack::kPassKeyFirst)};
        mKeyIndexes[pass] = KeyHashIndex(keys, variants);
    }
    return Ok{};
}

// Table chunks: u32 fieldCount, u32 recordCount, then exactly that many records, with at least
// the fields this reader knows.
Status PackImage::loadTables(const ChunkDirectory& directory) {
    for (size_t i = 0; i < pack::kChunkCount; ++i) {
        auto chunk = static_cast<pack::Chunk>(i);
        std::span<const std::byte> bytes = directory.chunk(chunk);
        mRaw[i] = bytes;
        if (!pack::chunkInfo(chunk).table) continue;
        std::string name = pack::chunkInfo(chunk).name;
        if (bytes.empty() && !pack::chunkInfo(chunk).required) {
            // An absent optional table reads as one without records.
            mTables[i] =
                TableView{nullptr, static_cast<uint32_t>(pack::tableSchema(chunk).size()), 0};
            continue;
        }
        if (bytes.size() < pack::kTableHeaderSize) {
            return makeError(ErrorCode::InvalidInput, "table chunk " + name + " is too short");
        }
        uint32_t fields = pack::loadU32(bytes.data());
        uint32_t records = pack::loadU32(bytes.data() + 4);
        uint64_t body = bytes.size() - pack::kTableHeaderSize;
        if (fields < pack::tableSchema(chunk).size() ||
            body != uint64_t{fields} * 4 * uint64_t{records}) {
            return makeError(ErrorCode::InvalidInput, "table chunk " + name + " has a bad shape (" +
                                                          std::to_string(fields) + " fields x " +
                                                          std::to_string(records) + " records in " +
                                                          std::to_string(body) + " bytes)");
        }
        mTables[i] = TableView{bytes.data() + pack::kTableHeaderSize, fields, records};
    }
    if (raw(pack::Chunk::VariantKeys).size() % 8 != 0) {
        return makeError(ErrorCode::InvalidInput, "chunk VKEY is not a whole number of keys");
    }
    return Ok{};
}

std::string_view PackImage::string(uint32_t id) const {
    const TableView& strings = table(pack::Chunk::Strings);
    auto bytes = raw(pack::Chunk::StringBytes);
    return {reinterpret_cast<const char*>(bytes.data()) + strings.get(id, pack::kStringOffset),
            strings.get(id, pack::kStringLength)};
}

std::string_view PackImage::listString(uint32_t record) const {
    return string(get(pack::Chunk::StringLists, record, pack::kStringListString));
}

Result<std::span<const uint32_t>> PackImage::blobWords(uint32_t blob) const {
    return mBlobs->words(blob);
}

const std::vector<variants::VariantKey>& PackImage::enumerationKeys(uint32_t pass) const {
    PassKeys& cache = mPassKeys[pass];
    std::call_once(cache.once, [&] {
        using pack::Chunk;
        uint32_t words = get(Chunk::Passes, pass, pack::kPassKeyWords);
        uint32_t keyFirst = get(Chunk::Passes, pass, pack::kPassKeyFirst);
        uint32_t first = get(Chunk::Passes, pass, pack::kPassVariantFirst);
        uint32_t n = get(Chunk::Passes, pass, pack::kPassVariantCount);
        const std::byte* keys = raw(Chunk::VariantKeys).data();
        cache.keys.reserve(n);
        for (uint32_t e = 0; e < n; ++e) {
            uint32_t sorted = get(Chunk::VariantOrder, first + e, pack::kOrderPosition);
            size_t word = keyFirst + static_cast<size_t>(sorted) * words;
            cache.keys.push_back(pack::loadKey(keys + 8 * word, words));
        }
    });
    return cache.keys;
}

}  // namespace varc::reader::detail
