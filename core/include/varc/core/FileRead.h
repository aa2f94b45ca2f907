// SPDX-License-Identifier: Apache-2.0
// Reads a whole file, the one way every varc library does it.
#pragma once

#include <cstddef>
#include <string>

#include "varc/core/Result.h"

namespace varc {

// The contents of the regular file |path|. Errors (ErrorCode::IoError), each naming the path
// and the reason: it cannot be opened ("cannot open 'x': No such file or directory"), it is a
// directory or another non-regular file, a read fails, or it holds more than |maxBytes|.
// Never throws (std::ifstream with istreambuf_iterator throws on a directory in libstdc++).
Result<std::string> readFile(const std::string& path, size_t maxBytes = size_t{1} << 32);

}  // namespace varc
