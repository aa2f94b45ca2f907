// SPDX-License-Identifier: Apache-2.0
// checkVk: turns a VkResult into a Status (error tier 2), naming the call and the call site.
#pragma once

#include <vulkan/vulkan.h>

#include "varc/core/CallSite.h"
#include "varc/core/Result.h"

namespace varc::vulkan {

// The enumerator name of |result|, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY"; "VkResult(unknown)" for
// values this build does not name (checkVk then prints the number).
const char* vkResultName(VkResult result);

// Returns Ok for VK_SUCCESS and the other non-negative success codes (VK_INCOMPLETE, ...), whose
// meaning depends on the call; callers that wait with finite timeouts check VK_TIMEOUT
// themselves. A negative |result| becomes ErrorCode::VulkanError whose detail names |call|, the
// result and |where|, e.g.
//     "vkCreateImage failed: VK_ERROR_OUT_OF_DEVICE_MEMORY (RenderTarget.cpp:87)".
// Typical use:
//     checkVk(vkCreateFence(device, &info, nullptr, &fence), "vkCreateFence",
//             CallSite::current())
Status checkVk(VkResult result, const char* call, CallSite where = CallSite::current());

}  // namespace varc::vulkan
