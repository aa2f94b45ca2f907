// SPDX-License-Identifier: Apache-2.0
// ShadowReference: CPU shadow maps and the interval shadow term.
#include "varc/reference/ShadowReference.h"

#include <algorithm>
#include <cmath>

#include "varc/reference/Rasterizer.h"
#include "varc/scene/Mesh.h"

namespace varc::reference {
namespace {

// How close a texture coordinate may come to a texel boundary (in texels), and a receiver depth
// to the stored depth, before the tap could go either way on a conformant GPU: Vulkan's nearest
// filter resolves coordinates to a sub-texel grid and interpolated depths differ in the last
// bits of a float.
constexpr float kTexelEpsilon = 1.0f / 128.0f;
constexpr float kDepthEpsilon = 1e-5f;

// The caster vertex of LIGHTING.md §6 in a shadow camera's clip space: the world position moved
// against the normal by bias.z * sin(angle to the light), then clip z pushed back by
// saturate(bias.x / w) * w and kept in front of the far plane. |light| is _WorldSpaceLightPos0:
// (position, 1), or (direction towards the light, 0).
glm::vec4 casterClip(const glm::vec3& world, const glm::vec3& normal, const glm::vec4& light,
                     const glm::mat4& viewProjection, const glm::vec4& bias) {
    glm::vec3 p = world;
    if (bias.z != 0.0f) {
        const glm::vec3 toLight = glm::vec3(light) - world * light.w;
        const float cosine = glm::dot(normal, glm::normalize(toLight));
        const float sine = std::sqrt(std::max(0.0f, 1.0f - cosine * cosine));
        p -= normal * (bias.z * sine);
    }
    glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    // saturate(bias.x / w): 0 when w is not positive (the vertex is clipped anyway; 0 / 0 would
    // be NaN, which saturate turns into 0 on the GPU but std::clamp keeps).
    const float shift = clip.w > 0.0f ? std::clamp(bias.x / clip.w, 0.0f, 1.0f) : 0.0f;
    clip.z += shift * clip.w;
    clip.z = std::min(clip.z, clip.w);
    return clip;
}

// Vulkan's cube map faces (the specification's table of major axes): for a direction r on face
// i, sc = dot(sc, r), tc = dot(tc, r), ma = dot(ma, r) > 0, s = (sc / ma + 1) / 2,
// t = (tc / ma + 1) / 2. Written here from the specification, independently of the runtime's
// face cameras (scene::pointShadowCamera), which must agree with it.
struct CubeFace {
    glm::vec3 sc, tc, ma;
};
constexpr CubeFace kCubeFaces[6] = {
    {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}},  {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},    {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
    {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},   {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
};

// How close two components of a direction may be before either could be the major axis.
constexpr float kAxisEpsilon = 1e-5f;

}  // namespace

namespace {

// How close the alpha test's value may come to 0 (or the dither slice coordinate to a slice
// boundary) before a conformant GPU could decide either way: 8-bit texels, bilinear weights,
// half-precision alpha and interpolated texture coordinates of finite precision.
constexpr float kClipEpsilon = 1.0f / 64.0f;

enum class Coverage { None, Unknown, Full };

// Whether the caster's fragment at mesh uv |uv| writes depth (ShadowCaster's clip()).
Coverage coverageAt(const ShadowCaster& caster, const glm::vec2& uv) {
    if (!caster.alphaTest && !caster.dither) return Coverage::Full;
    const glm::vec4& st = caster.mainTexST;
    const glm::vec2 at = uv * glm::vec2(st) + glm::vec2(st.z, st.w);
    const float texel = caster.mainTexture ? caster.mainTexture->sample(at).a : caster.mainTexAlpha;
    const float alpha = texel * caster.colorAlpha * caster.alphaScale + caster.alphaBias;
    if (caster.alphaTest) {
        const float value = alpha - caster.cutoff;
        return value < -kClipEpsilon ? Coverage::None
               : value > kClipEpsilon ? Coverage::Full
                                      : Coverage::Unknown;
    }
    const float slice = alpha * 15.0f;  // (alpha * 15/16) * 16 slices
    return slice < 1.0f - kClipEpsilon    ? Coverage::None
           : slice > 15.0f + kClipEpsilon ? Coverage::Full
                                          : Coverage::Unknown;
}

}  // namespace

void ShadowMapReference::drawCasters(const scene::Scene& scene,
                                     const std::vector<ShadowCaster>& casters,
                                     const glm::mat4& viewProjection, const glm::vec4& bias,
                                     bool mirrored, size_t face, glm::uvec2 origin,
                                     uint32_t tileSize) {
    std::vector<float>& depths = mFaces[face];
    std::vector<float>& nearDepths = mNearFaces[face];
    const uint32_t tile = tileSize ? tileSize : mSize;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        if (o >= casters.size() || !casters[o].casts) continue;
        const ShadowCaster& caster = casters[o];
        const scene::Object& object = scene.objects[o];
        const scene::Mesh& mesh = scene::builtinMesh(object.mesh);
        const glm::mat4 toWorld = object.transform.localToWorld();
        const glm::mat3 normalMatrix = glm::transpose(glm::mat3(glm::inverse(toWorld)));
        const bool flipped = (glm::determinant(toWorld) < 0.0f) != mirrored;
        const CullMode cull = caster.cullOff ? CullMode::None
                              : flipped      ? CullMode::Front
                                             : CullMode::Back;
        std::vector<glm::vec4> clip(mesh.positions.size());
        for (size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec3 world(toWorld * glm::vec4(mesh.positions[v], 1.0f));
            const glm::vec3 normal = glm::normalize(normalMatrix * mesh.normals[v]);
            clip[v] = casterClip(world, normal, mLightVector, viewProjection, bias);
        }
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::array<uint32_t, 3> index = {mesh.indices[t], mesh.indices[t + 1],
                                                   mesh.indices[t + 2]};
            const std::array<glm::vec4, 3> triangle = {clip[index[0]], clip[index[1]],
                                                       clip[index[2]]};
            rasterizeTriangle(triangle, tile, tile, cull, [&](const Fragment& f) {
                glm::vec2 uv(0.0f);
                for (int k = 0; k < 3; ++k) uv += f.bary[k] * mesh.uvs[index[size_t(k)]];
                const Coverage coverage = coverageAt(caster, uv);
                if (coverage == Coverage::None) return;  // discarded
                const bool sure = coverage == Coverage::Full;
                const size_t texel = size_t{f.y + origin.y} * mSize + f.x + origin.x;
                if (sure) depths[texel] = std::min(depths[texel], f.depth);
                nearDepths[texel] = std::min(nearDepths[texel], f.depth);
            });
        }
    }
}

