// SPDX-License-Identifier: Apache-2.0
// PropertyRunner: one lighting shader's renders and the relations between them; the tolerances
// are derived in docs/PROPERTIES.md.
#include "varc/properties/PropertyRunner.h"

#include <cctype>
#include <filesystem>
#include <map>
#include <utility>

#include "varc/image/Png.h"
#include "varc/reader/PassView.h"
#include "varc/properties/ImageRelations.h"
#include "varc/properties/PropertyScenes.h"
#include "varc/variants/LightKeywords.h"

namespace varc::properties {

namespace {

using image::Image;

// Half-float storage (RGBA16F) rounds to 11 significant bits: 2^-11 relative per stored value.
constexpr float kHalfUlp = 1.0f / 2048.0f;
// A value a correct shader leaves at zero, stored in RGBA16F: far below one 8-bit LSB (1/255).
constexpr float kZero = 1.0f / 4096.0f;
// A light beyond its range still adds the falloff table's last texel (~5.3e-5 x intensity 2 x a
// BRDF <= ~2): 5e-4 bounds it; a light left unattenuated adds ~0.1..1.
constexpr float kOutOfRange = 5.0e-4f;
// 8-bit target (RGBA8 UNORM, values stored as round(v x 255)): a sum of three rounded renders
// against one rounded render differs by up to 1.5 LSB; 2 LSB, saturated pixels skipped.
constexpr float kLsb = 1.0f / 255.0f;
// Scene moved or scaled: float32 vertex positions at |p| ~ 10 m shift rasterised edges (the 3x3
// window absorbs a pixel) and interior values by ~1e-5; 2^-8 relative + 2^-9 absolute leaves a
// margin over half-float storage and is far below the 50% of an unnormalised normal at scale 2.
constexpr float kMovedRelative = 1.0f / 256.0f;
constexpr float kMovedAbsolute = 1.0f / 512.0f;
// Forward against deferred: the G-buffer stores the colours as 8-bit sRGB and the smoothness in
// 8 bits. One sRGB LSB is <= 0.93% of a diffuse colour of 0.96, 3.4% of a specular colour of
// 0.04; half a smoothness LSB moves GGX's peak by ~3.2%: <= 0.93% x (1 - s) + 7% x s for a
// specular share s <= 14% (F0 0.04, smoothness 0.5) is <= 1.8% (docs/PROPERTIES.md; measured 0.5%).
constexpr float kGBufferRelative = 0.02f;
// The LDR light buffer holds q = 2^-c in 8 bits: half an LSB of q is 0.5 / (q ln 2) = 0.72 x 2^c
// LSB of the decoded c.
constexpr float kLdrDecodeLsb = 0.72f;

std::string fileSafe(std::string text) {
    for (char& c : text)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')) c = '_';
    return text;
}

// " [variant] [variant]": the distinct variants |frame| drew, in first-draw order.
std::string variantList(const render::RenderedFrame& frame) {
    std::set<std::string> seen;
    std::string list;
    for (const std::string& variant : frame.variants)
        if (seen.insert(variant).second) list += " [" + variant + "]";
    return list;
}

// The renders of one shader, by case label, and the relations checked on them.
class ShaderCheck {
public:
    ShaderCheck(render::Renderer& renderer, const PropertyOptions& options, ShaderReport& report)
        : mRenderer(renderer), mOptions(options), mReport(report) {
        for (const std::string& name : relationNames())
            mReport.relations.push_back({name, Verdict::NotApplicable, {}, {}});
    }

    // The frame of |scene| under |label| (drawn once); nullptr after recording a render error.
    const render::RenderedFrame* render(const std::string& label, const scene::Scene& scene) {
        auto found = mFrames.find(label);
        if (found != mFrames.end()) return &found->second;
        auto frame = mRenderer.render(scene);
        if (!frame) {
            if (mReport.error.empty()) mReport.error = label + ": " + frame.error().detail;
            return nullptr;
        }
        ++mReport.renders;
        mReport.variants.insert(frame->variants.begin(), frame->variants.end());
        checkFinite(label, *frame);
        return &mFrames.emplace(label, std::move(*frame)).first->second;
    }

