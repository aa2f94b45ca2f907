// SPDX-License-Identifier: Apache-2.0
// Shared by the SpeedTree value tests (SpeedTreeWindValueTest.cpp, SpeedTreeTreeValueTest.cpp):
// the formulas documented in shaders/builtin/SpeedTree*.cginc computed on the CPU, the inputs of
// tests/vulkan/helpers/SpeedTreeValues.shader, and a fixture that draws one of its variants and
// compares every pixel with a formula.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/reader/ShaderView.h"

namespace varc::render::speedtree {

inline constexpr uint32_t kSize = 32;
inline constexpr double kTwoPi = 6.28318530717958647692;
using Vec3 = std::array<double, 3>;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

// The documented formulas of SpeedTreeWind.cginc.
inline double frac(double x) { return x - std::floor(x); }
inline double triangleWave(double x) { return std::abs(frac(x + 0.5) * 2.0 - 1.0); }
inline double cubicSmooth(double x) { return x * x * (3.0 - 2.0 * x); }
inline double trig(double x) { return cubicSmooth(triangleWave(x)) * 2.0 - 1.0; }
inline double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 add(const Vec3& a, const Vec3& b, double s = 1.0) {
    return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}
inline Vec3 normalized(const Vec3& a) { return add({0, 0, 0}, a, 1.0 / length(a)); }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// Rodrigues: v turned by |angle| about the unit |axis|.
inline Vec3 rotate(const Vec3& axis, double angle, const Vec3& v) {
    Vec3 turned = add(add({0, 0, 0}, v, std::cos(angle)), cross(axis, v), std::sin(angle));
    return add(turned, axis, dot(axis, v) * (1.0 - std::cos(angle)));
}

// The helper shader's shared inputs.
inline Vec3 position(double u, double v) { return {4.0 * u - 2.0, 8.0 * v, 2.0 * u * v - 0.5}; }
inline const Vec3 kWind{0.9, 0.0, 1.2};
inline const Vec3 kInstance{3.0, 0.0, -7.0};
inline double instancePhase(const Vec3& p) { return dot(p, {0.131, 0.071, 0.113}); }
// The uniforms the wind groups run with.
inline const Vec4 kAnimation{0.3, 0.9, 0.2, 0.0};  // _ST_WindAnimation: roll min, speed, ripple
inline const Vec4 kGlobal{0.4, 0.6, 5.0, 1.5};  // _ST_WindGlobal: time, distance, height, exponent
inline const Vec4 kAdherences{0.3, 0.2, 0.0, 0.0};
inline const Vec4 kFrond{1.3, 0.4, 2.5, 0.0};  // _ST_WindFrondRipple: time, distance, tile

inline double roll(double current, double maxScale, double minScale, double speed, double ripple,
                   const Vec3& p, double time, const Vec3& wind) {
    double along = dot(p, normalized(wind));
    double wave = 0.5 + 0.5 * trig(time * speed - ripple * along);
    return current * (minScale + (maxScale - minScale) * wave);
}
inline double twitch(const Vec3& p, double amount, double sharpness, double time) {
    double combined = clamp01(0.5 + 0.5 * trig(time + p[0] + p[2]) * trig(0.87 * time + p[1]));
    return amount * std::pow(combined, 1.0 + 15.0 * clamp01(sharpness));
}
inline double turbulence(double time, double offset, double globalTime, double amount) {
    return 1.0 -
           amount * (0.5 + 0.5 * trig(0.1 * globalTime + offset) * trig(1.13 * time + offset));
}
// Oscillate's result and its four waves.
inline double oscillate(const Vec3& p, double time, double offset, double weight, double whip,
                        bool bWhip, bool bRoll, bool bComplex, double twitchShare,
                        double twitchScale, Vec4& waves) {
    double phase = time + offset;
    waves = {trig(phase), trig(phase * twitchScale), trig(0.5 * phase * twitchScale),
             trig(phase + 1.0 - weight)};
    double o = waves[0];
    if (bComplex) o += (waves[1] * waves[2] - o) * clamp01(twitchShare);
    if (bWhip) o *= 1.0 + whip * weight * (0.5 + 0.5 * waves[3]);
    if (bRoll) o = roll(o, 1.0, kAnimation[0], kAnimation[1], kAnimation[2], p, time, kWind);
    return o;
}
inline Vec3 globalWind(const Vec3& p, bool preserveShape, double time) {
    double height = std::max(p[1], 0.0) / kGlobal[2];
    double phase = time + instancePhase(kInstance);
    double sway = clamp01(0.5 + 0.35 * trig(phase) + 0.15 * trig(0.71 * phase));
    double amount = kGlobal[1] * std::pow(height, kGlobal[3]) *
                    (kAdherences[0] + (1.0 - kAdherences[0]) * sway);
    Vec3 moved = add(p, {kWind[0], 0.0, kWind[2]}, amount);
    return preserveShape ? add({0, 0, 0}, moved, length(p) / length(moved)) : moved;
}
// UnpackNormalFromFloat: frac(value / (16, 1, 1/16)) * 2 - 1.
inline Vec3 unpackDirection(double value) {
    return {frac(value / 16.0) * 2 - 1, frac(value) * 2 - 1, frac(value * 16.0) * 2 - 1};
}

class SpeedTreeValueTest : public testing::QuadDrawTest {
protected:
    SpeedTreeValueTest() : QuadDrawTest(kSize) {}

