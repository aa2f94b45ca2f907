// SPDX-License-Identifier: Apache-2.0
#include "varc/cli/RenderCommands.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <utility>
#include <vector>

#include "PropertyValidation.h"
#include "ValidationCoverage.h"
#include "ValidationReport.h"
#include "varc/image/Png.h"
#include "varc/reader/Pack.h"
#include "varc/reader/VariantRequests.h"
#include "varc/reference/DeferredReference.h"
#include "varc/reference/ImageCompare.h"
#include "varc/reference/ReferenceRenderer.h"
#include "varc/reference/SceneTolerance.h"
#include "varc/reference/SinglePassReference.h"
#include "varc/render/PipelineCacheFile.h"
#include "varc/render/SceneRenderer.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::cli {

namespace {

// Opens every pack; nullopt after printing why one failed.
std::optional<std::vector<reader::Pack>> openPacks(const std::vector<std::string>& paths,
                                                   std::ostream& err) {
    std::vector<reader::Pack> packs;
    for (const std::string& path : paths) {
        auto pack = reader::Pack::open(path);
        if (!pack) {
            err << "varc: error: " << pack.error().detail << "\n";
            return std::nullopt;
        }
        packs.push_back(std::move(*pack));
    }
    return packs;
}

// The renderer for every scene path, sharing the Vulkan context, the packs and |cache|.
Result<render::SceneRenderer> createSceneRenderer(vulkan::VulkanContext& context,
                                                  const std::vector<reader::Pack>& packs,
                                                  VkPipelineCache cache) {
    std::vector<const reader::Pack*> pointers;
    for (const reader::Pack& pack : packs) pointers.push_back(&pack);
    auto renderer = render::SceneRenderer::create(context, std::move(pointers));
    if (renderer) renderer->usePipelineCache(cache);
    return renderer;
}

// The CPU reference for the scene's path.
Result<reference::ReferenceImage> renderReferenceFor(const scene::Scene& scene) {
    if (scene.camera.path == scene::RenderPath::SinglePass)
        return reference::renderSinglePassReference(scene);
    if (scene.camera.path == scene::RenderPath::Deferred)
        return reference::renderDeferredReference(scene);
    return reference::renderReference(scene);
}

struct SceneOutcome {
    bool ok = false;          // rendered and compared
    bool passed = false;      // comparison within tolerance
    std::string noReference;  // why the scene has no reference model ("" when it has one)
    std::string error;        // why it could not render
    render::RenderedFrame frame;
    image::Image shown;           // the frame as written (HDR tonemapped), Rgba8
    image::Image referenceShown;  // the reference as written, Rgba8 (empty before comparing)
    reference::CompareResult comparison;
    double seconds = 0;
};

// Renders |scenePath| and, when |compare|, its reference; writes the PNGs that are asked for.
// With |allowNoReference|, a scene whose materials name no reference model is rendered and
// reported (SceneOutcome::noReference) instead of failing.
SceneOutcome renderScene(render::Renderer& renderer, const std::string& scenePath, bool compare,
                         const std::string& renderPng, const std::string& referencePng,
                         const std::string& diffPng, bool allowNoReference = false) {
    SceneOutcome outcome;
    auto start = std::chrono::steady_clock::now();
    auto scene = scene::loadScene(scenePath);
    if (!scene) {
        outcome.error = scene.error().detail;
        return outcome;
    }
    auto frame = renderer.render(*scene);
    if (!frame) {
        outcome.error = scenePath + ": " + frame.error().detail;
        return outcome;
    }
    outcome.frame = std::move(*frame);
    outcome.shown = outcome.frame.image.isFloat()
                        ? outcome.frame.image.toRgba8(image::Tonemap::Reinhard)
                        : outcome.frame.image;
    if (!renderPng.empty()) {
        if (Status written = image::writePng(renderPng, outcome.shown); !written) {
            outcome.error = written.error().detail;
            return outcome;
        }
    }
    outcome.ok = true;
    if (compare) {
        auto expected = renderReferenceFor(*scene);
        if (!expected && expected.error().code == ErrorCode::NotFound && !allowNoReference) {
            outcome.ok = false;
            outcome.error = scenePath + ": reference: " + expected.error().detail;
            return outcome;
        }
        if (!expected && expected.error().code == ErrorCode::NotFound) {
            outcome.noReference = expected.error().detail;  // rendered, nothing to compare with
            return outcome;
        }
        if (!expected) {
            outcome.ok = false;
            outcome.error = scenePath + ": reference: " + expected.error().detail;
            return outcome;
        }
        outcome.comparison =
            reference::compareImages(outcome.frame.image, expected->color, expected->classes,
                                     reference::toleranceFor(*scene),
                                     expected->colorHigh.width() ? &expected->colorHigh : nullptr);
        outcome.passed = outcome.comparison.passed;
        outcome.referenceShown = expected->color.toRgba8(
            scene->camera.hdr ? image::Tonemap::Reinhard : image::Tonemap::Clamp);
        // An image asked for and not written fails the scene: a run that exits 0 has written
        // everything it was asked to.
        if (!referencePng.empty()) {
            Status written = image::writePng(referencePng, outcome.referenceShown);
            if (!written) {
                outcome.ok = false;
                outcome.error = written.error().detail;
                return outcome;
            }
        }
        if (!diffPng.empty() && outcome.comparison.diff.width() > 0) {
            Status written = image::writePng(diffPng, outcome.comparison.diff);
            if (!written) {
                outcome.ok = false;
                outcome.error = written.error().detail;
                return outcome;
            }
        }
    }
    outcome.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
}

std::optional<vulkan::VulkanContext> makeContext(std::ostream& err) {
    auto context = vulkan::VulkanContext::create();
    if (!context) {
        err << "varc: error: " << context.error().detail << "\n";
        return std::nullopt;
    }
    return std::move(*context);
}

// The --pipeline-cache file, when asked for; a file for another device or driver is reported
// and replaced, never an error.
std::optional<render::PipelineCacheFile> openPipelineCache(const RenderSessionOptions& options,
                                                           vulkan::VulkanContext& context,
                                                           std::ostream& err) {
    if (options.pipelineCachePath.empty()) return std::nullopt;
    auto cache = render::PipelineCacheFile::open(context, options.pipelineCachePath);
    if (!cache) {
        err << "varc: warning: pipeline cache not used: " << cache.error().detail << "\n";
        return std::nullopt;
    }
    if (!cache->rejectedReason().empty()) {
        err << "varc: note: " << options.pipelineCachePath << " not used ("
            << cache->rejectedReason() << "); starting a new cache\n";
    }
    return std::move(*cache);
}

void savePipelineCache(const std::optional<render::PipelineCacheFile>& cache, std::ostream& err) {
    if (!cache) return;
    if (Status saved = cache->save(); !saved)
        err << "varc: warning: " << saved.error().detail << "\n";
}

// What render and validate draw with, alive together: the renderer points at the packs, the
// context and the cache, so the session lives on the heap and never moves.
struct RenderSession {
    std::vector<reader::Pack> packs;
    std::optional<vulkan::VulkanContext> context;
    std::optional<render::PipelineCacheFile> cache;
    std::optional<render::SceneRenderer> renderer;
};

// Opens the packs, the Vulkan context, the --pipeline-cache file and the renderer; nullptr after
// printing why, with |exitCode| set (usage errors for packs and the device, failure otherwise).
std::unique_ptr<RenderSession> openRenderSession(const RenderSessionOptions& options,
                                                 std::ostream& err, int& exitCode) {
    auto session = std::make_unique<RenderSession>();
    exitCode = kExitUsage;
    auto packs = openPacks(options.packPaths, err);
    if (!packs) return nullptr;
    session->packs = std::move(*packs);
    session->context = makeContext(err);
    if (!session->context) return nullptr;
    session->cache = openPipelineCache(options, *session->context, err);
    auto renderer = createSceneRenderer(*session->context, session->packs,
                                        session->cache ? session->cache->handle() : VK_NULL_HANDLE);
    if (!renderer) {
        err << "varc: error: " << renderer.error().detail << "\n";
        exitCode = kExitFailure;
        return nullptr;
    }
    session->renderer.emplace(std::move(*renderer));
    return session;
}

// Adds the shaders of |scenePath|'s materials that name no reference model to |shaders|.
void addUnreferencedShaders(const std::string& scenePath, std::set<std::string>& shaders) {
    auto scene = scene::loadScene(scenePath);
    if (!scene) return;  // it rendered a moment ago; nothing to add if it is gone
    for (const scene::Object& object : scene->objects) {
        if (scene::referenceModelOf(object.material).empty())
            shaders.insert(object.material.shader);
    }
}

// Prints each miss a draw drew another variant for, once; strict misses are the render's error.
void printNewMisses(reader::VariantRequests& requests, std::ostream& err) {
    for (const reader::VariantMiss& miss : requests.takeNewMisses()) {
        if (miss.policy == variants::SelectionPolicy::Closest ||
            miss.policy == variants::SelectionPolicy::First) {
            err << "varc: warning: " << miss.report << "\n";
        }
    }
}

size_t distinctCount(const std::vector<std::string>& names) {
    return std::set<std::string>(names.begin(), names.end()).size();
}

}  // namespace

