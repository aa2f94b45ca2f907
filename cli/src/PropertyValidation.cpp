// SPDX-License-Identifier: Apache-2.0
// `varc validate --properties`: packs and device opened, every lit shader checked, the table.
#include "PropertyValidation.h"

#include <chrono>
#include <cstdio>
#include <ostream>
#include <utility>

#include "varc/properties/PropertyRunner.h"
#include "varc/reader/Pack.h"

namespace varc::cli {

namespace {

void printHeader(std::ostream& out) {
    char cell[64];
    std::snprintf(cell, sizeof cell, "%-36s", "shader");
    out << cell;
    for (const std::string& name : properties::relationNames()) {
        std::snprintf(cell, sizeof cell, " %s", name.c_str());
        out << cell;
    }
    out << "  model       renders  drawn   time  lights\n";
}

void printRow(const properties::ShaderReport& report, double seconds, std::ostream& out) {
    char cell[64];
    std::snprintf(cell, sizeof cell, "%-36s", report.shader.c_str());
    out << cell;
    for (const properties::RelationOutcome& outcome : report.relations) {
        std::snprintf(cell, sizeof cell, " %*s", static_cast<int>(outcome.relation.size()),
                      properties::verdictName(outcome.verdict));
        out << cell;
    }
    const std::string drawn =
        std::to_string(report.litVariantsDrawn()) + "/" + std::to_string(report.litVariants);
    std::snprintf(cell, sizeof cell, "  %-10s %8zu %6s %5.2fs  ",
                  properties::modelName(report.model), report.renders, drawn.c_str(), seconds);
    out << cell << report.lights << (report.error.empty() ? "" : "  ERROR") << "\n";
}

void printFailures(const properties::ShaderReport& report, std::ostream& err) {
    if (!report.error.empty())
        err << "varc: error: " << report.shader << ": " << report.error << "\n";
    if (report.model != properties::LightingModel::Lit)
        err << report.shader << ": " << report.modelReason << "\n";
    for (const properties::RelationOutcome& outcome : report.relations) {
        if (outcome.verdict != properties::Verdict::Fail) continue;
        err << report.shader << ": relation " << outcome.relation << " fails:\n" << outcome.detail;
    }
}

}  // namespace

int runValidateProperties(const std::vector<reader::Pack>& packs, vulkan::VulkanContext& context,
                          render::Renderer& renderer, const ValidateOptions& options,
                          std::ostream& out, std::ostream& err, const std::set<std::string>* only,
                          std::vector<properties::ShaderReport>* reports) {
    std::vector<const reader::Pack*> pointers;
    for (const reader::Pack& pack : packs) pointers.push_back(&pack);
    std::vector<reader::ShaderView> shaders;
    for (const reader::ShaderView& shader : properties::lightingShaders(pointers))
        if (!only || only->count(std::string(shader.name()))) shaders.push_back(shader);
    if (only && shaders.empty()) return kExitOk;
    properties::PropertyOptions propertyOptions;
    propertyOptions.outDir = options.outputDir;
    properties::PropertyRunner runner(renderer, propertyOptions);
    printHeader(out);
    size_t failed = 0;
    for (const reader::ShaderView& shader : shaders) {
        auto start = std::chrono::steady_clock::now();
        properties::ShaderReport report = runner.check(shader);
        double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        printRow(report, seconds, out);
        printFailures(report, err);
        if (!report.passed()) ++failed;
        if (reports) reports->push_back(std::move(report));
    }
    out << shaders.size() - failed << "/" << shaders.size()
        << " lit shaders hold every relation; images of failures in " << propertyOptions.outDir
        << "\n";
    if (context.validationMessageCount() > 0) {
        err << "varc: error: Vulkan validation reported " << context.validationMessageCount()
            << " messages:\n"
            << context.validationReport() << "\n";
        return kExitFailure;
    }
    if (shaders.empty()) {
        err << "varc: error: no shader with a ForwardBase pass in the packs\n";
        return kExitFailure;
    }
    return failed ? kExitFailure : kExitOk;
}

}  // namespace varc::cli
