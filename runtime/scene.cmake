# SPDX-License-Identifier: Apache-2.0
# varc::scene (scene model, meshes, cameras, forward light rules, light textures; no Vulkan) and
# varc::reference (the CPU reference renderer and image comparator of issue #5 §6). Included
# from runtime/CMakeLists.txt. varc::reference links varc::vulkan only for the CPU Image and PNG
# classes; it makes no Vulkan call.
find_package(glm CONFIG REQUIRED)

add_library(varc_scene STATIC
    src/scene/CameraMatrices.cpp
    src/scene/ForwardLights.cpp
    src/scene/LightTextures.cpp
    src/scene/Mesh.cpp
    src/scene/Scene.cpp
    src/scene/SceneParser.cpp
    src/scene/VisibleLights.cpp
)
add_library(varc::scene ALIAS varc_scene)
target_include_directories(varc_scene
    PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(varc_scene
    PUBLIC glm::glm varc::core
    PRIVATE nlohmann_json::nlohmann_json)
varc_target_defaults(varc_scene)

add_library(varc_reference STATIC
    src/reference/DeferredReference.cpp
    src/reference/ImageCompare.cpp
    src/reference/LinearTexture.cpp
    src/reference/Rasterizer.cpp
    src/reference/ReferenceRenderer.cpp
    src/reference/SceneTolerance.cpp
    src/reference/Shading.cpp
    src/reference/SinglePassReference.cpp
)
add_library(varc::reference ALIAS varc_reference)
target_include_directories(varc_reference
    PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(varc_reference PUBLIC varc::scene varc::core varc::vulkan glm::glm)
varc_target_defaults(varc_reference)
