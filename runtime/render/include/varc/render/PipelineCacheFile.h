// SPDX-License-Identifier: Apache-2.0
// A VkPipelineCache persisted to a file: loaded only when its header matches this device
// (vendor, device, pipelineCacheUUID), written back atomically. On lavapipe the cache holds no
// pipelines (Mesa's own shader cache does the work), but on real GPUs it saves the compile.
#pragma once

#include <string>
#include <vector>

#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {

// Why a cache file's contents were not used (empty = they were).
std::string pipelineCacheMismatch(const VkPhysicalDeviceProperties& device,
                                  const std::vector<std::byte>& data);

class PipelineCacheFile {
public:
    // Opens |path| (missing file: a fresh cache). A header for another device, or a truncated or
    // corrupt header, starts a fresh cache and is reported by rejectedReason(); never an error.
    static Result<PipelineCacheFile> open(const vulkan::VulkanContext& context, std::string path);

    VkPipelineCache handle() const { return mCache.get(); }
    const std::string& rejectedReason() const { return mRejected; }
    bool loadedFromFile() const { return mLoaded; }

    // Writes the cache's current data to the path (temporary file, then rename).
    Status save() const;

private:
    const vulkan::VulkanContext* mContext = nullptr;
    std::string mPath;
    std::string mRejected;
    bool mLoaded = false;
    vulkan::UniqueHandle<VkPipelineCache> mCache;
};

}  // namespace varc::render
