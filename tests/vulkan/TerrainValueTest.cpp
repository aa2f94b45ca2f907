// SPDX-License-Identifier: Apache-2.0
// Value tests of TerrainEngine.cginc's vegetation helpers and TerrainPreview.cginc's paint-context
// maps (issue #27, docs/BUILTIN_API.md): each group runs on lavapipe over a grid of inputs
// (tests/vulkan/helpers/TerrainValues.shader, pixel centre (u, v) as input) with the engine's or
// the terrain tool's uniforms set here, and is compared with the documented meaning computed on
// the CPU: billboards span the camera's right and up vectors, grass past the cut-off distance
// collapses, the soft-occlusion bend is the bend matrix blended by alpha then squashed towards
// the squash plane, the main wind bending of GPU Gems 3 (chapter 16) keeps the vertex's distance
// to the origin, and the tool's maps are affine in paint-context pixels. scripts/builtin-api.py
// counts the functions named on the api-value-tested lines below as implemented.
//
// api-value-tested: FastSinCos TerrainBillboardGrass TerrainBillboardTree TerrainAnimateTree
// api-value-tested: ExpandBillboard AnimateVertex BuildProceduralQuadMeshVertex
// api-value-tested: PaintContextPixelsToHeightmapUV PaintContextPixelsToObjectPosition
// api-value-tested: TerrainObjectToWorldPosition SplatmapMix SplatmapFinalColor
// api-value-tested: SplatmapFinalPrepass SplatmapFinalGBuffer
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/scene/LightTextures.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, double t) { return a + (b - a) * t; }

class TerrainValueTest : public testing::QuadDrawTest {
protected:
    TerrainValueTest() : QuadDrawTest(kSize) {}

    void expectFormula(const std::string& keyword, const ShaderValues& values,
                       const Formula& formula, int channels, double absolute, double relative) {
        const BuiltinTextures& builtin = *mTextures;
        // The splat map: the falloff table as control texture over black, white, red and gray
        // layers.
        TextureLookup textures = [&builtin](std::string_view name, pack::ResourceDim dim) {
            if (name == "_Control") return std::optional(builtin.falloff());
            const char* layers[4] = {"black", "white", "red", "gray"};
            for (int i = 0; i < 4; ++i) {
                if (name == "_Splat" + std::to_string(i)) return builtin.named(layers[i], dim);
            }
            return builtin.named("white", dim);
        };
        expectPassFormula("Test/TerrainValues", keyword, values, textures, formula, channels,
                          absolute, relative);
    }
};

TEST_F(TerrainValueTest, SineAndCosine) {
    expectFormula(
        "TE_SINCOS", {},
        [](double u, double v) {
            return Vec4{std::sin(6 * u - 3), std::cos(10 * v), 1.0,
                        std::sin(-20 * u) * std::cos(-20 * u)};
        },
        4, 2e-5, 1e-4);
}

