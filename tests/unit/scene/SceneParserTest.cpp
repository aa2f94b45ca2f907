// SPDX-License-Identifier: Apache-2.0
// parseScene / loadScene: the docs/SCENES.md format, defaults, and JSON-pointer error messages.
#include <gtest/gtest.h>

#include "varc/scene/Scene.h"

namespace varc::scene {
namespace {

std::string errorOf(std::string_view json) {
    auto scene = parseScene(json, "scenes/a.json");
    EXPECT_FALSE(scene.ok());
    return scene.ok() ? std::string() : scene.error().detail;
}

TEST(SceneParser, ReadsTheIssueExample) {
    auto scene = parseScene(R"({
        "camera": {"position": [0, 1, -4], "target": [0, 0.5, 0], "fov_y": 50, "near": 0.3,
                   "far": 50, "width": 128, "height": 96, "hdr": true, "path": "forward"},
        "ambient": {"color": [0.1, 0.2, 0.3]},
        "quality": {"pixel_light_count": 2},
        "objects": [{"mesh": "cube", "position": [1, 2, 3], "rotation": [0, 45, 0],
                     "scale": [2, 2, 2],
                     "material": {"shader": "Custom/My First Lighting Shader",
                                  "properties": {"_Tint": [1, 0.5, 0.25, 1], "_Smoothness": 0.5,
                                                 "_MainTex": "white"}}}],
        "lights": [{"type": "spot", "color": [1, 0.9, 0.8], "intensity": 2, "position": [0, 3, 0],
                    "rotation": [90, 0, 0], "range": 7, "spot_angle": 40, "cookie": "default",
                    "render_mode": "important"}]
    })",
                            "a.json");
    ASSERT_TRUE(scene.ok()) << scene.error().detail;
    EXPECT_EQ(scene->camera.position, glm::vec3(0, 1, -4));
    EXPECT_EQ(scene->camera.fovY, 50.0f);
    EXPECT_EQ(scene->camera.nearPlane, 0.3f);
    EXPECT_EQ(scene->camera.width, 128u);
    EXPECT_EQ(scene->camera.height, 96u);
    EXPECT_TRUE(scene->camera.hdr);
    EXPECT_EQ(scene->ambient, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(scene->pixelLightCount, 2);
    ASSERT_EQ(scene->objects.size(), 1u);
    const Object& o = scene->objects[0];
    EXPECT_EQ(o.mesh, MeshKind::Cube);
    EXPECT_EQ(o.transform.rotationDegrees, glm::vec3(0, 45, 0));
    EXPECT_EQ(o.material.shader, "Custom/My First Lighting Shader");
    EXPECT_EQ(std::get<glm::vec4>(o.material.properties.at("_Tint")), glm::vec4(1, 0.5f, 0.25f, 1));
    EXPECT_EQ(std::get<float>(o.material.properties.at("_Smoothness")), 0.5f);
    EXPECT_EQ(std::get<std::string>(o.material.properties.at("_MainTex")), "white");
    ASSERT_EQ(scene->lights.size(), 1u);
    const Light& l = scene->lights[0];
    EXPECT_EQ(l.type, LightType::Spot);
    EXPECT_EQ(l.finalColor(), glm::vec3(2.0f, 1.8f, 1.6f));
    EXPECT_EQ(l.range, 7.0f);
    EXPECT_EQ(l.spotAngle, 40.0f);
    EXPECT_EQ(l.cookie, "default");
    EXPECT_EQ(l.renderMode, LightRenderMode::Important);
}

TEST(SceneParser, TextureFilesAreNamedRelativeToTheSceneFile) {
    auto scene = parseScene(R"({"objects":[{"mesh":"sphere","material":{"properties":{
        "_MainTex":"textures/wood.png","_BumpMap":"bump","_DetailTex":"/abs/d.png"}}}]})",
                            "scenes/forward/a.json");
    ASSERT_TRUE(scene.ok()) << scene.error().detail;
    const auto& properties = scene->objects[0].material.properties;
    EXPECT_EQ(std::get<std::string>(properties.at("_MainTex")), "scenes/forward/textures/wood.png");
    EXPECT_EQ(std::get<std::string>(properties.at("_BumpMap")), "bump");
    EXPECT_EQ(std::get<std::string>(properties.at("_DetailTex")), "/abs/d.png");
    EXPECT_TRUE(isTextureFile("a.png"));
    EXPECT_FALSE(isTextureFile("white"));
}

