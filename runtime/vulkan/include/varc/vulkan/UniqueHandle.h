// SPDX-License-Identifier: Apache-2.0
// UniqueHandle<VkT>: a move-only owner of one device-level Vulkan handle.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <type_traits>
#include <utility>

namespace varc::vulkan {

// HandleTraits<VkT> names the destroy function and the VkObjectType (for debug names) of a
// device-level handle type. Only the types listed below can be wrapped.
template <typename T>
struct HandleTraits;

#define VARC_VK_HANDLE_TRAITS(Type, destroyFunction, objectType)     \
    template <>                                                      \
    struct HandleTraits<Type> {                                      \
        static constexpr VkObjectType kObjectType = objectType;      \
        static void destroy(VkDevice device, Type handle) noexcept { \
            destroyFunction(device, handle, nullptr);                \
        }                                                            \
    }

VARC_VK_HANDLE_TRAITS(VkBuffer, vkDestroyBuffer, VK_OBJECT_TYPE_BUFFER);
VARC_VK_HANDLE_TRAITS(VkBufferView, vkDestroyBufferView, VK_OBJECT_TYPE_BUFFER_VIEW);
VARC_VK_HANDLE_TRAITS(VkDeviceMemory, vkFreeMemory, VK_OBJECT_TYPE_DEVICE_MEMORY);
VARC_VK_HANDLE_TRAITS(VkImage, vkDestroyImage, VK_OBJECT_TYPE_IMAGE);
VARC_VK_HANDLE_TRAITS(VkImageView, vkDestroyImageView, VK_OBJECT_TYPE_IMAGE_VIEW);
VARC_VK_HANDLE_TRAITS(VkSampler, vkDestroySampler, VK_OBJECT_TYPE_SAMPLER);
VARC_VK_HANDLE_TRAITS(VkShaderModule, vkDestroyShaderModule, VK_OBJECT_TYPE_SHADER_MODULE);
VARC_VK_HANDLE_TRAITS(VkRenderPass, vkDestroyRenderPass, VK_OBJECT_TYPE_RENDER_PASS);
VARC_VK_HANDLE_TRAITS(VkFramebuffer, vkDestroyFramebuffer, VK_OBJECT_TYPE_FRAMEBUFFER);
VARC_VK_HANDLE_TRAITS(VkPipeline, vkDestroyPipeline, VK_OBJECT_TYPE_PIPELINE);
VARC_VK_HANDLE_TRAITS(VkPipelineLayout, vkDestroyPipelineLayout, VK_OBJECT_TYPE_PIPELINE_LAYOUT);
VARC_VK_HANDLE_TRAITS(VkPipelineCache, vkDestroyPipelineCache, VK_OBJECT_TYPE_PIPELINE_CACHE);
VARC_VK_HANDLE_TRAITS(VkDescriptorSetLayout, vkDestroyDescriptorSetLayout,
                      VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT);
VARC_VK_HANDLE_TRAITS(VkDescriptorPool, vkDestroyDescriptorPool, VK_OBJECT_TYPE_DESCRIPTOR_POOL);
VARC_VK_HANDLE_TRAITS(VkCommandPool, vkDestroyCommandPool, VK_OBJECT_TYPE_COMMAND_POOL);
VARC_VK_HANDLE_TRAITS(VkFence, vkDestroyFence, VK_OBJECT_TYPE_FENCE);
VARC_VK_HANDLE_TRAITS(VkSemaphore, vkDestroySemaphore, VK_OBJECT_TYPE_SEMAPHORE);
VARC_VK_HANDLE_TRAITS(VkEvent, vkDestroyEvent, VK_OBJECT_TYPE_EVENT);
VARC_VK_HANDLE_TRAITS(VkQueryPool, vkDestroyQueryPool, VK_OBJECT_TYPE_QUERY_POOL);

#undef VARC_VK_HANDLE_TRAITS

// Owns |handle| created on |device| and destroys it with the matching vkDestroy*/vkFree* call.
// The VkDevice must outlive the handle: declare the VulkanContext before any UniqueHandle so it
// is destroyed last. Example:
//     UniqueHandle<VkFence> fence(device, rawFence);   // vkDestroyFence runs in ~UniqueHandle
template <typename T>
class UniqueHandle {
    // On 64-bit targets every non-dispatchable handle is a distinct pointer type, which is what
    // lets HandleTraits pick the destroy function by type. On 32-bit they are all uint64_t.
    static_assert(std::is_pointer_v<T>, "UniqueHandle needs typed (64-bit) Vulkan handles");

public:
    using Traits = HandleTraits<T>;

    UniqueHandle() noexcept = default;
    UniqueHandle(VkDevice device, T handle) noexcept : mDevice(device), mHandle(handle) {}
    ~UniqueHandle() { reset(); }

    UniqueHandle(const UniqueHandle&) = delete;
    UniqueHandle& operator=(const UniqueHandle&) = delete;
    UniqueHandle(UniqueHandle&& other) noexcept
        : mDevice(std::exchange(other.mDevice, VK_NULL_HANDLE)),
          mHandle(std::exchange(other.mHandle, VK_NULL_HANDLE)) {}
    UniqueHandle& operator=(UniqueHandle&& other) noexcept {
        if (this != &other) {
            reset();
            mDevice = std::exchange(other.mDevice, VK_NULL_HANDLE);
            mHandle = std::exchange(other.mHandle, VK_NULL_HANDLE);
        }
        return *this;
    }

    T get() const noexcept { return mHandle; }
    VkDevice device() const noexcept { return mDevice; }
    explicit operator bool() const noexcept { return mHandle != VK_NULL_HANDLE; }

    // Destroys the owned handle (if any) and leaves this empty.
    void reset() noexcept {
        if (mHandle != VK_NULL_HANDLE) Traits::destroy(mDevice, mHandle);
        mHandle = VK_NULL_HANDLE;
        mDevice = VK_NULL_HANDLE;
    }

    // Gives up ownership without destroying; the caller must destroy the returned handle.
    [[nodiscard]] T release() noexcept {
        mDevice = VK_NULL_HANDLE;
        return std::exchange(mHandle, VK_NULL_HANDLE);
    }

private:
    VkDevice mDevice = VK_NULL_HANDLE;
    T mHandle = VK_NULL_HANDLE;
};

static_assert(!std::is_copy_constructible_v<UniqueHandle<VkBuffer>>);
static_assert(!std::is_copy_assignable_v<UniqueHandle<VkBuffer>>);
static_assert(std::is_nothrow_move_constructible_v<UniqueHandle<VkBuffer>>);
static_assert(std::is_nothrow_move_assignable_v<UniqueHandle<VkBuffer>>);
static_assert(sizeof(UniqueHandle<VkBuffer>) == sizeof(VkDevice) + sizeof(VkBuffer),
              "UniqueHandle is exactly a device plus a handle");

}  // namespace varc::vulkan
