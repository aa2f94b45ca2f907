// SPDX-License-Identifier: Apache-2.0
// VulkanContext: a headless Vulkan instance, device, graphics queue and command pool.
#include "varc/vulkan/VulkanContext.h"

#include <cstdlib>
#include <optional>
#include <string>
#include <utility>

#include "varc/vulkan/CheckVk.h"
#include "ContextState.h"

namespace varc::vulkan {

namespace {

// Reads a non-empty environment variable, or returns an empty string.
std::string environment(const char* name) {
    const char* value = std::getenv(name);
    return value ? std::string(value) : std::string();
}

// Submits |commands| to |queue| and blocks until it has executed.
Status submitAndWaitForFence(VkDevice device, VkQueue queue, VkCommandBuffer commands) {
    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VkFence rawFence = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateFence(device, &fenceInfo, nullptr, &rawFence),
                                "vkCreateFence", CallSite::current());
        !status) {
        return status;
    }
    UniqueHandle<VkFence> fence(device, rawFence);
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    if (Status status = checkVk(vkQueueSubmit(queue, 1, &submit, fence.get()), "vkQueueSubmit",
                                CallSite::current());
        !status) {
        return status;
    }
    VkFence fences[] = {fence.get()};
    return checkVk(vkWaitForFences(device, 1, fences, VK_TRUE, UINT64_MAX), "vkWaitForFences",
                   CallSite::current());
}

}  // namespace

VulkanContext::State::~State() {
    if (device != VK_NULL_HANDLE) {
        vkDeviceWaitIdle(device);
        if (commandPool != VK_NULL_HANDLE) vkDestroyCommandPool(device, commandPool, nullptr);
        vkDestroyDevice(device, nullptr);
    }
    if (messenger != VK_NULL_HANDLE) destroyMessenger(instance, messenger, nullptr);
    if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
}

Result<VulkanContext> VulkanContext::create(const ContextOptions& options) {
    auto state = std::make_unique<State>(options.onMessage);
    state->validation =
        options.enableValidation.value_or(environment("VARC_VULKAN_VALIDATION") == "1");
    std::string preferred = environment("VARC_VULKAN_DEVICE");
    if (preferred.empty()) preferred = options.preferredDevice;

    if (Status status = createInstance(*state, options.applicationName); !status) {
        return status.error();
    }
    if (Status status = selectPhysicalDevice(*state, preferred); !status) return status.error();
    if (Status status = createDevice(*state); !status) return status.error();
    VulkanContext context(std::move(state));
    context.setObjectName(VK_OBJECT_TYPE_COMMAND_POOL,
                          reinterpret_cast<uint64_t>(context.commandPool()),
                          "VulkanContext command pool");
    return context;
}

VulkanContext::VulkanContext(std::unique_ptr<State> state) : mState(std::move(state)) {}
VulkanContext::VulkanContext(VulkanContext&&) noexcept = default;
VulkanContext& VulkanContext::operator=(VulkanContext&&) noexcept = default;
VulkanContext::~VulkanContext() = default;

VkInstance VulkanContext::instance() const { return mState->instance; }
VkPhysicalDevice VulkanContext::physicalDevice() const { return mState->physicalDevice; }
VkDevice VulkanContext::device() const { return mState->device; }
VkQueue VulkanContext::queue() const { return mState->queue; }
uint32_t VulkanContext::queueFamilyIndex() const { return mState->queueFamily; }
VkCommandPool VulkanContext::commandPool() const { return mState->commandPool; }
const VkPhysicalDeviceProperties& VulkanContext::properties() const { return mState->properties; }
const VkPhysicalDeviceMemoryProperties& VulkanContext::memoryProperties() const {
    return mState->memoryProperties;
}
const VkPhysicalDeviceFeatures& VulkanContext::enabledFeatures() const {
    return mState->enabledFeatures;
}
std::string VulkanContext::deviceName() const { return mState->properties.deviceName; }
bool VulkanContext::validationEnabled() const { return mState->validation; }
bool VulkanContext::debugUtilsEnabled() const { return mState->debugUtils; }

Result<uint32_t> VulkanContext::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                               VkMemoryPropertyFlags preferred) const {
    const VkPhysicalDeviceMemoryProperties& memory = mState->memoryProperties;
    std::optional<uint32_t> fallback;
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        VkMemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
        if (!(typeBits & (1u << i)) || (flags & required) != required) continue;
        if ((flags & preferred) == preferred) return i;
        if (!fallback) fallback = i;
    }
    if (fallback) return *fallback;
    return makeError(ErrorCode::Unsupported, "no Vulkan memory type has flags 0x" +
                                                 std::to_string(required) + " among type bits " +
                                                 std::to_string(typeBits));
}

Result<UniqueHandle<VkDeviceMemory>> VulkanContext::allocateMemory(
    const VkMemoryRequirements& requirements, VkMemoryPropertyFlags required,
    VkMemoryPropertyFlags preferred) const {
    Result<uint32_t> type = findMemoryType(requirements.memoryTypeBits, required, preferred);
    if (!type) return type.error();
    VkMemoryAllocateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = *type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    if (Status status = checkVk(vkAllocateMemory(device(), &info, nullptr, &memory),
                                "vkAllocateMemory", CallSite::current());
        !status) {
        return status.error();
    }
    return UniqueHandle<VkDeviceMemory>(device(), memory);
}

Status VulkanContext::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo allocateInfo{};
    allocateInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocateInfo.commandPool = commandPool();
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    if (Status status = checkVk(vkAllocateCommandBuffers(device(), &allocateInfo, &commands),
                                "vkAllocateCommandBuffers", CallSite::current());
        !status) {
        return status;
    }
    // Frees the command buffer on every path below.
    struct Free {
        VkDevice device;
        VkCommandPool pool;
        VkCommandBuffer commands;
        ~Free() { vkFreeCommandBuffers(device, pool, 1, &commands); }
    } freeOnExit{device(), commandPool(), commands};

    VkCommandBufferBeginInfo beginInfo{};
    beginInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (Status status = checkVk(vkBeginCommandBuffer(commands, &beginInfo), "vkBeginCommandBuffer",
                                CallSite::current());
        !status) {
        return status;
    }
    record(commands);
    if (Status status =
            checkVk(vkEndCommandBuffer(commands), "vkEndCommandBuffer", CallSite::current());
        !status) {
        return status;
    }
    return submitAndWaitForFence(device(), queue(), commands);
}

Status VulkanContext::waitIdle() const {
    return checkVk(vkDeviceWaitIdle(device()), "vkDeviceWaitIdle", CallSite::current());
}

std::size_t VulkanContext::validationMessageCount() const { return mState->log.count(); }
std::vector<ValidationMessage> VulkanContext::validationMessages() const {
    return mState->log.messages();
}
std::string VulkanContext::validationReport() const {
    std::string report;
    for (const ValidationMessage& message : mState->log.messages()) {
        report += toString(message) + "\n";
    }
    return report;
}
void VulkanContext::clearValidationMessages() { mState->log.clear(); }

void VulkanContext::setObjectName(VkObjectType type, uint64_t handle,
                                  const std::string& name) const {
    if (!mState->setObjectName || handle == 0) return;
    VkDebugUtilsObjectNameInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT;
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name.c_str();
    // Naming is best effort: a failure here must not fail the caller.
    (void)mState->setObjectName(device(), &info);
}

}  // namespace varc::vulkan