int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err) {
    int exitCode = kExitOk;
    std::unique_ptr<RenderSession> session = openRenderSession(options.session, err, exitCode);
    if (!session) return exitCode;
    bool compare = !options.referencePath.empty() || !options.diffPath.empty();
    reader::VariantRequests requests;
    session->renderer->useVariantRequests(&requests, options.variantPolicy);
    SceneOutcome outcome = renderScene(*session->renderer, options.scenePath, compare,
                                       options.outputPath, options.referencePath, options.diffPath);
    printNewMisses(requests, err);
    if (!outcome.error.empty()) err << "varc: error: " << outcome.error << "\n";
    savePipelineCache(session->cache, err);
    // Written after a failed render too: the requests made so far show what the pack lacks.
    if (!options.usageLogPath.empty()) {
        if (Status written = requests.writeUsageLog(options.usageLogPath); !written) {
            err << "varc: error: " << written.error().detail << "\n";
            return kExitFailure;
        }
    }
    if (!outcome.ok) return kExitFailure;
    out << "rendered " << options.scenePath << ": " << outcome.frame.draws << " draws, "
        << distinctCount(outcome.frame.variants) << " variants -> " << options.outputPath << "\n";
    for (const std::string& variant : outcome.frame.variants) out << "  " << variant << "\n";
    if (compare) {
        out << outcome.comparison.message << "\n";
        return outcome.passed ? kExitOk : kExitFailure;
    }
    return kExitOk;
}