    image::Image run(const std::string& keyword, const ShaderValues& values) {
        reader::PassView pass = *mPack->findShader("Test/SpeedTreeValues")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view, pack::ResourceDim dim) {
            return builtin.named("white", dim);
        };
        return drawQuad(pass, {keyword}, values, textures);
    }

    // Compares the first |channels| channels of every pixel with |formula| within |absolute| +
    // |relative| * |expected| and reports the worst pixel; the expected values must not all be
    // near zero (a formula of nothing proves nothing).
    void expectFormula(const std::string& keyword, const Formula& formula, int channels,
                       double absolute, double relative, const ShaderValues& values) {
        image::Image image = run(keyword, values);
        ASSERT_EQ(image.width(), kSize) << keyword;
        testing::FormulaComparison result =
            testing::compareWithFormula(image, formula, channels, absolute, relative);
        EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
        EXPECT_GT(result.largest, 0.05) << keyword << ": the expected values are all near zero";
    }

    // Values of the wind uniforms the formula groups use.
    static ShaderValues windValues() {
        ShaderValues values;
        values.set("_ST_WindAnimation", glm::vec4(0.3f, 0.9f, 0.2f, 0.0f));
        values.set("_ST_WindGlobal", glm::vec4(0.4f, 0.6f, 5.0f, 1.5f));
        values.set("_ST_WindBranchAdherences", glm::vec4(0.3f, 0.2f, 0.0f, 0.0f));
        values.set("_ST_WindFrondRipple", glm::vec4(1.3f, 0.4f, 2.5f, 0.0f));
        values.set("_ST_WindBranch", glm::vec4(2.0f, 0.5f, 0.0f, 0.0f));
        values.set("_ST_WindTurbulences", glm::vec4(0.5f, 0.0f, 0.0f, 0.0f));
        values.set("_ST_WindBranchTwitch", glm::vec4(0.3f, 1.9f, 0.0f, 0.0f));
        values.set("_ST_WindBranchWhip", glm::vec4(0.4f, 0.0f, 0.0f, 0.0f));
        values.set("_ST_WindLeaf1Ripple", glm::vec4(1.7f, 0.3f, 0.0f, 0.0f));
        values.set("_ST_WindLeaf2Ripple", glm::vec4(0.7f, 0.2f, 0.0f, 0.0f));
        values.set("_ST_WindLeaf2Tumble", glm::vec4(1.1f, 0.8f, 0.6f, 0.3f));
        values.set("_ST_WindLeaf2Twitch", glm::vec4(0.4f, 0.5f, 0.5f, 0.0f));
        return values;
    }
};

}  // namespace varc::render::speedtree
