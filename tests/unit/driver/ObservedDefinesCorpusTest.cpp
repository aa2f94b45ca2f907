// SPDX-License-Identifier: Apache-2.0
// Dropping the defines a text cannot observe must never change a program: on the real corpus
// (the seed fixtures and varc's shader library, built-in includes and all), builds with and
// without it give the same programs and variant tables, with fewer preprocessings.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

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

TEST(ObservedDefinesCorpus, SharingPreprocessingChangesNoProgram) {
    includes::DiskFileSystem fileSystem;
    includes::SourceMap sourceMap;
    includes::IncludeOptions includeOptions;
    includeOptions.builtinDir = std::string(VARC_SOURCE_DIR) + "/shaders/builtin";
    DiagnosticList diagnostics;
    std::vector<frontend::LoadedShader> shaders;
    for (const std::string& file : corpusFiles()) {
        auto shader =
            frontend::loadShader(file, fileSystem, sourceMap, includeOptions, diagnostics);
        ASSERT_TRUE(shader) << file;
        shaders.push_back(std::move(*shader));
    }
    ASSERT_GE(shaders.size(), 8u);
    BuildOptions shared, separate;
    separate.shareUnobservedDefines = false;
    auto withSharing = buildPrograms(shaders, sourceMap, shared, diagnostics);
    auto without = buildPrograms(shaders, sourceMap, separate, diagnostics);
    ASSERT_TRUE(withSharing && without);
    EXPECT_LT(withSharing->preprocessedPrograms, without->preprocessedPrograms);
    EXPECT_EQ(withSharing->compiledSources, without->compiledSources);
    ASSERT_EQ(withSharing->programs.size(), without->programs.size());
    for (size_t i = 0; i < without->programs.size(); ++i) {
        EXPECT_EQ(withSharing->programs[i].spirv, without->programs[i].spirv) << "program " << i;
    }
    ASSERT_EQ(withSharing->passes.size(), without->passes.size());
    for (size_t p = 0; p < without->passes.size(); ++p) {
        EXPECT_EQ(withSharing->passes[p].variants, without->passes[p].variants) << "pass " << p;
    }
}

}  // namespace
}  // namespace varc::driver
