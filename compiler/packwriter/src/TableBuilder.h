// SPDX-License-Identifier: Apache-2.0
// Accumulates the records of one table chunk (fixed-width records of u32 fields).
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace varc::packwriter {

class TableBuilder {
public:
    explicit TableBuilder(uint32_t fieldCount) : mFieldCount(fieldCount) {}

    // Appends one record; |fields| must have exactly fieldCount() values. Returns its index.
    uint32_t add(std::span<const uint32_t> fields);
    uint32_t add(std::initializer_list<uint32_t> fields) {
        return add(std::span<const uint32_t>(fields.begin(), fields.size()));
    }

    // Appends the records in |fields| (a whole number of records) as one run referenced by
    // (first, count), unless an identical run was added through addRun before: then returns that
    // run's first index and adds nothing. An empty run returns size().
    uint32_t addRun(std::span<const uint32_t> fields);

    uint32_t fieldCount() const { return mFieldCount; }
    uint32_t size() const { return static_cast<uint32_t>(mFields.size() / mFieldCount); }

    // The chunk: u32 fieldCount, u32 recordCount, then the records, little-endian.
    std::string serialize() const;

private:
    uint32_t mFieldCount;
    std::vector<uint32_t> mFields;
    std::map<std::vector<uint32_t>, uint32_t> mRuns;  // run fields -> first record
};

}  // namespace varc::packwriter
