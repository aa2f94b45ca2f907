// SPDX-License-Identifier: Apache-2.0
// Instance creation for VulkanContext: headless extensions, validation layer, messenger.
#include <cstring>
#include <string>
#include <vector>

#include "varc/vulkan/CheckVk.h"
#include "ContextState.h"

namespace varc::vulkan {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasLayer(const char* name) {
    uint32_t count = 0;
    if (vkEnumerateInstanceLayerProperties(&count, nullptr) < 0) return false;
    std::vector<VkLayerProperties> layers(count);
    if (vkEnumerateInstanceLayerProperties(&count, layers.data()) < 0) return false;
    for (const VkLayerProperties& layer : layers) {
        if (std::strcmp(layer.layerName, name) == 0) return true;
    }
    return false;
}

// Whether |extension| is offered by the loader/drivers or, when |layer| is set, by that layer.
bool hasInstanceExtension(const char* extension, const char* layer) {
    uint32_t count = 0;
    if (vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) < 0) return false;
    std::vector<VkExtensionProperties> extensions(count);
    if (vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()) < 0) return false;
    for (const VkExtensionProperties& properties : extensions) {
        if (std::strcmp(properties.extensionName, extension) == 0) return true;
    }
    return false;
}

Error noDriverError(VkResult result) {
    return makeError(ErrorCode::NotFound,
                     std::string("no Vulkan driver found (vkCreateInstance: ") +
                         vkResultName(result) +
                         "); install Debian's mesa-vulkan-drivers for the lavapipe CPU device, "
                         "and check VK_ICD_FILENAMES / VK_DRIVER_FILES if they are set");
}

Status createMessenger(VulkanContext::State& state) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(state.instance, "vkCreateDebugUtilsMessengerEXT"));
    state.destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(state.instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (!create || !state.destroyMessenger) {
        return makeError(ErrorCode::Unsupported, "VK_EXT_debug_utils entry points are missing");
    }
    VkDebugUtilsMessengerCreateInfoEXT info = state.log.messengerInfo();
    return checkVk(create(state.instance, &info, nullptr, &state.messenger),
                   "vkCreateDebugUtilsMessengerEXT", CallSite::current());
}

// Fills |layers| and |extensions| for the instance and sets |state.debugUtils|.
// Errors: ErrorCode::Unsupported when validation is asked for but cannot be provided.
Status chooseLayersAndExtensions(VulkanContext::State& state, std::vector<const char*>& layers,
                                 std::vector<const char*>& extensions) {
    if (state.validation) {
        if (!hasLayer(kValidationLayer)) {
            return makeError(ErrorCode::Unsupported,
                             "Vulkan validation was requested but VK_LAYER_KHRONOS_validation is "
                             "not installed; install Debian's vulkan-validationlayers");
        }
        layers.push_back(kValidationLayer);
    }
    state.debugUtils = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, nullptr) ||
                       (state.validation &&
                        hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME, kValidationLayer));
    if (state.validation && !state.debugUtils) {
        return makeError(ErrorCode::Unsupported, "validation needs VK_EXT_debug_utils");
    }
    if (state.debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    return Ok{};
}

}  // namespace

Status createInstance(VulkanContext::State& state, const std::string& applicationName) {
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    if (Status status = chooseLayersAndExtensions(state, layers, extensions); !status) {
        return status;
    }
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = applicationName.c_str();
    app.pEngineName = "varc";
    app.apiVersion = VK_API_VERSION_1_0;

    // Chaining the messenger info also reports problems inside vkCreate/DestroyInstance.
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo = state.log.messengerInfo();
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pNext = state.validation ? &messengerInfo : nullptr;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VkResult result = vkCreateInstance(&info, nullptr, &state.instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER) return noDriverError(result);
    if (Status status = checkVk(result, "vkCreateInstance", CallSite::current()); !status) {
        return status;
    }
    if (state.debugUtils) {
        state.setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetInstanceProcAddr(state.instance, "vkSetDebugUtilsObjectNameEXT"));
    }
    return state.validation ? createMessenger(state) : Status(Ok{});
}

}  // namespace varc::vulkan
