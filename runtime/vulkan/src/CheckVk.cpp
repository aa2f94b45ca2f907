// SPDX-License-Identifier: Apache-2.0
// checkVk: turns a VkResult into a Status (error tier 2), naming the call and the call site.
#include "varc/vulkan/CheckVk.h"

#include <string>
#include <string_view>

namespace varc::vulkan {

const char* vkResultName(VkResult result) {
    switch (result) {
#define VARC_VK_RESULT_CASE(name) \
    case name:                    \
        return #name
        VARC_VK_RESULT_CASE(VK_SUCCESS);
        VARC_VK_RESULT_CASE(VK_NOT_READY);
        VARC_VK_RESULT_CASE(VK_TIMEOUT);
        VARC_VK_RESULT_CASE(VK_EVENT_SET);
        VARC_VK_RESULT_CASE(VK_EVENT_RESET);
        VARC_VK_RESULT_CASE(VK_INCOMPLETE);
        VARC_VK_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY);
        VARC_VK_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY);
        VARC_VK_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED);
        VARC_VK_RESULT_CASE(VK_ERROR_DEVICE_LOST);
        VARC_VK_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED);
        VARC_VK_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT);
        VARC_VK_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT);
        VARC_VK_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT);
        VARC_VK_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER);
        VARC_VK_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS);
        VARC_VK_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED);
        VARC_VK_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL);
        VARC_VK_RESULT_CASE(VK_ERROR_UNKNOWN);
        VARC_VK_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY);
        VARC_VK_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE);
        VARC_VK_RESULT_CASE(VK_ERROR_FRAGMENTATION);
        VARC_VK_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS);
        VARC_VK_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR);
        VARC_VK_RESULT_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR);
        VARC_VK_RESULT_CASE(VK_SUBOPTIMAL_KHR);
        VARC_VK_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR);
        VARC_VK_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT);
#undef VARC_VK_RESULT_CASE
        default:
            return "VkResult(unknown)";
    }
}

Status checkVk(VkResult result, const char* call, CallSite where) {
    if (result >= 0) return Ok{};
    std::string_view file = where.fileName();
    if (auto slash = file.find_last_of('/'); slash != std::string_view::npos) {
        file.remove_prefix(slash + 1);
    }
    std::string name = vkResultName(result);
    if (name == "VkResult(unknown)") name = "VkResult(" + std::to_string(result) + ")";
    return makeError(ErrorCode::VulkanError, std::string(call) + " failed: " + name + " (" +
                                                 std::string(file) + ":" +
                                                 std::to_string(where.line()) + ")");
}

}  // namespace varc::vulkan