ShadowMapReference ShadowMapReference::renderSpot(const scene::Scene& scene,
                                                  const scene::Light& light,
                                                  const std::vector<ShadowCaster>& casters) {
    ShadowMapReference map;
    map.mCamera = scene::spotShadowCamera(light);
    map.mStrength = light.shadowStrength;
    map.mSize = map.mCamera.resolution;
    map.mLightPos = light.transform.position;
    map.mLightVector = glm::vec4(map.mLightPos, 1.0f);
    map.mFaces.assign(1, std::vector<float>(size_t{map.mSize} * map.mSize, 1.0f));
    map.mNearFaces = map.mFaces;
    map.drawCasters(scene, casters, map.mCamera.matrices.viewProjection, map.mCamera.bias, false,
                    0);
    return map;
}

ShadowMapReference ShadowMapReference::renderPoint(const scene::Scene& scene,
                                                   const scene::Light& light,
                                                   const std::vector<ShadowCaster>& casters) {
    const scene::PointShadowCamera camera = scene::pointShadowCamera(light);
    ShadowMapReference map;
    map.mCube = true;
    map.mProjectionParams = camera.projectionParams;
    map.mStrength = light.shadowStrength;
    map.mSize = camera.resolution;
    map.mLightPos = light.transform.position;
    map.mLightVector = glm::vec4(map.mLightPos, 1.0f);
    map.mFaces.assign(6, std::vector<float>(size_t{map.mSize} * map.mSize, 1.0f));
    map.mNearFaces = map.mFaces;
    for (size_t face = 0; face < 6; ++face) {
        map.drawCasters(scene, casters, camera.faceViewProjection[face], camera.bias,
                        camera.mirrored[face], face);
    }
    return map;
}

