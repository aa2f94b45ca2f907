// SPDX-License-Identifier: Apache-2.0
#include "varc/render/PipelineCacheFile.h"

#include <cstring>

#include "varc/core/AtomicFile.h"
#include "varc/core/FileRead.h"
#include "varc/vulkan/CheckVk.h"

namespace varc::render {

namespace {

uint32_t readU32(const std::vector<std::byte>& data, size_t offset) {
    uint32_t value = 0;
    std::memcpy(&value, data.data() + offset, 4);  // the header is in host byte order
    return value;
}

}  // namespace

std::string pipelineCacheMismatch(const VkPhysicalDeviceProperties& device,
                                  const std::vector<std::byte>& data) {
    // VkPipelineCacheHeaderVersionOne: length, version, vendorID, deviceID, UUID[16].
    constexpr size_t kHeaderSize = 16 + VK_UUID_SIZE;
    if (data.size() < kHeaderSize)
        return "truncated header (" + std::to_string(data.size()) + " bytes)";
    uint32_t length = readU32(data, 0);
    if (length < kHeaderSize || length > data.size())
        return "bad header length " + std::to_string(length);
    if (readU32(data, 4) != VK_PIPELINE_CACHE_HEADER_VERSION_ONE) return "unknown header version";
    if (readU32(data, 8) != device.vendorID || readU32(data, 12) != device.deviceID) {
        return "written for another device (vendor/device id differ)";
    }
    if (std::memcmp(data.data() + 16, device.pipelineCacheUUID, VK_UUID_SIZE) != 0) {
        return "written by another driver build (pipelineCacheUUID differs)";
    }
    return {};
}

Result<PipelineCacheFile> PipelineCacheFile::open(const vulkan::VulkanContext& context,
                                                  std::string path) {
    PipelineCacheFile file;
    file.mContext = &context;
    file.mPath = std::move(path);
    std::vector<std::byte> data;
    // A missing or unreadable file starts an empty cache (save() reports what it cannot write).
    if (Result<std::string> bytes = readFile(file.mPath); bytes) {
        data.resize(bytes->size());
        std::memcpy(data.data(), bytes->data(), bytes->size());
        file.mRejected = pipelineCacheMismatch(context.properties(), data);
        if (!file.mRejected.empty()) data.clear();
    }
    VkPipelineCacheCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO;
    info.initialDataSize = data.size();
    info.pInitialData = data.empty() ? nullptr : data.data();
    VkPipelineCache cache = VK_NULL_HANDLE;
    if (Status ok = vulkan::checkVk(vkCreatePipelineCache(context.device(), &info, nullptr, &cache),
                                    "vkCreatePipelineCache");
        !ok) {
        return ok.error();
    }
    file.mCache = vulkan::UniqueHandle<VkPipelineCache>(context.device(), cache);
    file.mLoaded = !data.empty();
    return file;
}

Status PipelineCacheFile::save() const {
    size_t size = 0;
    if (Status ok = vulkan::checkVk(
            vkGetPipelineCacheData(mContext->device(), mCache.get(), &size, nullptr),
            "vkGetPipelineCacheData");
        !ok) {
        return ok;
    }
    std::string data(size, '\0');
    if (Status ok = vulkan::checkVk(
            vkGetPipelineCacheData(mContext->device(), mCache.get(), &size, data.data()),
            "vkGetPipelineCacheData");
        !ok) {
        return ok;
    }
    data.resize(size);
    return writeFileAtomically(mPath, data);
}

}  // namespace varc::render
