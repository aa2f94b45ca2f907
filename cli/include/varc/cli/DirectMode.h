// SPDX-License-Identifier: Apache-2.0
// DirectMode: `varc build --direct`, ccache's direct mode for packs: reuse the pack of an earlier
// build with the same key when every file it read still has the same digest (BuildManifest.h).
//
// The key (XXH3-128) covers the running executable, the working folder, every option that can
// change the pack (-O, -g, --compression-level, --shard, --max-variants, --keep-going,
// --file-prefix-map, -I, --builtin-include-dir, --project-root), the PATH arguments, the
// .shader files they name with their digests, and the .shader files under the -I folders (which
// UsePass and Fallback may find). Builds with --project, --strip-rules or --usage-log read files
// the manifest does not follow, so direct mode leaves them alone.
//
// Cache entries, in every level of the chain: "<key>.manifest" (the BuildManifest text) and
// "<pack digest>.pack" (the pack's bytes, checked against the digest before use). The pack is
// stored before the manifest that names it; a damaged or missing entry is a miss.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "varc/cli/BuildManifest.h"
#include "varc/cli/Options.h"
#include "varc/core/Result.h"

namespace varc::cache {
class CacheChain;
}

namespace varc::cli {

// What direct mode did, for the build summary.
struct DirectOutcome {
    bool hit = false;
    std::string reason;       // a miss: why ("no manifest", "changed: inc/Light.cginc", ...)
    bool recorded = false;    // a miss: whether this build's manifest was stored
    std::string notRecorded;  // why not, when it was not
    size_t checkedQueries = 0;
    uint64_t packBytes = 0;
};

class DirectMode {
public:
    // Direct mode for |options| (nullopt when it is off or does not apply); reads the inputs
    // through |disk| to compute the key.
    static std::optional<DirectMode> open(const BuildCommandOptions& options,
                                          std::shared_ptr<cache::CacheChain> chain,
                                          const includes::FileSystem& disk);

    // The pack of an earlier build that this one would write, checked against its digest, or
    // nullopt (the reason is kept in outcome()). The manifest is kept for the depfile.
    std::optional<std::string> findPack(const includes::FileSystem& disk);

    // Stores |pack| and the manifest of a build that read what |queries| record.
    void record(const std::string& pack, std::vector<std::string> dependencies,
                std::vector<FileQuery> queries);

    const std::string& key() const { return mKey; }
    const BuildManifest& manifest() const { return mManifest; }
    DirectOutcome& outcome() { return mOutcome; }

private:
    DirectMode(std::string key, std::shared_ptr<cache::CacheChain> chain)
        : mKey(std::move(key)), mChain(std::move(chain)) {}

    std::string mKey;
    std::shared_ptr<cache::CacheChain> mChain;
    BuildManifest mManifest;
    DirectOutcome mOutcome;
};

// The summary's line about |outcome|, e.g. "Direct mode: miss (no manifest ...); recorded for
// the next build", and its JSON ({"result": "hit"|"miss", "reason", "recorded", "checked"}).
std::string directSummaryLine(const DirectOutcome& outcome);
nlohmann::ordered_json directJson(const DirectOutcome& outcome);

// The text the key hashes (exposed for tests), or nullopt when direct mode does not apply to
// |options| or an input cannot be found.
std::optional<std::string> directKeyText(const BuildCommandOptions& options,
                                         const includes::FileSystem& disk);

}  // namespace varc::cli
