// SPDX-License-Identifier: Apache-2.0
// Physical device selection and logical device creation for VulkanContext.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ContextState.h"
#include "varc/core/AsciiCase.h"
#include "varc/vulkan/CheckVk.h"

namespace varc::vulkan {

namespace {

// The name lavapipe reports, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
constexpr const char* kLavapipeName = "llvmpipe";

bool nameContains(const VkPhysicalDeviceProperties& properties, const std::string& needle) {
    return toAsciiLower(properties.deviceName).find(toAsciiLower(needle)) != std::string::npos;
}

std::optional<uint32_t> graphicsQueueFamily(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i) {
        if (families[i].queueCount > 0 && (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT)) {
            return i;
        }
    }
    return std::nullopt;
}

struct Candidate {
    VkPhysicalDevice device;
    VkPhysicalDeviceProperties properties;
    uint32_t queueFamily;
};

Result<std::vector<Candidate>> graphicsDevices(VkInstance instance, std::string& allNames) {
    uint32_t count = 0;
    if (Status status = checkVk(vkEnumeratePhysicalDevices(instance, &count, nullptr),
                                "vkEnumeratePhysicalDevices", CallSite::current());
        !status) {
        return status.error();
    }
    std::vector<VkPhysicalDevice> devices(count);
    if (Status status = checkVk(vkEnumeratePhysicalDevices(instance, &count, devices.data()),
                                "vkEnumeratePhysicalDevices", CallSite::current());
        !status) {
        return status.error();
    }
    std::vector<Candidate> candidates;
    for (uint32_t i = 0; i < count; ++i) {
        Candidate candidate{devices[i], {}, 0};
        vkGetPhysicalDeviceProperties(devices[i], &candidate.properties);
        allNames +=
            (allNames.empty() ? "'" : ", '") + std::string(candidate.properties.deviceName) + "'";
        if (std::optional<uint32_t> family = graphicsQueueFamily(devices[i])) {
            candidate.queueFamily = *family;
            candidates.push_back(candidate);
        }
    }
    return candidates;
}

// Device features varc may use, enabled when the device has them (lavapipe has all).
VkPhysicalDeviceFeatures wantedFeatures(VkPhysicalDevice device) {
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(device, &supported);
    VkPhysicalDeviceFeatures wanted{};
    wanted.independentBlend = supported.independentBlend;
    wanted.depthClamp = supported.depthClamp;
    wanted.depthBiasClamp = supported.depthBiasClamp;
    wanted.fillModeNonSolid = supported.fillModeNonSolid;
    wanted.samplerAnisotropy = supported.samplerAnisotropy;
    wanted.imageCubeArray = supported.imageCubeArray;
    wanted.shaderClipDistance = supported.shaderClipDistance;
    wanted.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
    wanted.geometryShader = supported.geometryShader;          // #pragma geometry
    wanted.tessellationShader = supported.tessellationShader;  // #pragma hull / domain
    return wanted;
}

}  // namespace

Status selectPhysicalDevice(VulkanContext::State& state, const std::string& preferred) {
    std::string allNames;
    Result<std::vector<Candidate>> candidates = graphicsDevices(state.instance, allNames);
    if (!candidates) return candidates.error();
    if (candidates->empty()) {
        return makeError(ErrorCode::NotFound,
                         "no Vulkan device with a graphics queue found" +
                             (allNames.empty() ? std::string() : " (devices: " + allNames + ")") +
                             "; install Debian's mesa-vulkan-drivers for the lavapipe CPU device");
    }
    const Candidate* chosen = nullptr;
    const std::string& needle = preferred.empty() ? std::string(kLavapipeName) : preferred;
    for (const Candidate& candidate : *candidates) {
        if (nameContains(candidate.properties, needle)) {
            chosen = &candidate;
            break;
        }
    }
    if (!chosen && !preferred.empty()) {
        return makeError(ErrorCode::NotFound, "no Vulkan device name contains '" + preferred +
                                                  "' (devices: " + allNames + ")");
    }
    if (!chosen) chosen = &candidates->front();
    state.physicalDevice = chosen->device;
    state.properties = chosen->properties;
    state.queueFamily = chosen->queueFamily;
    vkGetPhysicalDeviceMemoryProperties(state.physicalDevice, &state.memoryProperties);
    return Ok{};
}

// Device extensions varc enables when the device has them: VK_KHR_relaxed_block_layout, because
// HLSL cbuffers keep HLSL's packing (a float3 right after a float; core in Vulkan 1.1).
std::vector<const char*> wantedExtensions(VkPhysicalDevice device) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> available(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, available.data());
    std::vector<const char*> wanted;
    for (const VkExtensionProperties& extension : available) {
        if (std::string_view(extension.extensionName) == VK_KHR_RELAXED_BLOCK_LAYOUT_EXTENSION_NAME)
            wanted.push_back(VK_KHR_RELAXED_BLOCK_LAYOUT_EXTENSION_NAME);
    }
    return wanted;
}

Status createDevice(VulkanContext::State& state) {
    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = state.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    state.enabledFeatures = wantedFeatures(state.physicalDevice);
    VkDeviceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.pEnabledFeatures = &state.enabledFeatures;
    const std::vector<const char*> extensions = wantedExtensions(state.physicalDevice);
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    if (Status status = checkVk(vkCreateDevice(state.physicalDevice, &info, nullptr, &state.device),
                                "vkCreateDevice", CallSite::current());
        !status) {
        return status;
    }
    vkGetDeviceQueue(state.device, state.queueFamily, 0, &state.queue);

    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags =
        VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = state.queueFamily;
    return checkVk(vkCreateCommandPool(state.device, &poolInfo, nullptr, &state.commandPool),
                   "vkCreateCommandPool", CallSite::current());
}

}  // namespace varc::vulkan
