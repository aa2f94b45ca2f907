// SPDX-License-Identifier: Apache-2.0
// Value tests of varc's SpeedTree include files (shaders/builtin/SpeedTree*.cginc, issue #27):
// each group runs on lavapipe over a grid of inputs (tests/vulkan/helpers/SpeedTreeValues.shader,
// pixel centre (u, v) as input) and is compared with the formula documented in the include files
// computed here, or with a property of it (a calm tree does not move; rotations keep lengths; a
// billboard faces the camera).
//
// api-value-tested: TriangleWave CubicSmooth TrigApproximate UnpackNormalFromFloat RotationMatrix
// api-value-tested: mul_float3x3_float3 mul_float3x3_float3x3 wind_cross Roll Twitch Turbulence
// api-value-tested: Oscillate SimpleBranchWind DirectionalBranchWind GlobalWind LeafRipple
// api-value-tested: RippleFrondOneSided LeafTumble RippleFrondTwoSided RippleFrond BranchWind
// api-value-tested: DirectionalBranchWindFrondStyle LeafWind
#include "SpeedTreeValueTest.h"

namespace varc::render::speedtree {
namespace {

// TriangleWave, CubicSmooth and TrigApproximate = 2 CubicSmooth(TriangleWave(x)) - 1.
TEST_F(SpeedTreeValueTest, Waves) {
    expectFormula("ST_WAVES",
                  [](double u, double v) {
                      return Vec4{trig(3.0 * u - 1.0), triangleWave(2.5 * v), cubicSmooth(v),
                                  trig(4.0 * u * v)};
                  },
                  4, 1e-5, 1e-4, {});
}

// frac(value / (16, 1, 1/16)) * 2 - 1.
TEST_F(SpeedTreeValueTest, UnpackNormalFromFloat) {
    expectFormula("ST_UNPACK",
                  [](double u, double) {
                      Vec3 d = unpackDirection(15.99 * u);
                      return Vec4{d[0], d[1], d[2], 0.0};
                  },
                  3, 2e-4, 1e-4, {});
}

// Rodrigues' rotation; composing two turns about one axis adds the angles; wind_cross = cross.
TEST_F(SpeedTreeValueTest, RotationMatrices) {
    auto axis = [](double u, double v) { return normalized({u - 0.5, 1.0, v - 0.5}); };
    expectFormula("ST_ROTATE",
                  [&](double u, double v) {
                      Vec3 vec{1.0, 2.0 * v, -0.5};
                      Vec3 r = rotate(axis(u, v), 6.0 * u - 3.0, vec);
                      return Vec4{r[0], r[1], r[2], cross(vec, axis(u, v))[0]};
                  },
                  4, 1e-5, 1e-4, {});
    expectFormula("ST_COMPOSE",
                  [&](double u, double v) {
                      Vec3 vec{1.0, 2.0 * v, -0.5};
                      Vec3 r = rotate(axis(u, v), 2.0 * v + 1.0 - u, vec);
                      return Vec4{r[0], r[1], r[2], cross(vec, axis(u, v))[2]};
                  },
                  4, 1e-5, 1e-4, {});
}

TEST_F(SpeedTreeValueTest, RollTwitchTurbulence) {
    expectFormula("ST_ROLL_TWITCH",
                  [](double u, double v) {
                      Vec3 p = position(u, v);
                      return Vec4{roll(1.3, 1.2, 0.4, 0.8, 0.3, p, 5.0 * v, kWind),
                                  twitch(p, 0.9, v, 3.0 * u), turbulence(2.0 * u, v, 7.0 * v, 0.6),
                                  0.0};
                  },
                  3, 1e-4, 1e-3, {});
}

TEST_F(SpeedTreeValueTest, Oscillate) {
    expectFormula(
        "ST_OSCILLATE",
        [](double u, double v) {
            Vec3 p = position(u, v);
            Vec4 waves, plainWaves;
            double full = oscillate(p, 3.0 * u, v, 0.7, 0.5, true, true, true, 0.4, 1.7, waves);
            double plain =
                oscillate(p, 3.0 * u, v, 0.7, 0.5, false, false, false, 0.4, 1.7, plainWaves);
            return Vec4{full, waves[1], waves[3], plain};
        },
        4, 1e-4, 1e-3, windValues());
}

// Simple: p + wind * weight * distance * oscillation; directional: the bend is adherence plus
// the rest oscillating, weakened by turbulence.
TEST_F(SpeedTreeValueTest, BranchWind) {
    expectFormula(
        "ST_BRANCH",
        [](double u, double v) {
            Vec3 p = position(u, v);
            double phase = u + instancePhase(kInstance);
            Vec4 waves;
            double o = oscillate(p, 2.3, phase, v, 0.4, true, false, true, 0.3, 1.9, waves);
            Vec3 simple = add(p, kWind, v * 0.8 * o);
            double bend = 0.35 + 0.65 * o * turbulence(2.3, phase, kGlobal[0], 0.5);
            return Vec4{simple[0], simple[1], simple[2], p[2] + kWind[2] * v * 0.8 * bend};
        },
        4, 1e-4, 1e-3, windValues());
}

// The global bend is horizontal and downwind; preserving the shape keeps the distance from the
// base (a bend, not a stretch).
TEST_F(SpeedTreeValueTest, GlobalWind) {
    ShaderValues values = windValues();
    expectFormula(
        "ST_GLOBAL",
        [](double u, double v) {
            Vec3 bent = globalWind(position(u, v), false, 1.7 * u);
            return Vec4{bent[0], bent[1], bent[2], length(position(u, v))};
        },
        4, 1e-4, 1e-4, values);
    expectFormula(
        "ST_GLOBAL_SHAPE",
        [](double u, double v) {
            Vec3 bent = globalWind(position(u, v), true, 1.7 * u);
            return Vec4{bent[0], bent[1], bent[2], 0.0};
        },
        3, 1e-4, 1e-4, values);
    image::Image image = run("ST_GLOBAL", values);
    ASSERT_EQ(image.width(), kSize);
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) {
            Vec3 p = position((x + 0.5) / kSize, (y + 0.5) / kSize);
            std::array<float, 4> got = image.pixelFloat(x, y);
            Vec3 moved = add({got[0], got[1], got[2]}, p, -1.0);
            EXPECT_NEAR(got[1], p[1], 1e-5) << "pixel " << x << ", " << y << " moved up or down";
            EXPECT_GE(dot(moved, kWind), -1e-5) << "pixel " << x << ", " << y << " went upwind";
        }
    }
}