    // Checks |relation| on case |label|: the render |actual| against sum(weight x render).
    void relate(const std::string& relation, const std::string& label,
                const render::RenderedFrame* actual,
                const std::vector<std::pair<const render::RenderedFrame*, float>>& terms,
                const Tolerance& tolerance) {
        if (!actual) return;
        std::vector<Term> imageTerms;
        for (const auto& [frame, weight] : terms) {
            if (!frame) return;
            imageTerms.push_back({&frame->image, weight});
        }
        RelationCheck check = checkRelation(actual->image, imageTerms, tolerance);
        RelationOutcome& outcome = outcomeOf(relation);
        if (check.passed) {
            if (outcome.verdict == Verdict::NotApplicable) outcome.verdict = Verdict::Pass;
            return;
        }
        recordFailure(outcome, label, check.summary(), *actual, &check);
    }

    // Checks that |lit| is brighter than |unlit| by more than 1/64 on at least 2% of its pixels:
    // a key light in range lights the objects (so the other relations compare lit images).
    void requireLight(const std::string& label, const render::RenderedFrame* lit,
                      const render::RenderedFrame* unlit) {
        if (!lit || !unlit) return;
        const size_t pixels = size_t{lit->image.width()} * lit->image.height();
        const size_t brighter = pixelsBrighter(lit->image, unlit->image, 1.0f / 64.0f);
        RelationOutcome& outcome = outcomeOf("lit");
        if (brighter * 50 >= pixels) {
            if (outcome.verdict == Verdict::NotApplicable) outcome.verdict = Verdict::Pass;
            return;
        }
        recordFailure(outcome, label,
                      "only " + std::to_string(brighter) + " of " + std::to_string(pixels) +
                          " pixels brighter than with no lights (2% needed)",
                      *lit, nullptr);
    }

    // Like render(), for a coverage render that may fail without failing the check (directional
    // shadows need Hidden/varc/ScreenSpaceShadows in a pack): the error goes to |why|.
    const render::RenderedFrame* tryRender(const std::string& label, const scene::Scene& scene,
                                           std::string& why) {
        auto frame = mRenderer.render(scene);
        if (!frame) {
            why = label + ": " + frame.error().detail;
            return nullptr;
        }
        ++mReport.renders;
        mReport.variants.insert(frame->variants.begin(), frame->variants.end());
        checkFinite(label, *frame);
        return &mFrames.insert_or_assign(label, std::move(*frame)).first->second;
    }

    // |source| with its image flipped left to right, kept under |label| (not a render).
    const render::RenderedFrame* flipped(const std::string& label,
                                         const render::RenderedFrame* source) {
        if (!source) return nullptr;
        render::RenderedFrame frame = *source;
        frame.image = flippedLeftRight(source->image);
        return &mFrames.insert_or_assign(label, std::move(frame)).first->second;
    }

    // |source| with its image turned a quarter turn clockwise, kept under |label| (not a render).
    const render::RenderedFrame* quarterTurned(const std::string& label,
                                               const render::RenderedFrame* source) {
        if (!source) return nullptr;
        render::RenderedFrame frame = *source;
        frame.image = properties::quarterTurned(source->image);
        return &mFrames.insert_or_assign(label, std::move(frame)).first->second;
    }

    // The frame drawn under |label|, or nullptr (not drawn, or its render failed).
    const render::RenderedFrame* frame(const std::string& label) const {
        auto found = mFrames.find(label);
        return found == mFrames.end() ? nullptr : &found->second;
    }

    RelationOutcome& outcomeOf(const std::string& relation) {
        for (RelationOutcome& outcome : mReport.relations)
            if (outcome.relation == relation) return outcome;
        return mReport.relations.front();
    }

private:
    void checkFinite(const std::string& label, const render::RenderedFrame& frame) {
        RelationOutcome& outcome = outcomeOf("finite");
        NonFinite found = findNonFinite(frame.image);
        if (found.count == 0) {
            if (outcome.verdict == Verdict::NotApplicable) outcome.verdict = Verdict::Pass;
            return;
        }
        recordFailure(outcome, label,
                      std::to_string(found.count) + " pixels hold NaN or Inf, first (" +
                          std::to_string(found.firstX) + "," + std::to_string(found.firstY) + ")",
                      frame, nullptr);
    }