ShadowMapReference ShadowMapReference::renderDirectional(const scene::Scene& scene,
                                                         const scene::Light& light,
                                                         const std::vector<ShadowCaster>& casters) {
    ShadowMapReference map;
    map.mDirectional = true;
    map.mCascades = scene::directionalShadowSetup(scene, light);
    map.mStrength = light.shadowStrength;
    map.mSize = map.mCascades.resolution;
    map.mLightVector = glm::vec4(-light.forward(), 0.0f);
    map.mFaces.assign(1, std::vector<float>(size_t{map.mSize} * map.mSize, 1.0f));
    map.mNearFaces = map.mFaces;
    for (int c = 0; c < map.mCascades.cascades; ++c) {
        const auto i = static_cast<size_t>(c);
        map.drawCasters(scene, casters, map.mCascades.viewProjection[i], map.mCascades.bias, false,
                        0, map.mCascades.tileOrigin[i], map.mCascades.tileSize);
    }
    return map;
}

ShadowInterval ShadowMapReference::tap(size_t face, const glm::vec2& uv, float z) const {
    // Nearest texel: floor(uv * size), clamped to the edge; near a boundary both neighbours.
    int candidates[2][2];
    int counts[2];
    for (int axis = 0; axis < 2; ++axis) {
        const float t = uv[axis] * static_cast<float>(mSize);
        const int last = static_cast<int>(mSize) - 1;
        const int i = std::clamp(static_cast<int>(std::floor(t)), 0, last);
        candidates[axis][0] = i;
        counts[axis] = 1;
        const float fraction = t - std::floor(t);
        int other = fraction < kTexelEpsilon ? i - 1 : fraction > 1.0f - kTexelEpsilon ? i + 1 : i;
        other = std::clamp(other, 0, last);
        if (other != i) candidates[axis][counts[axis]++] = other;
    }
    bool surelyLit = true, maybeLit = false;
    for (int a = 0; a < counts[0]; ++a) {
        for (int b = 0; b < counts[1]; ++b) {
            const auto x = static_cast<uint32_t>(candidates[0][a]);
            const auto y = static_cast<uint32_t>(candidates[1][b]);
            // The GPU stored a depth between the nearest and the farthest possible.
            const float nearest = mNearFaces[face][size_t{y} * mSize + x];
            for (const float stored : {depth(x, y, face), nearest}) {
                const bool lit = mFlipped ? z >= stored : z <= stored;
                const bool close = std::abs(z - stored) <= kDepthEpsilon;
                surelyLit = surelyLit && lit && !close;
                maybeLit = maybeLit || lit || close;
            }
        }
    }
    return {surelyLit ? 1.0f : 0.0f, maybeLit ? 1.0f : 0.0f};
}

ShadowInterval ShadowMapReference::cubeTap(const glm::vec3& r, float z) const {
    const float major = std::max({std::abs(r.x), std::abs(r.y), std::abs(r.z)});
    ShadowInterval result{1.0f, 0.0f};
    for (size_t face = 0; face < 6; ++face) {
        const CubeFace& f = kCubeFaces[face];
        const float ma = glm::dot(f.ma, r);
        if (ma <= 0.0f || ma < major * (1.0f - kAxisEpsilon)) continue;  // not (near) the major axis
        const glm::vec2 st(0.5f * (glm::dot(f.sc, r) / ma + 1.0f),
                           0.5f * (glm::dot(f.tc, r) / ma + 1.0f));
        const ShadowInterval t = tap(face, st, z);
        result.low = std::min(result.low, t.low);
        result.high = std::max(result.high, t.high);
    }
    return result;
}

