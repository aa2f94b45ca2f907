// SPDX-License-Identifier: Apache-2.0
// Writes the vertex and fragment programs of the passes a surface program becomes.
// Written for varc from Unity's documentation of surface shaders (the Input members by name, the
// options, the lighting function shapes); docs/SURFACE_SHADERS.md states what is generated.
#include "varc/frontend/SurfaceCodeGenerator.h"

#include <algorithm>
#include <array>

#include "surface/CodeWriter.h"
#include "surface/PassPlan.h"
#include "surface/SurfaceFragmentWriter.h"

namespace varc::frontend {

namespace surface {

// 0 for `uv_NAME`, 1 for `uv2_NAME`, ... 3 for `uv4_NAME`; -1 for other members. |texture|
// receives the texture's name: `uv_MainTex` reads texture `_MainTex` (Unity's convention).
int uvSet(std::string_view member, std::string& texture) {
    static constexpr std::array<std::string_view, 4> kPrefixes = {"uv", "uv2", "uv3", "uv4"};
    for (size_t i = kPrefixes.size(); i-- > 0;) {
        std::string_view rest = member.substr(std::min(member.size(), kPrefixes[i].size()));
        if (member.starts_with(kPrefixes[i]) && rest.size() > 1 && rest[0] == '_') {
            texture = std::string(rest);
            return static_cast<int>(i);
        }
    }
    return -1;
}

bool hasMember(const std::vector<std::string>& members, std::string_view name) {
    return std::find(members.begin(), members.end(), name) != members.end();
}

}  // namespace surface

namespace {

using namespace surface;

PassPlan makePlan(const shaderlab::SurfaceProgram& program, const SurfaceFacts& facts,
                  SurfacePassKind kind) {
    PassPlan plan{program, facts, kind, facts.writesNormal, {}, false, false, false, true};
    if (kind == SurfacePassKind::ShadowCaster) {
        plan.surfaceCall = !program.options.alphaTestProperty.empty() || facts.surfaceDiscards;
        if (!plan.surfaceCall) {
            plan.tangentSpace = false;
            return plan;  // nothing interpolated but the position
        }
    }
    for (const std::string& member : facts.inputMembers) {
        std::string texture;
        int set = uvSet(member, texture);
        if (set >= 0) plan.texcoords[static_cast<size_t>(set)] = true;
    }
    plan.color = facts.hasInputMember("color");
    plan.screenPos = facts.hasInputMember("screenPos");
    plan.customInput = facts.vertexWritesInput;
    return plan;
}

// `v.FIELD` when the vertex input has FIELD, else |fallback|.
std::string vertexField(const PassPlan& plan, std::string_view field, std::string_view fallback) {
    if (hasMember(plan.facts.vertexInputMembers, field)) return "v." + std::string(field);
    return std::string(fallback);
}

std::string passDefine(SurfacePassKind kind) {
    switch (kind) {
        case SurfacePassKind::ForwardBase:
            return "UNITY_PASS_FORWARDBASE";
        case SurfacePassKind::ForwardAdd:
            return "UNITY_PASS_FORWARDADD";
        case SurfacePassKind::ShadowCaster:
            return "UNITY_PASS_SHADOWCASTER";
    }
    return "";
}

void writeKeywordPragmas(const PassPlan& plan, CodeWriter& out) {
    const shaderlab::SurfaceOptions& options = plan.program.options;
    if (plan.base()) {
        std::string line = "#pragma multi_compile_fwdbase";
        for (const std::string& option : options.shortcutOptions) line += " " + option;
        out.line(line);
    }
    if (plan.add()) {
        out.line(std::string(options.fullForwardShadows ? "#pragma multi_compile_fwdadd_fullshadows"
                                                        : "#pragma multi_compile_fwdadd") +
                 (options.noShadow && options.fullForwardShadows ? " noshadow" : ""));
    }
    if (plan.caster()) out.line("#pragma multi_compile_shadowcaster");
    if (plan.fog()) out.line("#pragma multi_compile_fog");
    // As Unity: every generated pass of a `dithercrossfade` program fades between LOD levels.
    if (options.ditherCrossFade) out.line("#pragma multi_compile _ LOD_FADE_CROSSFADE");
}

void writeNormalMacros(const PassPlan& plan, CodeWriter& out) {
    if (plan.tangentSpace) {
        out.line(
            "#define INTERNAL_DATA float3 internalSurfaceTtoW0; float3 internalSurfaceTtoW1; "
            "float3 internalSurfaceTtoW2;");
        out.line(
            "#define WorldNormalVector(data, normal) float3(dot((data).internalSurfaceTtoW0, "
            "normal), dot((data).internalSurfaceTtoW1, normal), "
            "dot((data).internalSurfaceTtoW2, normal))");
        out.line(
            "#define WorldReflectionVector(data, normal) reflect((data).worldRefl, "
            "WorldNormalVector(data, normal))");
    } else {
        out.line("#define INTERNAL_DATA");
        out.line("#define WorldNormalVector(data, normal) (normal)");
        out.line("#define WorldReflectionVector(data, normal) (data).worldRefl");
    }
}

std::string writeBefore(const PassPlan& plan) {
    CodeWriter out;
    out.line("#define " + passDefine(plan.kind));
    if (effectiveAlpha(plan.program) == Alpha::Premultiply) {
        out.line("#define _ALPHAPREMULTIPLY_ON 1");
    }
    for (const char* file : {"HLSLSupport.cginc", "UnityShaderVariables.cginc", "UnityCG.cginc",
                             "Lighting.cginc", "UnityPBSLighting.cginc", "AutoLight.cginc"}) {
        out.line(std::string("#include \"") + file + "\"");
    }
    writeNormalMacros(plan, out);
    // glslang drops a struct member with a system-value semantic from the struct, so Input's
    // face member gets a user semantic while the program's text is read; the fragment program
    // fills it from its own SV_IsFrontFace parameter (after the #undef in the code after).
    if (!plan.facts.faceMember.empty())
        out.line("#define " + plan.facts.faceSemantic + " varc_input_face");
    out.line("#pragma vertex varc_surf_vert");
    out.line("#pragma fragment varc_surf_frag");
    writeKeywordPragmas(plan, out);
    return out.take();
}

// `float4 NAME_ST;` for every uvN_NAME member whose NAME_ST the program does not mention.
void writeTextureScales(const PassPlan& plan, CodeWriter& out) {
    std::vector<std::string> declared;
    for (const std::string& member : plan.facts.inputMembers) {
        std::string texture;
        if (uvSet(member, texture) < 0) continue;
        std::string scale = texture + "_ST";
        if (plan.facts.mentions(scale) ||
            std::find(declared.begin(), declared.end(), scale) != declared.end()) {
            continue;
        }
        out.line("float4 " + scale + ";");
        declared.push_back(scale);
    }
}

// `fixed PROP;` for `alphatest:PROP` when the program does not name PROP (Unity declares it).
void writeAlphaTestProperty(const PassPlan& plan, CodeWriter& out) {
    const std::string& property = plan.program.options.alphaTestProperty;
    if (!property.empty() && !plan.facts.mentions(property)) out.line("fixed " + property + ";");
}

// The base pass's optional interpolators, on when the fragment program reads them (an
// interpolator written and never read is a Vulkan interface warning): VARC_SURF_AMBIENT (the
// vertex lights: the (s, gi) models read them with light-probe SH only, as UnityGI_Base does;
// the legacy shapes always) and VARC_SURF_LIGHTMAP_UV (the (s, gi) models under a lightmap).
void writeBaseSwitches(const PassPlan& plan, CodeWriter& out) {
    if (!plan.base()) return;
    bool gi =
        plan.facts.lighting == LightingShape::Gi || plan.facts.lighting == LightingShape::GiViewDir;
    if (!plan.program.options.noAmbient) {
        out.line(gi ? "#if UNITY_SHOULD_SAMPLE_SH" : "#if 1");
        out.line("#define VARC_SURF_AMBIENT 1");
        out.line("#endif");
    }
    if (gi) {
        out.line("#if defined(LIGHTMAP_ON) || defined(DYNAMICLIGHTMAP_ON)");
        out.line("#define VARC_SURF_LIGHTMAP_UV 1");
        out.line("#endif");
    }
}

void writeVaryings(const PassPlan& plan, CodeWriter& out) {
    out.line("struct varc_surf_v2f {");
    out.line(plan.caster() ? "    V2F_SHADOW_CASTER;" : "    float4 pos : SV_POSITION;");
    if (plan.customInput) out.line("    Input custom;");
    if (plan.surfaceCall) {
        out.line("    float3 worldPos : TEXCOORD1;");
        out.line("    float3 worldNormal : TEXCOORD2;");
    }
    if (plan.tangentSpace) out.line("    float4 worldTangent : TEXCOORD3;");
    for (size_t i = 0; i < plan.texcoords.size(); ++i) {
        if (plan.texcoords[i]) {
            out.line("    float4 texcoord" + std::to_string(i) + " : TEXCOORD" +
                     std::to_string(4 + i) + ";");
        }
    }
    if (plan.color) out.line("    float4 vertexColor : COLOR0;");
    if (plan.screenPos) out.line("    float4 screenPos : TEXCOORD8;");
    if (plan.base()) {
        out.line("#if defined(VARC_SURF_AMBIENT)");
        out.line("    float3 vertexLights : TEXCOORD9;");
        out.line("#endif");
        out.line("#if defined(VARC_SURF_LIGHTMAP_UV)");
        out.line("    float4 lightmapUV : TEXCOORD12;");
        out.line("#endif");
    }
    if (!plan.caster()) {
        // Only the screen-space mask reads interpolated coordinates: varc's AutoLight computes
        // spot and point shadows from worldPos (an unread interpolator is an interface warning).
        out.line("#if defined(SHADOWS_SCREEN)");
        out.line("    UNITY_SHADOW_COORDS(10)");
        out.line("#endif");
    }
    if (plan.fog()) out.line("    UNITY_FOG_COORDS(11)");
    out.line("};");
}

void writeVertexModifier(const PassPlan& plan, CodeWriter& out) {
    const std::string& modifier = plan.program.options.vertexFunction;
    if (modifier.empty()) return;
    if (plan.facts.vertexWritesInput) {
        out.line("    Input customInput;");
        out.line("    UNITY_INITIALIZE_OUTPUT(Input, customInput);");
        out.line("    " + modifier + "(v, customInput);");
        if (plan.customInput) out.line("    o.custom = customInput;");
    } else {
        out.line("    " + modifier + "(v);");
    }
}

void writeVertexProgram(const PassPlan& plan, CodeWriter& out) {
    out.line("varc_surf_v2f varc_surf_vert(" + plan.facts.vertexInputType + " v) {");
    out.line("    varc_surf_v2f o;");
    out.line("    UNITY_INITIALIZE_OUTPUT(varc_surf_v2f, o);");
    writeVertexModifier(plan, out);
    out.line("    float3 worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;");
    out.line("    float3 worldNormal = UnityObjectToWorldNormal(v.normal);");
    if (plan.surfaceCall) {
        out.line("    o.worldPos = worldPos;");
        out.line("    o.worldNormal = worldNormal;");
    }
    if (plan.caster()) {
        out.line("    TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)");
    } else {
        out.line("    o.pos = UnityObjectToClipPos(v.vertex);");
    }
    if (plan.tangentSpace) {
        std::string tangent = vertexField(plan, "tangent", "float4(1, 0, 0, 1)");
        out.line("    o.worldTangent = float4(UnityObjectToWorldDir(" + tangent + ".xyz), " +
                 tangent + ".w * unity_WorldTransformParams.w);");
    }
    static constexpr std::array<std::string_view, 4> kTexcoords = {"texcoord", "texcoord1",
                                                                   "texcoord2", "texcoord3"};
    for (size_t i = 0; i < plan.texcoords.size(); ++i) {
        if (!plan.texcoords[i]) continue;
        out.line("    o.texcoord" + std::to_string(i) + " = " +
                 vertexField(plan, kTexcoords[i], "float4(0, 0, 0, 0)") + ";");
    }
    if (plan.color) {
        out.line("    o.vertexColor = " + vertexField(plan, "color", "float4(1, 1, 1, 1)") + ";");
    }
    if (plan.screenPos) out.line("    o.screenPos = ComputeScreenPos(o.pos);");
    if (plan.base()) {
        out.line("#if defined(VARC_SURF_LIGHTMAP_UV)");
        out.line("    o.lightmapUV = 0;");
        out.line("#endif");
        out.line("#if defined(VARC_SURF_LIGHTMAP_UV) && defined(LIGHTMAP_ON)");
        out.line("    o.lightmapUV.xy = " + vertexField(plan, "texcoord1", "float4(0, 0, 0, 0)") +
                 ".xy * unity_LightmapST.xy + unity_LightmapST.zw;");
        out.line("#endif");
        out.line("#if defined(VARC_SURF_LIGHTMAP_UV) && defined(DYNAMICLIGHTMAP_ON)");
        out.line("    o.lightmapUV.zw = " + vertexField(plan, "texcoord2", "float4(0, 0, 0, 0)") +
                 ".xy * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;");
        out.line("#endif");
        out.line("#if defined(VARC_SURF_AMBIENT)");
        out.line("    o.vertexLights = 0;");
        out.line("#endif");
        if (!plan.program.options.noVertexLights) {
            out.line("#if defined(VARC_SURF_AMBIENT) && defined(VERTEXLIGHT_ON)");
            out.line(
                "    o.vertexLights = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, "
                "unity_4LightPosZ0, unity_LightColor[0].rgb, unity_LightColor[1].rgb, "
                "unity_LightColor[2].rgb, unity_LightColor[3].rgb, unity_4LightAtten0, "
                "worldPos, worldNormal);");
            out.line("#endif");
        }
    }
    if (!plan.caster()) {
        out.line("#if defined(SHADOWS_SCREEN)");
        out.line("    UNITY_TRANSFER_SHADOW(o, v.texcoord1.xy);");
        out.line("#endif");
    }
    if (plan.fog()) out.line("    UNITY_TRANSFER_FOG(o, o.pos);");
    out.line("    return o;");
    out.line("}");
}

}  // namespace

std::string surfacePassLightMode(SurfacePassKind kind) {
    switch (kind) {
        case SurfacePassKind::ForwardBase:
            return "ForwardBase";
        case SurfacePassKind::ForwardAdd:
            return "ForwardAdd";
        case SurfacePassKind::ShadowCaster:
            return "ShadowCaster";
    }
    return "";
}

shaderlab::SurfaceOptions::Alpha effectiveAlpha(const shaderlab::SurfaceProgram& program) {
    Alpha alpha = program.options.alpha;
    if (alpha != Alpha::Blend) return alpha;
    bool physical =
        program.lightingModel == "Standard" || program.lightingModel == "StandardSpecular";
    return physical ? Alpha::Premultiply : Alpha::Fade;
}

shaderlab::GeneratedCode generateSurfaceCode(const shaderlab::SurfaceProgram& program,
                                             const SurfaceFacts& facts, SurfacePassKind kind) {
    PassPlan plan = makePlan(program, facts, kind);
    CodeWriter after;
    if (!plan.facts.faceMember.empty()) after.line("#undef " + plan.facts.faceSemantic);
    writeTextureScales(plan, after);
    writeAlphaTestProperty(plan, after);
    writeBaseSwitches(plan, after);
    writeVaryings(plan, after);
    writeVertexProgram(plan, after);
    writeFragmentProgram(plan, after);
    return {writeBefore(plan), after.take(), program.pragma};
}

}  // namespace varc::frontend
