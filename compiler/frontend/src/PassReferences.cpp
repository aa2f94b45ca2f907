// SPDX-License-Identifier: Apache-2.0
// Passes a shader borrows from other shaders: UsePass entries and the Fallback shadow caster.
#include "varc/frontend/PassReferences.h"

#include <algorithm>
#include <optional>
#include <set>

#include "varc/core/AsciiCase.h"

namespace varc::frontend {

namespace {

constexpr int kMaxReferenceDepth = 16;

bool isShadowCaster(const shaderlab::Pass& pass) {
    return equalsIgnoreAsciiCase(pass.lightMode(), "ShadowCaster");
}

bool hasShadowCaster(const shaderlab::SubShader& subShader) {
    return std::any_of(subShader.passes.begin(), subShader.passes.end(), isShadowCaster);
}

std::string quoted(std::string_view text) { return "\"" + std::string(text) + "\""; }

// The pass |reference| (a UsePass entry) names, resolved itself, or nullopt after a warning.
std::optional<shaderlab::Pass> findUsedPass(const shaderlab::Pass& reference,
                                            ShaderCatalog& catalog, DiagnosticSink& sink,
                                            int depth);

// Replaces the UsePass entries of |subShader| by the passes they name (those not found stay).
void resolveUsePasses(shaderlab::SubShader& subShader, ShaderCatalog& catalog,
                      DiagnosticSink& sink, int depth) {
    for (shaderlab::Pass& pass : subShader.passes) {
        if (pass.usePass.empty()) continue;
        if (std::optional<shaderlab::Pass> used = findUsedPass(pass, catalog, sink, depth)) {
            pass = std::move(*used);
        }
    }
}

std::optional<shaderlab::Pass> findUsedPass(const shaderlab::Pass& reference,
                                            ShaderCatalog& catalog, DiagnosticSink& sink,
                                            int depth) {
    const std::string& path = reference.usePass;
    size_t slash = path.rfind('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 == path.size()) {
        sink.warning(reference.location, "UsePass " + quoted(path) +
                                             " names no pass (expected \"Shader/PASSNAME\"); it is skipped");
        return std::nullopt;
    }
    if (depth >= kMaxReferenceDepth) {
        sink.warning(reference.location, "UsePass " + quoted(path) + " is nested more than " +
                                             std::to_string(kMaxReferenceDepth) +
                                             " levels deep (a cycle?); it is skipped");
        return std::nullopt;
    }
    std::string_view shaderName = std::string_view(path).substr(0, slash);
    std::string_view passName = std::string_view(path).substr(slash + 1);
    const shaderlab::ShaderFile* target = catalog.find(shaderName);
    if (!target) {
        sink.warning(reference.location,
                     "UsePass " + quoted(path) + ": no shader named " + quoted(shaderName) +
                         " among the inputs or varc's built-in shaders; the pass is skipped");
        return std::nullopt;
    }
    for (const shaderlab::SubShader& subShader : target->subShaders) {
        for (const shaderlab::Pass& candidate : subShader.passes) {
            if (!equalsIgnoreAsciiCase(candidate.name, passName)) continue;
            shaderlab::SubShader single;
            single.passes.push_back(candidate);
            resolveUsePasses(single, catalog, sink, depth + 1);
            shaderlab::Pass used = std::move(single.passes.front());
            if (!used.usePass.empty()) return std::nullopt;  // warned about at the inner level
            if (used.origin.kind == shaderlab::PassOrigin::Kind::Own) used.origin.shader = target->name;
            used.origin.kind = shaderlab::PassOrigin::Kind::UsePass;
            used.origin.reference = reference.location;
            return used;
        }
    }
    sink.warning(reference.location, "UsePass " + quoted(path) + ": shader " +
                                         quoted(target->name) + " has no pass named " +
                                         quoted(passName) + "; the pass is skipped");
    return std::nullopt;
}

// The ShadowCaster passes of the first shader along |shader|'s Fallback chain that has any.
std::vector<shaderlab::Pass> fallbackCasters(const shaderlab::ShaderFile& shader,
                                             ShaderCatalog& catalog, DiagnosticSink& sink) {
    std::set<std::string> visited = {shader.name};
    const shaderlab::ShaderFile* current = &shader;
    while (current->fallback) {
        const std::string& name = *current->fallback;
        const shaderlab::ShaderFile* next = catalog.find(name);
        if (!next) {
            sink.warning(current->fallbackLocation,
                         "Fallback " + quoted(name) + " names no shader among the inputs or varc's "
                         "built-in shaders; shader " + quoted(shader.name) +
                             " has no ShadowCaster pass and casts no shadows");
            return {};
        }
        if (!visited.insert(next->name).second || visited.size() > kMaxReferenceDepth) {
            sink.warning(current->fallbackLocation,
                         "the Fallback chain of shader " + quoted(shader.name) +
                             " returns to shader " + quoted(next->name) + "; it is not followed further");
            return {};
        }
        if (!next->subShaders.empty()) {
            shaderlab::SubShader first = next->subShaders.front();
            resolveUsePasses(first, catalog, sink, 1);
            std::vector<shaderlab::Pass> casters;
            for (shaderlab::Pass& pass : first.passes) {
                if (!isShadowCaster(pass)) continue;
                if (pass.origin.kind == shaderlab::PassOrigin::Kind::Own) pass.origin.shader = next->name;
                pass.origin.kind = shaderlab::PassOrigin::Kind::Fallback;
                pass.origin.reference = shader.fallbackLocation;
                casters.push_back(std::move(pass));
            }
            if (!casters.empty()) return casters;
        }
        current = next;
    }
    return {};
}

}  // namespace

void resolvePassReferences(shaderlab::ShaderFile& shader, ShaderCatalog& catalog,
                           DiagnosticSink& sink) {
    for (shaderlab::SubShader& subShader : shader.subShaders) {
        resolveUsePasses(subShader, catalog, sink, 0);
    }
    if (std::any_of(shader.subShaders.begin(), shader.subShaders.end(), hasShadowCaster)) return;
    std::vector<shaderlab::Pass> casters = fallbackCasters(shader, catalog, sink);
    if (casters.empty()) return;
    if (shader.subShaders.empty()) shader.subShaders.emplace_back();
    for (shaderlab::Pass& caster : casters) {
        shader.subShaders.back().passes.push_back(std::move(caster));
    }
}

}  // namespace varc::frontend
