// SPDX-License-Identifier: Apache-2.0
// rasterizeTriangle: coverage with the top-left rule, culling, clipping, perspective-correct
// barycentrics; classifyPixels.
#include <limits>
#include <map>

#include <gtest/gtest.h>

#include "varc/reference/Rasterizer.h"

namespace varc::reference {
namespace {

// Clip-space vertex (w = 1) at framebuffer position (sx, sy) of a |size| x |size| target.
glm::vec4 at(float sx, float sy, float size, float z = 0.5f) {
    return {sx / size * 2.0f - 1.0f, sy / size * 2.0f - 1.0f, z, 1.0f};
}

std::vector<Fragment> raster(const std::array<glm::vec4, 3>& tri, uint32_t size, CullMode cull) {
    std::vector<Fragment> out;
    rasterizeTriangle(tri, size, size, cull, [&](const Fragment& f) { out.push_back(f); });
    return out;
}

// (0,0), (8,0), (0,8) in y-down pixels is clockwise on screen: a front face. Pixel centres
// (x + .5, y + .5) are inside when x + y < 7; x + y = 7 lies on the hypotenuse, which runs down
// and to the left (neither top nor left edge), so it is excluded: 1 + 2 + ... + 7 = 28 pixels.
TEST(Rasterizer, CoversKnownTriangleWithTopLeftRule) {
    const auto frags = raster({at(0, 0, 8), at(8, 0, 8), at(0, 8, 8)}, 8, CullMode::Back);
    EXPECT_EQ(frags.size(), 28u);
    for (const Fragment& f : frags) EXPECT_LT(f.x + f.y, 7u);
}

TEST(Rasterizer, CullsCounterClockwiseTriangles) {
    EXPECT_TRUE(raster({at(0, 0, 8), at(0, 8, 8), at(8, 0, 8)}, 8, CullMode::Back).empty());
    EXPECT_EQ(raster({at(0, 0, 8), at(0, 8, 8), at(8, 0, 8)}, 8, CullMode::None).size(), 28u);
}

TEST(Rasterizer, CullFrontDropsClockwiseTrianglesAndKeepsCounterClockwiseOnes) {
    EXPECT_TRUE(raster({at(0, 0, 8), at(8, 0, 8), at(0, 8, 8)}, 8, CullMode::Front).empty());
    EXPECT_EQ(raster({at(0, 0, 8), at(0, 8, 8), at(8, 0, 8)}, 8, CullMode::Front).size(), 28u);
}

// A square split along a diagonal through pixel centres: every pixel exactly once.
TEST(Rasterizer, SharedEdgeCoversEachPixelOnce) {
    std::map<std::pair<uint32_t, uint32_t>, int> hits;
    for (const auto& tri : {std::array<glm::vec4, 3>{at(0, 0, 8), at(8, 0, 8), at(8, 8, 8)},
                            std::array<glm::vec4, 3>{at(0, 0, 8), at(8, 8, 8), at(0, 8, 8)}}) {
        for (const Fragment& f : raster(tri, 8, CullMode::Back)) ++hits[{f.x, f.y}];
    }
    EXPECT_EQ(hits.size(), 64u);
    for (const auto& [pixel, count] : hits) EXPECT_EQ(count, 1) << pixel.first << "," << pixel.second;
}

// Interpolating the clip positions with the returned weights must reproject to the pixel centre
// (perspective-correct), and give the fragment's depth.
TEST(Rasterizer, BarycentricsArePerspectiveCorrect) {
    const std::array<glm::vec4, 3> tri = {glm::vec4(-2.0f, -1.0f, 0.2f, 2.0f), glm::vec4(3.0f, -2.5f, 2.0f, 4.0f),
                                          glm::vec4(-1.0f, 5.0f, 5.0f, 6.0f)};
    const auto frags = raster(tri, 32, CullMode::None);
    ASSERT_GT(frags.size(), 50u);
    for (const Fragment& f : frags) {
        const glm::vec4 c = f.bary.x * tri[0] + f.bary.y * tri[1] + f.bary.z * tri[2];
        EXPECT_NEAR((c.x / c.w + 1.0f) * 16.0f, static_cast<float>(f.x) + 0.5f, 2e-3f);
        EXPECT_NEAR((c.y / c.w + 1.0f) * 16.0f, static_cast<float>(f.y) + 0.5f, 2e-3f);
        EXPECT_NEAR(c.z / c.w, f.depth, 1e-4f);
        EXPECT_NEAR(f.bary.x + f.bary.y + f.bary.z, 1.0f, 1e-5f);
    }
}

// A triangle crossing the near plane (z < 0 at one vertex) is clipped: no depth below 0.
TEST(Rasterizer, ClipsAgainstNearPlane) {
    const std::array<glm::vec4, 3> tri = {glm::vec4(-1, -1, -0.5f, 1), glm::vec4(1, -1, 0.5f, 1),
                                          glm::vec4(-1, 1, 0.5f, 1)};
    const auto frags = raster(tri, 16, CullMode::None);
    ASSERT_FALSE(frags.empty());
    for (const Fragment& f : frags) EXPECT_GE(f.depth, -1e-6f);
    // Unclipped it would cover about half of 256 pixels; the z < 0 corner is cut away.
    EXPECT_LT(frags.size(), 120u);
}

TEST(Rasterizer, ClassifiesSphereEdgesAndInterior) {
    scene::Scene s;
    s.camera.width = s.camera.height = 64;
    s.objects.push_back(scene::Object{});
    const VisibilityBuffer vis = rasterizeScene(s, scene::cameraMatrices(s.camera));
    const Classification c = classifyPixels(s, vis);
    EXPECT_EQ(c.at(0, 0), PixelClass::Background);
    EXPECT_EQ(c.at(32, 32), PixelClass::Interior);
    // Projected radius: 0.5 / sqrt(25 - 0.25) / tan(30°) * 32 = 5.57 px; pixel 37 is near the rim.
    size_t covered = 0;
    for (const SurfaceSample& sample : vis.samples) covered += sample.object == 0 ? 1 : 0;
    EXPECT_NEAR(static_cast<double>(covered), 3.14159 * 5.57 * 5.57, 10.0);
    for (uint32_t y = 0; y < 64; ++y) {
        for (uint32_t x = 0; x < 64; ++x) {
            if (c.at(x, y) != PixelClass::Edge) continue;
            // Each edge pixel has a covered and an uncovered pixel in its 3 x 3 neighbourhood.
            bool in = false, out = false;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const bool cov = vis.at(x + dx, y + dy).object == 0;
                    in = in || cov;
                    out = out || !cov;
                }
            }
            EXPECT_TRUE(in && out) << x << "," << y;
        }
    }
}

