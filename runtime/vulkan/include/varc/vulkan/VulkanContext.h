// SPDX-License-Identifier: Apache-2.0
// VulkanContext: a headless Vulkan instance, device, graphics queue and command pool.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/ValidationMessage.h"

namespace varc::vulkan {

struct ContextOptions {
    // Case-insensitive substring of VkPhysicalDeviceProperties::deviceName, e.g. "llvmpipe".
    // Empty: prefer lavapipe (name contains "llvmpipe"), else the first device with a graphics
    // queue. A non-empty environment variable VARC_VULKAN_DEVICE overrides this field.
    std::string preferredDevice;
    // Enables VK_LAYER_KHRONOS_validation and a VK_EXT_debug_utils messenger that records every
    // warning and error. Unset: enabled iff the environment has VARC_VULKAN_VALIDATION=1.
    std::optional<bool> enableValidation;
    // Called for each recorded message, after it is recorded; may run on a driver thread.
    std::function<void(const ValidationMessage&)> onMessage;
    std::string applicationName = "varc";
};

// Owns the instance, the debug messenger, the device, one graphics queue and a command pool.
// Every UniqueHandle made from it must be destroyed first: declare the context before them.
// Not thread-safe (the command pool and queue are used without locks).
class VulkanContext {
public:
    // Creates a Vulkan 1.0 instance without surface extensions, picks a device (see
    // ContextOptions::preferredDevice) and creates a device with one graphics queue.
    // Errors: ErrorCode::NotFound when there is no Vulkan driver or device (the message names
    // Debian's mesa-vulkan-drivers) or no device matches the preferred name (the message lists
    // the devices); ErrorCode::Unsupported when validation is asked for but the layer is not
    // installed (names vulkan-validationlayers); ErrorCode::VulkanError for other failures.
    static Result<VulkanContext> create(const ContextOptions& options = {});

    VulkanContext(VulkanContext&&) noexcept;
    VulkanContext& operator=(VulkanContext&&) noexcept;
    ~VulkanContext();

    VkInstance instance() const;
    VkPhysicalDevice physicalDevice() const;
    VkDevice device() const;
    VkQueue queue() const;
    uint32_t queueFamilyIndex() const;
    VkCommandPool commandPool() const;
    const VkPhysicalDeviceProperties& properties() const;
    const VkPhysicalDeviceMemoryProperties& memoryProperties() const;
    const VkPhysicalDeviceFeatures& enabledFeatures() const;
    std::string deviceName() const;
    bool validationEnabled() const;
    bool debugUtilsEnabled() const;

    // Index of a memory type allowed by |typeBits| (VkMemoryRequirements::memoryTypeBits) that
    // has all |required| flags, preferring one that also has |preferred|.
    // Errors: ErrorCode::Unsupported when no type qualifies.
    Result<uint32_t> findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                    VkMemoryPropertyFlags preferred = 0) const;
    // Allocates memory for |requirements| from findMemoryType(...).
    Result<UniqueHandle<VkDeviceMemory>> allocateMemory(const VkMemoryRequirements& requirements,
                                                        VkMemoryPropertyFlags required,
                                                        VkMemoryPropertyFlags preferred = 0) const;

    // Records |record| into a fresh one-time command buffer, submits it and waits for it.
    // Errors: ErrorCode::VulkanError from allocation, submission or the wait.
    Status submitAndWait(const std::function<void(VkCommandBuffer)>& record);
    Status waitIdle() const;

    // Warnings and errors the messenger recorded since creation or the last clear; always
    // empty when validation is off. validationReport() joins them, one per line.
    std::size_t validationMessageCount() const;
    std::vector<ValidationMessage> validationMessages() const;
    std::string validationReport() const;
    void clearValidationMessages();

    // Names |handle| for validation messages and debuggers; a no-op without VK_EXT_debug_utils.
    void setObjectName(VkObjectType type, uint64_t handle, const std::string& name) const;
    template <typename T>
    void nameObject(const UniqueHandle<T>& handle, const std::string& name) const {
        setObjectName(HandleTraits<T>::kObjectType, reinterpret_cast<uint64_t>(handle.get()), name);
    }

    // Opaque; defined in src/vulkan/ContextState.h.
    struct State;

private:
    explicit VulkanContext(std::unique_ptr<State> state);
    std::unique_ptr<State> mState;
};

}  // namespace varc::vulkan
