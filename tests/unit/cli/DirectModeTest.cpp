// SPDX-License-Identifier: Apache-2.0
// DirectMode's key: what changes it (options that change the pack, inputs and their bytes) and
// what does not (-j), and the builds it leaves alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "varc/cache/CacheSpec.h"
#include "varc/cli/DirectMode.h"

namespace varc::cli {
namespace {

namespace fs = std::filesystem;

class DirectModeKey : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = fs::temp_directory_path() /
               ("varc-direct-key-" +
                std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(mDir / "inc");
        write("a.shader", "Shader \"A\" {}");
        mOptions.direct = true;
        mOptions.compile.cacheLevels = {cache::directoryCacheSpec((mDir / "cache").string())};
        mOptions.input.inputs = {mDir.string()};
        mOptions.input.includeDirs = {(mDir / "inc").string()};
        mOptions.outputPath = (mDir / "out.svpack").string();
    }
    void TearDown() override { fs::remove_all(mDir); }
    void write(const std::string& name, const std::string& text) {
        std::ofstream(mDir / name) << text;
    }
    std::string key() const { return directKeyText(mOptions, mDisk).value_or("(none)"); }

    fs::path mDir;
    BuildCommandOptions mOptions;
    includes::DiskFileSystem mDisk;
};

TEST_F(DirectModeKey, ChangesWithEveryOptionThatChangesThePack) {
    const std::string base = key();
    ASSERT_NE(base, "(none)");
    auto changed = [&](auto edit) {
        BuildCommandOptions saved = mOptions;
        edit(mOptions);
        std::string other = key();
        mOptions = saved;
        return other != base && other != "(none)";
    };
    EXPECT_TRUE(changed([](auto& o) { o.compile.optimization = driver::OptimizationLevel::None; }));
    EXPECT_TRUE(changed([](auto& o) { o.compile.debugNames = true; }));
    EXPECT_TRUE(changed([](auto& o) { o.compressionLevel = 3; }));
    EXPECT_TRUE(changed([](auto& o) { o.compile.shard = {1, 2}; }));
    EXPECT_TRUE(changed([](auto& o) { o.compile.maxVariants = 5; }));
    EXPECT_TRUE(changed([](auto& o) { o.compile.filePrefixMaps = {"/a=/b"}; }));
    EXPECT_TRUE(changed([](auto& o) { o.input.includeDirs.push_back("/elsewhere"); }));
    EXPECT_TRUE(changed([](auto& o) { o.input.builtinIncludeDir = "/other/builtin"; }));
    EXPECT_TRUE(changed([](auto& o) { o.input.projectRoot = "/root"; }));
    // -j and the output's name leave the pack's bytes alone.
    EXPECT_FALSE(changed([](auto& o) { o.compile.jobs = 7; }));
    EXPECT_FALSE(changed([](auto& o) { o.outputPath = "/elsewhere.svpack"; }));
}

TEST_F(DirectModeKey, ChangesWithAShadersBytesAndWithANewShader) {
    const std::string base = key();
    write("a.shader", "Shader \"A2\" {}");
    const std::string edited = key();
    EXPECT_NE(edited, base);
    write("b.shader", "Shader \"B\" {}");
    EXPECT_NE(key(), edited);
    write("inc/c.shader", "Shader \"C\" {}");  // UsePass and Fallback may find it
    EXPECT_NE(key(), edited);
}

TEST_F(DirectModeKey, IsNoneWithoutDirectACacheOrForProjectBuilds) {
    auto none = [&](auto edit) {
        BuildCommandOptions saved = mOptions;
        edit(mOptions);
        bool result = !directKeyText(mOptions, mDisk);
        mOptions = saved;
        return result;
    };
    EXPECT_TRUE(none([](auto& o) { o.direct = false; }));
    EXPECT_TRUE(none([](auto& o) { o.compile.cacheLevels.clear(); }));
    EXPECT_TRUE(none([](auto& o) { o.input.projectDir = "game"; }));
    EXPECT_TRUE(none([](auto& o) { o.input.stripRulesPath = "strip.yaml"; }));
    EXPECT_TRUE(none([](auto& o) { o.input.usageLogs = {"usage.log"}; }));
    EXPECT_TRUE(none([&](auto& o) { o.input.inputs = {(mDir / "missing").string()}; }));
}

}  // namespace
}  // namespace varc::cli