TEST(SceneParser, PngCookiesAreForSpotAndDirectionalLights) {
    auto spot = parseScene(R"({"lights":[{"type":"spot","cookie":"c.png"}]})", "s/a.json");
    ASSERT_TRUE(spot.ok()) << spot.error().detail;
    EXPECT_EQ(spot->lights[0].cookie, "s/c.png");
    auto point = parseScene(R"({"lights":[{"type":"point","cookie":"c.png"}]})", "s/a.json");
    ASSERT_FALSE(point.ok());
    EXPECT_EQ(point.error().detail,
              "s/a.json: /lights/0/cookie: a point light's cookie is a cube map; PNG cookies are "
              "for spot and directional lights");
}

TEST(SceneParser, EmptyObjectGivesDefaults) {
    auto scene = parseScene("{}", "a.json");
    ASSERT_TRUE(scene.ok());
    EXPECT_EQ(scene->camera.position, glm::vec3(0, 0, -5));
    EXPECT_EQ(scene->camera.width, 256u);
    EXPECT_EQ(scene->pixelLightCount, 4);
    EXPECT_TRUE(scene->objects.empty());
}

TEST(SceneParser, MaterialKeywords) {
    auto scene = parseScene(R"({"objects":[{"mesh":"cube",
                                            "material":{"keywords":["_ALPHATEST_ON"]}}]})",
                            "a.json");
    ASSERT_TRUE(scene.ok()) << scene.error().detail;
    EXPECT_EQ(scene->objects[0].material.keywords, std::vector<std::string>{"_ALPHATEST_ON"});
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","material":{"keywords":"_ALPHATEST_ON"}}]})"),
              "scenes/a.json: /objects/0/material/keywords: expected an array of keyword names, "
              "got \"_ALPHATEST_ON\"");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","material":{"keywords":[1]}}]})")
                  .rfind("scenes/a.json: /objects/0/material/keywords/0: expected a string", 0),
              0u);
}

TEST(SceneParser, DeferredShaderNamesTheLightShader) {
    auto scene = parseScene(
        R"({"camera":{"path":"deferred","deferred_shader":"Custom/DeferredShading"}})", "a.json");
    ASSERT_TRUE(scene.ok());
    EXPECT_EQ(scene->camera.deferredShader, "Custom/DeferredShading");
    EXPECT_EQ(parseScene("{}", "a.json")->camera.deferredShader, "");  // the renderer's own
    EXPECT_EQ(errorOf(R"({"camera":{"deferred_shader":3}})"),
              "scenes/a.json: /camera/deferred_shader: expected a string, got number");
}

TEST(SceneParser, ColourWithThreeComponentsGetsAlphaOne) {
    auto scene = parseScene(
        R"({"objects":[{"mesh":"sphere","material":{"properties":{"_Color":[0.5,0.5,0.5]}}}]})",
        "a.json");
    ASSERT_TRUE(scene.ok());
    EXPECT_EQ(std::get<glm::vec4>(scene->objects[0].material.properties.at("_Color")),
              glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
}

TEST(SceneParser, BadEnumNamesPointerAndChoices) {
    EXPECT_EQ(
        errorOf(R"({"lights":[{"type":"point"},{"type":"spot"},{"type":"pointy"}]})"),
        "scenes/a.json: /lights/2/type: expected one of directional, point, spot, got 'pointy'");
}

TEST(SceneParser, UnknownKeysAreErrors) {
    EXPECT_EQ(
        errorOf(R"({"camera":{"fov":60}})").rfind("scenes/a.json: /camera/fov: unknown key", 0),
        0u);
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","colour":[1,1,1]}]})")
                  .rfind("scenes/a.json: /objects/0/colour: unknown key", 0),
              0u);
    EXPECT_EQ(errorOf(R"({"sky":1})").rfind("scenes/a.json: /sky: unknown key", 0), 0u);
}

