// SPDX-License-Identifier: Apache-2.0
// SinglePassRenderer: groups objects into draws (instanced batches where the lights allow it),
// fills the light buffer and per-draw light lists, records one render pass.
#include "varc/render/SinglePassRenderer.h"

#include <algorithm>
#include <deque>
#include <map>
#include <set>

#include "CameraTargetCache.h"
#include "Draw.h"
#include "GpuMesh.h"
#include "RendererBase.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/DrawResources.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"
#include "varc/render/SinglePassValues.h"
#include "varc/render/VertexLayout.h"
#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Mesh.h"
#include "varc/variants/RuntimeKeywords.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {

namespace {

constexpr const char* kArraySuffix = "Array";

// What an instanced variant reads per instance: the names P of its `PArray` members other than
// the object matrices, and how many instances its arrays hold (the smallest array).
struct InstancedLayout {
    std::set<std::string> properties;
    uint32_t maxInstances = 0;
};

InstancedLayout instancedLayout(const reader::VariantView& variant) {
    InstancedLayout layout;
    layout.maxInstances = UINT32_MAX;
    for (Stage stage : {Stage::Vertex, Stage::Fragment}) {
        std::optional<reader::ProgramView> program = variant.program(stage);
        if (!program) continue;
        for (const pack::UniformBlock& block : program->reflection().uniformBlocks) {
            for (const pack::BlockMember& member : block.members) {
                std::string_view name = member.name;
                if (member.arrayCount == 0 || !name.ends_with(kArraySuffix)) continue;
                layout.maxInstances = std::min(layout.maxInstances, member.arrayCount);
                name.remove_suffix(std::string_view(kArraySuffix).size());
                if (name != "unity_ObjectToWorld" && name != "unity_WorldToObject")
                    layout.properties.emplace(name);
            }
        }
    }
    if (layout.maxInstances == UINT32_MAX) layout.maxInstances = 1;
    return layout;
}

// One draw: an object, or an instanced batch of objects that share everything but their
// per-instance properties.
struct DrawGroup {
    const reader::Pack* pack = nullptr;
    std::optional<reader::PassView> pass;
    scene::MeshKind mesh = scene::MeshKind::Sphere;
    scene::ObjectLightList lights;
    std::map<std::string, scene::PropertyValue> sharedProperties;  // instanced ones blanked
    std::vector<pack::ShaderProperty> propertyDefaults;  // the shader's, for per-instance values
    std::vector<std::string> dynamicKeywords;            // ShaderView::dynamicKeywords
    bool mirrored = false;  // negative-determinant transform: culls the other side (one pipeline)
    std::vector<size_t> objects;
    const InstancedLayout* instancing = nullptr;  // null: the shader cannot instance
};

bool sameBatch(const DrawGroup& group, const DrawGroup& candidate) {
    return group.instancing && group.pack == candidate.pack &&
           group.pass->describe() == candidate.pass->describe() && group.mesh == candidate.mesh &&
           group.lights == candidate.lights && group.mirrored == candidate.mirrored &&
           group.sharedProperties == candidate.sharedProperties &&
           group.objects.size() < group.instancing->maxInstances;
}

// Per-instance arrays of an instanced batch: object matrices and each instanced property.
ShaderValues instanceValues(const scene::Scene& scene, const DrawGroup& group) {
    std::vector<glm::mat4> toWorld, toObject;
    std::map<std::string, std::vector<glm::vec4>> properties;
    for (size_t index : group.objects) {
        const scene::Object& object = scene.objects[index];
        toWorld.push_back(object.transform.localToWorld());
        toObject.push_back(glm::inverse(toWorld.back()));
        for (const std::string& name : group.instancing->properties) {
            const scene::Material material =
                withPropertyDefaults(object.material, group.propertyDefaults);
            auto it = material.properties.find(name);
            glm::vec4 value(0.0f);
            if (it != material.properties.end()) {
                if (const auto* v = std::get_if<glm::vec4>(&it->second)) value = *v;
                if (const auto* f = std::get_if<float>(&it->second))
                    value = glm::vec4(*f, 0.0f, 0.0f, 0.0f);
            }
            properties[name].push_back(value);
        }
    }
    ShaderValues values;
    values.setArray("unity_ObjectToWorldArray", toWorld);
    values.setArray("unity_WorldToObjectArray", toObject);
    for (const auto& [name, perInstance] : properties)
        values.setArray(name + kArraySuffix, perInstance);
    return values;
}

ShaderValues singleObjectValues(const scene::Object& object) {
    ShaderValues values;
    glm::mat4 toWorld = object.transform.localToWorld();
    values.set("unity_ObjectToWorld", toWorld);
    values.set("unity_WorldToObject", glm::inverse(toWorld));
    return values;
}

}  // namespace

struct SinglePassRenderer::State : RendererBase {
    CameraTargetCache<vulkan::RenderTarget> targets;
    // Per shader pass (PassView::describe()): the INSTANCING_ON variant's layout, or null.
    std::map<std::string, std::optional<InstancedLayout>> instancedLayouts;

    const InstancedLayout* instancing(const reader::PassView& pass);
    Result<std::vector<DrawGroup>> group(const scene::Scene& scene,
                                         const scene::VisibleLightSet& visible, bool instancing);
};

const InstancedLayout* SinglePassRenderer::State::instancing(const reader::PassView& pass) {
    auto [it, inserted] = instancedLayouts.try_emplace(pass.describe());
    if (inserted && pass.keywordIndex(variants::kInstancingKeyword)) {
        std::vector<std::string> keywords = {variants::kInstancingKeyword};
        auto variant = pass.lookup(keywords, variants::SelectionPolicy::Exact);
        if (variant) it->second = instancedLayout(*variant);
    }
    return it->second ? &*it->second : nullptr;
}

