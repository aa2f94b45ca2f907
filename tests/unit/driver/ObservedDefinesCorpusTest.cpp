// SPDX-License-Identifier: Apache-2.0
// Dropping the defines a text cannot observe must never change a program: on the real corpus
// (the seed fixtures and varc's shader library, built-in includes and all), builds with and
// without it give the same programs and variant tables, with fewer preprocessings; so do builds
// with and without the keyword projection.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <utility>

#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc::driver {
namespace {

std::vector<std::string> corpusFiles() {
    std::vector<std::string> files;
    for (const std::string& root :
         {std::string(VARC_SHARED_DIR) + "/fixtures", std::string(VARC_SOURCE_DIR) + "/shaders"}) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
            if (entry.path().extension() == ".shader") files.push_back(entry.path().string());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

// Builds the corpus with |a| and with |b|: the same programs and variant tables, and returns
// the two preprocessing counts.
std::pair<size_t, size_t> compareBuilds(const BuildOptions& a, const BuildOptions& b) {
    includes::DiskFileSystem fileSystem;
    includes::SourceMap sourceMap;
    includes::IncludeOptions includeOptions;
    includeOptions.builtinDir = std::string(VARC_SOURCE_DIR) + "/shaders/builtin";
    DiagnosticList diagnostics;
    std::vector<frontend::LoadedShader> shaders;
    for (const std::string& file : corpusFiles()) {
        auto shader =
            frontend::loadShader(file, fileSystem, sourceMap, includeOptions, diagnostics);
        EXPECT_TRUE(shader) << file;
        if (shader) shaders.push_back(std::move(*shader));
    }
    EXPECT_GE(shaders.size(), 8u);
    auto first = buildPrograms(shaders, sourceMap, a, diagnostics);
    auto second = buildPrograms(shaders, sourceMap, b, diagnostics);
    EXPECT_TRUE(first && second);
    if (!first || !second) return {0, 0};
    EXPECT_EQ(first->compiledSources, second->compiledSources);
    EXPECT_EQ(first->programs.size(), second->programs.size());
    for (size_t i = 0; i < std::min(first->programs.size(), second->programs.size()); ++i) {
        EXPECT_EQ(first->programs[i].spirv, second->programs[i].spirv) << "program " << i;
    }
    EXPECT_EQ(first->passes.size(), second->passes.size());
    for (size_t p = 0; p < std::min(first->passes.size(), second->passes.size()); ++p) {
        EXPECT_EQ(first->passes[p].variants, second->passes[p].variants) << "pass " << p;
    }
    return {first->preprocessedPrograms, second->preprocessedPrograms};
}

TEST(ObservedDefinesCorpus, SharingPreprocessingChangesNoProgram) {
    BuildOptions shared, separate;
    shared.projectKeywords = separate.projectKeywords = false;
    separate.shareUnobservedDefines = false;
    auto [withSharing, without] = compareBuilds(shared, separate);
    EXPECT_LT(withSharing, without);
}

// The keyword projection (KeywordProjection.h) on top of the sharing above.
TEST(ObservedDefinesCorpus, KeywordProjectionChangesNoProgram) {
    BuildOptions projected, observed;
    observed.projectKeywords = false;
    auto [withProjection, without] = compareBuilds(projected, observed);
    EXPECT_LT(withProjection, without);
}

}  // namespace
}  // namespace varc::driver
