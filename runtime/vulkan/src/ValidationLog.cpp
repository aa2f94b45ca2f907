// SPDX-License-Identifier: Apache-2.0
// ValidationLog: thread-safe record of the messages a debug-utils messenger delivers.
#include "ValidationLog.h"

#include <string>
#include <utility>

namespace varc::vulkan {

std::string toString(const ValidationMessage& message) {
    std::string out =
        (message.severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    if (!message.idName.empty()) out += " [" + message.idName + "]";
    return out + " " + message.text;
}

ValidationLog::ValidationLog(std::function<void(const ValidationMessage&)> observer)
    : mObserver(std::move(observer)) {}

VkDebugUtilsMessengerCreateInfoEXT ValidationLog::messengerInfo() {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity = kSeverities;
    info.messageType = kTypes;
    info.pfnUserCallback = &ValidationLog::callback;
    info.pUserData = this;
    return info;
}

std::size_t ValidationLog::count() const {
    std::lock_guard lock(mMutex);
    return mMessages.size();
}

std::vector<ValidationMessage> ValidationLog::messages() const {
    std::lock_guard lock(mMutex);
    return mMessages;
}

void ValidationLog::clear() {
    std::lock_guard lock(mMutex);
    mMessages.clear();
}

VKAPI_ATTR VkBool32 VKAPI_CALL ValidationLog::callback(
    VkDebugUtilsMessageSeverityFlagBitsEXT severity, VkDebugUtilsMessageTypeFlagsEXT types,
    const VkDebugUtilsMessengerCallbackDataEXT* data, void* userData) {
    ValidationMessage message;
    message.severity = severity;
    message.types = types;
    if (data && data->pMessageIdName) message.idName = data->pMessageIdName;
    if (data && data->pMessage) message.text = data->pMessage;
    static_cast<ValidationLog*>(userData)->record(std::move(message));
    // VK_FALSE: let the call proceed, as the spec asks of application callbacks.
    return VK_FALSE;
}

void ValidationLog::record(ValidationMessage message) {
    {
        std::lock_guard lock(mMutex);
        mMessages.push_back(message);
    }
    if (mObserver) mObserver(message);
}

}  // namespace varc::vulkan
