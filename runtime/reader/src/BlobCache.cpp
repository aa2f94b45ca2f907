// SPDX-License-Identifier: Apache-2.0
// Lazily decompressed SPIR-V blobs: each blob is decoded once, on first use, by any thread.
#include "BlobCache.h"

#include <zstd.h>

#include <bit>
#include <cstring>

#include "varc/pack/PackTables.h"

namespace varc::reader::detail {

namespace {

struct DCtxDeleter {
    void operator()(ZSTD_DCtx* context) const { ZSTD_freeDCtx(context); }
};

bool alignedForWords(const std::byte* p) {
    return reinterpret_cast<uintptr_t>(p) % alignof(uint32_t) == 0;
}

}  // namespace

BlobCache::BlobCache(TableView blobs, std::span<const std::byte> data,
                     std::span<const std::byte> dictionary)
    : mBlobs(blobs),
      mData(data),
      mDictionaryBytes(dictionary),
      mSlots(std::make_unique<Slot[]>(blobs.count)) {}

BlobCache::~BlobCache() { ZSTD_freeDDict(mDictionary); }

Result<std::span<const uint32_t>> BlobCache::words(uint32_t blob) const {
    Slot& slot = mSlots[blob];
    std::call_once(slot.once, [&] { fill(blob, slot); });
    if (!slot.error.empty()) return makeError(ErrorCode::InvalidInput, slot.error);
    return slot.words;
}

void BlobCache::fill(uint32_t blob, Slot& slot) const {
    auto codec = static_cast<pack::BlobCodec>(mBlobs.get(blob, pack::kBlobCodecField));
    std::span<const std::byte> stored =
        mData.subspan(mBlobs.get(blob, pack::kBlobOffset), mBlobs.get(blob, pack::kBlobSize));
    if (codec != pack::BlobCodec::Stored) {
        decompress(blob, stored, codec == pack::BlobCodec::ZstdDictionary, slot);
        return;
    }
    size_t count = stored.size() / 4;
    if (std::endian::native == std::endian::little && alignedForWords(stored.data())) {
        slot.words = {reinterpret_cast<const uint32_t*>(stored.data()), count};
        return;
    }
    slot.owned = std::make_unique<uint32_t[]>(count);
    for (size_t i = 0; i < count; ++i) slot.owned[i] = pack::loadU32(stored.data() + 4 * i);
    slot.words = {slot.owned.get(), count};
}

void BlobCache::decompress(uint32_t blob, std::span<const std::byte> frame, bool withDictionary,
                           Slot& slot) const {
    uint32_t rawSize = mBlobs.get(blob, pack::kBlobRawSize);
    const ZSTD_DDict* dict = withDictionary ? dictionary() : nullptr;
    if (withDictionary && dict == nullptr) {
        slot.error = "blob " + std::to_string(blob) + ": the pack's zstd dictionary is corrupt";
        return;
    }
    std::unique_ptr<ZSTD_DCtx, DCtxDeleter> context(ZSTD_createDCtx());
    if (context == nullptr) {
        slot.error = "blob " + std::to_string(blob) + ": cannot create a zstd context";
        return;
    }
    auto owned = std::make_unique<uint32_t[]>(rawSize / 4);
    size_t size = ZSTD_decompress_usingDDict(context.get(), owned.get(), rawSize, frame.data(),
                                             frame.size(), dict);
    if (ZSTD_isError(size) || size != rawSize) {
        slot.error = "blob " + std::to_string(blob) + " does not decompress to its " +
                     std::to_string(rawSize) + " bytes" +
                     (ZSTD_isError(size) ? std::string(": ") + ZSTD_getErrorName(size) : "");
        return;
    }
    if constexpr (std::endian::native != std::endian::little) {
        for (size_t i = 0; i < rawSize / 4; ++i) owned[i] = pack::littleEndian(owned[i]);
    }
    slot.words = {owned.get(), rawSize / 4};
    slot.owned = std::move(owned);
}

// Built on first use (ZSTD_createDDict digests a copy; the by-reference variant is zstd's
// experimental API, which the shared library does not promise to keep).
const ZSTD_DDict_s* BlobCache::dictionary() const {
    std::call_once(mDictionaryOnce, [&] {
        if (mDictionaryBytes.empty()) return;
        mDictionary = ZSTD_createDDict(mDictionaryBytes.data(), mDictionaryBytes.size());
    });
    return mDictionary;
}

}  // namespace varc::reader::detail
