// SPDX-License-Identifier: Apache-2.0
// The shader sets the build benchmarks compile, loaded the one way they all load them: the
// fixtures and the shader library, and the compatibility corpus (../shared/compat, read in
// place). Loading is never what a benchmark measures, so callers keep one BenchInputs for the run.
#pragma once

#include <cstdint>
#include <vector>

#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc::bench {

struct BenchInputs {
    includes::DiskFileSystem fileSystem;
    includes::SourceMap sourceMap;
    std::vector<frontend::LoadedShader> shaders;
    uint64_t variants = 0;  // of every shader loaded
    size_t corpusFiles = 0;  // corpus files among the shaders
    bool ok = true;          // false when a fixture or library shader failed to load
};

// Adds every .shader file of ../shared/fixtures and shaders/, sorted by path.
void addLibraryAndFixtures(BenchInputs& inputs);

// Adds the corpus shaders that `varc build` accepts with passes of at most |maxVariantsPerPass| variants
// (those varc refuses are listed in docs/COMPATIBILITY.md; the few larger passes would dominate
// any timing), each with its repository folder as include root, as the corpus test builds them.
// Finding out which build costs one cold build of each, on |jobs| threads.
void addBuildableCorpus(BenchInputs& inputs, uint64_t maxVariantsPerPass, unsigned jobs);

}  // namespace varc::bench
