// SPDX-License-Identifier: Apache-2.0
// A bounds-checked little-endian cursor over bytes (filament's Unflattener discipline).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace varc::reader::detail {

// Every read checks the remaining size first (sizes are compared, never pointers past the end)
// and returns false, leaving the cursor unchanged, when the bytes are not there.
class Unflattener {
public:
    explicit Unflattener(std::span<const std::byte> bytes) : mBytes(bytes) {}

    bool seek(size_t offset);
    bool readU16(uint16_t& out);
    bool readU32(uint32_t& out);
    bool readU64(uint64_t& out);
    bool readBytes(size_t count, std::span<const std::byte>& out);

    size_t offset() const { return mOffset; }
    size_t remaining() const { return mBytes.size() - mOffset; }

private:
    template <typename T>
    bool read(T& out);

    std::span<const std::byte> mBytes;
    size_t mOffset = 0;
};

}  // namespace varc::reader::detail
