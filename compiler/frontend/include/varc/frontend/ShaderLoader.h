// SPDX-License-Identifier: Apache-2.0
// Loads a .shader file: ShaderLab parse, include expansion and keyword model for every pass.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/IncludeResolver.h"
#include "varc/includes/SourceMap.h"
#include "varc/frontend/ShaderCatalog.h"
#include "varc/frontend/VariantPlan.h"
#include "varc/shaderlab/ShaderAst.h"
#include "varc/variants/PassKeywords.h"
#include "varc/variants/VariantSpace.h"

namespace varc::frontend {

// One pass that has a program block, ready for variant expansion and compilation.
struct LoadedPass {
    size_t index = 0;                     // position among all passes of the shader, file order
    const shaderlab::Pass* pass = nullptr;  // points into LoadedShader::ast
    includes::ExpandedSource source;      // *INCLUDE blocks + program, includes spliced
    variants::PassKeywords keywords;
    std::optional<variants::VariantSpace> space;  // always set after a successful load
    // Set when a Unity project chose the variants (planPass); otherwise every variant of
    // |space| ships.
    std::optional<VariantPlan> plan;

    // The variants that ship: the plan's last stage, else every variant of |space|.
    uint64_t variantCount() const;
    // Visits them in enumeration order; stop early by returning false. With a plan that was not
    // enumerated (over the limit) it visits nothing.
    void forEachVariant(const std::function<bool(const variants::VariantKey&)>& visit) const;
};

// Move-only: LoadedPass::pass points into |ast| (a vector move keeps element addresses).
struct LoadedShader {
    LoadedShader() = default;
    LoadedShader(LoadedShader&&) = default;
    LoadedShader& operator=(LoadedShader&&) = default;
    LoadedShader(const LoadedShader&) = delete;
    LoadedShader& operator=(const LoadedShader&) = delete;

    std::string path;                     // as given by the caller
    FileId file = kNoFile;
    shaderlab::ShaderFile ast;
    std::vector<LoadedPass> passes;       // passes without a program (UsePass, GrabPass,
                                          // fixed function) are not listed; indices keep gaps

    uint64_t variantCount() const;        // sum over passes, saturating
};

// Reads |path| through |fileSystem|, registers it in |sourceMap| and loads every pass.
// With a |catalog|, UsePass entries and the Fallback shadow caster are resolved first
// (resolvePassReferences); without one, UsePass entries compile nothing.
// Pass-level errors get a note naming the shader and pass. Returns nullopt after reporting at
// least one error; a shader with no program passes is valid (zero variants).
std::optional<LoadedShader> loadShader(const std::string& path,
                                       const includes::FileSystem& fileSystem,
                                       includes::SourceMap& sourceMap,
                                       const includes::IncludeOptions& includeOptions,
                                       DiagnosticSink& sink, ShaderCatalog* catalog = nullptr);

// "from Fallback \"Legacy Shaders/VertexLit\"", "from UsePass of \"...\"", or "" for own passes.
std::string describePassOrigin(const shaderlab::PassOrigin& origin);

// A human-readable description of pass |index| for diagnostics:
// `pass 1 "FORWARD" (LightMode ForwardAdd) of shader "Custom/X"`, and for a borrowed pass
// `pass 2 "SHADOWCASTER" (LightMode ShadowCaster, from Fallback "Legacy Shaders/VertexLit") ...`.
std::string describePass(const shaderlab::ShaderFile& shader, const shaderlab::Pass& pass,
                         size_t index);

}  // namespace varc::frontend
