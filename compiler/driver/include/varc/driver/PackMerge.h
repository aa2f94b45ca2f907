// SPDX-License-Identifier: Apache-2.0
// `varc merge`: the parts of a sharded build joined into the pack the whole build writes.
#pragma once

#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"

namespace varc::driver {

// One part, decoded (reader::decodePack of a pack opened with acceptPartial).
struct PartialPackInput {
    std::string path;  // for messages
    pack::PackContents contents;
};

struct MergedPack {
    pack::PackContents contents;  // what the unsharded build assembles, up to normalisation
    int compressionLevel = 19;    // the zstd level the parts were built for
    // Fragment inputs that no earlier stage writes, in variants whose programs came from different
    // parts (each part checked its own pairs): "file:line:1: error: ...". Not empty: write nothing.
    std::vector<std::string> errors;
};

// Joins |parts|, given in any order: every shard 1..N of one build exactly once, all from the
// same inputs, options and toolchain (equal inputs hash, toolchain, shaders, passes and variant
// keys), each variant's program per stage taken from the part that compiled it. Errors
// (InvalidInput) name the offending part: "b.svpack: not a partial pack (built without
// --shard)", "shard 3/4 is missing", "a.svpack and b.svpack are both shard 2/4",
// "b.svpack: built from other inputs or options than a.svpack (inputs hash ...)".
// Serialising the result with the parts' compression level gives the unsharded build's bytes.
Result<MergedPack> mergePartialPacks(std::vector<PartialPackInput> parts);

}  // namespace varc::driver
