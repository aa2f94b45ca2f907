// SPDX-License-Identifier: Apache-2.0
// How much of each pack `varc validate` compared with the reference.
#include "ValidationCoverage.h"

#include <filesystem>

#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"

namespace varc::cli {

namespace {

PackCoverage packCoverage(const reader::Pack& pack, const std::string& path,
                          const std::set<std::string>& compared) {
    PackCoverage coverage;
    coverage.packName = std::filesystem::path(path).filename().string();
    for (size_t s = 0; s < pack.shaderCount(); ++s) {
        const reader::ShaderView shader = pack.shader(s);
        for (size_t i = 0; i < shader.passCount(); ++i) {
            std::optional<reader::PassView> pass = shader.pass(i);
            if (!pass) continue;
            CoverageTally& mode = coverage.byLightMode[std::string(pass->lightMode())];
            for (size_t v = 0; v < pass->variantCount(); ++v) {
                std::string name = pass->variant(v).describe();
                const bool seen = compared.count(name) > 0;
                ++coverage.all.total;
                ++mode.total;
                coverage.all.compared += seen;
                mode.compared += seen;
                if (!seen) coverage.uncovered.push_back(std::move(name));
            }
        }
    }
    return coverage;
}

}  // namespace

std::vector<PackCoverage> computeValidationCoverage(const std::vector<reader::Pack>& packs,
                                                    const std::vector<std::string>& packPaths,
                                                    const std::set<std::string>& compared) {
    std::vector<PackCoverage> coverage;
    for (size_t p = 0; p < packs.size(); ++p)
        coverage.push_back(packCoverage(packs[p], packPaths[p], compared));
    return coverage;
}

std::string lightModeSummary(const PackCoverage& coverage) {
    std::string text;
    const char* separator = "";
    for (const auto& [lightMode, tally] : coverage.byLightMode) {
        text += separator;
        text += (lightMode.empty() ? "no LightMode" : lightMode) + " " +
                std::to_string(tally.compared) + "/" + std::to_string(tally.total);
        separator = ", ";
    }
    return text;
}

void printValidationCoverage(const std::vector<reader::Pack>& packs,
                             const std::vector<std::string>& packPaths,
                             const std::set<std::string>& compared, bool listUncovered,
                             std::ostream& out) {
    for (const PackCoverage& coverage : computeValidationCoverage(packs, packPaths, compared)) {
        out << coverage.packName << ": " << coverage.all.compared << " of " << coverage.all.total
            << " variants compared with the reference (" << lightModeSummary(coverage) << ")\n";
        if (listUncovered) {
            for (const std::string& name : coverage.uncovered)
                out << "  not compared: " << name << "\n";
        }
    }
}

}  // namespace varc::cli
