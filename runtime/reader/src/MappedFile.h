// SPDX-License-Identifier: Apache-2.0
// A read-only memory mapping of a whole file, unmapped on destruction (move-only).
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "varc/core/Result.h"

namespace varc::reader::detail {

class MappedFile {
public:
    MappedFile() = default;
    MappedFile(MappedFile&& other) noexcept;
    MappedFile& operator=(MappedFile&& other) noexcept;
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    ~MappedFile();

    // Maps |path| read-only (MAP_PRIVATE). An empty file maps to an empty span. Returns an
    // IoError naming |path| and the system's reason when it cannot be opened or mapped.
    static Result<MappedFile> map(const std::string& path);

    std::span<const std::byte> bytes() const { return {mData, mSize}; }

private:
    void reset();

    const std::byte* mData = nullptr;
    size_t mSize = 0;
};

}  // namespace varc::reader::detail
