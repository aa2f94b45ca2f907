// SPDX-License-Identifier: Apache-2.0
// Dropping the defines a text cannot observe must never change a program: on the real corpus
// (the seed fixtures and varc's shader library, built-in includes and all), builds with and
// without it give the same programs and variant tables, with fewer preprocessings; so do builds
// with and without the keyword projection.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string_view>
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

// |text| without its leading newlines: glslang writes one per preamble line before the text.
std::string_view withoutLeadingNewlines(std::string_view text) {
    return text.substr(std::min(text.find_first_not_of('\n'), text.size()));
}

// Per variant and stage, |a|'s and |b|'s pruned sources agree but for leading newlines.
void expectSameSources(const BuildOutput& a, const BuildOutput& b) {
    for (size_t p = 0; p < std::min(a.passes.size(), b.passes.size()); ++p) {
        const CompiledPass& x = a.passes[p];
        const CompiledPass& y = b.passes[p];
        ASSERT_EQ(x.variantSources.size(), y.variantSources.size());
        for (size_t v = 0; v < x.variantSources.size(); ++v) {
            for (size_t s = 0; s < kStageCount; ++s) {
                ASSERT_EQ(x.variantSources[v][s] == kNoProgram,
                          y.variantSources[v][s] == kNoProgram);
                if (x.variantSources[v][s] == kNoProgram) continue;
                EXPECT_EQ(withoutLeadingNewlines(a.prunedSources[x.variantSources[v][s]]),
                          withoutLeadingNewlines(b.prunedSources[y.variantSources[v][s]]))
                    << "pass " << p << " variant " << v << " stage " << s;
            }
        }
    }
}

// Builds the corpus with |a| and with |b|: the same programs and variant tables, and returns
// the two preprocessing counts. With |sameSourceCount| the distinct pruned sources agree too.
std::pair<size_t, size_t> compareBuilds(const BuildOptions& a, const BuildOptions& b,
                                        bool sameSourceCount = true) {
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
    if (sameSourceCount) {
        EXPECT_EQ(first->compiledSources, second->compiledSources);
    }
    if (a.keepPrunedSources && b.keepPrunedSources) expectSameSources(*first, *second);
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
    projected.projectReachableCode = false;
    // A shorter preamble means fewer leading newlines in glslang's output: sources that differed
    // only in those merge, so the source count may drop; the texts must agree otherwise.
    projected.keepPrunedSources = observed.keepPrunedSources = true;
    auto [withProjection, without] = compareBuilds(projected, observed, false);
    EXPECT_LT(withProjection, without);
    // Leaving out the lookups of unreachable code changes no program either, and preprocesses
    // no more often.
    BuildOptions reachable;
    reachable.keepPrunedSources = true;
    auto [withReachable, observedAgain] = compareBuilds(reachable, observed, false);
    EXPECT_LE(withReachable, withProjection);
}

}  // namespace
}  // namespace varc::driver
