// SPDX-License-Identifier: Apache-2.0
// Decodes a whole open Pack back into PackContents (for tests, tools and round trips).
#pragma once

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"
#include "varc/reader/Pack.h"

namespace varc::reader {

// Everything |pack| holds, with every blob decompressed and variants in enumeration order:
// equal to the contents given to packwriter::serializePack() after its normalisation (programs
// merged, renumbered in first-use order, unused ones dropped). Fails only when a blob does not
// decompress. Allocates freely; not meant for the render loop.
Result<pack::PackContents> decodePack(const Pack& pack);

}  // namespace varc::reader
