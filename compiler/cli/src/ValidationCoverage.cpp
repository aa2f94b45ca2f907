// SPDX-License-Identifier: Apache-2.0
// How much of each pack `varc validate` compared with the reference.
#include "ValidationCoverage.h"

#include <filesystem>
#include <map>

#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"

namespace varc::cli {

namespace {

struct Tally {
    size_t compared = 0, total = 0;
};

}  // namespace

void printValidationCoverage(const std::vector<runtime::Pack>& packs,
                             const std::vector<std::string>& packPaths,
                             const std::set<std::string>& compared, bool listUncovered,
                             std::ostream& out) {
    for (size_t p = 0; p < packs.size(); ++p) {
        Tally all;
        std::map<std::string, Tally> byLightMode;  // "" = no LightMode tag
        std::vector<std::string> uncovered;
        for (size_t s = 0; s < packs[p].shaderCount(); ++s) {
            const runtime::ShaderView shader = packs[p].shader(s);
            for (size_t i = 0; i < shader.passCount(); ++i) {
                std::optional<runtime::PassView> pass = shader.pass(i);
                if (!pass) continue;
                Tally& mode = byLightMode[std::string(pass->lightMode())];
                for (size_t v = 0; v < pass->variantCount(); ++v) {
                    const std::string name = pass->variant(v).describe();
                    const bool seen = compared.count(name) > 0;
                    if (!seen) uncovered.push_back(name);
                    ++all.total;
                    ++mode.total;
                    all.compared += seen;
                    mode.compared += seen;
                }
            }
        }
        out << std::filesystem::path(packPaths[p]).filename().string() << ": " << all.compared
            << " of " << all.total << " variants compared with the reference (";
        const char* separator = "";
        for (const auto& [lightMode, tally] : byLightMode) {
            out << separator << (lightMode.empty() ? "no LightMode" : lightMode) << " "
                << tally.compared << "/" << tally.total;
            separator = ", ";
        }
        out << ")\n";
        if (listUncovered) {
            for (const std::string& name : uncovered) out << "  not compared: " << name << "\n";
        }
    }
}

}  // namespace varc::cli
