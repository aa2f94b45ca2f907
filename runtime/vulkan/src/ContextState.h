// SPDX-License-Identifier: Apache-2.0
// VulkanContext::State: the raw handles a context owns, destroyed in reverse creation order.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>
#include <utility>

#include "varc/core/Result.h"
#include "varc/vulkan/VulkanContext.h"
#include "ValidationLog.h"

namespace varc::vulkan {

// Heap-allocated so the ValidationLog keeps its address (it is the messenger's pUserData) when
// the context moves.
struct VulkanContext::State {
    explicit State(std::function<void(const ValidationMessage&)> observer)
        : log(std::move(observer)) {}
    ~State();
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    ValidationLog log;
    bool validation = false;
    bool debugUtils = false;
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger = nullptr;
    PFN_vkSetDebugUtilsObjectNameEXT setObjectName = nullptr;

    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkPhysicalDeviceProperties properties{};
    VkPhysicalDeviceMemoryProperties memoryProperties{};
    VkPhysicalDeviceFeatures enabledFeatures{};
    uint32_t queueFamily = 0;

    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    VkCommandPool commandPool = VK_NULL_HANDLE;
};

// Creates |state.instance| (plus the validation layer and messenger when |state.validation|),
// and resolves the debug-utils entry points. See VulkanContext::create for the errors.
Status createInstance(VulkanContext::State& state, const std::string& applicationName);

// Picks |state.physicalDevice| and a graphics |state.queueFamily|: the first device whose name
// contains |preferred| (case-insensitive), or lavapipe, or the first device, when |preferred|
// is empty. Fills properties and memoryProperties.
Status selectPhysicalDevice(VulkanContext::State& state, const std::string& preferred);

// Creates |state.device|, |state.queue| and |state.commandPool|.
Status createDevice(VulkanContext::State& state);

}  // namespace varc::vulkan
