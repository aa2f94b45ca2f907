// SPDX-License-Identifier: Apache-2.0
// Lays out header, chunk table and chunks into the final file, with checksums and padding.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "varc/pack/PackFormat.h"

namespace varc::packwriter {

// Returns the pack file for |chunks| (in the order given) and |inputsHash|: the 64-byte header,
// the chunk table, then each chunk at the next 8-aligned offset with zero padding between.
std::string assembleChunks(const std::vector<std::pair<pack::Chunk, std::string>>& chunks,
                           uint64_t inputsHash);

}  // namespace varc::packwriter
