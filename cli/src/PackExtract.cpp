// SPDX-License-Identifier: Apache-2.0
// `varc extract`: every program of a pack as a .spv file, plus a manifest tying them to
// shader / pass / variant / stage. Programs shared by many variants are written once.
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>

#include "OpenPack.h"
#include "varc/cli/PackCommands.h"
#include "varc/core/AtomicFile.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ProgramView.h"
#include "varc/reader/ShaderView.h"
#include "varc/reader/VariantView.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

// "program-0007-fragment.spv": sorted listings follow program order.
std::string programFileName(const reader::ProgramView& program) {
    char index[16];
    std::snprintf(index, sizeof index, "%04u", program.index());
    return std::string("program-") + index + "-" + stageName(program.stage()) + ".spv";
}

Json variantJson(const reader::VariantView& variant) {
    Json stages = Json::object();
    for (Stage stage : kStages) {
        if (auto program = variant.program(stage)) {
            stages[stageName(program->stage())] = programFileName(*program);
        }
    }
    return {{"keywords", variant.keywords()}, {"stages", stages}};
}

Json shadersJson(const reader::Pack& pack) {
    Json shaders = Json::array();
    for (size_t s = 0; s < pack.shaderCount(); ++s) {
        reader::ShaderView shader = pack.shader(s);
        Json passes = Json::array();
        for (size_t p = 0; p < shader.passCount(); ++p) {
            reader::PassView pass = *shader.pass(p);
            Json variants = Json::array();
            for (size_t v = 0; v < pass.variantCount(); ++v)
                variants.push_back(variantJson(pass.variant(v)));
            passes.push_back({{"index", pass.index()},
                              {"name", pass.name()},
                              {"lightmode", pass.lightMode()},
                              {"variants", variants}});
        }
        shaders.push_back({{"name", shader.name()}, {"passes", passes}});
    }
    return shaders;
}

// Writes one program's words; the error names the program and the reason.
Status writeProgram(const reader::ProgramView& program, const std::filesystem::path& dir) {
    Result<std::span<const uint32_t>> words = program.spirv();
    if (!words) return words.error();
    std::string_view bytes(reinterpret_cast<const char*>(words->data()), words->size_bytes());
    return writeFileAtomically((dir / programFileName(program)).string(), bytes);
}

}  // namespace

int runExtract(const ExtractOptions& options, std::ostream& out, std::ostream& err) {
    std::optional<reader::Pack> pack = openPackOrReport(options.packPath, err);
    if (!pack) return kExitUsage;
    std::filesystem::path dir = options.outputDir;
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) {
        err << "varc: error: cannot create directory '" << dir.string() << "': " << error.message()
            << "\n";
        return kExitFailure;
    }
    Json programs = Json::array();
    for (size_t i = 0; i < pack->programCount(); ++i) {
        reader::ProgramView program = pack->program(i);
        if (Status written = writeProgram(program, dir); !written) {
            err << "varc: error: " << program.describe() << ": " << written.error().detail << "\n";
            return kExitFailure;
        }
        programs.push_back({{"file", programFileName(program)},
                            {"stage", stageName(program.stage())},
                            {"entry_point", program.entryPoint()},
                            {"bytes", program.spirvByteSize()},
                            {"source", std::string(program.sourceFile()) + ":" +
                                           std::to_string(program.sourceLine())}});
    }
    Json manifest = {
        {"pack", options.packPath}, {"programs", programs}, {"shaders", shadersJson(*pack)}};
    if (Status written =
            writeFileAtomically((dir / "manifest.json").string(), manifest.dump(2) + "\n");
        !written) {
        err << "varc: error: " << written.error().detail << "\n";
        return kExitFailure;
    }
    out << "wrote " << pack->programCount() << " programs and manifest.json to " << dir.string()
        << "\n";
    return kExitOk;
}

}  // namespace varc::cli
