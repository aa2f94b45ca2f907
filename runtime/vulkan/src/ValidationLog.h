// SPDX-License-Identifier: Apache-2.0
// ValidationLog: thread-safe record of the messages a debug-utils messenger delivers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

#include "varc/vulkan/ValidationMessage.h"

namespace varc::vulkan {

// Records every message handed to |callback| (the messenger's pfnUserCallback, with the log as
// pUserData) and forwards it to an optional observer. Layers may call from any thread.
class ValidationLog {
public:
    explicit ValidationLog(std::function<void(const ValidationMessage&)> observer);

    // Severities and types the messenger subscribes to: warnings and errors of every type.
    static constexpr VkDebugUtilsMessageSeverityFlagsEXT kSeverities =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    static constexpr VkDebugUtilsMessageTypeFlagsEXT kTypes =
        VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
        VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
        VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;

    // A messenger create info that delivers to this log.
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo();

    std::size_t count() const;
    std::vector<ValidationMessage> messages() const;
    void clear();

private:
    static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* userData);
    void record(ValidationMessage message);

    std::function<void(const ValidationMessage&)> mObserver;
    mutable std::mutex mMutex;
    std::vector<ValidationMessage> mMessages;
};

}  // namespace varc::vulkan
