// SPDX-License-Identifier: Apache-2.0
// The program cache on the command line: the levels `--cache`/`--cache-dir`/`VARC_CACHE` name,
// and `varc cache stats|clear`.
#pragma once

#include <iosfwd>
#include <memory>
#include <vector>

#include "varc/cli/Options.h"

namespace varc::cache {
class CacheChain;
}

namespace varc::cli {

// The chain of |levels| in order (the parser already checked them; nothing connects yet);
// nullptr when there are none.
std::shared_ptr<cache::CacheChain> openCacheLevels(const std::vector<cache::CacheSpec>& levels);

// `varc cache stats`: per level "URL: N entries, B KiB" (--json: [{"url","entries","bytes"}]).
// `varc cache clear`: removes every entry varc stored in each level, and nothing else.
// Exit 1 when a level cannot be read or cleared (the others are still done), 2 without a level.
int runCache(const CacheOptions& options, std::ostream& out, std::ostream& err);

}  // namespace varc::cli