TEST(SceneParser, MissingRequiredKeys) {
    EXPECT_EQ(errorOf(R"({"objects":[{}]})"), "scenes/a.json: /objects/0: missing key 'mesh'");
    EXPECT_EQ(errorOf(R"({"lights":[{"color":[1,1,1]}]})"),
              "scenes/a.json: /lights/0: missing key 'type'");
}

TEST(SceneParser, WrongTypesAndRanges) {
    EXPECT_EQ(errorOf(R"({"camera":{"position":[0,1]}})"),
              "scenes/a.json: /camera/position: expected an array of 3 numbers, got [0,1]");
    EXPECT_EQ(errorOf(R"({"camera":{"position":[0,"1",2]}})"),
              "scenes/a.json: /camera/position/1: expected a number, got string");
    EXPECT_EQ(errorOf(R"({"camera":{"width":0}})"),
              "scenes/a.json: /camera/width: expected an integer in [1, 16384], got 0");
    EXPECT_EQ(errorOf(R"({"camera":{"near":1,"far":0.5}})"),
              "scenes/a.json: /camera/far: expected far > near");
    EXPECT_EQ(errorOf(R"({"lights":[{"type":"point","range":-1}]})"),
              "scenes/a.json: /lights/0/range: expected a number > 0, got -1");
    EXPECT_EQ(errorOf(R"({"quality":{"pixel_light_count":1.5}})"),
              "scenes/a.json: /quality/pixel_light_count: expected an integer, got 1.5");
    EXPECT_EQ(errorOf(R"({"objects":{}})"), "scenes/a.json: /objects: expected an array");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","material":{"properties":{"_X":[]}}}]})")
                  .rfind("scenes/a.json: /objects/0/material/properties/_X: expected a number", 0),
              0u);
}

TEST(SceneParser, ReadsLightmapsAndMixedLighting) {
    auto scene = parseScene(R"({"lighting": {"mixed_mode": "subtractive"}, "objects": [
        {"mesh": "cube", "lightmap": {"baked": [2, 1, 0.5], "directional": [0, 2, 0, 0.5],
                                      "shadowmask": [1, 0, 0, 0],
                                      "scale_offset": [0.5, 0.5, 0.25, 0]}},
        {"mesh": "sphere", "lightmap": {"realtime": [0.1, 0.2, 0.3]}, "light_probes": true},
        {"mesh": "plane", "light_probes": false},
        {"mesh": "plane"}]})",
                            "a.json");
    ASSERT_TRUE(scene.ok()) << scene.error().detail;
    EXPECT_EQ(scene->mixedLighting, MixedLightingMode::Subtractive);
    const Lightmap& baked = *scene->objects[0].lightmap;
    EXPECT_EQ(*baked.baked, glm::vec3(2, 1, 0.5f));
    EXPECT_FALSE(baked.realtime.has_value());
    EXPECT_EQ(*baked.directional, glm::vec4(0, 1, 0, 0.5f));  // unit direction, w kept
    EXPECT_EQ(baked.shadowmask, glm::vec4(1, 0, 0, 0));
    EXPECT_EQ(baked.scaleOffset, glm::vec4(0.5f, 0.5f, 0.25f, 0));
    EXPECT_EQ(baked.realtimeScaleOffset, glm::vec4(1, 1, 0, 0));
    EXPECT_FALSE(scene->objects[0].usesLightProbes());  // lightmapped: no probes by default
    EXPECT_TRUE(scene->objects[1].usesLightProbes());
    EXPECT_FALSE(scene->objects[2].usesLightProbes());
    EXPECT_TRUE(scene->objects[3].usesLightProbes());
    EXPECT_FALSE(scene->objects[3].lightmap.has_value());
}

