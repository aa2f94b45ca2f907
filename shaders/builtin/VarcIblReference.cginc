// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of UnityImageBasedLighting.cginc (included by it): Monte Carlo reference
// integrals of image-based lighting that tools and tests use to check pre-filtered probes:
// random numbers, importance sampling of the cosine, Lambert and GGX lobes, and the integrals
// of the diffuse and specular BRDFs against a cube map. Conventions: roughness is the GGX alpha;
// weightOverPdf is BRDF * NdotL / pdf with the BRDF in physical units (Lambert 1/pi); the GGX
// visibility is SmithJointGGXVisibilityTerm. Written for varc from the textbook formulas
// (Karis 2013, "Real Shading in Unreal Engine 4"; Walter et al. 2007).
#if !defined(UNITY_IMAGE_BASED_LIGHTING_INCLUDED)
#error "VarcIblReference.cginc is a part of UnityImageBasedLighting.cginc: include that file instead"
#elif !defined(VARC_IBL_REFERENCE_INCLUDED)
#define VARC_IBL_REFERENCE_INCLUDED

// Thomas Wang's 32-bit integer hash, mapped to [0, 1).
float Hash(uint s) {
    s = (s ^ 61u) ^ (s >> 16);
    s *= 9u;
    s = s ^ (s >> 4);
    s *= 0x27d4eb2du;
    s = s ^ (s >> 15);
    return float(s) * 2.3283064365386963e-10;
}
// Two decorrelated numbers in [0, 1) from a position (the hash of each component's bits).
float2 InitRandom(float2 input) { return float2(Hash(asuint(input.x)), Hash(asuint(input.y) ^ 0x9e3779b9u)); }

// Cosine-weighted direction: r = sqrt(u.x), phi = 2 pi u.y, cos(theta) = sqrt(1 - u.x).
void ImportanceSampleCosDir(float2 u, float3 N, float3 tangentX, float3 tangentY, out float3 L) {
    float r = sqrt(u.x);
    float phi = 2.0 * UNITY_PI * u.y;
    L = normalize(tangentX * (r * cos(phi)) + tangentY * (r * sin(phi)) + N * sqrt(max(0.0, 1.0 - u.x)));
}
// GGX half vector: cos(theta) = sqrt((1 - u.x) / (1 + (a^2 - 1) u.x)), phi = 2 pi u.y; L is V
// mirrored about it.
void ImportanceSampleGGXDir(float2 u, float3 V, float3 N, float3 tangentX, float3 tangentY, float roughness,
                            out float3 H, out float3 L) {
    float a2 = roughness * roughness;
    float cosTheta = sqrt((1.0 - u.x) / (1.0 + (a2 - 1.0) * u.x));
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * UNITY_PI * u.y;
    H = normalize(tangentX * (sinTheta * cos(phi)) + tangentY * (sinTheta * sin(phi)) + N * cosTheta);
    L = 2.0 * dot(V, H) * H - V;
}
// GGX sample with its weight: D V NdotL / pdf, pdf = D NdotH / (4 VdotH), so
// weightOverPdf = 4 Vis NdotL VdotH / NdotH (Vis = SmithJointGGXVisibilityTerm).
void ImportanceSampleGGX(float2 u, float3 V, float3 N, float3 tangentX, float3 tangentY, float roughness, float NdotV,
                         out float3 L, out float VdotH, out float NdotL, out float weightOverPdf) {
    float3 H;
    ImportanceSampleGGXDir(u, V, N, tangentX, tangentY, roughness, H, L);
    float NdotH = saturate(dot(N, H));
    VdotH = saturate(dot(V, H));
    NdotL = saturate(dot(N, L));
    float vis = SmithJointGGXVisibilityTerm(NdotL, NdotV, roughness);
    weightOverPdf = NdotH > 0 ? 4.0 * vis * NdotL * VdotH / NdotH : 0.0;
}
// Lambert sample: cosine-distributed, so (NdotL / pi) / (NdotL / pi) = 1.
void ImportanceSampleLambert(float2 u, float3 N, float3 tangentX, float3 tangentY,
                             out float3 L, out float NdotL, out float weightOverPdf) {
    ImportanceSampleCosDir(u, N, tangentX, tangentY, L);
    NdotL = saturate(dot(N, L));
    weightOverPdf = 1.0;
}

// Split-sum terms over sampleCount Hammersley points: x = mean (1 - Fc) w, y = mean Fc w
// (Fc = (1 - VdotH)^5, w the GGX weight; specular = f0 x + f90 y), z = mean Disney diffuse
// factor over cosine samples, w = 1.
float4 IntegrateDFG(float3 V, float3 N, float roughness, uint sampleCount) {
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    float NdotV = saturate(dot(N, V));
    float4 acc = 0;
    for (uint i = 0; i < sampleCount; ++i) {
        float2 u = Hammersley2d(i, sampleCount);
        float3 L;
        float VdotH, NdotL, weightOverPdf;
        ImportanceSampleGGX(u, V, N, tangentX, tangentY, roughness, NdotV, L, VdotH, NdotL, weightOverPdf);
        if (NdotL > 0) {
            float fc = Pow5(1.0 - VdotH);
            acc.x += (1.0 - fc) * weightOverPdf;
            acc.y += fc * weightOverPdf;
        }
        ImportanceSampleCosDir(u, N, tangentX, tangentY, L);
        NdotL = saturate(dot(N, L));
        if (NdotL > 0) {
            float LdotH = saturate(dot(L, normalize(V + L)));
            acc.z += DisneyDiffuse(NdotV, NdotL, LdotH, RoughnessToPerceptualRoughness(roughness));
        }
    }
    return float4(acc.xyz / float(max(sampleCount, 1u)), 1.0);
}