    // Fails |outcome| on case |label|: its detail line (the finding, the variants |frame| drew,
    // the images written) and its FailedCase.
    void recordFailure(RelationOutcome& outcome, const std::string& label,
                       const std::string& finding, const render::RenderedFrame& frame,
                       const RelationCheck* check) {
        outcome.verdict = Verdict::Fail;
        FailedCase failed{label, finding, {}, {}};
        std::set<std::string> seen;
        for (const std::string& variant : frame.variants)
            if (seen.insert(variant).second) failed.variants.push_back(variant);
        outcome.detail += label + ": " + finding + "; variants:" + variantList(frame) +
                          writeImages(outcome.relation, label, frame.image, check, failed.images) +
                          "\n";
        outcome.cases.push_back(std::move(failed));
    }

    // Writes <outDir>/<shader>/<relation>.<label>.{actual,expected,diff}.png, their paths to
    // |written| once all are written; " -> <files>" or " (images not written: why)".
    std::string writeImages(const std::string& relation, const std::string& label,
                            const Image& actual, const RelationCheck* check,
                            std::vector<std::string>& written) {
        std::filesystem::path dir =
            std::filesystem::path(mOptions.outDir) / fileSafe(mReport.shader);
        std::error_code error;
        std::filesystem::create_directories(dir, error);
        if (error) return " (images not written: " + error.message() + ")";
        std::string base = (dir / (relation + "." + fileSafe(label))).string();
        auto shown = [](const Image& image) {
            return image.isFloat() ? image.toRgba8(image::Tonemap::Reinhard) : image;
        };
        std::vector<std::pair<std::string, Image>> images{{base + ".actual.png", shown(actual)}};
        if (check) {
            images.emplace_back(base + ".expected.png", shown(check->expected));
            images.emplace_back(base + ".diff.png", check->diff);
        }
        for (const auto& [path, image] : images) {
            if (Status status = image::writePng(path, image); !status)
                return " (images not written: " + status.error().detail + ")";
        }
        for (const auto& image : images) written.push_back(image.first);
        return " -> " + base + ".*.png";
    }

