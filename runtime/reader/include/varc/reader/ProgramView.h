// SPDX-License-Identifier: Apache-2.0
// One stage program of an open Pack: SPIR-V (decompressed lazily), reflection, source info.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"

namespace varc::reader {

namespace detail {
class PackImage;
}

// A cheap handle; valid while its Pack lives. See Pack for the thread-safety contract.
class ProgramView {
public:
    ProgramView(const detail::PackImage* image, uint32_t index) : mImage(image), mIndex(index) {}

    uint32_t index() const { return mIndex; }
    Stage stage() const;
    std::string_view entryPoint() const;
    size_t spirvByteSize() const;  // without decompressing

    // The SPIR-V words. The first call for a blob decompresses it (blocking concurrent callers
    // of the same blob until done); later calls return the same span without work. Stored
    // blobs are returned in place from the mapping. InvalidInput, naming the program's source,
    // when the blob does not decompress (a corrupt pack that passed the checksums).
    Result<std::span<const uint32_t>> spirv() const;

    pack::ProgramReflection reflection() const;  // decoded on each call; allocates
    pack::SourceInfo source() const;             // allocates
    std::string_view sourceFile() const;
    uint32_t sourceLine() const;

    // "Assets/Lit.shader:42 (vertex program 'vert')", for runtime error messages.
    std::string describe() const;

private:
    uint32_t field(uint32_t field) const;

    const detail::PackImage* mImage;
    uint32_t mIndex;
};

}  // namespace varc::reader