// Leaf ripple along the packed direction (or the normal); one-sided frond ripple along the
// normal, more towards the edges, the normal tilting along the binormal.
TEST_F(SpeedTreeValueTest, LeafAndFrondRipple) {
    expectFormula("ST_LEAF",
                  [](double u, double v) {
                      Vec3 p = position(u, v);
                      double offset = 0.8 * 0.5 * trig(2.0 * v + u);
                      Vec3 rippled = add(p, unpackDirection(7.3 + u), offset);
                      return Vec4{rippled[0], rippled[1], rippled[2], p[1] + offset};
                  },
                  4, 1e-4, 1e-4, {});
    expectFormula(
        "ST_FROND",
        [](double u, double v) {
            Vec3 p = position(u, v);
            double phase = kFrond[0] + v * kFrond[2], edge = 2.0 * std::abs(u - 0.5);
            double amplitude = 0.7 * kFrond[1] * edge;
            return Vec4{p[0], p[1], p[2] + amplitude * trig(phase),
                        amplitude * trig(phase + 0.25) * kFrond[2]};
        },
        4, 1e-4, 1e-4, windValues());
}

// A frond with a packed ripple direction ripples two-sided along it, more towards its tip (the
// length percentage), the normal tilting along the tangent.
TEST_F(SpeedTreeValueTest, TwoSidedFrondRipple) {
    expectFormula(
        "ST_FROND2",
        [](double u, double v) {
            Vec3 p = position(u, v);
            double phase = kFrond[0] + u * kFrond[2], amplitude = 0.7 * kFrond[1] * v;
            Vec3 rippled = add(p, unpackDirection(7.3 + u), amplitude * trig(phase));
            return Vec4{rippled[0], rippled[1], rippled[2],
                        amplitude * trig(phase + 0.25) * kFrond[2]};
        },
        4, 1e-4, 1e-4, windValues());
}

// BranchWind with the _ST_WindBranch* uniforms: the palm style (a directional bend with gusts,
// plus the pull towards the anchor) and the simple style.
TEST_F(SpeedTreeValueTest, BranchWindStyles) {
    expectFormula(
        "ST_PALM",
        [](double u, double v) {
            Vec3 p = position(u, v), anchor{0.0, 0.5, 0.0};
            double phase = u + instancePhase(kInstance);
            Vec4 waves;
            double o = oscillate(p, 2.0, phase, v, 0.4, true, false, true, 0.3, 1.9, waves);
            double bend = 0.2 + 0.8 * o * turbulence(2.0, phase, kGlobal[0], 0.5);
            Vec3 push = add(add({0, 0, 0}, kWind, bend), anchor, length(kWind) * 0.2);
            Vec3 palm = add(p, push, v * 0.5);
            double simple = oscillate(p, 2.0, phase, v, 0.4, false, false, true, 0.3, 1.9, waves);
            return Vec4{palm[0], palm[1], palm[2], p[0] + kWind[0] * v * 0.5 * simple};
        },
        4, 1e-4, 1e-3, windValues());
}

// LeafWind: leaf group 1 ripples along the packed direction by _ST_WindLeaf1Ripple; with the
// best quality group 2 ripples by its own uniforms, then tumbles rigidly about the anchor.
TEST_F(SpeedTreeValueTest, LeafWind) {
    expectFormula(
        "ST_LEAFWIND",
        [](double u, double v) {
            Vec3 p = position(u, v), anchor = add(p, {0.3, -0.2, 0.1});
            Vec3 rippled = add(p, unpackDirection(7.3 + u), 0.8 * 0.3 * trig(1.7 + u));
            Vec3 rippled2 = add(p, unpackDirection(7.3 + u), 0.8 * 0.2 * trig(0.7 + u));
            return Vec4{rippled[0], rippled[1], rippled[2], length(add(rippled2, anchor, -1.0))};
        },
        4, 1e-4, 1e-4, windValues());
}

// A tumbling leaf turns rigidly about its anchor: distance to the anchor, the normal's length and
// their dot product are kept, and the leaf does move.
TEST_F(SpeedTreeValueTest, LeafTumbleIsARotation) {
    Vec3 offset{-0.3, 0.2, -0.1};
    expectFormula(
        "ST_TUMBLE",
        [&](double u, double v) {
            return Vec4{length(offset), 1.0, dot(offset, normalized({u, 1.0, v})), 0.0};
        },
        3, 1e-5, 1e-4, windValues());
    image::Image image = run("ST_TUMBLE", windValues());
    ASSERT_EQ(image.width(), kSize);
    int moved = 0;
    for (uint32_t y = 0; y < kSize; ++y) {
        for (uint32_t x = 0; x < kSize; ++x) moved += image.pixelFloat(x, y)[3] > 1e-3 ? 1 : 0;
    }
    EXPECT_GE(moved, static_cast<int>(kSize * kSize * 9 / 10));
}

}  // namespace
}  // namespace varc::render::speedtree
