// SPDX-License-Identifier: Apache-2.0
// `varc build --skip-failing-shaders`: the pack without the shaders that fail, as a Unity player
// build leaves out a shader with errors instead of failing.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/pack/PackModel.h"

namespace varc::cli {

// A build that went as far as the pack model.
struct BuiltPack {
    driver::BuildOutput build;
    pack::PackContents contents;
};

// Builds |shaders| (compile, stage interfaces, assembly) reporting to |sink|; nullopt after an
// error. Must depend on nothing but its arguments, so a shader that fails alone fails in any set.
using PackBuildStep = std::function<std::optional<BuiltPack>(
    const std::vector<frontend::LoadedShader>& shaders, DiagnosticSink& sink)>;

// After a build of |shaders| failed (its diagnostics in |reported|): removes every shader that
// |buildPack| fails on alone, appending its file to |leftOut| and reporting the problems its own
// build found that |reported| lacks, then builds the others. Only the shaders' own builds
// decide, so the pack equals a build of the remaining shaders; that build's diagnostics repeat
// earlier ones and are dropped, unless it fails anyway (then they are reported). nullopt when no
// shader is left or that build fails.
std::optional<BuiltPack> buildWithoutFailingShaders(std::vector<frontend::LoadedShader>& shaders,
                                                    const PackBuildStep& buildPack,
                                                    std::vector<std::string>& leftOut,
                                                    DiagnosticList& reported);

// The program cache the rebuilds share when the build has none: a private folder under the
// system's temporary folder, removed (with what varc wrote in it) when this object goes.
class ScratchProgramCache {
public:
    ScratchProgramCache() = default;
    ~ScratchProgramCache();
    ScratchProgramCache(const ScratchProgramCache&) = delete;
    ScratchProgramCache& operator=(const ScratchProgramCache&) = delete;

    // |options|' cache, or a scratch one (nullptr when no scratch folder can be made: the
    // rebuilds then compile again).
    std::shared_ptr<cache::CacheChain> levelsFor(const driver::BuildOptions& options);

private:
    std::string mDirectory;  // "" until made
};

}  // namespace varc::cli
