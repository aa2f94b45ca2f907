// SPDX-License-Identifier: Apache-2.0
// The CLI11 definition of the commands that read built packs: merge, info, extract, lookup.
#include <memory>
#include <sstream>

#include "OptionDefinitions.h"

namespace varc::cli {

namespace {

// Sets state.finish, when |command| runs, to return |options| as parsed.
template <typename T>
void finishAsParsed(CLI::App& command, ParseState& state, std::shared_ptr<T> options) {
    command.callback([&state, options] {
        state.finish = [options]() -> Result<CommandOptions> { return CommandOptions(*options); };
    });
}

std::vector<std::string> splitWords(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream stream(text);
    for (std::string word; stream >> word;) words.push_back(word);
    return words;
}

// What `lookup` parses as text, decoded when the parse ends.
struct LookupFlags {
    LookupOptions options;
    std::string keywords;
    std::string light;  // "" = no --light
    bool cookie = false;
    std::optional<std::string> shadows;  // absent: LightDescription's default
    int vertexLights = 0;
    bool hdr = false;
    std::optional<std::string> policy;  // absent: LookupOptions' default
};

// The light --light and its companions describe, or the usage error.
Result<variants::LightDescription> lightOf(const LookupFlags& flags) {
    variants::LightDescription light;
    auto type = variants::parseLightType(flags.light);
    if (!type) {
        return usageError("--light expects directional, point or spot, got '" + flags.light + "'");
    }
    light.type = *type;
    if (flags.shadows) {
        auto shadows = variants::parseShadowMode(*flags.shadows);
        if (!shadows) {
            return usageError("--shadows expects none, hard or soft, got '" + *flags.shadows + "'");
        }
        light.shadows = *shadows;
    }
    light.cookie = flags.cookie;
    light.vertexLightCount = flags.vertexLights;
    light.hdr = flags.hdr;
    return light;
}

// The lookup options of |flags|, or the usage error.
Result<CommandOptions> finishLookup(LookupFlags& flags) {
    LookupOptions& options = flags.options;
    if (flags.policy) {
        auto policy = variants::parseSelectionPolicy(*flags.policy);
        if (!policy) {
            return usageError("--policy expects exact, closest, first or strict, got '" +
                              *flags.policy + "'");
        }
        options.policy = *policy;
    }
    options.keywords = splitWords(flags.keywords);
    if (!flags.light.empty()) {
        Result<variants::LightDescription> light = lightOf(flags);
        if (!light) return light.error();
        options.light = *light;
    }
    return CommandOptions(options);
}

}  // namespace

void addMerge(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<MergeOptions>();
    CLI::App* cmd = app.add_subcommand(
        "merge", "Join the partial packs of `varc build --shard K/N` into the whole build's pack");
    cmd->add_option("-o,--output", options->outputPath, "Pack file to write")->required();
    cmd->add_option("parts", options->parts, "The N partial packs, in any order")
        ->required()
        ->type_name("PART");
    finishAsParsed(*cmd, state, options);
}

void addInfo(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd =
        app.add_subcommand("info", "Describe a pack: shaders, passes, variants, programs");
    cmd->add_flag("--json", options->json, "Print JSON");
    cmd->add_option("pack", options->packPath, "Pack file")->required()->type_name("PACK");
    finishAsParsed(*cmd, state, options);
}

void addExtract(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<ExtractOptions>();
    CLI::App* cmd = app.add_subcommand("extract", "Write every program as .spv plus manifest.json");
    cmd->add_option("pack", options->packPath, "Pack file")->required()->type_name("PACK");
    cmd->add_option("-o,--output", options->outputDir, "Directory to write")
        ->required()
        ->type_name("DIR");
    finishAsParsed(*cmd, state, options);
}

void addLookup(CLI::App& app, ParseState& state) {
    auto flags = std::make_shared<LookupFlags>();
    CLI::App* cmd = app.add_subcommand("lookup", "Find the variant for keywords or a light");
    cmd->add_option("pack", flags->options.packPath, "Pack file")->required()->type_name("PACK");
    cmd->add_option("--shader", flags->options.shader, "Shader name")
        ->required()
        ->type_name("NAME");
    cmd->add_option("--pass", flags->options.pass, "Pass index or LightMode")
        ->required()
        ->type_name("N|LIGHTMODE");
    auto* keywords =
        cmd->add_option("--keywords", flags->keywords,
                        "Enabled keywords, space-separated (with --light: the material's)")
            ->type_name("\"A B\"");
    auto* light = cmd->add_option("--light", flags->light, "Light type: directional, point or spot")
                      ->type_name("TYPE");
    cmd->add_flag("--cookie", flags->cookie, "The light has a cookie")->needs(light);
    cmd->add_option("--shadows", flags->shadows, "none, hard or soft")
        ->type_name("MODE")
        ->needs(light);
    cmd->add_option("--vertex-lights", flags->vertexLights, "Point lights shaded per vertex")
        ->needs(light);
    cmd->add_flag("--hdr", flags->hdr, "The camera renders HDR")->needs(light);
    cmd->add_option("--policy", flags->policy, "exact, closest (default), first or strict")
        ->type_name("POLICY");
    cmd->add_flag("--json", flags->options.json, "Print JSON");
    cmd->callback([&state, flags, keywords, light] {
        if (keywords->count() == 0 && light->count() == 0) {
            throw CLI::RequiredError("lookup needs --keywords or --light");
        }
        state.finish = [flags]() { return finishLookup(*flags); };
    });
}

}  // namespace varc::cli
