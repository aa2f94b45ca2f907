// SPDX-License-Identifier: Apache-2.0
// ValidationMessage: one warning or error reported through VK_EXT_debug_utils.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace varc::vulkan {

struct ValidationMessage {
    VkDebugUtilsMessageSeverityFlagBitsEXT severity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    VkDebugUtilsMessageTypeFlagsEXT types = 0;
    std::string idName;  // e.g. "VUID-VkBufferCreateInfo-usage-requiredbitmask"; may be empty
    std::string text;    // the layer's full message
};

// "error [VUID-...] text" or "warning [...] text", for test output and logs.
std::string toString(const ValidationMessage& message);

}  // namespace varc::vulkan
