// SPDX-License-Identifier: Apache-2.0
// ShadowReference: a light's shadow map rasterised on the CPU from the facts of docs/LIGHTING.md
// §6 (the caster's normal offset and linear bias, Vulkan depth, nearest texel, lit when the
// receiver's depth <= the stored depth), and the shadow term as an interval: a tap whose texel
// or depth comparison is too close to call is taken both ways. No Vulkan.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "varc/reference/LinearTexture.h"
#include "varc/scene/Scene.h"
#include "varc/scene/ShadowSetup.h"

namespace varc::reference {

// The bounds of a shadow term (1 = lit, 1 - strength = shadowed). low == high away from edges.
struct ShadowInterval {
    float low = 1.0f, high = 1.0f;
};

// The shadow-distance fade as UNITY_SHADOW_ATTENUATION applies it (LIGHTING.md §6):
// shadow = saturate(realtime + saturate(viewDepth * scale + offset)), viewDepth the positive eye
// depth of the receiver; scale and offset are _LightShadowData.zw.
struct ShadowFade {
    glm::vec3 cameraPos{0.0f};
    glm::vec3 cameraForward{0.0f, 0.0f, 1.0f};  // unit
    float scale = 0.0f, offset = 0.0f;
    ShadowInterval apply(const ShadowInterval& realtime, const glm::vec3& p) const;
};

// The fade of |light|'s shadows seen from |scene|'s camera.
ShadowFade shadowFadeFor(const scene::Scene& scene, const scene::Light& light);

// How one object draws into shadow maps and the collector's camera depth: whether it casts, its
// caster pass's culling, and its alpha test (Legacy Shaders/Transparent/Cutout/VertexLit's
// caster, as Unity's: clip(tex2D(_MainTex, TRANSFORM_TEX(uv, _MainTex)).a * _Color.a - _Cutoff),
// a fragment with a negative value writes no depth) or Standard's dithered coverage
// (_ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON: slice floor(alpha * 15) of _DitherMaskLOD; slice 0
// covers nothing, slice 15 everything; the partial slices are not modelled: their fragments
// are taken both ways).
struct ShadowCaster {
    bool casts = false;
    bool cullOff = false;    // Cull Off (else Cull Back)
    bool alphaTest = false;  // clip against _Cutoff
    float cutoff = 0.5f;     // _Cutoff
    float colorAlpha = 1.0f;                           // _Color.a
    bool dither = false;     // Standard's alpha-blended caster
    // alpha = tex.a * _Color.a * alphaScale + alphaBias (premultiplied Standard materials cast
    // their reflective part: scale = oneMinusReflectivity, bias = 1 - oneMinusReflectivity).
    float alphaScale = 1.0f, alphaBias = 0.0f;
    float mainTexAlpha = 1.0f;                         // the constant _MainTex's alpha
    std::shared_ptr<const LinearTexture> mainTexture;  // _MainTex as a PNG file, else null
    glm::vec4 mainTexST{1.0f, 1.0f, 0.0f, 0.0f};       // _MainTex_ST
};

class ShadowMapReference {
public:
    // The map of spot light |light| with the objects whose |casters| entry casts drawn as casters
    // (their pass's culling, flipped for a mirrored transform; alpha-tested fragments whose
    // clip value is too close to 0 to call are stored both ways), cleared to depth 1.
    static ShadowMapReference renderSpot(const scene::Scene& scene, const scene::Light& light,
                                         const std::vector<ShadowCaster>& casters);
    // The depth cube map of point light |light|: six faces drawn through
    // scene::pointShadowCamera's face cameras (culling flipped on mirrored faces), read back
    // through Vulkan's cube face selection.
    static ShadowMapReference renderPoint(const scene::Scene& scene, const scene::Light& light,
                                          const std::vector<ShadowCaster>& casters);
    // The cascade atlas of directional light |light| (scene::directionalShadowSetup's cameras,
    // each cascade in its tile).
    static ShadowMapReference renderDirectional(const scene::Scene& scene,
                                                const scene::Light& light,
                                                const std::vector<ShadowCaster>& casters);

    // Directional lights: the screen-space shadow mask as the collector makes it (LIGHTING.md
    // §6): per camera pixel, the world position of the nearest caster (the camera depth texture
    // holds casters only; none: lit), its cascade (close fit by view depth, stable fit by split
    // spheres, a near-tie taken both ways), then one tap (hard) or the 7 x 7 tent (soft).
    // A pixel whose nearest caster is alpha-tested is taken as unknown (1 - strength to 1): the
    // camera depth is not alpha-tested here. Row-major, camera.width x camera.height.
    std::vector<ShadowInterval> screenMask(const scene::Scene& scene,
                                           const std::vector<ShadowCaster>& casters,
                                           bool soft) const;

    // The shadow term at world position |p|, then lerp(1 - strength, 1, lit). Spot: hard = one
    // tap at the shadow coordinate, soft = the mean of four taps at +-0.5 texel. Point: the
    // receiver depth of LIGHTING.md §6 compared in the cube; soft = four taps at +-1/128 m.
    ShadowInterval at(const glm::vec3& p, bool soft) const;

    // The stored depth of texel (x, y) of face |face| (row 0 at v = 0). For tests.
    float depth(uint32_t x, uint32_t y, size_t face = 0) const {
        return mFaces[face][size_t{y} * mSize + x];
    }
    uint32_t size() const { return mSize; }

    // Mutation hook for the comparator's tests: flips the comparison (lit when deeper).
    void flipCompareForTests() { mFlipped = true; }

private:
    // Bounds of one comparison at texture coordinate |uv| of face |face| against depth |z|.
    ShadowInterval tap(size_t face, const glm::vec2& uv, float z) const;
    // Bounds of one cube lookup in direction |r| against depth |z|.
    ShadowInterval cubeTap(const glm::vec3& r, float z) const;
    // Rasterises the casters through |viewProjection| into face |face|, in the square of
    // |tileSize| texels at |origin| (the whole face by default).
    void drawCasters(const scene::Scene& scene, const std::vector<ShadowCaster>& casters,
                     const glm::mat4& viewProjection, const glm::vec4& bias, bool mirrored,
                     size_t face, glm::uvec2 origin = glm::uvec2(0), uint32_t tileSize = 0);

    // The collector's shadow term at world position |p| (view depth |viewZ|).
    ShadowInterval collect(const glm::vec3& p, float viewZ, bool soft) const;
    // Bounds of the tent of half-width |halfWidth| texels (1.5: Unity's 3 x 3, 3.5: 7 x 7) at
    // texel position |position| of face 0 against |z|.
    ShadowInterval tent(const glm::vec2& position, float z, float halfWidth) const;

    bool mCube = false;
    bool mDirectional = false;
    scene::DirectionalShadowSetup mCascades;  // directional
    scene::ShadowCamera mCamera;             // spot
    glm::vec4 mProjectionParams{0.0f};       // point: _LightProjectionParams
    glm::vec3 mLightPos{0.0f};
    glm::vec4 mLightVector{0.0f};  // _WorldSpaceLightPos0: (position, 1) or (to the light, 0)
    float mStrength = 1.0f;
    uint32_t mSize = 0;
    std::vector<std::vector<float>> mFaces;  // one (spot) or six (point, +X -X +Y -Y +Z -Z)
    // mFaces with the alpha-tested fragments too close to call drawn as well: the nearest depth
    // the GPU may have stored (mFaces holds the farthest).
    std::vector<std::vector<float>> mNearFaces;
    bool mFlipped = false;
};

}  // namespace varc::reference