TEST(SceneParser, LightmapPngFilesAreNamedRelativeToTheSceneFile) {
    auto scene = parseScene(R"({"objects": [{"mesh": "cube", "lightmap": {
        "baked": "maps/baked.png", "realtime": [1, 1, 1], "directional": "maps/dir.png",
        "shadowmask": "/abs/mask.png"}}]})",
                            "scenes/a.json");
    ASSERT_TRUE(scene.ok()) << scene.error().detail;
    const Lightmap& m = *scene->objects[0].lightmap;
    EXPECT_EQ(m.bakedFile, "scenes/maps/baked.png");
    EXPECT_TRUE(m.baked.has_value());  // a file turns LIGHTMAP_ON on as a colour does
    EXPECT_EQ(m.realtimeFile, "");
    EXPECT_EQ(m.directionalFile, "scenes/maps/dir.png");
    EXPECT_TRUE(m.directional.has_value());
    EXPECT_EQ(m.shadowmaskFile, "/abs/mask.png");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","lightmap":{"baked":"baked.exr"}}]})"),
              "scenes/a.json: /objects/0/lightmap/baked: expected a PNG file (\"*.png\") or a "
              "value, got 'baked.exr'");
}

TEST(SceneParser, BadLightmapsNameThePointer) {
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","lightmap":{"shadowmask":[1,1,1,1]}}]})"),
              "scenes/a.json: /objects/0/lightmap: a lightmap needs 'baked' (LIGHTMAP_ON), "
              "'realtime' (DYNAMICLIGHTMAP_ON) or both");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","lightmap":{"baked":[1,-1,1]}}]})"),
              "scenes/a.json: /objects/0/lightmap/baked: expected components >= 0 (linear HDR), "
              "got [1,-1,1]");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","lightmap":{"baked":[1,1,1],
              "directional":[0,0,0]}}]})"),
              "scenes/a.json: /objects/0/lightmap/directional: expected a direction of non-zero "
              "length");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","lightmap":{"baked":[1,1,1],
              "scale_offset":[1,1]}}]})"),
              "scenes/a.json: /objects/0/lightmap/scale_offset: expected an array of 4 numbers, "
              "got [1,1]");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","lightmap":{"baked":[1,1,1],
              "shadowmask":[2,0,0,0]}}]})"),
              "scenes/a.json: /objects/0/lightmap/shadowmask: expected components in [0, 1] "
              "(baked occlusion)");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","light_probes":"yes"}]})"),
              "scenes/a.json: /objects/0/light_probes: expected true or false, got \"yes\"");
    EXPECT_EQ(errorOf(R"({"lighting":{"mixed_mode":"mixed"}})"),
              "scenes/a.json: /lighting/mixed_mode: expected one of baked_indirect, subtractive, "
              "shadowmask, distance_shadowmask, got 'mixed'");
    EXPECT_EQ(errorOf(R"({"objects":[{"mesh":"cube","lightmap":{"baked":[1,1,1],"uv":1}}]})")
                  .rfind("scenes/a.json: /objects/0/lightmap/uv: unknown key", 0),
              0u);
}

TEST(SceneParser, SyntaxErrorNamesPath) {
    EXPECT_EQ(errorOf("{\"camera\": ").rfind("scenes/a.json: /: invalid JSON", 0), 0u);
}

TEST(SceneParser, LoadSceneReportsUnreadableFile) {
    auto scene = loadScene("/nonexistent/varc/scene.json");
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().code, ErrorCode::IoError);
    EXPECT_NE(scene.error().detail.find("/nonexistent/varc/scene.json"), std::string::npos);
}

TEST(SceneParser, ShippedScenesParse) {
    for (const char* name :
         {"directional", "point", "spot", "point-cookie", "directional-cookie", "vertex-lights",
          "many-lights", "simple-diffuse", "glsl-vertex-lights",
          "lightmaps-shadowmask-shadow-vertex"}) {
        const std::string path =
            std::string(VARC_SOURCE_DIR) + "/tests/scenes/forward/" + name + ".json";
        auto scene = loadScene(path);
        EXPECT_TRUE(scene.ok()) << scene.error().detail;
    }
}

// The limits of docs/SECURITY.md: each accepted at the limit and refused one past it.
std::string sceneWithCamera(uint32_t width, uint32_t height) {
    return R"({"camera": {"width": )" + std::to_string(width) + R"(, "height": )" +
           std::to_string(height) + "}}";
}

TEST(SceneParserLimits, ImageSizeAtTheLimitAndPast) {
    EXPECT_TRUE(parseScene(sceneWithCamera(4096, 4096), "a.json").ok());
    EXPECT_TRUE(parseScene(sceneWithCamera(kMaxImageSide, 1), "a.json").ok());
    EXPECT_NE(errorOf(sceneWithCamera(4096, 4097)).find("at most 16777216"), std::string::npos);
    EXPECT_NE(errorOf(sceneWithCamera(kMaxImageSide + 1, 1)).find("/camera/width"),
              std::string::npos);
}

