// SPDX-License-Identifier: Apache-2.0
// CacheBundle: many cache entries in one file. A local folder receives the hits of a shared
// level in one bundle per build instead of a file per entry: creating a file costs far more
// than writing its bytes (about 0.3 ms per file on this project's CI machines), and a fresh
// folder filled from Redis would otherwise spend more time creating files than the build
// spends on everything else.
//
// Layout (little-endian):
//   "VARCBDL1"  u32 count  u32 indexBytes
//   index: count × { u16 keyLength, key bytes, u64 valueOffset, u32 valueLength }
//   values, at their offsets from the start of the file
// Offsets are checked against the file's size when the index is read; the values themselves
// are opaque here and checked by whoever reads them (ProgramCache checksums every entry).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace varc::cache {

// One key and its value.
struct CacheEntry {
    std::string key;
    std::string value;
};

// Where one entry's value lies in a bundle file.
struct BundleSlot {
    std::string key;
    uint64_t offset = 0;
    uint32_t length = 0;
};

// The bytes of a bundle holding |entries| (keys longer than 65535 bytes are left out).
std::string encodeBundle(const std::vector<CacheEntry>& entries);

// How many bytes from the start of a bundle its header and index take, read from the first
// kBundleHeaderBytes bytes; 0 when they do not start a bundle.
constexpr size_t kBundleHeaderBytes = 16;
uint64_t bundleIndexEnd(std::string_view header);

// The slots listed by |headerAndIndex| (the file's first bundleIndexEnd() bytes) whose values
// lie inside a file of |fileSize| bytes; an index that is cut short or malformed yields the
// slots before the damage, never a read outside the bytes given.
std::vector<BundleSlot> decodeBundleIndex(std::string_view headerAndIndex, uint64_t fileSize);

}  // namespace varc::cache
