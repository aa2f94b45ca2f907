// SPDX-License-Identifier: Apache-2.0
// Writes the vertex and fragment programs of the passes a surface program becomes.
// Written for varc from Unity's documentation of surface shaders (the Input members by name, the
// options, the lighting function shapes); docs/SURFACE_SHADERS.md states what is generated.
#include "varc/frontend/SurfaceCodeGenerator.h"

#include <algorithm>
#include <array>

namespace varc::frontend {

namespace {

using Alpha = shaderlab::SurfaceOptions::Alpha;

// What one generated pass needs, worked out once from the program, its facts and the pass.
struct PassPlan {
    const shaderlab::SurfaceProgram& program;
    const SurfaceFacts& facts;
    SurfacePassKind kind;
    bool tangentSpace;                // the surface function writes o.Normal (tangent space)
    std::array<bool, 4> texcoords{};  // uv_, uv2_, uv3_, uv4_ members read texcoord0..3
    bool color;
    bool screenPos;
    bool customInput;                 // Input travels whole from the vertex modifier
    // The fragment program calls the surface function: always in the forward passes; in the
    // caster only for alphatest or a surface function that clips (else it writes depth only).
    bool surfaceCall;
    bool base() const { return kind == SurfacePassKind::ForwardBase; }
    bool add() const { return kind == SurfacePassKind::ForwardAdd; }
    bool caster() const { return kind == SurfacePassKind::ShadowCaster; }
    bool fog() const { return !caster() && !program.options.noFog; }
};

class Writer {
public:
    void line(std::string_view text) {
        mText.append(text);
        mText.push_back('\n');
    }
    std::string take() { return std::move(mText); }

private:
    std::string mText;
};

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

bool hasMember(const std::vector<std::string>& members, std::string_view name) {
    return std::find(members.begin(), members.end(), name) != members.end();
}

// `v.FIELD` when the vertex input has FIELD, else |fallback|.
std::string vertexField(const PassPlan& plan, std::string_view field, std::string_view fallback) {
    if (hasMember(plan.facts.vertexInputMembers, field)) return "v." + std::string(field);
    return std::string(fallback);
}

std::string passDefine(SurfacePassKind kind) {
    switch (kind) {
    case SurfacePassKind::ForwardBase: return "UNITY_PASS_FORWARDBASE";
    case SurfacePassKind::ForwardAdd: return "UNITY_PASS_FORWARDADD";
    case SurfacePassKind::ShadowCaster: return "UNITY_PASS_SHADOWCASTER";
    }
    return "";
}

void writeKeywordPragmas(const PassPlan& plan, Writer& out) {
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
}

void writeNormalMacros(const PassPlan& plan, Writer& out) {
    if (plan.tangentSpace) {
        out.line("#define INTERNAL_DATA float3 internalSurfaceTtoW0; float3 internalSurfaceTtoW1; "
                 "float3 internalSurfaceTtoW2;");
        out.line("#define WorldNormalVector(data, normal) float3(dot((data).internalSurfaceTtoW0, "
                 "normal), dot((data).internalSurfaceTtoW1, normal), "
                 "dot((data).internalSurfaceTtoW2, normal))");
        out.line("#define WorldReflectionVector(data, normal) reflect((data).worldRefl, "
                 "WorldNormalVector(data, normal))");
    } else {
        out.line("#define INTERNAL_DATA");
        out.line("#define WorldNormalVector(data, normal) (normal)");
        out.line("#define WorldReflectionVector(data, normal) (data).worldRefl");
    }
}

std::string writeBefore(const PassPlan& plan) {
    Writer out;
    out.line("#define " + passDefine(plan.kind));
    if (effectiveAlpha(plan.program) == Alpha::Premultiply) {
        out.line("#define _ALPHAPREMULTIPLY_ON 1");
    }
    for (const char* file : {"HLSLSupport.cginc", "UnityShaderVariables.cginc", "UnityCG.cginc",
                             "Lighting.cginc", "UnityPBSLighting.cginc", "AutoLight.cginc"}) {
        out.line(std::string("#include \"") + file + "\"");
    }
    writeNormalMacros(plan, out);
    out.line("#pragma vertex varc_surf_vert");
    out.line("#pragma fragment varc_surf_frag");
    writeKeywordPragmas(plan, out);
    return out.take();
}

// `float4 NAME_ST;` for every uvN_NAME member whose NAME_ST the program does not mention.
void writeTextureScales(const PassPlan& plan, Writer& out) {
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
void writeAlphaTestProperty(const PassPlan& plan, Writer& out) {
    const std::string& property = plan.program.options.alphaTestProperty;
    if (!property.empty() && !plan.facts.mentions(property)) out.line("fixed " + property + ";");
}

// The base pass's optional interpolators, on when the fragment program reads them (an
// interpolator written and never read is a Vulkan interface warning): VARC_SURF_AMBIENT (the
// vertex lights: the (s, gi) models read them with light-probe SH only, as UnityGI_Base does;
// the legacy shapes always) and VARC_SURF_LIGHTMAP_UV (the (s, gi) models under a lightmap).
void writeBaseSwitches(const PassPlan& plan, Writer& out) {
    if (!plan.base()) return;
    bool gi = plan.facts.lighting == LightingShape::Gi ||
              plan.facts.lighting == LightingShape::GiViewDir;
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

void writeVaryings(const PassPlan& plan, Writer& out) {
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

void writeVertexModifier(const PassPlan& plan, Writer& out) {
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

void writeVertexProgram(const PassPlan& plan, Writer& out) {
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
            out.line("    o.vertexLights = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, "
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

// The Input members varc fills by name (docs/SURFACE_SHADERS.md), from the interpolators.
void writeInputMembers(const PassPlan& plan, Writer& out) {
    for (const std::string& member : plan.facts.inputMembers) {
        std::string texture;
        int set = uvSet(member, texture);
        std::string target = "    surfIN." + member + " = ";
        if (set >= 0) {
            out.line(target + "TRANSFORM_TEX(i.texcoord" + std::to_string(set) + ", " + texture +
                     ");");
        } else if (member == "worldPos") {
            out.line(target + "worldPos;");
        } else if (member == "worldNormal") {
            out.line(target + "worldNormal;");
        } else if (member == "worldRefl") {
            out.line(target + (plan.tangentSpace ? "-worldViewDir;"
                                                 : "reflect(-worldViewDir, worldNormal);"));
        } else if (member == "viewDir") {
            out.line(target + (plan.tangentSpace ? "tangentSpace0 * worldViewDir.x + "
                                                   "tangentSpace1 * worldViewDir.y + "
                                                   "tangentSpace2 * worldViewDir.z;"
                                                 : "worldViewDir;"));
        } else if (member == "screenPos") {
            out.line(target + "i.screenPos;");
        } else if (member == "color") {
            out.line(target + "i.vertexColor;");
        }
    }
    if (plan.tangentSpace && plan.facts.inputHasInternalData) {
        out.line("    surfIN.internalSurfaceTtoW0 = tangentSpace0;");
        out.line("    surfIN.internalSurfaceTtoW1 = tangentSpace1;");
        out.line("    surfIN.internalSurfaceTtoW2 = tangentSpace2;");
    }
}

// Declares `o` of the output type with Unity's starting values and calls the surface function.
void writeSurfaceCall(const PassPlan& plan, Writer& out) {
    const std::string& type = plan.facts.outputType;
    const std::vector<std::string>& members = plan.facts.outputMembers;
    out.line("    " + type + " o;");
    out.line("    UNITY_INITIALIZE_OUTPUT(" + type + ", o);");
    if (hasMember(members, "Occlusion")) out.line("    o.Occlusion = 1.0;");
    if (hasMember(members, "Normal")) {
        out.line(plan.tangentSpace ? "    o.Normal = float3(0, 0, 1);"
                                   : "    o.Normal = worldNormal;");
    }
    out.line("    " + plan.program.function + "(surfIN, o);");
    if (!plan.program.options.alphaTestProperty.empty()) {
        out.line("    clip(o.Alpha - " + plan.program.options.alphaTestProperty + ");");
    }
    if (plan.tangentSpace && hasMember(members, "Normal")) {
        out.line("    worldNormal = normalize(float3(dot(tangentSpace0, o.Normal), "
                 "dot(tangentSpace1, o.Normal), dot(tangentSpace2, o.Normal)));");
        out.line("    o.Normal = worldNormal;");
    }
}

bool keepsAlpha(const shaderlab::SurfaceProgram& program) {
    return program.options.keepAlpha || program.options.alpha != Alpha::Off ||
           program.options.decal == shaderlab::SurfaceOptions::Decal::Blend;
}

void writeGiLighting(const PassPlan& plan, Writer& out) {
    const std::string model = "Lighting" + plan.program.lightingModel;
    bool viewDir = plan.facts.lighting == LightingShape::GiViewDir;
    out.line("    UnityGI gi;");
    out.line("    UNITY_INITIALIZE_OUTPUT(UnityGI, gi);");
    out.line("    gi.indirect.diffuse = 0;");
    out.line("    gi.indirect.specular = 0;");
    out.line("    gi.light.color = _LightColor0.rgb;");
    out.line("    gi.light.dir = lightDir;");
    if (plan.base()) {
        out.line("    UnityGIInput giInput;");
        out.line("    UNITY_INITIALIZE_OUTPUT(UnityGIInput, giInput);");
        out.line("    giInput.light = gi.light;");
        out.line("    giInput.worldPos = worldPos;");
        out.line("    giInput.worldViewDir = worldViewDir;");
        out.line("    giInput.atten = atten;");
        out.line("    giInput.ambient = 0;");
        out.line("#if defined(VARC_SURF_AMBIENT)");
        out.line("    giInput.ambient = i.vertexLights;");
        out.line("#endif");
        out.line("#if defined(VARC_SURF_LIGHTMAP_UV)");
        out.line("    giInput.lightmapUV = i.lightmapUV;");
        out.line("#endif");
        out.line("    giInput.probeHDR[0] = unity_SpecCube0_HDR;");
        out.line("    giInput.probeHDR[1] = unity_SpecCube1_HDR;");
        out.line("    giInput.boxMin[0] = unity_SpecCube0_BoxMin;");
        out.line("    giInput.boxMin[1] = unity_SpecCube1_BoxMin;");
        out.line("    giInput.boxMax[0] = unity_SpecCube0_BoxMax;");
        out.line("    giInput.boxMax[1] = unity_SpecCube1_BoxMax;");
        out.line("    giInput.probePosition[0] = unity_SpecCube0_ProbePosition;");
        out.line("    giInput.probePosition[1] = unity_SpecCube1_ProbePosition;");
        if (plan.facts.hasGiFunction) {
            out.line("    " + model + "_GI(o, giInput, gi);");
        } else {
            out.line("    gi = UnityGlobalIllumination(giInput, 1.0, o.Normal);");
        }
    } else {
        out.line("    gi.light.color *= atten;");
    }
    out.line("    c += " + model + "(o, " + (viewDir ? "worldViewDir, " : "") + "gi);");
}

void writeLegacyLighting(const PassPlan& plan, Writer& out) {
    bool viewDir = plan.facts.lighting == LightingShape::LegacyViewDir;
    out.line("    c += Lighting" + plan.program.lightingModel + "(o, lightDir, " +
             (viewDir ? "worldViewDir, " : "") + "atten);");
    if (plan.base() && !plan.program.options.noAmbient) {
        out.line("    float3 ambient = i.vertexLights;");  // VARC_SURF_AMBIENT is on
        out.line("#if UNITY_SHOULD_SAMPLE_SH");
        out.line("    ambient += max(0, ShadeSH9(float4(o.Normal, 1)));");
        out.line("#endif");
        out.line("    c.rgb += o.Albedo * ambient;");
    }
}

void writeLitFragmentEnd(const PassPlan& plan, Writer& out) {
    const shaderlab::SurfaceOptions& options = plan.program.options;
    if (!keepsAlpha(plan.program) && hasMember(plan.facts.outputMembers, "Alpha")) {
        out.line("    o.Alpha = 1;");  // opaque: no alpha premultiplication in the lighting
    }
    out.line("    float3 lightDir = normalize(UnityWorldSpaceLightDir(worldPos));");
    out.line("    UNITY_LIGHT_ATTENUATION(atten, i, worldPos);");
    out.line("    fixed4 c = 0;");
    bool gi = plan.facts.lighting == LightingShape::Gi ||
              plan.facts.lighting == LightingShape::GiViewDir;
    if (gi) writeGiLighting(plan, out);
    else writeLegacyLighting(plan, out);
    if (plan.base() && hasMember(plan.facts.outputMembers, "Emission")) {
        out.line("    c.rgb += o.Emission;");
    }
    if (!options.finalColorFunction.empty()) {
        out.line("    " + options.finalColorFunction + "(surfIN, o, c);");
    }
    if (plan.fog()) out.line("    UNITY_APPLY_FOG(i.fogCoord, c);");
    if (!keepsAlpha(plan.program)) out.line("    c.a = 1;");
    out.line("    return c;");
}

void writeFragmentProgram(const PassPlan& plan, Writer& out) {
    out.line(std::string(plan.caster() ? "float4" : "fixed4") +
             " varc_surf_frag(varc_surf_v2f i) : SV_Target {");
    if (!plan.surfaceCall) {
        out.line("    SHADOW_CASTER_FRAGMENT(i)");
        out.line("}");
        return;
    }
    out.line("    Input surfIN;");
    out.line("    UNITY_INITIALIZE_OUTPUT(Input, surfIN);");
    if (plan.customInput) out.line("    surfIN = i.custom;");
    out.line("    float3 worldPos = i.worldPos;");
    out.line("    float3 worldViewDir = normalize(UnityWorldSpaceViewDir(worldPos));");
    out.line("    float3 worldNormal = normalize(i.worldNormal);");
    if (plan.tangentSpace) {
        out.line("    float3 worldTangent = i.worldTangent.xyz;");
        out.line("    float3 worldBinormal = cross(worldNormal, worldTangent) * i.worldTangent.w;");
        for (char axis : {'x', 'y', 'z'}) {  // the rows of the tangent-to-world matrix
            std::string row = std::string("tangentSpace") + char('0' + (axis - 'x'));
            std::string c(1, axis);
            out.line("    float3 " + row + " = float3(worldTangent." + c + ", worldBinormal." + c +
                     ", worldNormal." + c + ");");
        }
    }
    writeInputMembers(plan, out);
    writeSurfaceCall(plan, out);
    if (plan.caster()) {
        out.line("    SHADOW_CASTER_FRAGMENT(i)");
    } else {
        writeLitFragmentEnd(plan, out);
    }
    out.line("}");
}

}  // namespace

std::string surfacePassLightMode(SurfacePassKind kind) {
    switch (kind) {
    case SurfacePassKind::ForwardBase: return "ForwardBase";
    case SurfacePassKind::ForwardAdd: return "ForwardAdd";
    case SurfacePassKind::ShadowCaster: return "ShadowCaster";
    }
    return "";
}

shaderlab::SurfaceOptions::Alpha effectiveAlpha(const shaderlab::SurfaceProgram& program) {
    Alpha alpha = program.options.alpha;
    if (alpha != Alpha::Blend) return alpha;
    bool physical = program.lightingModel == "Standard" ||
                    program.lightingModel == "StandardSpecular";
    return physical ? Alpha::Premultiply : Alpha::Fade;
}

shaderlab::GeneratedCode generateSurfaceCode(const shaderlab::SurfaceProgram& program,
                                             const SurfaceFacts& facts, SurfacePassKind kind) {
    PassPlan plan = makePlan(program, facts, kind);
    Writer after;
    writeTextureScales(plan, after);
    writeAlphaTestProperty(plan, after);
    writeBaseSwitches(plan, after);
    writeVaryings(plan, after);
    writeVertexProgram(plan, after);
    writeFragmentProgram(plan, after);
    return {writeBefore(plan), after.take(), program.pragma};
}

}  // namespace varc::frontend
