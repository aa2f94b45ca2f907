// SPDX-License-Identifier: Apache-2.0
#include "varc/cli/CacheCommands.h"

#include <nlohmann/json.hpp>
#include <ostream>

#include "varc/cache/CacheChain.h"

namespace varc::cli {

namespace {

// The levels for `varc cache`, or an exit code after printing why there are none.
std::shared_ptr<cache::CacheChain> levelsOrReport(const Options& options, std::ostream& err,
                                                  int& exitCode) {
    Result<std::shared_ptr<cache::CacheChain>> chain = openCacheLevels(options);
    if (!chain) {
        err << "varc: error: " << chain.error().detail << "\n";
        exitCode = kExitUsage;
        return nullptr;
    }
    if (!*chain) {
        err << "varc: error: no cache named: give --cache URL or set VARC_CACHE\n";
        exitCode = kExitUsage;
    }
    return *chain;
}

}  // namespace

Result<std::shared_ptr<cache::CacheChain>> openCacheLevels(const Options& options) {
    std::vector<cache::CacheSpec> specs;
    std::vector<std::string> urls;
    if (!options.cacheDirectory.empty()) urls.push_back("file:" + options.cacheDirectory);
    urls.insert(urls.end(), options.cacheUrls.begin(), options.cacheUrls.end());
    for (const std::string& url : urls) {
        Result<cache::CacheSpec> spec = cache::parseCacheSpec(url);
        if (!spec) return spec.error();
        specs.push_back(std::move(*spec));
    }
    if (specs.empty()) return std::shared_ptr<cache::CacheChain>();
    return std::make_shared<cache::CacheChain>(cache::CacheChain::open(specs));
}

int runCacheStats(const Options& options, std::ostream& out, std::ostream& err) {
    int exitCode = kExitOk;
    std::shared_ptr<cache::CacheChain> chain = levelsOrReport(options, err, exitCode);
    if (!chain) return exitCode;
    nlohmann::ordered_json levels = nlohmann::ordered_json::array();
    for (const auto& level : chain->levels()) {
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

int runCacheClear(const Options& options, std::ostream& out, std::ostream& err) {
    int exitCode = kExitOk;
    std::shared_ptr<cache::CacheChain> chain = levelsOrReport(options, err, exitCode);
    if (!chain) return exitCode;
    for (const auto& level : chain->levels()) {
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

}  // namespace varc::cli