TEST(Rasterizer, CubeCreasesAreEdges) {
    scene::Scene s;
    s.camera.width = s.camera.height = 64;
    s.camera.position = {2, 2, -3};
    scene::Object cube;
    cube.mesh = scene::MeshKind::Cube;
    s.objects.push_back(cube);
    const VisibilityBuffer vis = rasterizeScene(s, scene::cameraMatrices(s.camera));
    const Classification c = classifyPixels(s, vis);
    // Two covered neighbours on different faces (different triangles' normals) are edges.
    int creases = 0;
    for (uint32_t y = 1; y < 63; ++y) {
        for (uint32_t x = 1; x < 63; ++x) {
            const SurfaceSample &a = vis.at(x, y), &b = vis.at(x + 1, y);
            if (a.object == 0 && b.object == 0 && a.triangle / 2 != b.triangle / 2) {
                ++creases;
                EXPECT_EQ(c.at(x, y), PixelClass::Edge);
            }
        }
    }
    EXPECT_GT(creases, 5);
}

TEST(Rasterizer, AVertexThatIsNotAFinitePointDrawsNothing) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (glm::vec4 bad : {glm::vec4(0.0f, 0.0f, nan, 1.0f), glm::vec4(inf, 0.0f, 0.5f, 1.0f)}) {
        int fragments = 0;
        rasterizeTriangle({glm::vec4(-1, -1, 0.5f, 1), glm::vec4(1, -1, 0.5f, 1), bad}, 8, 8,
                          CullMode::None, [&](const Fragment&) { ++fragments; });
        EXPECT_EQ(fragments, 0);
    }
}

}  // namespace
}  // namespace varc::reference
