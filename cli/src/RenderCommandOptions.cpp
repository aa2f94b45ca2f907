// SPDX-License-Identifier: Apache-2.0
// The CLI11 definition of render, validate and the program cache's `cache stats|clear`.
#include <memory>

#include "OptionDefinitions.h"

namespace varc::cli {

namespace {

void addPipelineCache(CLI::App& command, RenderSessionOptions& session) {
    command
        .add_option("--pipeline-cache", session.pipelineCachePath,
                    "VkPipelineCache file to load and save")
        ->type_name("FILE");
}

// What `cache stats` and `cache clear` parse: the URLs, decoded when the parse ends.
struct CacheFlags {
    CacheOptions options;
    std::vector<std::string> urls;
};

void finishCache(CLI::App& command, ParseState& state, std::shared_ptr<CacheFlags> flags) {
    command.callback([&state, flags] {
        state.finish = [flags]() -> Result<CommandOptions> {
            auto levels = cacheLevelsOf("", flags->urls);
            if (!levels) return levels.error();
            flags->options.levels = std::move(*levels);
            return CommandOptions(flags->options);
        };
    });
}

}  // namespace

void addRender(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render a scene with pack variants on Vulkan");
    cmd->add_option("packs", options->session.packPaths, "Pack files")
        ->required()
        ->type_name("PACK");
    cmd->add_option("--scene", options->scenePath, "Scene JSON")->required()->type_name("FILE");
    cmd->add_option("-o,--output", options->outputPath, "PNG to write")
        ->required()
        ->type_name("FILE");
    cmd->add_option("--reference", options->referencePath,
                    "Also render the CPU reference to this PNG")
        ->type_name("FILE");
    cmd->add_option("--diff", options->diffPath, "Also compare and write the diff image here")
        ->type_name("FILE");
    addPipelineCache(*cmd, options->session);
    auto policy = std::make_shared<std::string>("closest");
    cmd->add_option("--variant-policy", *policy,
                    "A variant the pack lacks: closest (default; a warning once each) or strict "
                    "(an error)")
        ->check(CLI::IsMember({"closest", "strict"}))
        ->type_name("POLICY");
    cmd->add_option("--usage-log", options->usageLogPath,
                    "Write every distinct variant request as JSON Lines (docs/USAGE_LOG.md)")
        ->type_name("FILE");
    cmd->callback([&state, options, policy] {
        state.finish = [options, policy]() -> Result<CommandOptions> {
            options->variantPolicy = *policy == "strict" ? variants::SelectionPolicy::Strict
                                                         : variants::SelectionPolicy::Closest;
            return CommandOptions(*options);
        };
    });
}

void addValidate(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<ValidateOptions>();
    CLI::App* cmd =
        app.add_subcommand("validate", "Render every scene and compare with the CPU reference");
    cmd->add_option("--pack", options->session.packPaths, "Pack files (repeat)")
        ->required()
        ->type_name("PACK");
    cmd->add_option("--scenes", options->scenesDir,
                    std::string("Scene folder (default ") + kDefaultScenesDir + ")")
        ->type_name("DIR");
    cmd->add_option("--out", options->outputDir,
                    std::string("Folder for the PNGs (default ") + kDefaultValidateOut + ")")
        ->type_name("DIR");
    cmd->add_flag("--properties", options->properties,
                  "Check metamorphic relations on generated scenes for every lit shader "
                  "(docs/PROPERTIES.md) instead of comparing scenes with the reference")
        ->excludes("--scenes");
    cmd->add_flag("--list-uncovered", options->listUncovered,
                  "Also list each variant no matching scene drew");
    cmd->add_option("--report", options->reportPath,
                    "Also write a self-contained HTML page of the images, variants and property "
                    "checks")
        ->type_name("FILE");
    addPipelineCache(*cmd, options->session);
    cmd->callback([&state, options] {
        state.finish = [options]() -> Result<CommandOptions> {
            // An empty folder name means the default, as if the flag were not given.
            if (options->scenesDir.empty()) options->scenesDir = kDefaultScenesDir;
            if (options->outputDir.empty()) options->outputDir = kDefaultValidateOut;
            return CommandOptions(*options);
        };
    });
}

void addCache(CLI::App& app, ParseState& state) {
    CLI::App* cmd = app.add_subcommand("cache", "Inspect or empty program cache levels");
    cmd->require_subcommand(1);
    auto statsFlags = std::make_shared<CacheFlags>();
    CLI::App* stats = cmd->add_subcommand("stats", "Entries and bytes in each cache level");
    addCacheUrls(*stats, statsFlags->urls);
    stats->add_flag("--json", statsFlags->options.json, "Print JSON");
    finishCache(*stats, state, statsFlags);
    auto clearFlags = std::make_shared<CacheFlags>();
    clearFlags->options.action = CacheOptions::Action::Clear;
    CLI::App* clear = cmd->add_subcommand("clear", "Remove every entry varc stored in each level");
    addCacheUrls(*clear, clearFlags->urls);
    finishCache(*clear, state, clearFlags);
}

}  // namespace varc::cli
