// SPDX-License-Identifier: Apache-2.0
// The runtime on lavapipe (issue #5): pipeline creation plus the first draw per variant, with
// Mesa's on-disk shader cache disabled (cold) or warm, the frame time of the forward
// validation scenes once their pipelines exist, and what shadows add to a frame (#11). lavapipe compiles shaders lazily at the first
// draw, so "create + first draw" is what an application waits for.
// Needs the test pack: build the project with tests, run ctest -R vulkan.build_packs once, then
//   ./build/bench/varc_bench_render
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>

#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ProgramView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/DrawResources.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/VariantPipeline.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/RenderTarget.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {
namespace {

constexpr const char* kPack = VARC_BINARY_DIR "/tests/vulkan/packs/library.svpack";
constexpr const char* kMesaCache = VARC_BINARY_DIR "/bench-mesa-cache";

// A fresh context per run: Mesa reads MESA_SHADER_CACHE_DISABLE when the device is created.
std::optional<vulkan::VulkanContext> makeContext(bool cold) {
    if (cold) {
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    } else {
        unsetenv("MESA_SHADER_CACHE_DISABLE");
        setenv("MESA_SHADER_CACHE_DIR", kMesaCache, 1);
    }
    auto context = vulkan::VulkanContext::create();
    if (!context) return std::nullopt;
    return std::move(*context);
}

// Creates a pipeline for every forward-pass variant of the seed 000 shader and draws nothing but
// a single empty-vertex draw through it, which makes lavapipe compile the shaders.
void BM_PipelinePlusFirstDraw(benchmark::State& state) {
    bool cold = state.range(0) == 0;
    auto pack = reader::Pack::open(kPack);
    if (!pack) return state.SkipWithError("test pack missing: run ctest -R vulkan.build_packs");
    std::optional<vulkan::VulkanContext> context = makeContext(cold);
    if (!context) return state.SkipWithError("no Vulkan device");
    vulkan::RenderTargetDesc desc;
    desc.width = desc.height = 64;
    auto target = vulkan::RenderTarget::create(*context, desc);
    auto resources = DrawResources::create(*context, 1u << 20, 64);
    if (!target || !resources) return state.SkipWithError("target or resources failed");
    ShaderValues none;
    const ShaderValues* layers[] = {&none};
    auto shader = pack->findShader("Custom/My First Lighting Shader");
    if (!shader) return state.SkipWithError("seed 000 shader missing from the pack");
    size_t variants = 0;
    for (auto _ : state) {
        for (size_t p = 0; p < shader->passCount(); ++p) {
            reader::PassView pass = *shader->pass(p);
            for (size_t v = 0; v < pass.variantCount(); ++v) {
                auto pipeline = VariantPipeline::create(
                    *context, pass.variant(v), resolveRenderState(pass.renderState(), none),
                    {target->renderPass(vulkan::LoadOp::Clear), true, 1});
                if (!pipeline) return state.SkipWithError(pipeline.error().detail.c_str());
                Status ok = Ok{};
                Status drawn = context->submitAndWait([&](VkCommandBuffer commands) {
                    target->begin(commands, vulkan::LoadOp::Clear);
                    VkViewport viewport = target->viewport();
                    VkRect2D area = target->area();
                    vkCmdSetViewport(commands, 0, 1, &viewport);
                    vkCmdSetScissor(commands, 0, 1, &area);
                    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                      pipeline->pipeline());
                    ok = resources->bind(commands, *pipeline, layers,
                                         [](std::string_view, pack::ResourceDim) {
                                             return std::optional<TextureBinding>();
                                         });
                    if (ok) vkCmdDraw(commands, 3, 1, 0, 0);
                    target->end(commands);
                });
                (void)resources->reset();
                if (!drawn) return state.SkipWithError(drawn.error().detail.c_str());
                ++variants;
            }
        }
    }
    state.counters["variants"] =
        static_cast<double>(variants) / static_cast<double>(state.iterations());
    state.counters["per_variant_ms"] =
        benchmark::Counter(static_cast<double>(variants) * 1e-3,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PipelinePlusFirstDraw)
    ->ArgName("warm")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One forward validation scene per run, pipelines already created: the steady frame time.
void BM_ForwardSceneFrame(benchmark::State& state) {
    std::vector<std::string> scenes;
    for (const auto& entry :
         std::filesystem::directory_iterator(VARC_SOURCE_DIR "/tests/scenes/forward")) {
        if (entry.path().extension() == ".json") scenes.push_back(entry.path().string());
    }
    std::sort(scenes.begin(), scenes.end());
    auto index = static_cast<size_t>(state.range(0));
    if (index >= scenes.size()) return state.SkipWithError("no such scene");
    state.SetLabel(std::filesystem::path(scenes[index]).stem().string());
    auto pack = reader::Pack::open(kPack);
    if (!pack) return state.SkipWithError("test pack missing: run ctest -R vulkan.build_packs");
    std::optional<vulkan::VulkanContext> context = makeContext(false);
    if (!context) return state.SkipWithError("no Vulkan device");
    auto renderer = ForwardRenderer::create(*context, {&*pack});
    auto scene = scene::loadScene(scenes[index]);
    if (!renderer || !scene) return state.SkipWithError("renderer or scene failed");
    if (auto warm = renderer->render(*scene); !warm)
        return state.SkipWithError(warm.error().detail.c_str());
    for (auto _ : state) {
        auto frame = renderer->render(*scene);
        if (!frame) return state.SkipWithError(frame.error().detail.c_str());
        benchmark::DoNotOptimize(frame->draws);
    }
}
BENCHMARK(BM_ForwardSceneFrame)->DenseRange(0, 8)->Unit(benchmark::kMillisecond)->UseRealTime();

// The cost of real-time shadows per light type (#11): the frame time of one shadow scene (a
// plane, a sphere and a cube, 160², varc/SimpleDiffuse) lit by one spot or point light without
// shadows, with hard and with soft shadows (512² maps; a point light draws six faces). The
// difference to the unshadowed frame is what the shadow map and its sampling cost.
void BM_ShadowedFrame(benchmark::State& state) {
    const bool point = state.range(0) == 1;
    const auto shadows = static_cast<scene::ShadowType>(state.range(1));
    auto scene = scene::loadScene(VARC_SOURCE_DIR "/tests/scenes/forward/point-shadow-hard.json");
    if (!scene) return state.SkipWithError(scene.error().detail.c_str());
    scene::Light& light = scene->lights.front();
    light.shadows = shadows;
    if (!point) {
        light.type = scene::LightType::Spot;
        light.transform.rotationDegrees = {90.0f, 0.0f, 0.0f};  // straight down
        light.spotAngle = 100.0f;
    }
    const char* names[] = {"none", "hard", "soft"};
    state.SetLabel(std::string(point ? "point" : "spot") + " shadows " + names[state.range(1)]);
    auto pack = reader::Pack::open(kPack);
    if (!pack) return state.SkipWithError("test pack missing: run ctest -R vulkan.build_packs");
    std::optional<vulkan::VulkanContext> context = makeContext(false);
    if (!context) return state.SkipWithError("no Vulkan device");
    auto renderer = ForwardRenderer::create(*context, {&*pack});
    if (!renderer) return state.SkipWithError(renderer.error().detail.c_str());
    if (auto warm = renderer->render(*scene); !warm)
        return state.SkipWithError(warm.error().detail.c_str());
    for (auto _ : state) {
        auto frame = renderer->render(*scene);
        if (!frame) return state.SkipWithError(frame.error().detail.c_str());
        benchmark::DoNotOptimize(frame->draws);
    }
}
BENCHMARK(BM_ShadowedFrame)
    ->ArgNames({"point", "shadows"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace varc::render
