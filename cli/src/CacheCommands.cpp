// SPDX-License-Identifier: Apache-2.0
// `varc cache stats|clear`, and the chain of cache levels `varc build` compiles with.
#include "varc/cli/CacheCommands.h"

#include <nlohmann/json.hpp>
#include <ostream>

#include "varc/cache/CacheChain.h"

namespace varc::cli {

namespace {

int runCacheStats(const CacheOptions& options, cache::CacheChain& chain, std::ostream& out,
                  std::ostream& err) {
    int exitCode = kExitOk;
    nlohmann::ordered_json levels = nlohmann::ordered_json::array();
    for (const auto& level : chain.levels()) {
        Result<cache::CacheUsage> usage = level->usage();
        if (!usage) {
            err << "varc: error: " << usage.error().detail << "\n";
            exitCode = kExitFailure;
            continue;
        }
        if (options.json) {
            levels.push_back(
                {{"url", level->name()}, {"entries", usage->entries}, {"bytes", usage->bytes}});
        } else {
            out << level->name() << ": " << usage->entries << " entries, " << usage->bytes
                << " bytes\n";
        }
    }
    if (options.json) out << levels.dump() << "\n";
    return exitCode;
}

int runCacheClear(cache::CacheChain& chain, std::ostream& out, std::ostream& err) {
    int exitCode = kExitOk;
    for (const auto& level : chain.levels()) {
        Result<uint64_t> removed = level->clear();
        if (!removed) {
            err << "varc: error: " << removed.error().detail << "\n";
            exitCode = kExitFailure;
            continue;
        }
        out << level->name() << ": removed " << *removed << " entries\n";
    }
    return exitCode;
}

}  // namespace

std::shared_ptr<cache::CacheChain> openCacheLevels(const std::vector<cache::CacheSpec>& levels) {
    if (levels.empty()) return nullptr;
    return std::make_shared<cache::CacheChain>(cache::CacheChain::open(levels));
}

int runCache(const CacheOptions& options, std::ostream& out, std::ostream& err) {
    std::shared_ptr<cache::CacheChain> chain = openCacheLevels(options.levels);
    if (!chain) {
        err << "varc: error: no cache named: give --cache URL or set VARC_CACHE\n";
        return kExitUsage;
    }
    return options.action == CacheOptions::Action::Stats ? runCacheStats(options, *chain, out, err)
                                                         : runCacheClear(*chain, out, err);
}

}  // namespace varc::cli
