# SPDX-License-Identifier: Apache-2.0
# varc::vulkan: the headless Vulkan foundation of the runtime (context, RAII handles, offscreen
# targets, readback, PNG). Included from runtime/CMakeLists.txt. Never links glslang.
find_package(Vulkan REQUIRED)
find_package(PNG REQUIRED)

add_library(varc_vulkan STATIC
    src/vulkan/Buffer.cpp
    src/vulkan/CheckVk.cpp
    src/vulkan/DeviceImage.cpp
    src/vulkan/DeviceSetup.cpp
    src/vulkan/Image.cpp
    src/vulkan/InstanceSetup.cpp
    src/vulkan/Png.cpp
    src/vulkan/RenderPass.cpp
    src/vulkan/RenderTarget.cpp
    src/vulkan/Sampler.cpp
    src/vulkan/ShaderModule.cpp
    src/vulkan/Texture.cpp
    src/vulkan/ValidationLog.cpp
    src/vulkan/VulkanContext.cpp
)
add_library(varc::vulkan ALIAS varc_vulkan)
target_include_directories(varc_vulkan
    PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(varc_vulkan
    PUBLIC Vulkan::Vulkan varc::core
    PRIVATE PNG::PNG)
varc_target_defaults(varc_vulkan)
