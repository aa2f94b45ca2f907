// SPDX-License-Identifier: Apache-2.0
// Turns loaded shaders plus compiled programs into the pack model, then writes the pack.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/SourceMap.h"
#include "varc/includes/SourcePathMap.h"
#include "varc/pack/PackModel.h"

namespace varc::driver {

// The versions a pack records and `varc --version` prints, in this order: varc (the project
// version), glslang (major.minor.patch) and SPIRV-Tools (its software version string).
std::vector<pack::ToolVersion> toolchainVersions();

// Fills shaders -> passes (render state, tags, keyword table, declared sets, variants in
// enumeration order) and programs (SPIR-V, reflection, source info), the toolchain versions and
// a hash of every input (file contents and their paths as |paths| records them,
// |optionsFingerprint|, versions). Render-state values
// that are not valid ShaderLab are reported at the pass; returns nullopt then.
std::optional<pack::PackContents> assemblePack(const std::vector<frontend::LoadedShader>& shaders,
                                               const BuildOutput& build,
                                               const includes::SourceMap& sourceMap,
                                               const includes::SourcePathMap& paths,
                                               const std::string& optionsFingerprint,
                                               DiagnosticSink& sink);

// Every vertex output a fragment program reads must exist, at the same location, with the same
// type, in each variant. Reports a mismatch once per (vertex, fragment) program pair.
bool checkStageInterfaces(const std::vector<frontend::LoadedShader>& shaders,
                          const BuildOutput& build, DiagnosticSink& sink);

}  // namespace varc::driver
