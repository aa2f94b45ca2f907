// SPDX-License-Identifier: Apache-2.0
// The relations of a property check on one shader's renders, in relationNames() order.
#include <filesystem>
#include <vector>

#include "PropertySteps.h"
#include "PropertyTolerances.h"
#include "varc/image/Png.h"

namespace varc::properties {

namespace {

using image::Image;

scene::Light brighter(scene::Light light) {
    light.intensity *= 2.0f;
    return light;
}

// One `forward_deferred` case: |scene| drawn on the forward path (under |label|, shared with the
// other relations) and on the deferred path (G-buffer, then varc/DeferredLight per light),
// compared within |tolerance|. A deferred render that fails (no deferred light shader in the
// packs, a G-buffer variant missing) fails the relation with the renderer's error.
void compareDeferred(ShaderCheck& c, const std::string& label, scene::Scene scene,
                     const Tolerance& tolerance) {
    const render::RenderedFrame* forward = c.render(label, scene);
    scene.camera.path = scene::RenderPath::Deferred;
    std::string why;
    const render::RenderedFrame* deferred = c.tryRender(label + " deferred", scene, why);
    if (!deferred) {
        RelationOutcome& outcome = c.outcomeOf("forward_deferred");
        outcome.verdict = Verdict::Fail;
        outcome.detail += why + "\n";  // "<label> deferred: <the renderer's error>"
        return;
    }
    c.relate("forward_deferred", label, deferred, {{forward, 1.0f}}, tolerance);
}

// `forward_deferred` for a shader with a Deferred pass (n/a without one): each key light it takes
// alone, and |allLit| when it holds more than one light, in HDR; the directional light alone and
// |allLit|'s lights in LDR. Tolerances (docs/PROPERTIES.md): HDR, the G-buffer's 8-bit colours
// and smoothness (kGBufferRelative). LDR adds the light buffer's encoding: q = exp2(-c) in 8-bit
// UNORM, multiplied into by each of n lights, rounds q n times by <= 1/2 LSB, which decodes to
// <= n x 0.72 LSB x 2^c <= n x 0.72 LSB x (1 + c) for c <= 1; the forward target is rounded n
// times (base, then each add) and the decode once, 1/2 LSB each. Pixels at 254/255 or more are
// skipped (the targets clamp).
void checkForwardDeferred(ShaderCheck& c, const LightSupport& support, const scene::Scene& empty,
                          const scene::Scene& allLit) {
    if (!support.deferred) {
        c.outcomeOf("forward_deferred").detail = "no Deferred pass";
        return;
    }
    const Tolerance hdr{kZero, kGBufferRelative, 0};
    compareDeferred(c, "directional", withLights(empty, {keyDirectional()}), hdr);
    if (support.point) compareDeferred(c, "point", withLights(empty, {keyPoint()}), hdr);
    if (support.spot) compareDeferred(c, "spot", withLights(empty, {keySpot()}), hdr);
    if (allLit.lights.size() > 1) compareDeferred(c, "all lights", allLit, hdr);

    scene::Scene ldr = empty;
    ldr.camera.hdr = false;
    auto ldrTolerance = [](size_t lights) {
        const float n = static_cast<float>(lights);
        return Tolerance{((kLdrDecodeLsb + 0.5f) * n + 0.5f) * kLsb,
                         kGBufferRelative + kLdrDecodeLsb * n * kLsb, 0, 254.0f / 255.0f};
    };
    compareDeferred(c, "ldr directional", withLights(ldr, {keyDirectional()}), ldrTolerance(1));
    if (allLit.lights.size() > 1)
        compareDeferred(c, "ldr all lights", withLights(ldr, allLit.lights),
                        ldrTolerance(allLit.lights.size()));
}

// The relations of checkRelations, in relationNames() order, one step each. The steps run in
// this order and share the key renders, so renders and failures come out in the same order.
class RelationChecks {
public:
    RelationChecks(ShaderCheck& c, const std::string& shader, const LightSupport& support,
                   const std::pair<std::string, std::string>& cookies, uint32_t size)
        : mCheck(c),
          mSupport(support),
          mCookies(cookies),
          mShader(shader),
          mSize(size),
          mEmpty(emptyScene(shader, true, size)) {}

    std::string run() {
        checkDarkAndRange();
        checkCookies();
        checkAdditivity();
        checkIntensity();
        const scene::Scene allLit = checkMotion();
        checkLightAxis();
        checkBehind();
        checkForwardDeferred(mCheck, mSupport, mEmpty, allLit);
        return drawCoverage(mCheck, mSupport, mCookies, mEmpty);
    }

private:
    scene::Scene lit(const std::vector<scene::Light>& lights) const {
        return withLights(mEmpty, lights);
    }