std::string sceneWithEntries(const char* key, const char* entry, size_t count) {
    std::string text = std::string("{\"") + key + "\": [";
    for (size_t i = 0; i < count; ++i) text += (i ? "," : "") + std::string(entry);
    return text + "]}";
}

TEST(SceneParserLimits, ObjectAndLightCountsAtTheLimitAndPast) {
    const char* object = R"({"mesh": "cube"})";
    const char* light = R"({"type": "point"})";
    EXPECT_TRUE(parseScene(sceneWithEntries("objects", object, kMaxSceneObjects), "a.json").ok());
    EXPECT_NE(errorOf(sceneWithEntries("objects", object, kMaxSceneObjects + 1))
                  .find("/objects: 4097 entries; at most 4096"),
              std::string::npos);
    EXPECT_TRUE(parseScene(sceneWithEntries("lights", light, kMaxSceneLights), "a.json").ok());
    EXPECT_NE(errorOf(sceneWithEntries("lights", light, kMaxSceneLights + 1))
                  .find("/lights: 1025 entries; at most 1024"),
              std::string::npos);
}

TEST(SceneParserLimits, NestingAtTheLimitAndPast) {
    auto nested = [](int depth) {  // {"camera": [[...]]}: |depth| levels in all
        return "{\"camera\": " + std::string(static_cast<size_t>(depth - 1), '[') +
               std::string(static_cast<size_t>(depth - 1), ']') + "}";
    };
    std::string atLimit = errorOf(nested(kMaxSceneNesting));
    EXPECT_EQ(atLimit.find("nested"), std::string::npos) << atLimit;  // refused for its shape
    EXPECT_NE(atLimit.find("/camera: expected an object"), std::string::npos) << atLimit;
    EXPECT_NE(errorOf(nested(kMaxSceneNesting + 1)).find("nested 33 levels deep; at most 32"),
              std::string::npos);
    // Brackets inside strings do not count.
    EXPECT_TRUE(
        parseScene(
            R"({"objects": [{"mesh": "cube", "name": "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[["}]})",
            "a.json")
            .ok());
}

TEST(SceneParserLimits, FileSizeAtTheLimitAndPast) {
    std::string padded = "{}" + std::string(kMaxSceneFileBytes - 2, ' ');
    EXPECT_TRUE(parseScene(padded, "a.json").ok());
    padded += ' ';
    EXPECT_NE(errorOf(padded).find("bytes; at most 16777216"), std::string::npos);
}

TEST(SceneParserLimits, ZeroScaleIsRefusedTinyAndMirroredScalesAreNot) {
    auto withScale = [](const char* scale) {
        return std::string(R"({"objects": [{"mesh": "cube", "scale": )") + scale + "}]}";
    };
    EXPECT_NE(errorOf(withScale("[1, 0, 1]")).find("/objects/0/scale/1: expected a scale"),
              std::string::npos);
    EXPECT_NE(errorOf(withScale("[1, 1, 1e-7]")).find("/objects/0/scale/2"), std::string::npos);
    EXPECT_TRUE(parseScene(withScale("[1e-6, 1, 1]"), "a.json").ok());
    EXPECT_TRUE(parseScene(withScale("[-1, 1, 1]"), "a.json").ok());
}

TEST(SceneParserLimits, LongValuesAreCutInMessages) {
    std::string wrongType =
        errorOf(R"({"camera": {"position": ")" + std::string(5000, 'x') + "\"}}");
    EXPECT_LT(wrongType.size(), 300u) << wrongType;
    EXPECT_NE(wrongType.find("expected an array of 3 numbers"), std::string::npos);
    EXPECT_NE(wrongType.find("..."), std::string::npos);
    std::string syntax = errorOf(R"({"camera": {"position": [)" + std::string(5000, '1') + "]}}");
    EXPECT_LT(syntax.size(), 300u) << syntax;
    EXPECT_NE(syntax.find("invalid JSON"), std::string::npos);
}

}  // namespace
}  // namespace varc::scene
