// SPDX-License-Identifier: Apache-2.0
// Small, fully featured PackContents for the pack tests (already in the writer's normal form).
#include "PackTestData.h"

#include <algorithm>
#include <map>

namespace varc::packtest {

namespace {

using pack::PackProgram;
using varc::Stage;

// Adds programs in first-use order: the same (stage, name) returns the same index.
class ProgramMaker {
public:
    explicit ProgramMaker(pack::PackContents& contents) : mContents(contents) {}

    uint32_t get(Stage stage, const std::string& name) {
        auto [it, inserted] = mIndex.try_emplace({stage, name}, 0);
        if (!inserted) return it->second;
        PackProgram program;
        program.stage = stage;
        program.entryPoint = stage == Stage::Vertex ? "vert" : "frag";
        program.spirv = fakeSpirv(static_cast<uint32_t>(mContents.programs.size() * 7 + 3));
        program.reflection = reflectionFor(stage);
        program.source = {"Assets/Shaders/" + name + ".shader",
                          20 + static_cast<uint32_t>(mContents.programs.size()),
                          {"UnityCG.cginc", "Lighting.cginc"}};
        it->second = static_cast<uint32_t>(mContents.programs.size());
        mContents.programs.push_back(std::move(program));
        return it->second;
    }

private:
    static pack::ProgramReflection reflectionFor(Stage stage) {
        pack::ProgramReflection r;
        r.uniformBlocks.push_back({"UnityPerDraw",
                                   0,
                                   0,
                                   128,
                                   {{"unity_ObjectToWorld", 0, 64, "float4x4", 0, false},
                                    {"unity_WorldToObject", 64, 64, "float4x4", 0, true}}});
        r.resources.push_back({"_MainTex", pack::ResourceKind::CombinedImageSampler,
                               pack::ResourceDim::Dim2D, 1, 0, 1, false});
        r.resources.push_back({"_Lights", pack::ResourceKind::StorageBuffer,
                               pack::ResourceDim::None, 1, 1, 0, false});
        if (stage == Stage::Vertex) {
            r.vertexInputs.push_back({"v.vertex", "POSITION", 0, "float4"});
            r.vertexInputs.push_back({"v.uv", "TEXCOORD0", 1, "float2"});
            r.outputs.push_back({"o.uv", 0, "float2"});
        } else {
            r.inputs.push_back({"i.uv", 0, "float2"});
            r.outputs.push_back({"SV_Target", 0, "float4"});
        }
        r.pushConstants.push_back({"Push", 16, {{"_Tint", 0, 16, "float4", 0, false}}});
        return r;
    }

