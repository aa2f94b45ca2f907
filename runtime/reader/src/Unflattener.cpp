// SPDX-License-Identifier: Apache-2.0
// A bounds-checked little-endian cursor over bytes (filament's Unflattener discipline).
#include "Unflattener.h"

#include "varc/pack/LittleEndian.h"

namespace varc::reader::detail {

bool Unflattener::seek(size_t offset) {
    if (offset > mBytes.size()) return false;
    mOffset = offset;
    return true;
}

template <typename T>
bool Unflattener::read(T& out) {
    if (remaining() < sizeof(T)) return false;
    out = pack::loadLittle<T>(mBytes.data() + mOffset);
    mOffset += sizeof(T);
    return true;
}

bool Unflattener::readU16(uint16_t& out) { return read(out); }
bool Unflattener::readU32(uint32_t& out) { return read(out); }
bool Unflattener::readU64(uint64_t& out) { return read(out); }

bool Unflattener::readBytes(size_t count, std::span<const std::byte>& out) {
    if (remaining() < count) return false;
    out = mBytes.subspan(mOffset, count);
    mOffset += count;
    return true;
}

}  // namespace varc::reader::detail