namespace {

// What the scenes of a validate run add up to.
struct ValidateTotals {
    int failures = 0;
    size_t unreferenced = 0;         // rendered, but no material names a reference model
    std::set<std::string> compared;  // variants drawn in scenes that matched the reference
    std::set<std::string> unreferencedShaders;  // checked by their properties instead
};

// Prints |outcome|'s row of the table (and why it failed, or has no reference, on |err|), adds it
// to |totals| and returns its result: "pass", "FAIL", "ERROR" or "no reference".
std::string tallyScene(const std::string& stem, const SceneOutcome& outcome, ValidateTotals& totals,
                       std::ostream& out, std::ostream& err) {
    char line[256];
    if (!outcome.ok) {
        ++totals.failures;
        std::snprintf(line, sizeof line, "%-28s %6s %9s %9s %10s %7s  %s\n", stem.c_str(), "-", "-",
                      "-", "-", "-", "ERROR");
        out << line;
        err << "varc: error: " << outcome.error << "\n";
        return "ERROR";
    }
    if (!outcome.noReference.empty()) {
        ++totals.unreferenced;
        std::snprintf(line, sizeof line, "%-28s %6u %9zu %9s %10s %6.2fs  %s\n", stem.c_str(),
                      outcome.frame.draws, distinctCount(outcome.frame.variants), "-", "-",
                      outcome.seconds, "no reference");
        out << line;
        err << stem << ": no reference: " << outcome.noReference << "\n";
        return "no reference";
    }
    if (!outcome.passed) ++totals.failures;
    if (outcome.passed)
        totals.compared.insert(outcome.frame.variants.begin(), outcome.frame.variants.end());
    std::snprintf(line, sizeof line, "%-28s %6u %9zu %9.2f %10.3f %6.2fs  %s\n", stem.c_str(),
                  outcome.frame.draws, distinctCount(outcome.frame.variants),
                  static_cast<double>(outcome.comparison.maxErrorLsb),
                  static_cast<double>(outcome.comparison.meanSignedErrorLsb), outcome.seconds,
                  outcome.passed ? "pass" : "FAIL");
    out << line;
    if (!outcome.passed) err << stem << ": " << outcome.comparison.message << "\n";
    return outcome.passed ? "pass" : "FAIL";
}

// |image| as a PNG for the report, when there is one to show.
void addReportImage(ReportScene& scene, const char* caption, const image::Image& image) {
    if (image.width() == 0) return;
    if (auto png = image::encodePng(image)) scene.images.push_back({caption, std::move(*png)});
}

// The report's record of one scene: its result, errors, variants and images (GPU, reference,
// amplified difference and pixel-class mask, those it has).
ReportScene reportSceneOf(const std::string& scenePath, const SceneOutcome& outcome,
                          std::string status) {
    ReportScene scene;
    scene.name = std::filesystem::path(scenePath).stem().string();
    scene.path = scenePath;
    scene.status = std::move(status);
    scene.message = !outcome.ok                    ? outcome.error
                    : !outcome.noReference.empty() ? outcome.noReference
                                                   : outcome.comparison.message;
    scene.compared = outcome.ok && outcome.noReference.empty();
    scene.draws = outcome.frame.draws;
    scene.maxErrorLsb = outcome.comparison.maxErrorLsb;
    scene.meanSignedErrorLsb = outcome.comparison.meanSignedErrorLsb;
    scene.meanAbsErrorLsb = outcome.comparison.meanAbsErrorLsb;
    scene.seconds = outcome.seconds;
    scene.variants = outcome.frame.variants;
    addReportImage(scene, "GPU", outcome.shown);
    addReportImage(scene, "reference", outcome.referenceShown);
    addReportImage(scene, "difference (amplified)", outcome.comparison.diff);
    addReportImage(scene, "edge/interval mask", outcome.comparison.mask);
    return scene;
}

// The *.json scenes in |scenesDir|, sorted; empty after printing why when there are none.
std::vector<std::string> findScenes(const std::string& scenesDir, std::ostream& err) {
    std::vector<std::string> scenes;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(scenesDir, error)) {
        if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
    }
    if (error || scenes.empty()) {
        err << "varc: error: no *.json scenes in '" << scenesDir << "'\n";
        return {};
    }
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

// Writes |report| to --report; false after printing why it could not be written.
bool writeReport(const ValidationReport& report, const ValidateOptions& options,
                 const std::set<std::string>& compared, std::ostream& out, std::ostream& err) {
    if (Status written = report.write(options.reportPath, compared); !written) {
        err << "varc: error: report: " << written.error().detail << "\n";
        return false;
    }
    out << "report: " << options.reportPath << "\n";
    return true;
}

// `varc validate --properties [--report PAGE]`: the property checks of every lit shader.
int runValidatePropertiesOnly(const ValidateOptions& options, std::ostream& out,
                              std::ostream& err) {
    int exitCode = kExitOk;
    std::unique_ptr<RenderSession> session = openRenderSession(options.session, err, exitCode);
    if (!session) return exitCode;
    std::vector<properties::ShaderReport> reports;
    exitCode = runValidateProperties(session->packs, *session->context, *session->renderer, options,
                                     out, err, nullptr, &reports);
    savePipelineCache(session->cache, err);
    if (!options.reportPath.empty()) {
        ValidationReport report(session->packs, options.session.packPaths);
        report.addProperties(std::move(reports));
        if (!writeReport(report, options, {}, out, err)) return kExitFailure;
    }
    return exitCode;
}

}  // namespace