ShadowInterval ShadowMapReference::at(const glm::vec3& p, bool soft) const {
    ShadowInterval lit{0.0f, 0.0f};
    if (mCube) {
        // LIGHTING.md §6: the depth the face camera of the major axis gives |vec|, after the bias.
        const glm::vec3 vec = p - mLightPos;
        const float major = std::max({std::abs(vec.x), std::abs(vec.y), std::abs(vec.z)});
        const float m = std::max(1e-5f, major - mProjectionParams.z) * mProjectionParams.w;
        const float z = -mProjectionParams.x + mProjectionParams.y / m;
        if (soft) {
            const float o = 1.0f / 128.0f;
            for (glm::vec3 offset : {glm::vec3(o, o, o), glm::vec3(-o, -o, o),
                                     glm::vec3(-o, o, -o), glm::vec3(o, -o, -o)}) {
                const ShadowInterval t = cubeTap(vec + offset, z);
                lit.low += 0.25f * t.low;
                lit.high += 0.25f * t.high;
            }
        } else {
            lit = cubeTap(vec, z);
        }
    } else {
        const glm::vec4 s = mCamera.worldToShadow * glm::vec4(p, 1.0f);
        const glm::vec3 c = glm::vec3(s) / s.w;
        if (soft) {
            lit = tent(glm::vec2(c) * static_cast<float>(mSize), c.z, 1.5f);
        } else {
            lit = tap(0, glm::vec2(c), c.z);
        }
    }
    const float shadowed = 1.0f - mStrength;
    return {shadowed + mStrength * lit.low, shadowed + mStrength * lit.high};
}

namespace {

// Area left of |x| under a tent of half-width |h| and unit area (Unity's 3- and 7-texel tents).
float tentArea(float x, float h) {
    const float t = std::clamp((x + h) / h, 0.0f, 1.0f);
    const float u = std::clamp((h - x) / h, 0.0f, 1.0f);
    return x <= 0.0f ? 0.5f * t * t : 1.0f - 0.5f * u * u;
}

// How close a view depth may come to a split distance, or a squared distance to a split
// sphere's, before the GPU's rebuilt position could fall in the other cascade.
constexpr float kSplitEpsilon = 1e-4f;

}  // namespace

ShadowInterval ShadowMapReference::tent(const glm::vec2& position, float z, float halfWidth) const {
    const glm::vec2 centre = glm::floor(position + 0.5f);
    const glm::vec2 offset = position - centre;
    // The texels the tent can reach from a centre within half a texel: [-h - 0.5, h + 0.5].
    const int reach = static_cast<int>(std::ceil(halfWidth + 0.5f));
    ShadowInterval lit{0.0f, 0.0f};
    for (int j = -reach; j < reach; ++j) {
        const float wy = tentArea(static_cast<float>(j + 1) - offset.y, halfWidth) -
                         tentArea(static_cast<float>(j) - offset.y, halfWidth);
        for (int i = -reach; i < reach; ++i) {
            const float wx = tentArea(static_cast<float>(i + 1) - offset.x, halfWidth) -
                             tentArea(static_cast<float>(i) - offset.x, halfWidth);
            const float w = wx * wy;
            if (w <= 0.0f) continue;
            // The texel's centre: a tap there is never near a texel boundary.
            const glm::vec2 uv = (centre + glm::vec2(i, j) + 0.5f) / static_cast<float>(mSize);
            const ShadowInterval t = tap(0, uv, z);
            lit.low += w * t.low;
            lit.high += w * t.high;
        }
    }
    return lit;
}

