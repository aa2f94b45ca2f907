// SPDX-License-Identifier: Apache-2.0
// Rasterizer: clipping, Vulkan fill rules, perspective-correct barycentrics, visibility and
// pixel classification.
#include "varc/reference/Rasterizer.h"

#include <algorithm>
#include <cmath>

#include "varc/scene/Mesh.h"

namespace varc::reference {
namespace {

constexpr double kSubPixels = 256.0;  // lavapipe's 8 sub-pixel bits (subPixelPrecisionBits)

struct ClipVertex {
    glm::vec4 clip;
    glm::vec3 bary;
};

// Sutherland-Hodgman against the plane where |distance|(v) >= 0.
template <typename D>
std::vector<ClipVertex> clipAgainst(const std::vector<ClipVertex>& in, D distance) {
    std::vector<ClipVertex> out;
    for (size_t i = 0; i < in.size(); ++i) {
        const ClipVertex& a = in[i];
        const ClipVertex& b = in[(i + 1) % in.size()];
        const float da = distance(a.clip), db = distance(b.clip);
        if (da >= 0.0f) out.push_back(a);
        if ((da >= 0.0f) != (db >= 0.0f)) {
            const float t = da / (da - db);
            out.push_back({a.clip + (b.clip - a.clip) * t, a.bary + (b.bary - a.bary) * t});
        }
    }
    return out;
}

struct ScreenVertex {
    int64_t x, y;  // sub-pixel fixed point
    double z, invW;
    glm::dvec3 bary;
};

ScreenVertex toScreen(const ClipVertex& v, uint32_t width, uint32_t height) {
    const double invW = 1.0 / static_cast<double>(v.clip.w);
    const double sx = (static_cast<double>(v.clip.x) * invW + 1.0) * 0.5 * width;
    const double sy = (static_cast<double>(v.clip.y) * invW + 1.0) * 0.5 * height;
    return {std::llround(sx * kSubPixels), std::llround(sy * kSubPixels),
            static_cast<double>(v.clip.z) * invW, invW, glm::dvec3(v.bary)};
}

// Edge function of edge a -> b at p; > 0 inside for triangles with positive |area|.
int64_t edge(const ScreenVertex& a, const ScreenVertex& b, int64_t px, int64_t py) {
    return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

// Top-left rule for a triangle that is clockwise in y-down framebuffer space (positive area):
// a top edge runs exactly horizontally to the right, a left edge runs upwards.
bool isTopLeft(const ScreenVertex& a, const ScreenVertex& b) {
    const int64_t dx = b.x - a.x, dy = b.y - a.y;
    return (dy == 0 && dx > 0) || dy < 0;
}

void rasterizeScreenTriangle(std::array<ScreenVertex, 3> v, uint32_t width, uint32_t height,
                             CullMode cull, const FragmentFn& emit) {
    // Shoelace sum in y-down coordinates; Vulkan's area a = -sum/2, front (clockwise) when a < 0.
    int64_t area = 0;
    for (int i = 0; i < 3; ++i) area += v[i].x * v[(i + 1) % 3].y - v[(i + 1) % 3].x * v[i].y;
    if (area == 0) return;
    if (cull == CullMode::Front && area > 0) return;
    if (area < 0) {
        if (cull == CullMode::Back) return;
        std::swap(v[1], v[2]);
        area = -area;
    }
    const auto sub = static_cast<int64_t>(kSubPixels);
    int64_t minX = std::min({v[0].x, v[1].x, v[2].x}), maxX = std::max({v[0].x, v[1].x, v[2].x});
    int64_t minY = std::min({v[0].y, v[1].y, v[2].y}), maxY = std::max({v[0].y, v[1].y, v[2].y});
    // Pixel x covers centre x*sub + sub/2.
    const int64_t x0 = std::max<int64_t>(0, (minX - sub / 2) / sub);
    const int64_t x1 = std::min<int64_t>(width - 1, (maxX - sub / 2) / sub + 1);
    const int64_t y0 = std::max<int64_t>(0, (minY - sub / 2) / sub);
    const int64_t y1 = std::min<int64_t>(height - 1, (maxY - sub / 2) / sub + 1);
    const bool topLeft[3] = {isTopLeft(v[0], v[1]), isTopLeft(v[1], v[2]), isTopLeft(v[2], v[0])};
    for (int64_t y = y0; y <= y1; ++y) {
        const int64_t py = y * sub + sub / 2;
        for (int64_t x = x0; x <= x1; ++x) {
            const int64_t px = x * sub + sub / 2;
            const int64_t e[3] = {edge(v[0], v[1], px, py), edge(v[1], v[2], px, py),
                                  edge(v[2], v[0], px, py)};
            bool inside = true;
            for (int i = 0; i < 3; ++i) inside = inside && (e[i] > 0 || (e[i] == 0 && topLeft[i]));
            if (!inside) continue;
            // Screen-space weights: vertex k is opposite edge k+1.
            const double l0 = static_cast<double>(e[1]) / static_cast<double>(area);
            const double l1 = static_cast<double>(e[2]) / static_cast<double>(area);
            const double l2 = 1.0 - l0 - l1;
            const double q0 = l0 * v[0].invW, q1 = l1 * v[1].invW, q2 = l2 * v[2].invW;
            const glm::dvec3 bary =
                (q0 * v[0].bary + q1 * v[1].bary + q2 * v[2].bary) / (q0 + q1 + q2);
            Fragment f;
            f.x = static_cast<uint32_t>(x);
            f.y = static_cast<uint32_t>(y);
            f.depth = static_cast<float>(l0 * v[0].z + l1 * v[1].z + l2 * v[2].z);
            f.bary = glm::vec3(bary);
            emit(f);
        }
    }
}

}  // namespace

void rasterizeTriangle(const std::array<glm::vec4, 3>& clip, uint32_t width, uint32_t height,
                       CullMode cull, const FragmentFn& emit) {
    // A vertex that is not a finite point draws nothing (Vulkan leaves such triangles undefined).
    for (const glm::vec4& c : clip) {
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) || !std::isfinite(c.w))
            return;
    }
    std::vector<ClipVertex> polygon = {
        {clip[0], {1, 0, 0}}, {clip[1], {0, 1, 0}}, {clip[2], {0, 0, 1}}};
    polygon = clipAgainst(polygon, [](const glm::vec4& c) { return c.z; });
    polygon = clipAgainst(polygon, [](const glm::vec4& c) { return c.w - c.z; });
    if (polygon.size() < 3) return;
    std::vector<ScreenVertex> screen;
    for (const ClipVertex& v : polygon) screen.push_back(toScreen(v, width, height));
    for (size_t i = 1; i + 1 < screen.size(); ++i) {
        rasterizeScreenTriangle({screen[0], screen[i], screen[i + 1]}, width, height, cull, emit);
    }
}