int runValidate(const ValidateOptions& options, std::ostream& out, std::ostream& err) {
    if (options.properties) return runValidatePropertiesOnly(options, out, err);
    const std::string& scenesDir = options.scenesDir;
    const std::string& outDir = options.outputDir;
    std::vector<std::string> scenes = findScenes(scenesDir, err);
    if (scenes.empty()) return kExitUsage;
    std::error_code error;
    std::filesystem::create_directories(outDir, error);
    if (error) {
        err << "varc: error: cannot create '" << outDir << "': " << error.message() << "\n";
        return kExitUsage;
    }
    int exitCode = kExitOk;
    std::unique_ptr<RenderSession> session = openRenderSession(options.session, err, exitCode);
    if (!session) return exitCode;
    std::optional<ValidationReport> report;
    if (!options.reportPath.empty()) report.emplace(session->packs, options.session.packPaths);
    char line[256];
    std::snprintf(line, sizeof line, "%-28s %6s %9s %9s %10s %7s  %s\n", "scene", "draws",
                  "variants", "max LSB", "mean LSB", "time", "result");
    out << line;
    ValidateTotals totals;
    for (const std::string& scenePath : scenes) {
        std::string stem = std::filesystem::path(scenePath).stem().string();
        std::string base = (std::filesystem::path(outDir) / stem).string();
        SceneOutcome outcome = renderScene(*session->renderer, scenePath, true, base + ".png",
                                           base + ".reference.png", base + ".diff.png", true);
        std::string status = tallyScene(stem, outcome, totals, out, err);
        if (status == "no reference") addUnreferencedShaders(scenePath, totals.unreferencedShaders);
        if (report) report->addScene(reportSceneOf(scenePath, outcome, std::move(status)));
    }
    out << scenes.size() - static_cast<size_t>(totals.failures) - totals.unreferenced << "/"
        << scenes.size() - totals.unreferenced << " scenes match the reference";
    if (totals.unreferenced)
        out << " (" << totals.unreferenced << " more rendered with no reference model)";
    out << "; PNGs in " << outDir << "\n";
    printValidationCoverage(session->packs, options.session.packPaths, totals.compared,
                            options.listUncovered, out);
    if (!totals.unreferencedShaders.empty()) {
        out << "materials without a reference model: their shaders' properties "
               "(docs/PROPERTIES.md)\n";
        std::vector<properties::ShaderReport> reports;
        int propertiesExit =
            runValidateProperties(session->packs, *session->context, *session->renderer, options,
                                  out, err, &totals.unreferencedShaders, &reports);
        if (propertiesExit != kExitOk) ++totals.failures;
        if (report) report->addProperties(std::move(reports));
    }
    savePipelineCache(session->cache, err);
    if (report && !writeReport(*report, options, totals.compared, out, err)) return kExitFailure;
    // With VARC_VULKAN_VALIDATION=1 the layer's warnings and errors fail the run too.
    if (session->context->validationMessageCount() > 0) {
        err << "varc: error: Vulkan validation reported "
            << session->context->validationMessageCount() << " messages:\n"
            << session->context->validationReport() << "\n";
        return kExitFailure;
    }
    return totals.failures ? kExitFailure : kExitOk;
}

}  // namespace varc::cli
