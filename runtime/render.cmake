# SPDX-License-Identifier: Apache-2.0
# varc::render: pipelines, uniforms and descriptors for pack variants on Vulkan (issue #5).
# Included from runtime/CMakeLists.txt. Never links glslang.
find_package(glm CONFIG REQUIRED)

add_library(varc_render STATIC
    src/render/BuiltinTextures.cpp
    src/render/CameraTargetCache.cpp
    src/render/DeferredRenderer.cpp
    src/render/DeferredTargets.cpp
    src/render/DeferredValues.cpp
    src/render/DescriptorSlots.cpp
    src/render/Draw.cpp
    src/render/DrawResources.cpp
    src/render/ForwardRenderer.cpp
    src/render/GpuMesh.cpp
    src/render/LightVolume.cpp
    src/render/RendererBase.cpp
    src/render/PipelineCacheFile.cpp
    src/render/RenderStateResolver.cpp
    src/render/SceneValues.cpp
    src/render/ShaderValues.cpp
    src/render/SinglePassRenderer.cpp
    src/render/SinglePassValues.cpp
    src/render/UniformBlockWriter.cpp
    src/render/VariantPipeline.cpp
    src/render/VertexLayout.cpp
)
add_library(varc::render ALIAS varc_render)
target_include_directories(varc_render
    PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(varc_render PUBLIC varc::runtime varc::vulkan varc::scene glm::glm)
varc_target_defaults(varc_render)
