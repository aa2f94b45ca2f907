// SPDX-License-Identifier: Apache-2.0
// VulkanContext on lavapipe: device choice, validation capture, submission, RAII handles.
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "VulkanTestSupport.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/CheckVk.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

extern char** environ;

namespace varc::render {
namespace {

using testing::VulkanTest;

bool deviceOverridden() {
    const char* value = std::getenv("VARC_VULKAN_DEVICE");
    return value && *value;
}

TEST_F(VulkanTest, PicksLavapipeByDefaultWithValidationOn) {
    if (deviceOverridden()) GTEST_SKIP() << "VARC_VULKAN_DEVICE chooses the device";
    EXPECT_NE(context().deviceName().find("llvmpipe"), std::string::npos) << context().deviceName();
    EXPECT_TRUE(context().validationEnabled());
    EXPECT_TRUE(context().debugUtilsEnabled());
    EXPECT_NE(context().queue(), VK_NULL_HANDLE);
    EXPECT_NE(context().commandPool(), VK_NULL_HANDLE);
}

TEST_F(VulkanTest, RecordsValidationErrors) {
    expectMessages(true);
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = 16;
    info.usage = 0;  // invalid: VUID-VkBufferCreateInfo-usage-requiredbitmask
    VkBuffer buffer = VK_NULL_HANDLE;
    VkResult result = vkCreateBuffer(context().device(), &info, nullptr, &buffer);
    vulkan::UniqueHandle<VkBuffer> owned(context().device(),
                                         result == VK_SUCCESS ? buffer : nullptr);
    owned.reset();

    ASSERT_GE(context().validationMessageCount(), 1u);
    std::vector<vulkan::ValidationMessage> messages = context().validationMessages();
    EXPECT_NE(messages[0].idName.find("VkBufferCreateInfo-usage"), std::string::npos)
        << toString(messages[0]);
    EXPECT_TRUE(messages[0].severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT);
    context().clearValidationMessages();
    EXPECT_EQ(context().validationMessageCount(), 0u);
    expectMessages(false);
}

TEST(VulkanContext, UnknownPreferredDeviceIsNotFoundAndListsDevices) {
    if (deviceOverridden()) GTEST_SKIP() << "VARC_VULKAN_DEVICE overrides preferredDevice";
    vulkan::ContextOptions options;
    options.enableValidation = false;
    options.preferredDevice = "no-such-gpu";
    Result<vulkan::VulkanContext> context = vulkan::VulkanContext::create(options);
    ASSERT_FALSE(context.ok());
    EXPECT_EQ(context.error().code, ErrorCode::NotFound);
    EXPECT_NE(context.error().detail.find("no-such-gpu"), std::string::npos);
    EXPECT_NE(context.error().detail.find("llvmpipe"), std::string::npos) << context.error().detail;
}

TEST(VulkanContext, PreferredDeviceMatchesCaseInsensitively) {
    if (deviceOverridden()) GTEST_SKIP() << "VARC_VULKAN_DEVICE overrides preferredDevice";
    vulkan::ContextOptions options;
    options.enableValidation = false;
    options.preferredDevice = "LLVMPIPE";
    Result<vulkan::VulkanContext> context = vulkan::VulkanContext::create(options);
    ASSERT_TRUE(context.ok()) << context.error().detail;
    EXPECT_FALSE(context->validationEnabled());
    EXPECT_EQ(context->validationMessageCount(), 0u);
}

// Runs the probe executable with the loader pointed at a driver manifest that does not exist,
// in a child process so this process's loader state is untouched. The probe exits 0 only when
// VulkanContext::create returned ErrorCode::NotFound; its output is the error text.
TEST(VulkanContext, MissingDriverIsACleanNotFoundError) {
    std::vector<std::string> variables = {"VK_ICD_FILENAMES=/nonexistent/varc_icd.json",
                                          "VK_DRIVER_FILES=/nonexistent/varc_icd.json"};
    for (char** entry = environ; *entry; ++entry) {
        std::string variable = *entry;
        if (variable.rfind("VK_ICD_FILENAMES=", 0) != 0 &&
            variable.rfind("VK_DRIVER_FILES=", 0) != 0) {
            variables.push_back(variable);
        }
    }
    std::vector<char*> envp;
    for (std::string& variable : variables) envp.push_back(variable.data());
    envp.push_back(nullptr);

    int pipeFds[2];
    ASSERT_EQ(pipe(pipeFds), 0);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDERR_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipeFds[0]);
    std::string probe = VARC_VULKAN_PROBE;
    char* argv[] = {probe.data(), nullptr};
    pid_t child = 0;
    int spawned = posix_spawn(&child, probe.c_str(), &actions, nullptr, argv, envp.data());
    posix_spawn_file_actions_destroy(&actions);
    close(pipeFds[1]);
    ASSERT_EQ(spawned, 0) << probe;
    std::string output;
    char chunk[512];
    for (ssize_t n; (n = read(pipeFds[0], chunk, sizeof chunk)) > 0;) {
        output.append(chunk, static_cast<std::size_t>(n));
    }
    close(pipeFds[0]);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << output;
    EXPECT_EQ(WEXITSTATUS(status), 0) << output;
    EXPECT_NE(output.find("mesa-vulkan-drivers"), std::string::npos) << output;
}

TEST_F(VulkanTest, SubmitAndWaitRunsTheRecordedCommands) {
    Result<vulkan::Buffer> buffer =
        vulkan::Buffer::create(context(), 64, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                               vulkan::MemoryLocation::HostVisible, "fill target");
    ASSERT_TRUE(buffer.ok()) << buffer.error().detail;
    Status submitted = context().submitAndWait([&](VkCommandBuffer commands) {
        vkCmdFillBuffer(commands, buffer->handle(), 0, 64, 0xA5A5A5A5u);
        VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER, nullptr,
                                VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_HOST_READ_BIT};
        vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                             0, 1, &barrier, 0, nullptr, 0, nullptr);
    });
    ASSERT_TRUE(submitted.ok()) << submitted.error().detail;
    for (std::size_t i = 0; i < 64; ++i) {
        EXPECT_EQ(static_cast<uint8_t>(buffer->mapped()[i]), 0xA5u) << i;
    }
}