// Pre-filtered radiance along N (V = N assumed by the pre-filter): GGX samples weighted by
// NdotL. With prefilter, each sample reads the mip whose texel solid angle matches the
// sample's, 0.5 log2(omegaS * invOmegaP) + 1 (omegaS = 1 / (sampleCount pdf), invOmegaP = 1 /
// solid angle of a mip-0 texel), clamped to [0, mipmapcount]. Returns (radiance, 1).
float4 IntegrateLD(UNITY_ARGS_TEXCUBE(tex), float3 V, float3 N, float roughness, float mipmapcount, float invOmegaP,
                   uint sampleCount, bool prefilter) {
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    float3 acc = 0;
    float accWeight = 0;
    for (uint i = 0; i < sampleCount; ++i) {
        float3 H, L;
        ImportanceSampleGGXDir(Hammersley2d(i, sampleCount), V, N, tangentX, tangentY, roughness, H, L);
        float NdotL = saturate(dot(N, L));
        if (NdotL > 0) {
            float mip = 0;
            if (prefilter) {
                float NdotH = saturate(dot(N, H));
                float pdf = GGXTerm(NdotH, roughness) * 0.25;  // D NdotH / (4 VdotH), V = N
                float omegaS = 1.0 / (float(sampleCount) * max(pdf, 1e-6));
                mip = clamp(0.5 * log2(omegaS * invOmegaP) + 1.0, 0.0, mipmapcount);
            }
            acc += UNITY_SAMPLE_TEXCUBE_LOD(tex, L, mip).rgb * NdotL;
            accWeight += NdotL;
        }
    }
    return float4(acc / max(accWeight, 1e-6), 1.0);
}

// Reference diffuse lighting: albedo times the mean decoded radiance over cosine samples
// (Lambert), optionally times the Disney diffuse factor of the sample.
void VarcIntegrateDiffuseIBL(out float3 diffuseLighting, UNITY_ARGS_TEXCUBE(tex), float4 texHdrParam, float3 N,
                             float3 V, float perceptualRoughness, bool disney, float3 diffuseAlbedo, uint sampleCount) {
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    float NdotV = saturate(dot(N, V));
    float3 acc = 0;
    for (uint i = 0; i < sampleCount; ++i) {
        float3 L;
        float NdotL, weightOverPdf;
        ImportanceSampleLambert(Hammersley2d(i, sampleCount), N, tangentX, tangentY, L, NdotL, weightOverPdf);
        if (NdotL > 0) {
            float3 radiance = DecodeHDR(UNITY_SAMPLE_TEXCUBE_LOD(tex, L, 0), texHdrParam);
            float factor = disney ? DisneyDiffuse(NdotV, NdotL, saturate(dot(L, normalize(V + L))), perceptualRoughness) : 1.0;
            acc += radiance * weightOverPdf * factor;
        }
    }
    diffuseLighting = diffuseAlbedo * acc / float(max(sampleCount, 1u));
}
void IntegrateLambertDiffuseIBLRef(out float3 diffuseLighting, UNITY_ARGS_TEXCUBE(tex), float4 texHdrParam, float3 N,
                                   float3 diffuseAlbedo, uint sampleCount) {
    VarcIntegrateDiffuseIBL(diffuseLighting, UNITY_PASS_TEXCUBE(tex), texHdrParam, N, N, 1.0, false, diffuseAlbedo, sampleCount);
}
void IntegrateDisneyDiffuseIBLRef(out float3 diffuseLighting, UNITY_ARGS_TEXCUBE(tex), float4 texHdrParam, float3 N, float3 V,
                                  float roughness, float3 diffuseAlbedo, uint sampleCount) {
    VarcIntegrateDiffuseIBL(diffuseLighting, UNITY_PASS_TEXCUBE(tex), texHdrParam, N, V, RoughnessToPerceptualRoughness(roughness),
                            true, diffuseAlbedo, sampleCount);
}
// Reference specular lighting: mean over GGX samples of radiance * F(VdotH) * weightOverPdf,
// F = f0 + (f90 - f0) (1 - VdotH)^5.
void IntegrateSpecularGGXIBLRef(out float3 specularLighting, UNITY_ARGS_TEXCUBE(tex), float4 texHdrParam, float3 N, float3 V,
                                float roughness, float3 f0, float f90, uint sampleCount) {
    float3 tangentX, tangentY;
    GetLocalFrame(N, tangentX, tangentY);
    float NdotV = saturate(dot(N, V));
    float3 acc = 0;
    for (uint i = 0; i < sampleCount; ++i) {
        float3 L;
        float VdotH, NdotL, weightOverPdf;
        ImportanceSampleGGX(Hammersley2d(i, sampleCount), V, N, tangentX, tangentY, roughness, NdotV, L, VdotH, NdotL, weightOverPdf);
        if (NdotL > 0) {
            float3 radiance = DecodeHDR(UNITY_SAMPLE_TEXCUBE_LOD(tex, L, 0), texHdrParam);
            float3 F = f0 + (f90 - f0) * Pow5(1.0 - VdotH);
            acc += radiance * F * weightOverPdf;
        }
    }
    specularLighting = acc / float(max(sampleCount, 1u));
}

#endif // VARC_IBL_REFERENCE_INCLUDED
