// SPDX-License-Identifier: Apache-2.0
// The program cache on the command line: the levels `--cache`/`--cache-dir`/`VARC_CACHE` name,
// and `varc cache stats|clear`.
#pragma once

#include <iosfwd>
#include <memory>

#include "varc/cli/Options.h"
#include "varc/core/Result.h"

namespace varc::cache {
class CacheChain;
}

namespace varc::cli {

// The cache levels in order: --cache-dir DIR first (as file:DIR), then every --cache URL (or
// VARC_CACHE's); nullptr when none is named. A malformed URL is an error quoting it.
Result<std::shared_ptr<cache::CacheChain>> openCacheLevels(const Options& options);

// `varc cache stats`: per level "URL: N entries, B KiB" (--json: [{"url","entries","bytes"}]).
// Exit 1 when a level cannot be read (the others are still listed), 2 without a level.
int runCacheStats(const Options& options, std::ostream& out, std::ostream& err);

// `varc cache clear`: removes every entry varc stored in each level, and nothing else.
int runCacheClear(const Options& options, std::ostream& out, std::ostream& err);

}  // namespace varc::cli
