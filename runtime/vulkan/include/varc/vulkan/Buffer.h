// SPDX-License-Identifier: Apache-2.0
// Buffer: a VkBuffer with its own memory, optionally host-visible and persistently mapped.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <string>

#include "varc/core/Result.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::vulkan {

enum class MemoryLocation {
    DeviceLocal,  // for vertex/index/uniform data written once through a staging buffer
    HostVisible,  // host-visible and coherent, mapped for the buffer's lifetime (staging, readback)
};

class Buffer {
public:
    // Creates a |size|-byte buffer with |usage| in |location| memory, named |name| for debuggers.
    // HostVisible buffers are mapped (mapped() != nullptr) and prefer host-cached memory.
    // Errors: ErrorCode::VulkanError, or Unsupported when no memory type fits.
    static Result<Buffer> create(const VulkanContext& context, VkDeviceSize size,
                                 VkBufferUsageFlags usage, MemoryLocation location,
                                 const std::string& name = "Buffer");
    // Creates a device-local buffer holding |data|, uploaded through a staging buffer (|usage|
    // gains TRANSFER_DST). Example:
    //     Buffer::createWithData(context, std::as_bytes(std::span(vertices)),
    //                            VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, "quad vertices");
    static Result<Buffer> createWithData(VulkanContext& context, std::span<const std::byte> data,
                                         VkBufferUsageFlags usage,
                                         const std::string& name = "Buffer");

    VkBuffer handle() const { return mBuffer.get(); }
    VkDeviceSize size() const { return mSize; }
    // The mapping of a HostVisible buffer; nullptr for DeviceLocal ones.
    std::byte* mapped() const { return mMapped; }
    // Copies |data| into a HostVisible buffer at |offset|; the range must fit (VARC_CHECK).
    void write(std::span<const std::byte> data, VkDeviceSize offset = 0);

private:
    // Memory is declared first so the buffer is destroyed before the memory is freed.
    UniqueHandle<VkDeviceMemory> mMemory;
    UniqueHandle<VkBuffer> mBuffer;
    VkDeviceSize mSize = 0;
    std::byte* mMapped = nullptr;
};

}  // namespace varc::vulkan