    // dark, lit (the directional light) and out_of_range.
    void checkDarkAndRange() {
        ShaderCheck& c = mCheck;
        const auto& d = mD;
        mNone = c.render("no lights", mEmpty);
        mDOnly = c.render("directional", lit({d}));
        c.relate("dark", "no lights", mNone, {}, {kZero, 0, 0});
        c.requireLight("directional", mDOnly, mNone);

        const Tolerance outOfRange{kOutOfRange, kHalfUlp, 0};
        if (mSupport.point)
            c.relate("out_of_range", "point",
                     c.render("directional + far point", lit({d, outOfRangePoint()})),
                     {{mDOnly, 1.0f}}, outOfRange);
        if (mSupport.spot)
            c.relate("out_of_range", "spot",
                     c.render("directional + far spot", lit({d, outOfRangeSpot()})),
                     {{mDOnly, 1.0f}}, outOfRange);
    }

    // black_cookie, white_cookie, then lit for the point and spot lights.
    void checkCookies() {
        ShaderCheck& c = mCheck;
        const auto &d = mD, &p = mP, &s = mS;
        const auto& cookies = mCookies;
        const auto* none = mNone;
        const Tolerance same{kZero, 2 * kHalfUlp, 0};
        if (mSupport.directionalCookie)
            c.relate("black_cookie", "directional",
                     c.render("directional black cookie", lit({withCookie(d, cookies.second)})),
                     {{none, 1.0f}}, same);
        if (mSupport.spot)
            c.relate("black_cookie", "spot",
                     c.render("spot black cookie", lit({withCookie(s, cookies.second)})),
                     {{none, 1.0f}}, same);
        if (mSupport.directionalCookie)
            c.relate("white_cookie", "directional",
                     c.render("directional white cookie", lit({withCookie(d, cookies.first)})),
                     {{mDOnly, 1.0f}}, same);

        mPOnly = mSupport.point ? c.render("point", lit({p})) : nullptr;
        // The built-in white cube cookie (alpha 1) turns POINT into POINT_COOKIE, which must draw
        // the same light: the cookie multiplies the falloff by exactly 1.
        if (mSupport.pointCookie)
            c.relate("white_cookie", "point",
                     c.render("point white cookie", lit({withCookie(p, "white")})),
                     {{mPOnly, 1.0f}}, same);
        if (mSupport.point) c.requireLight("point", mPOnly, none);
        if (mSupport.spot) c.requireLight("spot", c.render("spot", lit({s})), none);
    }

    // additivity (HDR) and additivity_ldr.
    void checkAdditivity() {
        ShaderCheck& c = mCheck;
        const auto &d = mD, &d2 = mD2, &p = mP, &s = mS;
        const auto *none = mNone, *dOnly = mDOnly, *pOnly = mPOnly;
        const Tolerance sum{kZero, 3 * kHalfUlp, 0};
        if (mSupport.forwardAdd) {
            const auto* d2Only = c.render("second directional", lit({d2}));
            c.relate("additivity", "directional + directional",
                     c.render("directional + second", lit({d, d2})),
                     {{dOnly, 1.0f}, {d2Only, 1.0f}, {none, -1.0f}}, sum);
        }
        if (mSupport.point)
            c.relate("additivity", "directional + point",
                     c.render("directional + point", lit({d, p})),
                     {{dOnly, 1.0f}, {pOnly, 1.0f}, {none, -1.0f}}, sum);
        if (mSupport.point && mSupport.spot)
            c.relate("additivity", "point + spot", c.render("point + spot", lit({p, s})),
                     {{pOnly, 1.0f}, {c.render("spot", lit({s})), 1.0f}, {none, -1.0f}}, sum);
        if (mSupport.forwardAdd) {
            const scene::Scene ldr = emptyScene(mShader, false, mSize);
            const scene::Light extra = mSupport.point ? p : d2;
            const auto* ldrNone = c.render("ldr no lights", ldr);
            const auto* ldrD = c.render("ldr directional", withLights(ldr, {d}));
            const auto* ldrExtra = c.render("ldr extra", withLights(ldr, {extra}));
            c.relate("additivity_ldr", "directional + extra",
                     c.render("ldr both", withLights(ldr, {d, extra})),
                     {{ldrD, 1.0f}, {ldrExtra, 1.0f}, {ldrNone, -1.0f}},
                     {2 * kLsb, 0, 0, 254.0f / 255.0f});
        }
    }

    void checkIntensity() {
        ShaderCheck& c = mCheck;
        const Tolerance sum{kZero, 3 * kHalfUlp, 0};
        c.relate("intensity", "directional", c.render("directional x2", lit({brighter(mD)})),
                 {{mDOnly, 2.0f}, {mNone, -1.0f}}, sum);
        if (mSupport.point)
            c.relate("intensity", "point", c.render("point x2", lit({brighter(mP)})),
                     {{mPOnly, 2.0f}, {mNone, -1.0f}}, sum);
    }

