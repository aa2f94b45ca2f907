// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/CacheBundle.h"

#include <limits>

namespace varc::cache {

namespace {

constexpr std::string_view kMagic = "VARCBDL1";

void putLittleEndian(std::string& out, uint64_t value, size_t bytes) {
    for (size_t i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

// Reads |bytes| little-endian bytes at |at|, advancing it; false when they run past |text|.
bool getLittleEndian(std::string_view text, size_t& at, size_t bytes, uint64_t& value) {
    if (text.size() < at || text.size() - at < bytes) return false;
    value = 0;
    for (size_t i = 0; i < bytes; ++i) {
        value |= uint64_t{static_cast<unsigned char>(text[at + i])} << (8 * i);
    }
    at += bytes;
    return true;
}

bool fitsInBundle(const CacheEntry& entry) {
    return entry.key.size() <= std::numeric_limits<uint16_t>::max() &&
           entry.value.size() <= std::numeric_limits<uint32_t>::max();
}

}  // namespace

std::string encodeBundle(const std::vector<CacheEntry>& entries) {
    uint64_t count = 0, indexBytes = 0;
    for (const CacheEntry& entry : entries) {
        if (!fitsInBundle(entry)) continue;
        ++count;
        indexBytes += 2 + entry.key.size() + 8 + 4;
    }
    std::string out(kMagic);
    putLittleEndian(out, count, 4);
    putLittleEndian(out, indexBytes, 4);
    uint64_t offset = kBundleHeaderBytes + indexBytes;
    for (const CacheEntry& entry : entries) {
        if (!fitsInBundle(entry)) continue;
        putLittleEndian(out, entry.key.size(), 2);
        out += entry.key;
        putLittleEndian(out, offset, 8);
        putLittleEndian(out, entry.value.size(), 4);
        offset += entry.value.size();
    }
    for (const CacheEntry& entry : entries) {
        if (fitsInBundle(entry)) out += entry.value;
    }
    return out;
}

uint64_t bundleIndexEnd(std::string_view header) {
    if (header.size() < kBundleHeaderBytes || header.substr(0, kMagic.size()) != kMagic) return 0;
    size_t at = kMagic.size() + 4;
    uint64_t indexBytes = 0;
    getLittleEndian(header, at, 4, indexBytes);
    return kBundleHeaderBytes + indexBytes;
}

std::vector<BundleSlot> decodeBundleIndex(std::string_view headerAndIndex, uint64_t fileSize) {
    std::vector<BundleSlot> slots;
    const uint64_t end = bundleIndexEnd(headerAndIndex);
    if (end == 0 || end > headerAndIndex.size()) return slots;
    std::string_view index = headerAndIndex.substr(0, end);
    size_t at = kMagic.size();
    uint64_t count = 0;
    getLittleEndian(index, at, 4, count);
    at = kBundleHeaderBytes;
    for (uint64_t n = 0; n < count; ++n) {
        uint64_t keyLength = 0, offset = 0, length = 0;
        if (!getLittleEndian(index, at, 2, keyLength) || index.size() - at < keyLength) break;
        std::string key(index.substr(at, keyLength));
        at += keyLength;
        if (!getLittleEndian(index, at, 8, offset) || !getLittleEndian(index, at, 4, length)) break;
        if (offset < end || offset > fileSize || fileSize - offset < length) continue;
        slots.push_back({std::move(key), offset, static_cast<uint32_t>(length)});
    }
    return slots;
}

}  // namespace varc::cache
