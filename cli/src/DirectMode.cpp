// SPDX-License-Identifier: Apache-2.0
// DirectMode: the key of a `varc build --direct`, and finding and recording its pack.
#include "varc/cli/DirectMode.h"

#include <filesystem>
#include <system_error>

#include "varc/cache/CacheChain.h"
#include "varc/cli/DriverOptions.h"
#include "varc/cli/ShaderInputs.h"
#include "varc/driver/ProgramCache.h"

namespace varc::cli {

namespace {

// Whether direct mode can follow everything |input| makes the build read.
bool appliesTo(const ShaderInputOptions& input) {
    return input.projectDir.empty() && input.projectShaders.empty() &&
           input.builtinShaderDirs.empty() && input.stripRulesPath.empty() &&
           input.usageLogs.empty();
}

// Appends "tag value\n"; false when |value| would break the line structure.
bool addLine(std::string& text, std::string_view tag, const std::string& value) {
    if (value.find('\n') != std::string::npos) return false;
    text.append(tag).append(" ").append(value).append("\n");
    return true;
}

// The options that can change the pack's bytes (-j cannot: builds are deterministic).
std::string optionLines(const BuildCommandOptions& options) {
    const CompileOptions& compile = options.compile;
    std::string text;
    text += "optimization " + optimizationFlag(compile.optimization) + "\n";
    text += "debug-names " + std::to_string(compile.debugNames) + "\n";
    text += "compression-level " + std::to_string(options.compressionLevel) + "\n";
    text += "shard " + compile.shard.text() + "\n";
    text += "max-variants " + std::to_string(compile.maxVariants) + "\n";
    text += "sample-variants " + std::to_string(compile.sampleVariants) + "\n";
    text += "keep-going " + std::to_string(compile.keepGoing) + "\n";
    return text;
}

}  // namespace

std::optional<std::string> directKeyText(const BuildCommandOptions& options,
                                         const includes::FileSystem& disk) {
    const ShaderInputOptions& input = options.input;
    if (!options.direct || options.compile.cacheLevels.empty() || !appliesTo(input)) {
        return std::nullopt;
    }
    DiagnosticList errors, searchErrors;
    std::vector<std::string> shaders = findShaderFiles(input.inputs, errors);
    if (errors.hasErrors()) return std::nullopt;  // the normal build reports them
    std::error_code error;
    std::string text = "varc-direct 1\n";
    bool ok = addLine(text, "tool", driver::ProgramCache::executableKey().hex()) &&
              addLine(text, "cwd", std::filesystem::current_path(error).string());
    text += optionLines(options);
    for (const std::string& rule : options.compile.filePrefixMaps)
        ok = addLine(text, "file-prefix-map", rule) && ok;
    for (const std::string& dir : input.includeDirs) ok = addLine(text, "include-dir", dir) && ok;
    ok = addLine(text, "builtin-include-dir", input.builtinIncludeDir) &&
         addLine(text, "project-root", input.projectRoot) && ok;
    for (const std::string& path : input.inputs) ok = addLine(text, "input", path) && ok;
    for (const std::string& path : shaders) {
        ok = addLine(text, "shader", answerQuery(disk, FileQueryKind::Read, path) + " " + path) &&
             ok;
    }
    for (const std::string& path : findShaderFiles(input.includeDirs, searchErrors))
        ok = addLine(text, "search-shader", path) && ok;
    if (!ok || error) return std::nullopt;
    return text;
}

std::optional<DirectMode> DirectMode::open(const BuildCommandOptions& options,
                                           std::shared_ptr<cache::CacheChain> chain,
                                           const includes::FileSystem& disk) {
    if (!chain) return std::nullopt;
    std::optional<std::string> text = directKeyText(options, disk);
    if (!text) return std::nullopt;
    return DirectMode(contentDigest(*text), std::move(chain));
}

std::optional<std::string> DirectMode::findPack(const includes::FileSystem& disk) {
    std::optional<BuildManifest> manifest;
    mChain->get(mKey + ".manifest", [&](std::string_view text) {
        manifest = parseManifest(text, mKey);
        return manifest.has_value();
    });
    if (!manifest) {
        mOutcome.reason = "no manifest for these inputs and options";
        return std::nullopt;
    }
    mOutcome.checkedQueries = manifest->queries.size();
    if (std::optional<std::string> changed = firstChangedQuery(*manifest, disk)) {
        mOutcome.reason = "changed since the recorded build: " + *changed;
        return std::nullopt;
    }
    std::optional<std::string> pack =
        mChain->get(manifest->packDigest + ".pack", [&](std::string_view bytes) {
            return bytes.size() == manifest->packBytes &&
                   contentDigest(bytes) == manifest->packDigest;
        });
    if (!pack) {
        mOutcome.reason = "the recorded pack is missing or damaged";
        return std::nullopt;
    }
    mOutcome.hit = true;
    mOutcome.packBytes = pack->size();
    mManifest = std::move(*manifest);
    return pack;
}

void DirectMode::record(const std::string& pack, std::vector<std::string> dependencies,
                        std::vector<FileQuery> queries) {
    BuildManifest manifest{mKey, contentDigest(pack), pack.size(), std::move(dependencies),
                           std::move(queries)};
    std::optional<std::string> text = serializeManifest(manifest);
    if (!text) {
        mOutcome.notRecorded = "a path holds a line break";
        return;
    }
    // The pack first: a manifest is never visible before the pack it names.
    Status stored = mChain->put(manifest.packDigest + ".pack", pack);
    if (stored) stored = mChain->put(mKey + ".manifest", *text);
    if (!stored) {
        mOutcome.notRecorded = stored.error().detail;
        return;
    }
    mOutcome.recorded = true;
}

std::string directSummaryLine(const DirectOutcome& outcome) {
    if (outcome.hit) {
        return "direct hit: pack reused (" + std::to_string(outcome.checkedQueries) +
               " recorded file checks unchanged)";
    }
    return "Direct mode: miss (" + outcome.reason + "); " +
           (outcome.recorded ? "recorded for the next build"
                             : "not recorded (" + outcome.notRecorded + ")");
}

nlohmann::ordered_json directJson(const DirectOutcome& outcome) {
    nlohmann::ordered_json json = {{"result", outcome.hit ? "hit" : "miss"},
                                   {"checked", outcome.checkedQueries}};
    if (!outcome.hit) {
        json["reason"] = outcome.reason;
        json["recorded"] = outcome.recorded;
        if (!outcome.recorded) json["not_recorded"] = outcome.notRecorded;
    }
    return json;
}

}  // namespace varc::cli
