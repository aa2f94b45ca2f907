// SPDX-License-Identifier: Apache-2.0
// The pipeline cache file: saved after creating pipelines, reloaded on the same device, and
// rejected (a fresh cache, with the reason) when its header is for another device or corrupt.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "VulkanTestSupport.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/PipelineCacheFile.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/VariantPipeline.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {
namespace {

std::vector<std::byte> readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::byte> data(bytes.size());
    std::memcpy(data.data(), bytes.data(), bytes.size());
    return data;
}

void writeAll(const std::string& path, const std::vector<std::byte>& data) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(data.data()),
               static_cast<std::streamsize>(data.size()));
}

class PipelineCacheFileTest : public testing::VulkanTest {
protected:
    std::string path() const {
        return std::string(VARC_TEST_PACK_DIR) + "/" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".pipelinecache";
    }
};

TEST_F(PipelineCacheFileTest, SavedCacheReloadsOnTheSameDevice) {
    std::remove(path().c_str());
    auto fresh = PipelineCacheFile::open(context(), path());
    ASSERT_TRUE(fresh) << fresh.error().detail;
    EXPECT_FALSE(fresh->loadedFromFile());
    EXPECT_EQ(fresh->rejectedReason(), "");

    auto pack = reader::Pack::open(VARC_TEST_PACK_DIR "/library.svpack");
    ASSERT_TRUE(pack) << pack.error().detail;
    vulkan::RenderTargetDesc desc;
    desc.width = desc.height = 8;
    auto target = vulkan::RenderTarget::create(context(), desc);
    ASSERT_TRUE(target) << target.error().detail;
    reader::PassView pass =
        *pack->findShader("Custom/My First Lighting Shader")->pass("ForwardAdd");
    auto pipeline = VariantPipeline::create(
        context(), pass.variant(0), resolveRenderState(pass.renderState(), {}),
        {target->renderPass(vulkan::LoadOp::Clear), true, 1}, fresh->handle());
    ASSERT_TRUE(pipeline) << pipeline.error().detail;
    ASSERT_TRUE(fresh->save());

    std::vector<std::byte> saved = readAll(path());
    ASSERT_GE(saved.size(), 32u) << "a cache file holds at least its header";
    EXPECT_EQ(pipelineCacheMismatch(context().properties(), saved), "");
    auto reloaded = PipelineCacheFile::open(context(), path());
    ASSERT_TRUE(reloaded) << reloaded.error().detail;
    EXPECT_TRUE(reloaded->loadedFromFile());
}

TEST_F(PipelineCacheFileTest, ForeignOrCorruptHeadersStartAFreshCache) {
    std::remove(path().c_str());
    auto fresh = PipelineCacheFile::open(context(), path());
    ASSERT_TRUE(fresh);
    ASSERT_TRUE(fresh->save());
    std::vector<std::byte> good = readAll(path());
    ASSERT_GE(good.size(), 32u);

    std::vector<std::byte> otherDevice = good;
    otherDevice[12] ^= std::byte{0xff};  // deviceID
    writeAll(path(), otherDevice);
    auto foreign = PipelineCacheFile::open(context(), path());
    ASSERT_TRUE(foreign);
    EXPECT_FALSE(foreign->loadedFromFile());
    EXPECT_NE(foreign->rejectedReason().find("another device"), std::string::npos)
        << foreign->rejectedReason();

    std::vector<std::byte> otherDriver = good;
    otherDriver[20] ^= std::byte{0x01};  // inside pipelineCacheUUID
    writeAll(path(), otherDriver);
    auto rebuilt = PipelineCacheFile::open(context(), path());
    ASSERT_TRUE(rebuilt);
    EXPECT_NE(rebuilt->rejectedReason().find("pipelineCacheUUID"), std::string::npos)
        << rebuilt->rejectedReason();

    writeAll(path(), std::vector<std::byte>(good.begin(), good.begin() + 10));
    auto truncated = PipelineCacheFile::open(context(), path());
    ASSERT_TRUE(truncated);
    EXPECT_NE(truncated->rejectedReason().find("truncated"), std::string::npos)
        << truncated->rejectedReason();
}

}  // namespace
}  // namespace varc::render
