// SPDX-License-Identifier: Apache-2.0
// Serializes PackContents to the varc pack format (docs/PACK_FORMAT.md) and writes pack files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"

namespace varc::packwriter {

enum class PackDictionary {
    Auto,    // train a zstd dictionary across the blobs; keep it only if the pack gets smaller
    Never,   // compress every blob on its own
    Always,  // use a trained dictionary whenever training succeeds (for tests)
};

struct PackWriteOptions {
    int compressionLevel = 19;  // zstd level, 1..22
    PackDictionary dictionary = PackDictionary::Auto;
    size_t maxDictionaryBytes = 64 * 1024;
};

// What serializePack() stored, for build summaries and benchmarks.
struct PackWriteStats {
    size_t programs = 0;           // distinct programs after merging equal ones
    size_t blobs = 0;              // distinct SPIR-V modules
    uint64_t rawSpirvBytes = 0;    // of the distinct modules, uncompressed
    uint64_t storedBlobBytes = 0;  // of the distinct modules as stored (compressed)
    size_t dictionaryBytes = 0;    // 0 when no dictionary is used
    uint64_t packBytes = 0;        // the whole pack
};

// Encodes |contents| as a pack. Deterministic: equal contents (and options, and zstd version)
// give identical bytes. Programs equal in stage, entry point and SPIR-V are stored once (the
// first one's reflection and source info are kept) and renumbered in first-use order (shader,
// pass, variant in enumeration order, stage); programs no variant uses are dropped, so the
// order of |contents.programs| does not affect the bytes.
//
// |contents| must be well formed, or this aborts through VARC_CHECK (a bug in the caller):
// every keyword table sorted and unique with at most 256 non-empty names; variant keys unique
// within their pass and using only bits of the pass's table; program indices in range, in the
// slot of their stage; SPIR-V non-empty and at most pack::kMaxBlobBytes.
//
// Example: serializePack(contents, {.compressionLevel = 3}) for a quick debug build.
std::string serializePack(const pack::PackContents& contents, const PackWriteOptions& options = {},
                          PackWriteStats* stats = nullptr);

// serializePack() then varc::writeFileAtomically(): readers of |path| see the old pack or the
// new one, never a mix. Returns an IoError naming |path| on failure.
Status writePack(const std::string& path, const pack::PackContents& contents,
                 const PackWriteOptions& options = {}, PackWriteStats* stats = nullptr);

}  // namespace varc::packwriter