    pack::PackContents& mContents;
    std::map<std::pair<Stage, std::string>, uint32_t> mIndex;
};

pack::PackPass forwardBase(ProgramMaker& programs) {
    pack::PackPass pass;
    pass.index = 0;
    pass.name = "FORWARD";
    pass.lightMode = "ForwardBase";
    pass.tags = {{"LightMode", "ForwardBase"}, {"RenderType", "Opaque"}};
    pass.keywordTable = {"DIRECTIONAL", "FOG_EXP", "LIGHTPROBE_SH", "SHADOWS_SCREEN",
                         "VERTEXLIGHT_ON"};
    pass.sets = {{"multi_compile_fwdbase", {"DIRECTIONAL"}},
                 {"multi_compile_fwdbase", {"", "LIGHTPROBE_SH"}},
                 {"multi_compile_fwdbase", {"", "SHADOWS_SCREEN"}},
                 {"multi_compile_fwdbase", {"", "VERTEXLIGHT_ON"}},
                 {"multi_compile_fog", {"", "FOG_EXP"}}};
    // Enumeration order: the first set varies slowest.
    for (int bits = 0; bits < 16; ++bits) {
        bool probe = bits & 8, shadows = bits & 4, vlight = bits & 2, fog = bits & 1;
        std::vector<std::string> names = {"DIRECTIONAL"};
        if (probe) names.push_back("LIGHTPROBE_SH");
        if (shadows) names.push_back("SHADOWS_SCREEN");
        if (vlight) names.push_back("VERTEXLIGHT_ON");
        if (fog) names.push_back("FOG_EXP");
        pack::PackVariant variant;
        variant.key = keyOf(pass.keywordTable, names);
        variant.programs[0] = programs.get(
            Stage::Vertex, std::string("base_v") + (probe ? "P" : "") + (vlight ? "V" : ""));
        variant.programs[1] = programs.get(
            Stage::Fragment, std::string("base_f") + (shadows ? "S" : "") + (fog ? "F" : ""));
        pass.variants.push_back(variant);
    }
    return pass;
}

pack::PackPass forwardAdd(ProgramMaker& programs) {
    pack::PackPass pass;
    pass.index = 1;
    pass.name = "FORWARD_DELTA";
    pass.lightMode = "ForwardAdd";
    pass.tags = {{"LightMode", "ForwardAdd"}};
    pass.state.blendEnabled = true;
    pass.state.srcColor = {pack::BlendFactor::One, "_SrcBlend"};
    pass.state.dstColor = {pack::BlendFactor::One, ""};
    pass.state.srcAlpha = {pack::BlendFactor::One, "_SrcBlend"};
    pass.state.dstAlpha = {pack::BlendFactor::One, ""};
    pass.state.zWrite = {false, ""};
    pass.state.offsetFactor = {-1.5f, ""};
    pass.state.offsetUnits = {0.0f, "_OffsetUnits"};
    pass.state.stencilEnabled = true;
    pass.state.stencilRef = {7, ""};
    pass.state.front.comp = {pack::CompareFunction::Equal, ""};
    pass.state.back.pass = {pack::StencilOp::Replace, "_StencilOp"};
    std::vector<std::string> lights = {"POINT", "DIRECTIONAL", "SPOT", "POINT_COOKIE",
                                       "DIRECTIONAL_COOKIE"};
    pass.keywordTable = lights;
    std::sort(pass.keywordTable.begin(), pass.keywordTable.end());
    pass.sets = {{"multi_compile_fwdadd", lights}};
    for (const std::string& light : lights) {
        pack::PackVariant variant;
        variant.key = keyOf(pass.keywordTable, {light});
        variant.programs[0] = programs.get(Stage::Vertex, "add_v_" + light);
        variant.programs[1] = programs.get(Stage::Fragment, "add_f_" + light);
        pass.variants.push_back(variant);
    }
    return pass;
}

pack::PackPass shadowCaster(ProgramMaker& programs) {
    pack::PackPass pass;
    pass.index = 2;
    pass.name = "ShadowCaster";
    pass.lightMode = "ShadowCaster";
    pass.tags = {{"LightMode", "ShadowCaster"}};
    pass.state.cull = {pack::CullMode::Off, ""};
    pass.state.colorMask = {0, ""};
    pass.keywordTable = {"SHADOWS_CUBE", "SHADOWS_DEPTH"};
    pass.sets = {{"multi_compile_shadowcaster", {"SHADOWS_DEPTH", "SHADOWS_CUBE"}}};
    for (const char* name : {"SHADOWS_DEPTH", "SHADOWS_CUBE"}) {
        pack::PackVariant variant;
        variant.key = keyOf(pass.keywordTable, {name});
        variant.programs[0] = programs.get(Stage::Vertex, std::string("shadow_v_") + name);
        variant.programs[1] = programs.get(Stage::Fragment, "shadow_f");
        pass.variants.push_back(variant);
    }
    return pass;
}

}  // namespace

std::vector<uint32_t> fakeSpirv(uint32_t seed, size_t words) {
    std::vector<uint32_t> spirv = {0x07230203u, 0x00010000u, 0x00080001u, 64u + seed % 32, 0u};
    uint32_t state = seed * 2654435761u + 1;
    while (spirv.size() < words) {
        state = state * 1103515245u + 12345u;
        uint32_t opcode = 59 + (state >> 27);  // a small set of opcodes
        spirv.push_back((3u << 16) | opcode);
        spirv.push_back(10 + (state >> 20) % 40);
        spirv.push_back(seed % 3 == 0 ? 5u : (state >> 12) % 60);
    }
    spirv.resize(words);
    return spirv;
}

variants::VariantKey keyOf(const std::vector<std::string>& table,
                           const std::vector<std::string>& names) {
    variants::VariantKey key;
    for (const std::string& name : names) {
        auto it = std::lower_bound(table.begin(), table.end(), name);
        key.words()[(it - table.begin()) / 64] |= uint64_t{1} << ((it - table.begin()) % 64);
    }
    return key;
}

pack::PackContents makeSampleContents() {
    pack::PackContents contents;
    contents.toolchain = {{"varc", "0.1.0"}, {"glslang", "12.0.0"}, {"zstd", "1.5.4"}};
    contents.inputsHash = 0x0123456789abcdefull;
    ProgramMaker programs(contents);
    pack::PackShader lit{"Custom/Lit", {}, {}};
    lit.properties = {{"_Color", pack::PropertyKind::Color, {1.0f, 0.5f, 0.25f, 1.0f}, ""},
                      {"_Glossiness", pack::PropertyKind::Float, {0.5f, 0, 0, 0}, ""},
                      {"_MainTex", pack::PropertyKind::Texture, {}, "white"}};
    lit.passes.push_back(forwardBase(programs));
    lit.passes.push_back(forwardAdd(programs));
    lit.passes.push_back(shadowCaster(programs));
    pack::PackShader unlit{"Custom/Unlit", {}, {}};
    unlit.properties = {{"_BumpMap", pack::PropertyKind::Texture, {}, "bump"}};
    pack::PackPass only;
    only.variants.push_back({});
    only.variants[0].programs[0] = programs.get(Stage::Vertex, "base_v");  // shared with Lit
    only.variants[0].programs[1] = programs.get(Stage::Fragment, "unlit_f");
    unlit.passes.push_back(only);
    pack::PackShader empty{"Custom/Empty", {}, {}};
    empty.passes.emplace_back();
    empty.passes[0].keywordTable = {"UNUSED"};
    empty.passes[0].sets = {{"shader_feature", {"", "UNUSED"}}};
    contents.shaders = {std::move(lit), std::move(unlit), std::move(empty)};
    return contents;
}

}  // namespace varc::packtest
