// SPDX-License-Identifier: Apache-2.0
#include "BenchInputs.h"

#include <algorithm>
#include <filesystem>
#include <string>

#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/PackAssembler.h"

namespace varc::bench {

namespace {

namespace fs = std::filesystem;

constexpr const char* kCorpus = VARC_SOURCE_DIR "/../shared/compat";

// The .shader files under |root|, sorted, leaving out |skip| folders.
std::vector<std::string> shaderFilesUnder(const std::string& root, const std::string& skip = "") {
    std::vector<std::string> files;
    if (!fs::is_directory(root)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".shader") continue;
        if (!skip.empty() && path.find(skip) != std::string::npos) continue;
        files.push_back(path);
    }
    std::sort(files.begin(), files.end());
    return files;
}

// The repository folder of a corpus file: the include root the corpus test uses.
std::string repositoryOf(const std::string& file) {
    std::string rest = file.substr(std::string(kCorpus).size() + 1);
    return std::string(kCorpus) + "/" + rest.substr(0, rest.find('/'));
}

}  // namespace

void addLibraryAndFixtures(BenchInputs& inputs) {
    includes::IncludeOptions options;
    options.builtinDir = VARC_SOURCE_DIR "/shaders/builtin";
    DiagnosticList diagnostics;
    for (const char* root : {VARC_SOURCE_DIR "/../shared/fixtures", VARC_SOURCE_DIR "/shaders"}) {
        for (const std::string& file : shaderFilesUnder(root)) {
            auto shader = frontend::loadShader(file, inputs.fileSystem, inputs.sourceMap, options,
                                               diagnostics);
            if (!shader) continue;
            inputs.variants += shader->variantCount();
            inputs.shaders.push_back(std::move(*shader));
        }
    }
    if (diagnostics.hasErrors() || inputs.shaders.empty()) inputs.ok = false;
}

void addBuildableCorpus(BenchInputs& inputs, uint64_t maxVariantsPerPass, unsigned jobs) {
    // The surface-shader folder holds shaders varc does not build (surface shaders).
    for (const std::string& file : shaderFilesUnder(kCorpus, "/compat/surface/")) {
        includes::IncludeOptions options;
        options.builtinDir = VARC_SOURCE_DIR "/shaders/builtin";
        options.includeDirs = {repositoryOf(file)};
        DiagnosticList diagnostics;
        auto shader =
            frontend::loadShader(file, inputs.fileSystem, inputs.sourceMap, options, diagnostics);
        if (!shader) continue;
        std::vector<frontend::LoadedShader> one;
        one.push_back(std::move(*shader));
        driver::BuildOptions build;
        build.jobs = jobs;
        build.maxVariantsPerPass = maxVariantsPerPass;
        // As `varc build` accepts a shader: it compiles and its stages fit together.
        std::optional<driver::BuildOutput> output =
            driver::buildPrograms(one, inputs.sourceMap, build, diagnostics);
        if (!output || !driver::checkStageInterfaces(one, *output, diagnostics)) continue;
        inputs.variants += one.front().variantCount();
        inputs.shaders.push_back(std::move(one.front()));
        ++inputs.corpusFiles;
    }
}

}  // namespace varc::bench