TEST_F(VulkanTest, FindMemoryTypeHonoursRequiredFlags) {
    Result<uint32_t> host = context().findMemoryType(
        ~0u, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    ASSERT_TRUE(host.ok()) << host.error().detail;
    VkMemoryPropertyFlags flags = context().memoryProperties().memoryTypes[*host].propertyFlags;
    EXPECT_TRUE(flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT);
    Result<uint32_t> none = context().findMemoryType(0u, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().code, ErrorCode::Unsupported);
}

TEST_F(VulkanTest, UniqueHandleMovesOwnershipAndDestroysOnce) {
    VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO, nullptr, 0};
    VkFence raw = VK_NULL_HANDLE;
    ASSERT_EQ(vkCreateFence(context().device(), &info, nullptr, &raw), VK_SUCCESS);
    vulkan::UniqueHandle<VkFence> first(context().device(), raw);
    context().nameObject(first, "moved fence");
    vulkan::UniqueHandle<VkFence> second(std::move(first));
    EXPECT_FALSE(first);  // NOLINT(bugprone-use-after-move): checks the moved-from state
    EXPECT_EQ(second.get(), raw);
    vulkan::UniqueHandle<VkFence> third;
    third = std::move(second);
    EXPECT_EQ(third.get(), raw);
    third.reset();
    EXPECT_FALSE(third);
    // A double destroy or a leak would be a validation message, failing this test.
}

TEST(CheckVk, NamesTheCallTheResultAndTheSite) {
    Status ok = vulkan::checkVk(VK_SUCCESS, "vkCreateFence", CallSite::current());
    EXPECT_TRUE(ok.ok());
    EXPECT_TRUE(vulkan::checkVk(VK_INCOMPLETE, "vkEnumeratePhysicalDevices").ok());
    Status failed =
        vulkan::checkVk(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory", CallSite::current());
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().code, ErrorCode::VulkanError);
    EXPECT_NE(failed.error().detail.find("vkAllocateMemory failed: VK_ERROR_OUT_OF_DEVICE_MEMORY"),
              std::string::npos)
        << failed.error().detail;
    EXPECT_NE(failed.error().detail.find("VulkanContextTest.cpp:"), std::string::npos);
    Status unknown = vulkan::checkVk(static_cast<VkResult>(-12345), "vkFoo");
    EXPECT_NE(unknown.error().detail.find("VkResult(-12345)"), std::string::npos);
}

}  // namespace
}  // namespace varc::render
