// SPDX-License-Identifier: Apache-2.0
// A table chunk's records, read in place; only used after the schema check has passed.
#pragma once

#include <cstddef>
#include <cstdint>

#include "varc/pack/LittleEndian.h"

namespace varc::reader::detail {

struct TableView {
    const std::byte* records = nullptr;
    uint32_t fieldCount = 0;  // as stored; >= the schema's (newer minor versions append fields)
    uint32_t count = 0;

    // Field |field| of record |record|. Unchecked: the reader validated every record and field
    // index it derives before any accessor runs.
    uint32_t get(uint32_t record, uint32_t field) const {
        return pack::loadU32(records + (static_cast<size_t>(record) * fieldCount + field) * 4);
    }
};

}  // namespace varc::reader::detail
