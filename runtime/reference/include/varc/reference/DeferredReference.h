// SPDX-License-Identifier: Apache-2.0
// DeferredReference: renders a deferred Scene (camera.path = deferred) on the CPU as the GPU
// deferred renderer should: the same rasterised surfaces, the G-buffer contents with their
// attachment quantisation, the deferred light formulas of docs/LIGHTING.md §3 / §8.3, the light
// buffer's blending and, in LDR, the exp2(−c) encoding and the decode. No Vulkan.
#pragma once

#include "varc/core/Result.h"
#include "varc/reference/LinearTexture.h"
#include "varc/reference/ReferenceRenderer.h"
#include "varc/scene/Scene.h"

namespace varc::reference {

// The material of varc/DeferredGBuffer with its Properties defaults.
struct GBufferMaterial {
    glm::vec4 color{1.0f};    // _Color
    glm::vec4 mainTex{1.0f};  // constant value of _MainTex ("white" or "black")
    std::shared_ptr<const LinearTexture> mainTexture;  // _MainTex as a PNG file, else null
    glm::vec4 mainTexST{1.0f, 1.0f, 0.0f, 0.0f};       // _MainTex_ST
    float metallic = 0.0f;                             // _Metallic
    float smoothness = 0.5f;                           // _Smoothness
    glm::vec3 emission{0.0f};                          // _EmissionColor.rgb
};
// Unsupported for another shader or texture name; InvalidInput for a property of the wrong kind.
Result<GBufferMaterial> resolveGBufferMaterial(const scene::Material& material);

// What the G-buffer holds at one pixel, after the attachments' quantisation (SHADER_ABI.md §6 with
// varc's RT2 format): RT0/RT1 RGBA8_SRGB (rgb through sRGB 8 bits, alpha linear 8 bits), RT2
// R32G32B32A32_SFLOAT (exact), RT3 half floats (HDR) or 8-bit exp2(−c) (LDR, in 0..255 units).
struct GBufferTexel {
    glm::vec3 diffuse{0.0f}, specular{0.0f};
    float smoothness = 0.0f;
    glm::vec3 encodedNormal{0.0f};  // n · 0.5 + 0.5
    glm::vec3 light{0.0f};          // RT3 rgb
};

// One 8-bit sRGB round trip: linear -> sRGB-encoded byte (rounded) -> linear.
float srgb8RoundTrip(float linear);

// Renders |scene|: background = camera.background; per object pixel the G-buffer values, then per
// light (scene order) the deferred light pass evaluated from the G-buffer texel and the rasterised
// world position, accumulated as the light buffer does (HDR: half(buffer + half(c)); LDR:
// round(buffer8 · round(255·exp2(−c)) / 255)), and in LDR the decode
// round(255·saturate(−log2(buffer8/255))). LDR alpha is the background's (the renderer keeps the
// clear alpha), HDR alpha 1 on objects. Errors: Unsupported for another path or shader, or a cookie
// other than "none"/"default".
Result<ReferenceImage> renderDeferredReference(const scene::Scene& scene);

}  // namespace varc::reference
