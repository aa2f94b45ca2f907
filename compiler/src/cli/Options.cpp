// SPDX-License-Identifier: Apache-2.0
// Command-line parsing for `varc`, through CLI11, into an Options struct.
#include "varc/compiler/cli/Options.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <ostream>

namespace varc::cli {

namespace {

// "12" -> 12 variants; "10%" -> 10 percent.
std::optional<GrowthLimit> parseGrowth(const std::string& text) {
    GrowthLimit limit;
    std::string number = text;
    if (!number.empty() && number.back() == '%') {
        limit.percent = true;
        number.pop_back();
    }
    char* end = nullptr;
    limit.amount = std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || limit.amount < 0) {
        return std::nullopt;
    }
    return limit;
}

void addInputOptions(CLI::App& command, Options& options) {
    command.add_option("-I,--include-dir", options.includeDirs, "Add an include directory")
        ->type_name("DIR");
    command.add_option("--builtin-include-dir", options.builtinIncludeDir,
                       "Override the built-in include directory")
        ->type_name("DIR");
    command.add_option("paths", options.inputs, "Shader files, or directories to search")
        ->required()
        ->type_name("PATH");
}

void addVariants(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("variants", "List passes, keyword sets and variant counts");
    cmd->add_flag("--json", options.json, "Print JSON");
    cmd->add_flag("--list", options.list, "List every variant in enumeration order");
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Variants; });
}

void addLock(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("lock", "Write variant counts to a lock file");
    cmd->add_option("-o,--output", options.lockPath, "Lock file to write")->required();
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Lock; });
}

void addCheck(CLI::App& app, Options& options, std::string& growthText) {
    CLI::App* cmd = app.add_subcommand("check", "Compare variant counts with a lock file");
    cmd->add_option("--lock", options.lockPath, "Lock file to compare with")->required();
    auto* growth = cmd->add_option("--max-growth", growthText,
                                   "Allow each shader to grow by N variants (or N%)");
    cmd->add_option("--budget", options.budget, "Fail when a shader has more than N variants")
        ->excludes(growth);
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Check; });
}

}  // namespace

std::optional<int> parseOptions(int argc, const char* const* argv, Options& options,
                                std::ostream& out, std::ostream& err) {
    CLI::App app{"varc: Unity-style shader variants to SPIR-V packs", "varc"};
    app.require_subcommand(1);
    std::string growthText;
    addVariants(app, options);
    addLock(app, options);
    addCheck(app, options, growthText);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e, out, err);
        return code == 0 ? kExitOk : kExitUsage;
    }
    if (!growthText.empty()) {
        options.maxGrowth = parseGrowth(growthText);
        if (!options.maxGrowth) {
            err << "varc: error: --max-growth expects N or N%, got '" << growthText << "'\n";
            return kExitUsage;
        }
    }
    if (options.builtinIncludeDir.empty()) {
        if (const char* env = std::getenv("VARC_BUILTIN_INCLUDE_DIR")) {
            options.builtinIncludeDir = env;
        }
    }
    return std::nullopt;
}

}  // namespace varc::cli