// Grass: pos + offset.x * right + offset.y * up, offset zero beyond sqrt(_WaveAndDistance.w).
TEST_F(TerrainValueTest, GrassBillboard) {
    ShaderValues values;
    values.set("_CameraPosition", glm::vec4(0.0f, 1.0f, 0.0f, 0.1f));
    values.set("_WaveAndDistance", glm::vec4(0.0f, 0.0f, 0.0f, 40.0f));
    values.set("_CameraRight", glm::vec4(0.6f, 0.0f, 0.8f, 0.0f));
    values.set("_CameraUp", glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    expectFormula(
        "TE_GRASS", values,
        [](double u, double v) {
            glm::dvec3 p(10 * u, 1, 10 * v), right(0.6, 0, 0.8), up(0, 1, 0);
            bool near = 100 * (u * u + v * v) <= 40;
            if (near) p += u * right + (v - 0.5) * up;
            return Vec4{p.x, p.y, p.z, 1.0};
        },
        4, 1e-5, 1e-5);
}

// Tree billboards: right * offset.x + up * lerp(offset.y, offsetz, front.w) + front * offsetz *
// up.w, w = 1.
TEST_F(TerrainValueTest, TreeBillboard) {
    ShaderValues values;
    values.set("_TreeBillboardCameraRight", glm::vec4(1.0f, 0.0f, 0.5f, 0.0f));
    values.set("_TreeBillboardCameraUp", glm::vec4(0.0f, 1.0f, 0.0f, 0.3f));
    values.set("_TreeBillboardCameraFront", glm::vec4(0.0f, 0.0f, 1.0f, 0.25f));
    expectFormula(
        "TE_TREE", values,
        [](double u, double v) {
            glm::dvec3 p(u, v, 2.0), right(1, 0, 0.5), up(0, 1, 0), front(0, 0, 1);
            double oz = 0.5 + u;
            p += right * (u - 0.5) + up * (v + (oz - v) * 0.25) + front * (oz * 0.3);
            return Vec4{p.x, p.y, p.z, 1.0};
        },
        4, 1e-5, 1e-5);
}

// Soft-occlusion trees: lerp(pos, bendMatrix * (pos, 0), alpha), then squashed towards the plane
// (normal n, offset w) by _SquashAmount (1 = unchanged, 0 = on the plane).
TEST_F(TerrainValueTest, TreeBendAndSquash) {
    glm::mat4 bend(1.0f);
    bend[0] = glm::vec4(0.8f, 0.1f, -0.6f, 0.0f);  // columns: bend * p = sum p_i * column_i
    bend[1] = glm::vec4(0.0f, 1.2f, 0.0f, 0.0f);
    bend[2] = glm::vec4(0.6f, -0.2f, 0.8f, 0.0f);
    ShaderValues values;
    values.set("_TerrainEngineBendTree", bend);
    values.set("_SquashPlaneNormal", glm::vec4(0.0f, 0.8f, 0.6f, -0.5f));
    values.set("_SquashAmount", 0.25f);
    expectFormula(
        "TE_BEND", values,
        [bend](double u, double v) {
            glm::dvec3 p(u, 2 * v, 1 - u), n(0, 0.8, 0.6);
            glm::dvec3 bent = glm::dvec3(glm::dmat4(bend) * glm::dvec4(p, 0.0));
            p = lerp(p, bent, v);
            glm::dvec3 onPlane = p - (glm::dot(p, n) - 0.5) * n;
            p = lerp(onPlane, p, 0.25);
            return Vec4{p.x, p.y, p.z, 1.0};
        },
        4, 1e-5, 1e-4);
}

// Leaf billboards (tangent.w = 0): pos moves by (normal.xy, 0, 0) taken through the matrix as a
// row vector, normal and tangent become their normalised transforms; other vertices keep all.
TEST_F(TerrainValueTest, ExpandLeafBillboard) {
    expectFormula(
        "TE_EXPAND", {},
        [](double u, double v) {
            glm::dvec3 n(u - 0.5, v, 0.25);
            if (u >= 0.5) return Vec4{u, v + 0.5, n.x, 1.0};
            // Row vector (x, y, z) times the shader's matrix is (-y, 2x, z).
            auto through = [](const glm::dvec3& a) { return glm::dvec3(-a.y, 2 * a.x, a.z); };
            glm::dvec3 p = glm::dvec3(u, v, 0.5) + through(glm::dvec3(n.x, n.y, 0));
            return Vec4{p.x, p.y + p.z, glm::normalize(through(n)).x, 0.0};
        },
        4, 1e-5, 1e-4);
}

// Main bending (GPU Gems 3, 16.3.2): f = (1 + y * bendScale)^2, f = f^2 - f; xz += wind.xz *
// strength * f; the result is rescaled to the original length. bendScale = animParams.z * 0.0025.
TEST_F(TerrainValueTest, MainWindBending) {
    ShaderValues values;
    values.set("_Wind", glm::vec4(0.6f, 0.0f, 0.8f, 1.5f));
    expectFormula(
        "TE_WIND", values,
        [](double u, double v) {
            glm::dvec3 p(2 * u - 1, 10 * v, 0.5);
            double f = 1 + p.y * (2 + 4 * u) * 0.0025;
            f *= f;
            f = f * f - f;
            glm::dvec3 moved = p + glm::dvec3(0.6, 0, 0.8) * (1.5 * f);
            glm::dvec3 q = glm::normalize(moved) * glm::length(p);
            return Vec4{q.x, q.y, q.z, 0.0};
        },
        4, 2e-5, 1e-4);
}

// The preview grid: vertex id -> quad id / 6 (row-major, _QuadRez.x quads per row) + corner
// id % 6 of the triangles (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1); the tool's maps are
// p.x * X + p.y * Y (+ height * H) + offset, and object to world adds the terrain's offset.
TEST_F(TerrainValueTest, PreviewMaps) {
    ShaderValues values;
    values.set("_QuadRez", glm::vec4(5.0f, 3.0f, 0.0f, 0.0f));
    values.set("_HeightmapUV_PCPixelsX", glm::vec4(0.01f, 0.002f, 0.0f, 0.0f));
    values.set("_HeightmapUV_PCPixelsY", glm::vec4(-0.003f, 0.02f, 0.0f, 0.0f));
    values.set("_HeightmapUV_Offset", glm::vec4(0.1f, -0.2f, 0.0f, 0.0f));
    expectFormula(
        "TE_MESH", values,
        [](double u, double v) {
            static const double corners[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
            unsigned id = static_cast<unsigned>(u * 32) * 32 + static_cast<unsigned>(v * 32);
            unsigned quad = id / 6;
            double px = 64 * u, py = 64 * v;
            return Vec4{quad % 5 + corners[id % 6][0], quad / 5 + corners[id % 6][1],
                        px * 0.01 - py * 0.003 + 0.1, px * 0.002 + py * 0.02 - 0.2};
        },
        4, 1e-5, 1e-5);
    values.set("_ObjectPos_PCPixelsX", glm::vec4(0.5f, 0.0f, 0.01f, 0.0f));
    values.set("_ObjectPos_PCPixelsY", glm::vec4(0.0f, 0.02f, 0.5f, 0.0f));
    values.set("_ObjectPos_HeightMapSample", glm::vec4(0.0f, 2.0f, 0.0f, 0.0f));
    values.set("_ObjectPos_Offset", glm::vec4(1.0f, 2.0f, 3.0f, 0.0f));
    expectFormula(
        "TE_OBJECT", values,
        [](double u, double v) {
            double px = 64 * u, py = 64 * v, h = 0.5 * v;
            return Vec4{px * 0.5 + 1, py * 0.02 + h * 2 + 2, px * 0.01 + py * 0.5 + 3, 0};
        },
        4, 1e-5, 1e-5);
    values.set("_TerrainObjectToWorldOffset", glm::vec4(10.0f, -5.0f, 2.5f, 0.0f));
    expectFormula(
        "TE_WORLD", values,
        [](double u, double v) {
            return Vec4{u + 10, v - 5, u * v + 2.5, 0};
        },
        4, 1e-5, 1e-5);
}

// The splat mix: control texel c (each channel f, the falloff at u), weight = sum c, layers
// weighted by c / (weight + 1e-3); the final hooks multiply colour, prepass normal-specular and
// every G-buffer target by o.Alpha.
TEST_F(TerrainValueTest, SplatmapMix) {
    static const std::vector<uint16_t> table = scene::falloffTable();
    expectFormula(
        "TE_SPLAT", {},
        [](double u, double v) {
            double f = scene::sampleFalloffTable(table, static_cast<float>(u));
            double c = f / (4 * f + 1e-3), gray = 128.0 / 255.0, alpha = 0.25 + 0.5 * v;
            return Vec4{c * (2 + gray) + 40 * f, c * (1 + gray) + 10 * c, alpha, 15 * alpha};
        },
        4, 3e-3, 1e-3);
}

}  // namespace
}  // namespace varc::render
