// SPDX-License-Identifier: Apache-2.0
// Reading a CLI11 definition back for the generated man page and bash completion.
#include "CliWalk.h"

namespace varc::cli {

std::vector<const CLI::App*> visibleSubcommands(const CLI::App& app) {
    return app.get_subcommands([](const CLI::App* sub) { return !sub->get_group().empty(); });
}

std::vector<std::string> optionSpellings(const CLI::Option& option) {
    std::vector<std::string> spellings;
    for (const std::string& name : option.get_snames()) spellings.push_back("-" + name);
    for (const std::string& name : option.get_lnames()) spellings.push_back("--" + name);
    return spellings;
}

bool isFlag(const CLI::Option& option) { return option.get_expected_max() == 0; }

std::string valueName(const CLI::Option& option) {
    std::string name = option.get_type_name();
    name = name.substr(0, name.find(':'));
    return name.empty() ? "VALUE" : name;
}

}  // namespace varc::cli