    // translation, rotation, mirror and scale of the scene with every key light; returns it.
    scene::Scene checkMotion() {
        ShaderCheck& c = mCheck;
        std::vector<scene::Light> all{mD};
        if (mSupport.point) all.push_back(mP);
        if (mSupport.spot) all.push_back(mS);
        const scene::Scene allLit = lit(all);
        const auto* allFrame = c.render("all lights", allLit);
        const Tolerance moved{kMovedAbsolute, kMovedRelative, 1};
        c.relate("translation", "offset (3, -2, 5)",
                 c.render("all lights moved", similar(allLit, 1.0f, {3.0f, -2.0f, 5.0f})),
                 {{allFrame, 1.0f}}, moved);
        c.relate("rotation", "40 degrees about y",
                 c.render("all lights turned", turned(allLit, 40.0f)), {{allFrame, 1.0f}}, moved);
        c.relate("mirror", "in the plane x = 0", c.render("all lights mirrored", mirrored(allLit)),
                 {{c.flipped("all lights flipped", allFrame), 1.0f}}, moved);
        c.relate("scale", "x2",
                 c.render("all lights scaled", similar(allLit, 2.0f, glm::vec3(0.0f))),
                 {{allFrame, 1.0f}}, moved);
        return allLit;
    }

    // Seen from above with every light on the y axis: the objects turned a quarter turn about
    // it draw the image turned a quarter turn (exactly onto the pixel grid: no resampling).
    void checkLightAxis() {
        ShaderCheck& c = mCheck;
        const Tolerance moved{kMovedAbsolute, kMovedRelative, 1};
        std::vector<scene::Light> axial{overheadDirectional()};
        if (mSupport.point) axial.push_back(onLightAxis(mP, 1.6f));
        if (mSupport.spot) axial.push_back(onLightAxis(mS, 2.5f));
        const scene::Scene above = fromAbove(lit(axial));
        c.relate("light_axis", "objects turned 90 degrees about y",
                 c.render("axial lights, objects turned", objectsTurned(above, 90.0f)),
                 {{c.quarterTurned("axial lights, image turned", c.render("axial lights", above)),
                   1.0f}},
                 moved);
    }

    // A light behind an opaque surface does not light its front: with each light type the
    // shader takes under the floor (floorFromAbove(), underFloor()), the floor's top face, which
    // faces away from it, draws as with no lights. Catches a shader that ignores where its light
    // is (mutant FixedDirection) whatever its BRDF, as long as the light's term vanishes when
    // the light is behind the surface (not wrap or translucent lighting).
    void checkBehind() {
        ShaderCheck& c = mCheck;
        const Tolerance same{kZero, 2 * kHalfUlp, 0};
        const scene::Scene floor = floorFromAbove(mShader, mSize);
        const auto* dark = c.render("floor, no lights", floor);
        c.relate("behind", "directional",
                 c.render("floor, directional below", withLights(floor, {underFloor(mD)})),
                 {{dark, 1.0f}}, same);
        if (mSupport.point)
            c.relate("behind", "point",
                     c.render("floor, point below", withLights(floor, {underFloor(mP)})),
                     {{dark, 1.0f}}, same);
        if (mSupport.spot)
            c.relate("behind", "spot",
                     c.render("floor, spot below", withLights(floor, {underFloor(mS)})),
                     {{dark, 1.0f}}, same);
    }

    ShaderCheck& mCheck;
    const LightSupport& mSupport;
    const std::pair<std::string, std::string>& mCookies;
    const std::string mShader;
    const uint32_t mSize;
    const scene::Scene mEmpty;
    const scene::Light mD = keyDirectional(), mD2 = secondDirectional(), mP = keyPoint(),
                       mS = keySpot();
    const render::RenderedFrame* mNone = nullptr;
    const render::RenderedFrame* mDOnly = nullptr;
    const render::RenderedFrame* mPOnly = nullptr;
};

}  // namespace

// Cookie PNGs in <outDir>/cookies: alpha 1 everywhere (white) and alpha 0 (black).
Result<std::pair<std::string, std::string>> writeCookies(const std::string& outDir) {
    std::filesystem::path dir = std::filesystem::path(outDir) / "cookies";
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) return makeError(ErrorCode::IoError, dir.string() + ": " + error.message());
    std::pair<std::string, std::string> paths{(dir / "white.png").string(),
                                              (dir / "black.png").string()};
    Image white(16, 16, image::PixelFormat::Rgba8), black(16, 16, image::PixelFormat::Rgba8);
    for (uint8_t& byte : white.bytes()) byte = 255;
    for (size_t i = 0; i < black.bytes().size(); ++i) black.bytes()[i] = i % 4 == 3 ? 0 : 255;
    if (Status written = image::writePng(paths.first, white); !written) return written.error();
    if (Status written = image::writePng(paths.second, black); !written) return written.error();
    return paths;
}

scene::Light withCookie(scene::Light light, const std::string& cookie) {
    light.cookie = cookie;
    light.cookieSize = 2.0f;
    return light;
}

// The relations on HDR renders (and additivity_ldr on RGBA8), in relationNames() order, then
// the coverage renders; returns why directional shadows were not drawn ("" when they were).
std::string checkRelations(ShaderCheck& c, const std::string& shader, const LightSupport& support,
                           const std::pair<std::string, std::string>& cookies, uint32_t size) {
    return RelationChecks(c, shader, support, cookies, size).run();
}

}  // namespace varc::properties