VisibilityBuffer rasterizeScene(const scene::Scene& scene, const scene::CameraMatrices& camera,
                                const std::vector<bool>& drawn) {
    VisibilityBuffer buffer;
    buffer.width = scene.camera.width;
    buffer.height = scene.camera.height;
    buffer.samples.assign(size_t{buffer.width} * buffer.height, SurfaceSample{});
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        if (o < drawn.size() && !drawn[o]) continue;
        const scene::Object& object = scene.objects[o];
        const scene::Mesh& mesh = scene::builtinMesh(object.mesh);
        const glm::mat4 toWorld = object.transform.localToWorld();
        const glm::mat4 mvp = camera.viewProjection * toWorld;
        // A mirrored object's triangles turn over on screen: its back-face cull culls front faces.
        const CullMode cull = glm::determinant(toWorld) < 0.0f ? CullMode::Front : CullMode::Back;
        std::vector<glm::vec4> clip;
        clip.reserve(mesh.positions.size());
        for (const glm::vec3& p : mesh.positions) clip.push_back(mvp * glm::vec4(p, 1.0f));
        for (size_t t = 0; t * 3 < mesh.indices.size(); ++t) {
            const std::array<glm::vec4, 3> tri = {clip[mesh.indices[3 * t]],
                                                  clip[mesh.indices[3 * t + 1]],
                                                  clip[mesh.indices[3 * t + 2]]};
            rasterizeTriangle(tri, buffer.width, buffer.height, cull, [&](const Fragment& f) {
                SurfaceSample& s = buffer.samples[size_t{f.y} * buffer.width + f.x];
                if (f.depth <= s.depth) {
                    s = {static_cast<int>(o), static_cast<uint32_t>(t), f.bary, f.depth};
                }
            });
        }
    }
    return buffer;
}

Classification classifyPixels(const scene::Scene& scene, const VisibilityBuffer& visibility) {
    const uint32_t w = visibility.width, h = visibility.height;
    // The smooth group of the surface at pixel |i|: two neighbours of one object in different
    // groups straddle a crease.
    auto group = [&](size_t i) {
        const SurfaceSample& s = visibility.samples[i];
        return scene::builtinMesh(scene.objects[s.object].mesh).smoothGroups[s.triangle];
    };
    Classification out;
    out.width = w;
    out.height = h;
    out.classes.resize(size_t{w} * h);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const size_t i = size_t{y} * w + x;
            const int object = visibility.samples[i].object;
            bool edge = false;
            for (int dy = -1; dy <= 1 && !edge; ++dy) {
                for (int dx = -1; dx <= 1 && !edge; ++dx) {
                    const int64_t nx = int64_t{x} + dx, ny = int64_t{y} + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const size_t j = static_cast<size_t>(ny) * w + static_cast<size_t>(nx);
                    edge = visibility.samples[j].object != object ||
                           (object >= 0 && group(i) != group(j));
                }
            }
            out.classes[i] = edge ? PixelClass::Edge
                                  : (object >= 0 ? PixelClass::Interior : PixelClass::Background);
        }
    }
    return out;
}

}  // namespace varc::reference
