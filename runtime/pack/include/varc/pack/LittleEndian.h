// SPDX-License-Identifier: Apache-2.0
// Explicit little-endian loads and stores for the pack format, independent of the host's order.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace varc::pack {

// Converts between host order and little-endian; a no-op on little-endian hosts.
template <typename T>
constexpr T littleEndian(T value) {
    static_assert(sizeof(T) == 2 || sizeof(T) == 4 || sizeof(T) == 8);
    if constexpr (std::endian::native == std::endian::little) {
        return value;
    } else if constexpr (sizeof(T) == 2) {
        return static_cast<T>(__builtin_bswap16(value));
    } else if constexpr (sizeof(T) == 4) {
        return static_cast<T>(__builtin_bswap32(value));
    } else {
        return static_cast<T>(__builtin_bswap64(value));
    }
}

// Reads a little-endian value at |p|, which needs no particular alignment. The caller has
// checked that sizeof(T) bytes are readable.
template <typename T>
inline T loadLittle(const std::byte* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return littleEndian(value);
}

inline uint16_t loadU16(const std::byte* p) { return loadLittle<uint16_t>(p); }
inline uint32_t loadU32(const std::byte* p) { return loadLittle<uint32_t>(p); }
inline uint64_t loadU64(const std::byte* p) { return loadLittle<uint64_t>(p); }

// Appends |value| to |out| in little-endian order.
template <typename T>
inline void appendLittle(std::string& out, T value) {
    T le = littleEndian(value);
    char bytes[sizeof(T)];
    std::memcpy(bytes, &le, sizeof(T));
    out.append(bytes, sizeof(T));
}

inline void appendU16(std::string& out, uint16_t value) { appendLittle(out, value); }
inline void appendU32(std::string& out, uint32_t value) { appendLittle(out, value); }
inline void appendU64(std::string& out, uint64_t value) { appendLittle(out, value); }

// Overwrites the little-endian value at |out[offset]|; the bytes must already exist.
template <typename T>
inline void storeLittle(std::string& out, size_t offset, T value) {
    T le = littleEndian(value);
    std::memcpy(out.data() + offset, &le, sizeof(T));
}

// Floats are stored as the little-endian bits of their IEEE-754 binary32 form.
inline uint32_t floatBits(float value) { return std::bit_cast<uint32_t>(value); }
inline float floatFromBits(uint32_t bits) { return std::bit_cast<float>(bits); }

}  // namespace varc::pack
