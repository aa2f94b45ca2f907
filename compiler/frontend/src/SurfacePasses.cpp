// SPDX-License-Identifier: Apache-2.0
// Turns the surface programs of a parsed shader into the passes Unity's code generator makes.
#include "varc/frontend/SurfacePasses.h"

#include <utility>
#include <vector>

#include "varc/frontend/SurfaceCodeGenerator.h"

namespace varc::frontend {

namespace {

using Alpha = shaderlab::SurfaceOptions::Alpha;
using Decal = shaderlab::SurfaceOptions::Decal;

shaderlab::StateValue literal(std::string text) { return {std::move(text), ""}; }

shaderlab::BlendState blend(std::string src, std::string dst) {
    shaderlab::BlendState state;
    state.src = literal(std::move(src));
    state.dst = literal(std::move(dst));
    return state;
}

// The blending of the base pass for the program's alpha and decal options, if any.
std::optional<shaderlab::BlendState> baseBlend(const shaderlab::SurfaceProgram& program) {
    if (program.options.decal == Decal::Add) return blend("One", "One");
    if (program.options.decal == Decal::Blend) return blend("SrcAlpha", "OneMinusSrcAlpha");
    switch (effectiveAlpha(program)) {
    case Alpha::Off: return std::nullopt;
    case Alpha::Premultiply: return blend("One", "OneMinusSrcAlpha");
    case Alpha::Blend:
    case Alpha::Fade: return blend("SrcAlpha", "OneMinusSrcAlpha");
    }
    return std::nullopt;
}

bool transparent(const shaderlab::SurfaceProgram& program) {
    return program.options.alpha != Alpha::Off || program.options.decal != Decal::None;
}

shaderlab::Pass makePass(const shaderlab::Pass& placeholder, const SurfaceFacts& facts,
                         SurfacePassKind kind) {
    const shaderlab::SurfaceProgram& program = *placeholder.surface;
    shaderlab::Pass pass;
    pass.name = kind == SurfacePassKind::ShadowCaster ? "ShadowCaster" : "FORWARD";
    pass.tags = {{"LightMode", surfacePassLightMode(kind)}};
    pass.state = placeholder.state;
    pass.program = program.block;
    pass.includeBlocks = placeholder.includeBlocks;
    pass.location = program.pragma;
    pass.generated = generateSurfaceCode(program, facts, kind);
    if (kind == SurfacePassKind::ForwardBase) {
        if (!pass.state.blend) pass.state.blend = baseBlend(program);
        if (transparent(program) && !pass.state.zWrite.isSet()) pass.state.zWrite = literal("Off");
    } else if (kind == SurfacePassKind::ForwardAdd) {
        bool premultiplied = effectiveAlpha(program) == Alpha::Premultiply;
        bool alpha = program.options.alpha != Alpha::Off && !premultiplied;
        pass.state.blend = blend(alpha ? "SrcAlpha" : "One", "One");
        pass.state.zWrite = literal("Off");
    } else {
        pass.state.blend.reset();
        pass.state.zWrite = literal("On");
        pass.state.zTest = literal("LEqual");
    }
    return pass;
}

std::vector<shaderlab::Pass> passesOf(const shaderlab::Pass& placeholder,
                                      const SurfaceFacts& facts) {
    const shaderlab::SurfaceOptions& options = placeholder.surface->options;
    std::vector<shaderlab::Pass> passes;
    if (!options.excludeForward) {
        passes.push_back(makePass(placeholder, facts, SurfacePassKind::ForwardBase));
        if (!options.noForwardAdd) {
            passes.push_back(makePass(placeholder, facts, SurfacePassKind::ForwardAdd));
        }
    }
    if (options.addShadow) {
        passes.push_back(makePass(placeholder, facts, SurfacePassKind::ShadowCaster));
    }
    return passes;
}

}  // namespace

bool generateSurfacePasses(shaderlab::ShaderFile& shader, const SurfaceTextProvider& textOf,
                           DiagnosticSink& sink) {
    bool ok = true;
    for (shaderlab::SubShader& subShader : shader.subShaders) {
        std::vector<shaderlab::Pass> passes;
        for (shaderlab::Pass& pass : subShader.passes) {
            if (!pass.surface) {
                passes.push_back(std::move(pass));
                continue;
            }
            std::optional<std::string> text = textOf(pass);
            std::optional<SurfaceFacts> facts;
            if (text) facts = analyzeSurface(*pass.surface, *text, sink);
            if (!facts) {
                ok = false;
                continue;
            }
            for (shaderlab::Pass& generated : passesOf(pass, *facts)) {
                passes.push_back(std::move(generated));
            }
        }
        subShader.passes = std::move(passes);
    }
    return ok;
}

}  // namespace varc::frontend
