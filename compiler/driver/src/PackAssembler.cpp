// SPDX-License-Identifier: Apache-2.0
// Turns loaded shaders plus compiled programs into the pack model.
#include "varc/driver/PackAssembler.h"

#include <xxhash.h>

#include <set>

#include "varc/driver/GlslangFrontend.h"
#include "varc/driver/PropertyDefaults.h"
#include "varc/driver/SpirvOptimizer.h"
#include "varc/driver/StageInterfaces.h"
#include "varc/driver/RenderStateConversion.h"
#include "varc/variants/KeywordList.h"

namespace varc::driver {

namespace {

std::vector<pack::DeclaredSet> declaredSets(const variants::PassKeywords& keywords) {
    std::vector<pack::DeclaredSet> sets;
    for (const variants::KeywordSetDecl& set : keywords.sets)
        sets.push_back({set.directive, set.keywords});
    // The runtime learns the pass's dynamic_branch keywords (uniforms it sets per draw) here.
    for (const variants::KeywordSetDecl& set : keywords.dynamicBranches)
        sets.push_back({set.directive, set.keywords});
    return sets;
}

std::optional<pack::PackPass> assemblePass(const frontend::LoadedShader& shader,
                                           const CompiledPass& compiled, DiagnosticSink& sink) {
    const frontend::LoadedPass& loaded = shader.passes[compiled.passIndex];
    driver::ConvertedRenderState state = driver::fromShaderLab(loaded.pass->state);
    for (const std::string& error : state.errors) {
        sink.error(loaded.pass->location,
                   error + " in " + frontend::describePass(shader.ast, *loaded.pass, loaded.index));
    }
    if (!state.ok()) return std::nullopt;
    pack::PackPass pass;
    pass.index = static_cast<uint32_t>(loaded.index);
    pass.name = loaded.pass->name;
    pass.lightMode = loaded.pass->lightMode();
    pass.tags = loaded.pass->tags;
    pass.state = state.state;
    pass.keywordTable = loaded.space->table().names();
    pass.sets = declaredSets(loaded.keywords);
    pass.variants = compiled.variants;
    return pass;
}

// Hash of everything that decides the pack's bytes: every file read, options and versions.
uint64_t inputsHash(const includes::SourceMap& sourceMap, const includes::SourcePathMap& paths,
                    const std::string& fingerprint) {
    XXH64_state_t* state = XXH64_createState();
    XXH64_reset(state, 0);
    for (FileId id = 0; id < sourceMap.size(); ++id) {
        const std::string path = paths.map(sourceMap.path(id));
        const std::string& contents = sourceMap.contents(id);
        XXH64_update(state, path.data(), path.size() + 1);
        XXH64_update(state, contents.data(), contents.size());
    }
    XXH64_update(state, fingerprint.data(), fingerprint.size());
    uint64_t hash = XXH64_digest(state);
    XXH64_freeState(state);
    return hash;
}

// The shader's Properties defaults; one that cannot be read is left out with a warning (the
// runtime then has no default for it, as before packs stored them).
std::vector<pack::ShaderProperty> propertiesOf(const frontend::LoadedShader& shader,
                                               DiagnosticSink& sink) {
    std::vector<pack::ShaderProperty> properties;
    for (const shaderlab::Property& property : shader.ast.properties) {
        Result<pack::ShaderProperty> converted = toPackProperty(property);
        if (converted) {
            properties.push_back(std::move(*converted));
        } else {
            sink.warning(property.location, converted.error().detail);
        }
    }
    return properties;
}

}  // namespace

std::vector<pack::ToolVersion> toolchainVersions() {
    return {{"varc", VARC_VERSION},
            {"glslang", glslangVersionString()},
            {"SPIRV-Tools", spirvToolsVersionString()}};
}

std::optional<pack::PackContents> assemblePack(const std::vector<frontend::LoadedShader>& shaders,
                                               const BuildOutput& build,
                                               const includes::SourceMap& sourceMap,
                                               const includes::SourcePathMap& paths,
                                               const std::string& optionsFingerprint,
                                               DiagnosticSink& sink) {
    pack::PackContents contents;
    contents.toolchain = toolchainVersions();
    std::string fingerprint = optionsFingerprint;
    for (const pack::ToolVersion& tool : contents.toolchain)
        fingerprint += "|" + tool.name + " " + tool.version;
    contents.inputsHash = inputsHash(sourceMap, paths, fingerprint);
    bool ok = true;
    std::vector<size_t> shaderSlot(shaders.size(), SIZE_MAX);
    for (const CompiledPass& compiled : build.passes) {
        const frontend::LoadedShader& shader = shaders[compiled.shaderIndex];
        if (shaderSlot[compiled.shaderIndex] == SIZE_MAX) {
            shaderSlot[compiled.shaderIndex] = contents.shaders.size();
            contents.shaders.push_back({shader.ast.name, {}, propertiesOf(shader, sink)});
        }
        auto pass = assemblePass(shader, compiled, sink);
        if (!pass) {
            ok = false;
            continue;
        }
        contents.shaders[shaderSlot[compiled.shaderIndex]].passes.push_back(std::move(*pass));
    }
    contents.programs = build.programs;
    if (!ok) return std::nullopt;
    return contents;
}

bool checkStageInterfaces(const std::vector<frontend::LoadedShader>& shaders,
                          const BuildOutput& build, DiagnosticSink& sink) {
    bool ok = true;
    std::set<std::pair<uint32_t, uint32_t>> checked;
    for (const CompiledPass& pass : build.passes) {
        const frontend::LoadedShader& shader = shaders[pass.shaderIndex];
        const frontend::LoadedPass& loaded = shader.passes[pass.passIndex];
        auto report = [&](const pack::PackVariant& variant, Stage producer,
                          const pack::StageVariable& input) {
            sink.error(loaded.pass->program->origin,
                       "fragment input '" + input.name + "' (location " +
                           std::to_string(input.location) + ", " + input.type +
                           ") is not written by the " + stageName(producer) + " program in " +
                           frontend::describePass(shader.ast, *loaded.pass, loaded.index) +
                           ", keywords: " +
                           variants::joinKeywords(loaded.space->table().namesOf(variant.key)));
        };
        ok = checkVariantInterfaces(pass.variants, build.programs, checked, report) && ok;
    }
    return ok;
}

}  // namespace varc::driver