ShadowInterval ShadowMapReference::collect(const glm::vec3& p, float viewZ, bool soft) const {
    const scene::DirectionalShadowSetup& setup = mCascades;
    // Each cascade's test as the collector makes it: `sure` the outcome, `unsure` when the point
    // lies so close to the boundary that the GPU's rebuilt position may fall either side.
    uint32_t sure = 0, unsure = 0;
    for (int c = 0; c < setup.cascades; ++c) {
        bool inside = false, close = false;
        if (setup.stableFit) {
            const glm::vec3 centre(setup.splitSpheres[static_cast<size_t>(c)]);
            const float d2 = glm::dot(p - centre, p - centre), r2 = setup.splitSqRadii[c];
            inside = d2 < r2;
            close = std::abs(d2 - r2) <= kSplitEpsilon * r2;
        } else {
            const float nearZ = setup.splitsNear[c], farZ = setup.splitsFar[c];
            const float slack = kSplitEpsilon * std::max(1.0f, farZ);
            inside = viewZ >= nearZ && viewZ < farZ;
            close = std::abs(viewZ - nearZ) <= slack || std::abs(viewZ - farZ) <= slack;
        }
        if (inside) sure |= 1u << c;
        if (close) unsure |= 1u << c;
    }
    ShadowInterval lit{1.0f, 0.0f};
    // Every outcome the unsure tests allow (at most 2^4).
    for (uint32_t flip = 0; flip < 16; ++flip) {
        if ((flip & ~unsure) != 0) continue;
        const uint32_t inside = sure ^ flip;
        glm::vec3 coord(0.0f);
        if (setup.cascades == 1) {
            // SHADOWS_SINGLE_CASCADE: cascade 0, wherever the point is.
            const glm::vec4 s = setup.worldToShadow[0] * glm::vec4(p, 1.0f);
            coord = glm::vec3(s) / s.w;
        } else {
            // weights: close fit, one per cascade test; stable fit, yzw = saturate(yzw - xyz).
            float previous = 0.0f;
            for (int c = 0; c < setup.cascades; ++c) {
                const float test = (inside >> c) & 1u ? 1.0f : 0.0f;
                const float weight = setup.stableFit ? std::clamp(test - previous, 0.0f, 1.0f) : test;
                previous = test;
                if (weight == 0.0f) continue;
                const glm::vec4 s = setup.worldToShadow[static_cast<size_t>(c)] * glm::vec4(p, 1.0f);
                coord += weight * glm::vec3(s) / s.w;
            }
        }
        const glm::vec2 texels = glm::vec2(coord) * static_cast<float>(mSize);
        const ShadowInterval t =
            soft ? tent(texels, coord.z, 3.5f) : tap(0, glm::vec2(coord), coord.z);
        lit.low = std::min(lit.low, t.low);
        lit.high = std::max(lit.high, t.high);
    }
    const float shadowed = 1.0f - mStrength;
    return {shadowed + mStrength * lit.low, shadowed + mStrength * lit.high};
}

std::vector<ShadowInterval> ShadowMapReference::screenMask(const scene::Scene& scene,
                                                           const std::vector<ShadowCaster>& casters,
                                                           bool soft) const {
    scene::Scene casting = scene;
    casting.objects.clear();
    std::vector<size_t> original;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        if (o < casters.size() && casters[o].casts) {
            casting.objects.push_back(scene.objects[o]);
            original.push_back(o);
        }
    }
    const scene::CameraMatrices camera = scene::cameraMatrices(scene.camera);
    const VisibilityBuffer depth = rasterizeScene(casting, camera);
    const glm::vec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
    std::vector<ShadowInterval> mask(depth.samples.size(), ShadowInterval{1.0f, 1.0f});
    for (size_t i = 0; i < depth.samples.size(); ++i) {
        const SurfaceSample& sample = depth.samples[i];
        if (sample.object < 0) continue;  // the far plane: beyond every cascade, lit
        const size_t index = original[static_cast<size_t>(sample.object)];
        if (casters[index].alphaTest || casters[index].dither) {  // a hole or not: unknown
            mask[i] = {1.0f - mStrength, 1.0f};
            continue;
        }
        const scene::Object& object = scene.objects[index];
        const scene::Mesh& mesh = scene::builtinMesh(object.mesh);
        const glm::mat4 toWorld = object.transform.localToWorld();
        glm::vec3 p(0.0f);
        for (uint32_t k = 0; k < 3; ++k) {
            const glm::vec3 local = mesh.positions[mesh.indices[3 * sample.triangle + k]];
            p += sample.bary[static_cast<glm::length_t>(k)] * glm::vec3(toWorld * glm::vec4(local, 1.0f));
        }
        mask[i] = collect(p, glm::dot(p - scene.camera.position, forward), soft);
    }
    return mask;
}

ShadowInterval ShadowFade::apply(const ShadowInterval& realtime, const glm::vec3& p) const {
    const float viewDepth = glm::dot(p - cameraPos, cameraForward);
    const float fade = std::clamp(viewDepth * scale + offset, 0.0f, 1.0f);
    return {std::clamp(realtime.low + fade, 0.0f, 1.0f), std::clamp(realtime.high + fade, 0.0f, 1.0f)};
}

ShadowFade shadowFadeFor(const scene::Scene& scene, const scene::Light& light) {
    const glm::vec4 data = scene::lightShadowData(light, scene);
    ShadowFade fade;
    fade.cameraPos = scene.camera.position;
    fade.cameraForward = glm::normalize(scene.camera.target - scene.camera.position);
    fade.scale = data.z;
    fade.offset = data.w;
    return fade;
}

}  // namespace varc::reference
