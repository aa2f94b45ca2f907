// SPDX-License-Identifier: Apache-2.0
// The fragment program of a generated surface pass: Input from the varyings, the surface call,
// the lighting (GI or legacy shapes), emission, final colour and fog.
#include "SurfaceFragmentWriter.h"

#include <string>

namespace varc::frontend::surface {

namespace {

// The Input members varc fills by name (docs/SURFACE_SHADERS.md), from the interpolators.
void writeInputMembers(const PassPlan& plan, CodeWriter& out) {
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
        } else if (member == plan.facts.faceMember) {
            out.line(target +
                     (plan.facts.faceIsBool ? "varcFrontFace;" : "varcFrontFace ? 1 : -1;"));
        }
    }
    if (plan.tangentSpace && plan.facts.inputHasInternalData) {
        out.line("    surfIN.internalSurfaceTtoW0 = tangentSpace0;");
        out.line("    surfIN.internalSurfaceTtoW1 = tangentSpace1;");
        out.line("    surfIN.internalSurfaceTtoW2 = tangentSpace2;");
    }
}

// Declares `o` of the output type with Unity's starting values and calls the surface function.
void writeSurfaceCall(const PassPlan& plan, CodeWriter& out) {
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
        out.line(
            "    worldNormal = normalize(float3(dot(tangentSpace0, o.Normal), "
            "dot(tangentSpace1, o.Normal), dot(tangentSpace2, o.Normal)));");
        out.line("    o.Normal = worldNormal;");
    }
}

bool keepsAlpha(const shaderlab::SurfaceProgram& program) {
    return program.options.keepAlpha || program.options.alpha != Alpha::Off ||
           program.options.decal == shaderlab::SurfaceOptions::Decal::Blend;
}

void writeGiLighting(const PassPlan& plan, CodeWriter& out) {
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

void writeLegacyLighting(const PassPlan& plan, CodeWriter& out) {
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

void writeLitFragmentEnd(const PassPlan& plan, CodeWriter& out) {
    const shaderlab::SurfaceOptions& options = plan.program.options;
    if (!keepsAlpha(plan.program) && hasMember(plan.facts.outputMembers, "Alpha")) {
        out.line("    o.Alpha = 1;");  // opaque: no alpha premultiplication in the lighting
    }
    out.line("    float3 lightDir = normalize(UnityWorldSpaceLightDir(worldPos));");
    out.line("    UNITY_LIGHT_ATTENUATION(atten, i, worldPos);");
    out.line("    fixed4 c = 0;");
    bool gi =
        plan.facts.lighting == LightingShape::Gi || plan.facts.lighting == LightingShape::GiViewDir;
    if (gi)
        writeGiLighting(plan, out);
    else
        writeLegacyLighting(plan, out);
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

}  // namespace

void writeFragmentProgram(const PassPlan& plan, CodeWriter& out) {
    const bool face = plan.surfaceCall && !plan.facts.faceMember.empty();
    out.line(std::string(plan.caster() ? "float4" : "fixed4") + " varc_surf_frag(varc_surf_v2f i" +
             (face ? ", bool varcFrontFace : SV_IsFrontFace" : "") + ") : SV_Target {");
    if (plan.program.options.ditherCrossFade)
        out.line("    UNITY_APPLY_DITHER_CROSSFADE(i.pos.xy);");
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

}  // namespace varc::frontend::surface
