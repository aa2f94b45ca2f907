// SPDX-License-Identifier: Apache-2.0
// Accumulates the records of one table chunk (fixed-width records of u32 fields).
#include "TableBuilder.h"

#include "varc/core/Check.h"
#include "varc/pack/LittleEndian.h"
#include "varc/pack/PackFormat.h"

namespace varc::packwriter {

uint32_t TableBuilder::add(std::span<const uint32_t> fields) {
    VARC_CHECK(fields.size() == mFieldCount)
        << "table record has " << fields.size() << " fields, expected " << mFieldCount;
    uint32_t index = size();
    VARC_CHECK(index < pack::kNone) << "too many table records";
    mFields.insert(mFields.end(), fields.begin(), fields.end());
    return index;
}

uint32_t TableBuilder::addRun(std::span<const uint32_t> fields) {
    VARC_CHECK(fields.size() % mFieldCount == 0)
        << "table run has " << fields.size() << " fields, not a multiple of " << mFieldCount;
    if (fields.empty()) return size();
    auto [it, inserted] =
        mRuns.emplace(std::vector<uint32_t>(fields.begin(), fields.end()), size());
    if (!inserted) return it->second;
    for (size_t i = 0; i < fields.size(); i += mFieldCount) add(fields.subspan(i, mFieldCount));
    return it->second;
}

std::string TableBuilder::serialize() const {
    std::string out;
    out.reserve(pack::kTableHeaderSize + 4 * mFields.size());
    pack::appendU32(out, mFieldCount);
    pack::appendU32(out, size());
    for (uint32_t field : mFields) pack::appendU32(out, field);
    return out;
}

}  // namespace varc::packwriter