    render::Renderer& mRenderer;
    const PropertyOptions& mOptions;
    ShaderReport& mReport;
    std::map<std::string, render::RenderedFrame> mFrames;
};

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

scene::Light brighter(scene::Light light) {
    light.intensity *= 2.0f;
    return light;
}

// Four point lights drawn per vertex in the base pass (VERTEXLIGHT_ON).
std::vector<scene::Light> vertexLights() {
    std::vector<scene::Light> lights;
    for (int i = 0; i < 4; ++i) {
        scene::Light light = keyPoint();
        light.renderMode = scene::LightRenderMode::NotImportant;
        light.transform.position.x += 0.5f * static_cast<float>(i);
        lights.push_back(light);
    }
    return lights;
}

// The renders that reach the variants the relations leave out (each is checked for `finite`):
// per shadow type (hard, soft) the main light and every light type the shader takes, with
// cookies, in one scene (vertex lights too with hard shadows), and the second directional light
// shadowed under an unshadowed main light (both Important: the main light is the first
// directional light by importance, then brightness); vertex lights alone. When directional
// shadows cannot be drawn (no screen-space shadow shader in the packs) the scenes are drawn
// without them; returns why ("" when every coverage scene drew).
template <typename LitScene>
std::string drawCoverage(ShaderCheck& c, const LightSupport& support,
                         const std::pair<std::string, std::string>& cookies, const LitScene& lit) {
    using scene::Light;
    std::string why;
    bool directionalShadows = true;
    Light main = keyDirectional();
    main.renderMode = scene::LightRenderMode::Important;
    for (scene::ShadowType shadows : {scene::ShadowType::Hard, scene::ShadowType::Soft}) {
        const std::string kind = shadows == scene::ShadowType::Hard ? "hard" : "soft";
        auto scene = [&](bool withDirectional) {
            std::vector<Light> lights{main};
            if (support.point) lights.push_back(keyPoint());
            if (support.spot) lights.push_back(keySpot());
            if (support.directionalCookie)
                lights.push_back(withCookie(secondDirectional(), cookies.first));
            if (support.pointCookie) lights.push_back(withCookie(keyPoint(), "white"));
            for (Light& light : lights)
                if (withDirectional || light.type != scene::LightType::Directional)
                    light.shadows = shadows;
            // Vertex lights with hard shadows only: the base pass's SHADOWS_SCREEN is the same
            // for soft shadows, so the soft scene draws it without VERTEXLIGHT_ON.
            if (shadows == scene::ShadowType::Hard)
                for (const Light& light : vertexLights()) lights.push_back(light);
            return lit(lights);
        };
        const std::string label = "coverage " + kind + " shadows";
        if (directionalShadows && !c.tryRender(label, scene(true), why))
            directionalShadows = false;
        if (!directionalShadows) c.render(label + " (no directional)", scene(false));
        if (!support.forwardAdd || !directionalShadows) continue;
        Light second = secondDirectional();
        second.shadows = shadows;
        c.render(label + ", second directional", lit({main, second}));
    }
    std::vector<Light> vertexLit{main};
    for (const Light& light : vertexLights()) vertexLit.push_back(light);
    c.render("coverage vertex lights", lit(vertexLit));
    return why;
}

// The variants of |shader|'s (first) ForwardBase and ForwardAdd passes that the forward renderer
// can select for some light (variants::lightKeywords: light type, cookie, shadows, vertex
// lights, HDR; light probes on; no material keywords), as VariantView::describe() gives them.
std::set<std::string> reachableVariants(const reader::ShaderView& shader) {
    std::set<std::string> reachable;
    for (const char* lightMode : {"ForwardBase", "ForwardAdd"}) {
        std::optional<reader::PassView> pass = shader.pass(std::string_view(lightMode));
        if (!pass) continue;
        for (auto type : {variants::LightType::Directional, variants::LightType::Point,
                          variants::LightType::Spot}) {
            for (bool cookie : {false, true}) {
                for (auto shadows : {variants::ShadowMode::None, variants::ShadowMode::Hard,
                                     variants::ShadowMode::Soft}) {
                    for (int vertexLightCount : {0, 4}) {
                        variants::LightDescription light;
                        light.type = type;
                        light.cookie = cookie;
                        light.shadows = shadows;
                        light.vertexLightCount = vertexLightCount;
                        light.lightProbes = true;
                        for (bool hdr : {false, true}) {
                            light.hdr = hdr;
                            auto variant = pass->lookup(light, variants::SelectionPolicy::Closest);
                            if (variant) reachable.insert(variant->describe());
                        }
                    }
                }
            }
        }
    }
    return reachable;
}

// `every_variant`: each variant the renderer can select was drawn by some render of the check;
// when directional shadows could not be drawn (|why|), the SHADOWS_SCREEN variants are left out.
void checkEveryVariant(ShaderCheck& c, const reader::ShaderView& shader, ShaderReport& report,
                       const std::string& why) {
    if (!report.error.empty()) return;
    const std::set<std::string> reachable = reachableVariants(shader);
    std::vector<std::string> missing;
    for (const std::string& variant : reachable) {
        if (report.variants.count(variant)) continue;
        if (!why.empty() && variant.find("SHADOWS_SCREEN") != std::string::npos) continue;
        missing.push_back(variant);
    }
    RelationOutcome& outcome = c.outcomeOf("every_variant");
    outcome.verdict = missing.empty() ? Verdict::Pass : Verdict::Fail;
    if (missing.empty()) return;
    outcome.detail = std::to_string(missing.size()) + " of " + std::to_string(reachable.size()) +
                     " variants a light selects were not drawn:";
    for (const std::string& variant : missing) outcome.detail += " [" + variant + "]";
    if (!why.empty()) outcome.detail += "; SHADOWS_SCREEN variants left out: " + why;
    outcome.detail += "\n";
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

// The relations on HDR renders (and additivity_ldr on RGBA8), in relationNames() order, then
// the coverage renders; returns why directional shadows were not drawn ("" when they were).
std::string checkRelations(ShaderCheck& c, const std::string& shader, const LightSupport& support,
                           const std::pair<std::string, std::string>& cookies, uint32_t size) {
    using scene::Light;
    const scene::Scene empty = emptyScene(shader, true, size);
    auto lit = [&](const std::vector<Light>& lights) { return withLights(empty, lights); };
    const Light d = keyDirectional(), d2 = secondDirectional(), p = keyPoint(), s = keySpot();
    const auto* none = c.render("no lights", empty);
    const auto* dOnly = c.render("directional", lit({d}));
    c.relate("dark", "no lights", none, {}, {kZero, 0, 0});
    c.requireLight("directional", dOnly, none);

    const Tolerance outOfRange{kOutOfRange, kHalfUlp, 0};
    if (support.point)
        c.relate("out_of_range", "point",
                 c.render("directional + far point", lit({d, outOfRangePoint()})), {{dOnly, 1.0f}},
                 outOfRange);
    if (support.spot)
        c.relate("out_of_range", "spot",
                 c.render("directional + far spot", lit({d, outOfRangeSpot()})), {{dOnly, 1.0f}},
                 outOfRange);

    const Tolerance same{kZero, 2 * kHalfUlp, 0};
    if (support.directionalCookie)
        c.relate("black_cookie", "directional",
                 c.render("directional black cookie", lit({withCookie(d, cookies.second)})),
                 {{none, 1.0f}}, same);
    if (support.spot)
        c.relate("black_cookie", "spot",
                 c.render("spot black cookie", lit({withCookie(s, cookies.second)})),
                 {{none, 1.0f}}, same);
    if (support.directionalCookie)
        c.relate("white_cookie", "directional",
                 c.render("directional white cookie", lit({withCookie(d, cookies.first)})),
                 {{dOnly, 1.0f}}, same);

    const Tolerance sum{kZero, 3 * kHalfUlp, 0};
    const auto* pOnly = support.point ? c.render("point", lit({p})) : nullptr;
    // The built-in white cube cookie (alpha 1) turns POINT into POINT_COOKIE, which must draw
    // the same light: the cookie multiplies the falloff by exactly 1.
    if (support.pointCookie)
        c.relate("white_cookie", "point",
                 c.render("point white cookie", lit({withCookie(p, "white")})), {{pOnly, 1.0f}},
                 same);
    if (support.point) c.requireLight("point", pOnly, none);
    if (support.spot) c.requireLight("spot", c.render("spot", lit({s})), none);
    if (support.forwardAdd) {
        const auto* d2Only = c.render("second directional", lit({d2}));
        c.relate("additivity", "directional + directional",
                 c.render("directional + second", lit({d, d2})),
                 {{dOnly, 1.0f}, {d2Only, 1.0f}, {none, -1.0f}}, sum);
    }
    if (support.point)
        c.relate("additivity", "directional + point", c.render("directional + point", lit({d, p})),
                 {{dOnly, 1.0f}, {pOnly, 1.0f}, {none, -1.0f}}, sum);
    if (support.point && support.spot)
        c.relate("additivity", "point + spot", c.render("point + spot", lit({p, s})),
                 {{pOnly, 1.0f}, {c.render("spot", lit({s})), 1.0f}, {none, -1.0f}}, sum);

    if (support.forwardAdd) {
        const scene::Scene ldr = emptyScene(shader, false, size);
        const Light extra = support.point ? p : d2;
        const auto* ldrNone = c.render("ldr no lights", ldr);
        const auto* ldrD = c.render("ldr directional", withLights(ldr, {d}));
        const auto* ldrExtra = c.render("ldr extra", withLights(ldr, {extra}));
        c.relate("additivity_ldr", "directional + extra",
                 c.render("ldr both", withLights(ldr, {d, extra})),
                 {{ldrD, 1.0f}, {ldrExtra, 1.0f}, {ldrNone, -1.0f}},
                 {2 * kLsb, 0, 0, 254.0f / 255.0f});
    }

    c.relate("intensity", "directional", c.render("directional x2", lit({brighter(d)})),
             {{dOnly, 2.0f}, {none, -1.0f}}, sum);
    if (support.point)
        c.relate("intensity", "point", c.render("point x2", lit({brighter(p)})),
                 {{pOnly, 2.0f}, {none, -1.0f}}, sum);

    std::vector<Light> all{d};
    if (support.point) all.push_back(p);
    if (support.spot) all.push_back(s);
    const scene::Scene allLit = lit(all);
    const auto* allFrame = c.render("all lights", allLit);
    const Tolerance moved{kMovedAbsolute, kMovedRelative, 1};
    c.relate("translation", "offset (3, -2, 5)",
             c.render("all lights moved", similar(allLit, 1.0f, {3.0f, -2.0f, 5.0f})),
             {{allFrame, 1.0f}}, moved);
    c.relate("rotation", "40 degrees about y", c.render("all lights turned", turned(allLit, 40.0f)),
             {{allFrame, 1.0f}}, moved);
    c.relate("mirror", "in the plane x = 0",
             c.render("all lights mirrored", mirrored(allLit)),
             {{c.flipped("all lights flipped", allFrame), 1.0f}}, moved);
    c.relate("scale", "x2", c.render("all lights scaled", similar(allLit, 2.0f, glm::vec3(0.0f))),
             {{allFrame, 1.0f}}, moved);

    // Seen from above with every light on the y axis: the objects turned a quarter turn about
    // it draw the image turned a quarter turn (exactly onto the pixel grid: no resampling).
    std::vector<Light> axial{overheadDirectional()};
    if (support.point) axial.push_back(onLightAxis(p, 1.6f));
    if (support.spot) axial.push_back(onLightAxis(s, 2.5f));
    const scene::Scene above = fromAbove(lit(axial));
    c.relate("light_axis", "objects turned 90 degrees about y",
             c.render("axial lights, objects turned", objectsTurned(above, 90.0f)),
             {{c.quarterTurned("axial lights, image turned", c.render("axial lights", above)),
               1.0f}},
             moved);
    checkForwardDeferred(c, support, empty, allLit);
    return drawCoverage(c, support, cookies, lit);
}


// The share of the pixels a key light must change (or a doubled light brighten) to count: 2%, as
// for `lit`, by more than 1/64 (4 8-bit LSB, far above half-float rounding of values <= 4).
constexpr size_t kSharePercent = 2;
constexpr float kVisible = 1.0f / 64.0f;

bool atLeastShare(size_t pixels, const Image& image) {
    return pixels * 100 >= kSharePercent * image.width() * image.height();
}

void markNotApplicable(ShaderCheck& c, const std::vector<std::string>& relations,
                       const std::string& reason) {
    for (const std::string& relation : relations) {
        RelationOutcome& outcome = c.outcomeOf(relation);
        outcome.verdict = Verdict::NotApplicable;
        outcome.detail = reason;
        outcome.cases.clear();  // images already written stay on disk, not in the report
    }
}

// "not-lit" when no key light the shader takes changes kSharePercent of the pixels by more than
// kVisible against the unlit render; returns the counts ("directional 0, point 3 of 4096").
bool notLit(const ShaderCheck& c, const LightSupport& support, std::string& counts) {
    const render::RenderedFrame* none = c.frame("no lights");
    if (!none) return false;
    std::vector<std::string> keys{"directional"};
    if (support.point) keys.push_back("point");
    if (support.spot) keys.push_back("spot");
    for (const std::string& key : keys) {
        const render::RenderedFrame* lit = c.frame(key);
        if (!lit) return false;
        const size_t changed = pixelsChanged(lit->image, none->image, kVisible);
        if (atLeastShare(changed, lit->image)) return false;
        counts += (counts.empty() ? "" : ", ") + key + " " + std::to_string(changed);
    }
    counts += " of " + std::to_string(size_t{none->image.width()} * none->image.height());
    return true;
}

// "non-linear" when `intensity` failed but every doubled light brightens (no pixel darker than
// with the light once, within half-float rounding) and one of them brightens kSharePercent of the
// pixels by more than kVisible: the shader responds to intensity, only not in proportion.
bool nonLinear(const ShaderCheck& c, const LightSupport& support, std::string& counts) {
    std::vector<std::pair<std::string, std::string>> cases{{"directional", "directional x2"}};
    if (support.point) cases.emplace_back("point", "point x2");
    bool responds = false;
    for (const auto& [once, twice] : cases) {
        const render::RenderedFrame* a = c.frame(once);
        const render::RenderedFrame* b = c.frame(twice);
        if (!a || !b) return false;
        const Growth growth = contributionGrowth(a->image, b->image, kZero, 2 * kHalfUlp, kVisible);
        if (growth.shrinking > 0) return false;
        responds = responds || atLeastShare(growth.growing, a->image);
        counts += (counts.empty() ? "" : ", ") + once + " x2 brightens " +
                  std::to_string(growth.growing);
    }
    return responds;
}

// Decides the report's LightingModel from the renders and marks the relations that do not apply.
void classify(ShaderCheck& c, const LightSupport& support, ShaderReport& report) {
    if (!report.error.empty()) return;
    std::string counts;
    if (notLit(c, support, counts)) {
        report.model = LightingModel::NotLit;
        report.modelReason = "not a lit shader: no key light changes 2% of the pixels by > 1/64 (" +
                             counts + ")";
        markNotApplicable(c, notLitRelations(), report.modelReason);
        return;
    }
    counts.clear();
    if (c.outcomeOf("intensity").verdict == Verdict::Fail && nonLinear(c, support, counts)) {
        report.model = LightingModel::NonLinear;
        report.modelReason =
            "non-linear model: a doubled light brightens, darkens nothing, but does not double "
            "its contribution (" +
            counts + " pixels): intensity is n/a";
        markNotApplicable(c, {"intensity"}, report.modelReason);
    }
}

}  // namespace

const char* modelName(LightingModel model) {
    switch (model) {
        case LightingModel::Lit:
            return "lit";
        case LightingModel::NotLit:
            return "not-lit";
        case LightingModel::NonLinear:
            return "non-linear";
    }
    return "?";
}

const std::vector<std::string>& notLitRelations() {
    static const std::vector<std::string> kNames{"dark",         "lit",        "out_of_range",
                                                 "black_cookie", "white_cookie", "additivity",
                                                 "additivity_ldr", "intensity"};
    return kNames;
}

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass:
            return "pass";
        case Verdict::Fail:
            return "FAIL";
        case Verdict::NotApplicable:
            return "n/a";
    }
    return "?";
}

