// SPDX-License-Identifier: Apache-2.0
// Buffer: a VkBuffer with its own memory, optionally host-visible and persistently mapped.
#include "varc/vulkan/Buffer.h"

#include <cstring>
#include <utility>

#include "varc/core/Check.h"
#include "varc/vulkan/CheckVk.h"

namespace varc::vulkan {

Result<Buffer> Buffer::create(const VulkanContext& context, VkDeviceSize size,
                              VkBufferUsageFlags usage, MemoryLocation location,
                              const std::string& name) {
    VkDevice device = context.device();
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer rawBuffer = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateBuffer(device, &info, nullptr, &rawBuffer),
                                "vkCreateBuffer", CallSite::current());
        !status) {
        return status.error();
    }
    Buffer buffer;
    buffer.mBuffer = UniqueHandle<VkBuffer>(device, rawBuffer);
    buffer.mSize = size;
    context.nameObject(buffer.mBuffer, name);

    VkMemoryRequirements requirements{};
    vkGetBufferMemoryRequirements(device, rawBuffer, &requirements);
    bool host = location == MemoryLocation::HostVisible;
    VkMemoryPropertyFlags required =
        host ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
             : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    VkMemoryPropertyFlags preferred = host ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : 0;
    Result<UniqueHandle<VkDeviceMemory>> memory =
        context.allocateMemory(requirements, required, preferred);
    if (!memory) return memory.error();
    buffer.mMemory = std::move(*memory);
    if (Status status = checkVk(vkBindBufferMemory(device, rawBuffer, buffer.mMemory.get(), 0),
                                "vkBindBufferMemory", CallSite::current());
        !status) {
        return status.error();
    }
    if (host) {
        void* mapped = nullptr;
        if (Status status =
                checkVk(vkMapMemory(device, buffer.mMemory.get(), 0, VK_WHOLE_SIZE, 0, &mapped),
                        "vkMapMemory", CallSite::current());
            !status) {
            return status.error();
        }
        buffer.mMapped = static_cast<std::byte*>(mapped);
    }
    return buffer;
}

Result<Buffer> Buffer::createWithData(VulkanContext& context, std::span<const std::byte> data,
                                      VkBufferUsageFlags usage, const std::string& name) {
    VkDeviceSize size = data.size();
    Result<Buffer> staging = create(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                    MemoryLocation::HostVisible, name + " staging");
    if (!staging) return staging.error();
    staging->write(data);
    Result<Buffer> buffer = create(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                   MemoryLocation::DeviceLocal, name);
    if (!buffer) return buffer.error();
    Status copied = context.submitAndWait([&](VkCommandBuffer commands) {
        VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(commands, staging->handle(), buffer->handle(), 1, &region);
        // Makes the copy visible to every later use, including later submissions.
        VkMemoryBarrier barrier{};
        barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
        barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT;
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0, nullptr, 0,
                             nullptr);
    });
    if (!copied) return copied.error();
    return buffer;
}

void Buffer::write(std::span<const std::byte> data, VkDeviceSize offset) {
    VARC_CHECK(mMapped != nullptr) << "Buffer::write on a buffer that is not host-visible";
    VARC_CHECK(offset <= mSize && data.size() <= mSize - offset)
        << "Buffer::write of " << data.size() << " bytes at " << offset << " overflows " << mSize;
    if (!data.empty()) std::memcpy(mMapped + offset, data.data(), data.size());
}

}  // namespace varc::vulkan
