// SPDX-License-Identifier: Apache-2.0
// Creates a VulkanContext and prints the outcome; exits 0 only if creation failed with
// ErrorCode::NotFound. Run by VulkanContextTest with the loader pointed at no driver.
#include <cstdio>

#include "varc/vulkan/VulkanContext.h"

int main() {
    varc::vulkan::ContextOptions options;
    options.enableValidation = false;
    varc::Result<varc::vulkan::VulkanContext> context =
        varc::vulkan::VulkanContext::create(options);
    if (context.ok()) {
        std::printf("unexpected: created a context on '%s'\n", context->deviceName().c_str());
        return 1;
    }
    std::printf("%s: %s\n", varc::toString(context.error().code), context.error().detail.c_str());
    return context.error().code == varc::ErrorCode::NotFound ? 0 : 1;
}