bool ShaderReport::passed() const {
    if (!error.empty()) return false;
    for (const RelationOutcome& outcome : relations)
        if (outcome.verdict == Verdict::Fail) return false;
    return true;
}

size_t ShaderReport::litVariantsDrawn() const {
    size_t count = 0;
    for (const std::string& variant : variants)
        if (variant.find("(LightMode ForwardBase)") != std::string::npos ||
            variant.find("(LightMode ForwardAdd)") != std::string::npos)
            ++count;
    return count;
}

const std::vector<std::string>& relationNames() {
    static const std::vector<std::string> kNames{
        "finite",     "dark",           "lit",       "out_of_range", "black_cookie", "white_cookie",
        "additivity", "additivity_ldr", "intensity", "translation",  "rotation",     "mirror",
        "scale",      "light_axis",     "forward_deferred", "every_variant"};
    return kNames;
}

std::vector<reader::ShaderView> lightingShaders(const std::vector<const reader::Pack*>& packs) {
    std::vector<reader::ShaderView> shaders;
    std::set<std::string, std::less<>> seen;
    for (const reader::Pack* pack : packs) {
        for (size_t i = 0; i < pack->shaderCount(); ++i) {
            reader::ShaderView shader = pack->shader(i);
            if (!shader.pass("ForwardBase")) continue;
            if (seen.insert(std::string(shader.name())).second) shaders.push_back(shader);
        }
    }
    return shaders;
}

PropertyRunner::PropertyRunner(render::Renderer& renderer, PropertyOptions options)
    : mRenderer(renderer), mOptions(std::move(options)) {}

ShaderReport PropertyRunner::check(const reader::ShaderView& shader) {
    ShaderReport report;
    report.shader = std::string(shader.name());
    ShaderCheck check(mRenderer, mOptions, report);
    auto cookies = writeCookies(mOptions.outDir);
    if (!cookies) {
        report.error = cookies.error().detail;
        return report;
    }
    for (const char* lightMode : {"ForwardBase", "ForwardAdd"}) {
        if (std::optional<reader::PassView> pass = shader.pass(lightMode))
            report.litVariants += pass->variantCount();
    }
    const LightSupport support = lightSupportOf(shader);
    report.lights = "directional";
    if (support.point) report.lights += " point";
    if (support.spot) report.lights += " spot";
    if (support.directionalCookie) report.lights += " directional-cookie";
    if (support.pointCookie) report.lights += " point-cookie";
    const std::string noDirectionalShadows =
        checkRelations(check, report.shader, support, *cookies, mOptions.size);
    checkEveryVariant(check, shader, report, noDirectionalShadows);
    classify(check, support, report);
    return report;
}

}  // namespace varc::properties