Result<std::vector<DrawGroup>> SinglePassRenderer::State::group(
    const scene::Scene& scene, const scene::VisibleLightSet& visible, bool instancing) {
    std::vector<DrawGroup> groups;
    for (size_t o = 0; o < scene.objects.size(); ++o) {
        const scene::Object& object = scene.objects[o];
        std::string what = objectLabel(o, object);
        DrawGroup candidate;
        auto shader = objectShader(what, object, &candidate.pack);
        if (!shader) return shader.error();
        candidate.pass = shader->pass(size_t{0});
        if (!candidate.pass)
            return makeError(ErrorCode::NotFound, what + ": the shader has no pass");
        candidate.mesh = object.mesh;
        candidate.propertyDefaults = shader->properties();
        candidate.dynamicKeywords = shader->dynamicKeywords();
        candidate.mirrored = glm::determinant(object.transform.localToWorld()) < 0.0f;
        candidate.lights = scene::objectLightList(scene, visible, object);
        candidate.sharedProperties =
            withPropertyDefaults(object.material, shader->properties()).properties;
        candidate.objects = {o};
        if (instancing) candidate.instancing = this->instancing(*candidate.pass);
        if (candidate.instancing) {
            for (const std::string& name : candidate.instancing->properties) {
                if (candidate.sharedProperties.count(name)) candidate.sharedProperties[name] = 0.0f;
            }
        }
        auto batch = std::find_if(groups.begin(), groups.end(),
                                  [&](const DrawGroup& g) { return sameBatch(g, candidate); });
        if (batch != groups.end()) {
            batch->objects.push_back(o);
        } else {
            groups.push_back(std::move(candidate));
        }
    }
    return groups;
}

SinglePassRenderer::SinglePassRenderer(std::unique_ptr<State> state) : mState(std::move(state)) {}
SinglePassRenderer::SinglePassRenderer(SinglePassRenderer&&) noexcept = default;
SinglePassRenderer& SinglePassRenderer::operator=(SinglePassRenderer&&) noexcept = default;
SinglePassRenderer::~SinglePassRenderer() = default;

Result<SinglePassRenderer> SinglePassRenderer::create(vulkan::VulkanContext& context,
                                                      std::vector<const reader::Pack*> packs) {
    auto state = std::make_unique<State>();
    if (Status ready = state->init(context, std::move(packs)); !ready) return ready.error();
    return SinglePassRenderer(std::move(state));
}

Result<RenderedFrame> SinglePassRenderer::render(const scene::Scene& scene,
                                                 const SinglePassOptions& options) {
    State& s = *mState;
    auto target = s.targets.get(scene.camera, [&](const scene::Camera& camera) {
        return createCameraTarget(*s.context, camera, "single-pass target");
    });
    if (!target) return target.error();
    const scene::VisibleLightSet visible = scene::selectVisibleLights(scene);
    auto groups = s.group(scene, visible, options.instancing);
    if (!groups) return groups.error();

    const ShaderValues camera = cameraValues(scene, scene::cameraMatrices(scene.camera));
    const ShaderValues lightBuffer = lightBufferValues(scene, visible);
    FrameStorage storage;
    std::vector<Draw> draws;
    RenderedFrame frame;
    for (const DrawGroup& group : *groups) {
        const scene::Object& first = scene.objects[group.objects.front()];
        const std::string what = objectLabel(group.objects.front(), first);
        const bool instanced = group.objects.size() > 1;
        std::vector<std::string> keywords;
        if (instanced) keywords.push_back(variants::kInstancingKeyword);
        auto variant = s.variantFor(*group.pass, group.pass->keyOf(keywords),
                                    variants::SelectionPolicy::Exact);
        if (!variant) return makeError(variant.error().code, what + ": " + variant.error().detail);
        auto material = s.objectMaterial(what, first.material, group.propertyDefaults,
                                         group.dynamicKeywords, storage);
        if (!material) return material.error();
        auto draw = s.objectDraw({what,
                                  group.pack,
                                  &*group.pass,
                                  &*variant,
                                  *material,
                                  first.transform.localToWorld(),
                                  group.mesh,
                                  {(*target)->renderPass(vulkan::LoadOp::Clear), true, 1},
                                  scene.camera.hdr ? 1u : 0u});
        if (!draw) return draw.error();
        draw->instances = static_cast<uint32_t>(group.objects.size());
        const ShaderValues& objects = storage.values.emplace_back(
            instanced ? instanceValues(scene, group) : singleObjectValues(first));
        const ShaderValues& lights = storage.values.emplace_back(drawLightValues(group.lights));
        draw->layers = {&objects, &lights, material->values, &lightBuffer, &camera};
        draws.push_back(std::move(*draw));
        frame.variants.push_back(variant->describe());
    }

    if (Status drawn = s.drawFrame(**target, draws, frame); !drawn) return drawn.error();
    return frame;
}

Result<RenderedFrame> SinglePassRenderer::render(const scene::Scene& scene) {
    return render(scene, SinglePassOptions{});
}

void SinglePassRenderer::usePipelineCache(VkPipelineCache cache) { mState->pipelineCache = cache; }

void SinglePassRenderer::useVariantRequests(reader::VariantRequests* requests,
                                            variants::SelectionPolicy missPolicy) {
    mState->variantRequests = requests;
    mState->missPolicy = missPolicy;
}

}  // namespace varc::render
