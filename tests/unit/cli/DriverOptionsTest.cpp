// SPDX-License-Identifier: Apache-2.0
// toBuildOptions: the one path from the parsed flags to driver::BuildOptions, for build and
// explain.
#include <gtest/gtest.h>

#include <filesystem>

#include "varc/cache/CacheChain.h"
#include "varc/cli/DriverOptions.h"

namespace varc::cli {
namespace {

TEST(DriverOptionsTest, NoFlagsGiveTheDriversDefaults) {
    driver::BuildOptions defaults;
    driver::BuildOptions options = toBuildOptions(CompileOptions{}, ShaderInputOptions{});
    EXPECT_EQ(options.optimization, defaults.optimization);
    EXPECT_EQ(options.jobs, defaults.jobs);
    EXPECT_EQ(options.keepGoing, defaults.keepGoing);
    EXPECT_EQ(options.debugNames, defaults.debugNames);
    EXPECT_EQ(options.maxVariantsPerPass, defaults.maxVariantsPerPass);
    EXPECT_EQ(options.shard.index, defaults.shard.index);
    EXPECT_EQ(options.shard.count, defaults.shard.count);
    EXPECT_EQ(options.pruneStages, defaults.pruneStages);
    EXPECT_EQ(options.shareUnobservedDefines, defaults.shareUnobservedDefines);
    EXPECT_EQ(options.keepPrunedSources, defaults.keepPrunedSources);
    EXPECT_EQ(options.cache, nullptr) << "no level, no cache";
    EXPECT_FALSE(options.progress);
    // Only the varc executable enables the workers (they re-execute it): not this test binary.
    EXPECT_EQ(options.optimizerPool, nullptr);
}

TEST(DriverOptionsTest, EveryFlagIsCopied) {
    CompileOptions compile;
    compile.jobs = 5;
    compile.maxVariants = 77;
    compile.optimization = driver::OptimizationLevel::Size;
    compile.keepGoing = true;
    compile.debugNames = true;
    compile.shard = {2, 4};
    driver::BuildOptions options = toBuildOptions(compile, ShaderInputOptions{});
    EXPECT_EQ(options.jobs, 5u);
    EXPECT_EQ(options.maxVariantsPerPass, 77u);
    EXPECT_EQ(options.optimization, driver::OptimizationLevel::Size);
    EXPECT_TRUE(options.keepGoing);
    EXPECT_TRUE(options.debugNames);
    EXPECT_EQ(options.shard.index, 2u);
    EXPECT_EQ(options.shard.count, 4u);
}

TEST(DriverOptionsTest, TheCacheLevelsOpenInOrder) {
    CompileOptions compile;
    compile.cacheLevels = {cache::directoryCacheSpec("/tmp/varc-driver-options-a"),
                           *cache::parseCacheSpec("file:/tmp/varc-driver-options-b|read-only")};
    driver::BuildOptions options = toBuildOptions(compile, ShaderInputOptions{});
    ASSERT_NE(options.cache, nullptr);
    ASSERT_EQ(options.cache->levels().size(), 2u);
    EXPECT_EQ(options.cache->levels()[0]->name(), "file:/tmp/varc-driver-options-a");
    EXPECT_EQ(options.cache->levels()[1]->name(), "file:/tmp/varc-driver-options-b|read-only");
}

TEST(DriverOptionsTest, SourcePathsFollowTheProjectRootAndPrefixMaps) {
    CompileOptions compile;
    compile.filePrefixMaps = {"/opt/sdk=sdk"};
    ShaderInputOptions input;
    input.projectRoot = "/src/game";
    driver::BuildOptions options = toBuildOptions(compile, input);
    EXPECT_EQ(options.sourcePaths.map("/src/game/Assets/a.shader"), "Assets/a.shader");
    EXPECT_EQ(options.sourcePaths.map("/opt/sdk/inc/b.cginc"), "sdk/inc/b.cginc");
    EXPECT_EQ(options.sourcePaths.map("/elsewhere/c.cginc"), "/elsewhere/c.cginc");
    // Without --project-root, paths are relative to the current folder.
    options = toBuildOptions(CompileOptions{}, ShaderInputOptions{});
    std::string here = std::filesystem::current_path().lexically_normal().string();
    EXPECT_EQ(options.sourcePaths.map(here + "/x/y.shader"), "x/y.shader");
}

TEST(DriverOptionsTest, OptimizationFlagsRoundTrip) {
    EXPECT_EQ(optimizationFlag(driver::OptimizationLevel::None), "-O0");
    EXPECT_EQ(optimizationFlag(driver::OptimizationLevel::Performance), "-O");
    EXPECT_EQ(optimizationFlag(driver::OptimizationLevel::Size), "-Os");
    for (auto level : {driver::OptimizationLevel::None, driver::OptimizationLevel::Performance,
                       driver::OptimizationLevel::Size}) {
        EXPECT_EQ(driver::parseOptimizationLevel(optimizationFlag(level)), level);
    }
}

}  // namespace
}  // namespace varc::cli
