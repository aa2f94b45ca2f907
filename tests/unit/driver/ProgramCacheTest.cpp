// SPDX-License-Identifier: Apache-2.0
// ProgramCache: entries round-trip, keys tell every input apart, and no damaged or misplaced
// entry is ever trusted.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string_view>

#include "varc/cache/CacheChain.h"
#include "varc/cache/CacheSpec.h"
#include "varc/driver/ProgramCache.h"

namespace varc::driver {
namespace {

namespace fs = std::filesystem;

class ProgramCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = fs::path(::testing::TempDir()) /
               ("varc-program-cache-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(mDir);
    }
    void TearDown() override { fs::remove_all(mDir); }

    // A cache whose one level is the folder mDir, as `--cache-dir` makes it.
    ProgramCache makeCache() const {
        return ProgramCache(std::make_shared<cache::CacheChain>(
            cache::CacheChain::open({cache::directoryCacheSpec(mDir.string())})));
    }
    // Where the folder level keeps the entry for |key|: mDir/<2 hex>/<entry name>.
    std::string pathOf(const ProgramCacheKey& key, std::string_view extension = ".program") const {
        return (mDir / key.hex().substr(0, 2) / ProgramCache::entryName(key, extension)).string();
    }

    static CachedProgram sample() {
        return {{0x07230203u, 0x00010000u, 0u, 42u, 0u, 7u, 8u, 9u},
                {0x07230203u, 0x00010000u, 0u, 42u, 0u, 7u},
                {{0, "POSITION"}, {3, "TEXCOORD0"}},
                "WARNING: program:3: something harmless\n"};
    }

    static std::string readAll(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }
    static void writeAll(const std::string& path, const std::string& bytes) {
        std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    }

    fs::path mDir;
};

ProgramCacheInput input(std::string_view text) {
    return {OptimizationLevel::Performance, shaderlab::ProgramLanguage::Cg, Stage::Fragment, "frag",
            text};
}

TEST_F(ProgramCacheTest, AStoredEntryLoadsBackWhole) {
    ProgramCache cache = makeCache();
    ProgramCacheKey key = cache.keyOf(input("float4 frag() : SV_Target { return 1; }"));
    EXPECT_FALSE(cache.load(key));
    ASSERT_TRUE(cache.store(key, sample()).ok());
    std::optional<CachedProgram> loaded = cache.load(key);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(loaded->spirv, sample().spirv);
    EXPECT_EQ(loaded->stripped, sample().stripped);
    EXPECT_EQ(loaded->semantics, sample().semantics);
    EXPECT_EQ(loaded->log, sample().log);
    EXPECT_EQ(fs::path(pathOf(key)).parent_path().filename().string(), key.hex().substr(0, 2));
}

TEST_F(ProgramCacheTest, EveryInputChangesTheKey) {
    ProgramCache cache = makeCache();
    ProgramCacheInput base = input("text");
    std::vector<ProgramCacheInput> changed(5, base);
    changed[0].optimization = OptimizationLevel::None;
    changed[1].language = shaderlab::ProgramLanguage::Glsl;
    changed[2].stage = Stage::Vertex;
    changed[3].entryPoint = "frag2";
    changed[4].text = "text ";
    std::vector<std::string> keys = {cache.keyOf(base).hex()};
    for (const ProgramCacheInput& other : changed) keys.push_back(cache.keyOf(other).hex());
    std::sort(keys.begin(), keys.end());
    EXPECT_EQ(std::unique(keys.begin(), keys.end()), keys.end());
    EXPECT_EQ(cache.keyOf(base), makeCache().keyOf(base)) << "keys must be stable";
}

TEST_F(ProgramCacheTest, EveryTruncationAndEveryByteFlipIsRejected) {
    ProgramCache cache = makeCache();
    ProgramCacheKey key = cache.keyOf(input("x"));
    ASSERT_TRUE(cache.store(key, sample()).ok());
    const std::string path = pathOf(key);
    const std::string good = readAll(path);
    for (size_t size = 0; size < good.size(); ++size) {
        writeAll(path, good.substr(0, size));
        EXPECT_FALSE(cache.load(key)) << "truncated to " << size;
    }
    for (size_t at = 0; at < good.size(); ++at) {
        std::string bad = good;
        bad[at] = static_cast<char>(bad[at] ^ 0x01);
        writeAll(path, bad);
        EXPECT_FALSE(cache.load(key)) << "bit flipped at " << at;
    }
    writeAll(path, good);
    EXPECT_TRUE(cache.load(key));
}

TEST_F(ProgramCacheTest, PrunedSourcesRoundTripAndDamageIsRejected) {
    ProgramCache cache = makeCache();
    SourceCacheInput input{ProgramCache::hashText("pass text"),
                           shaderlab::ProgramLanguage::Cg,
                           Stage::Fragment,
                           "frag",
                           "#define POINT 1\n",
                           true};
    ProgramCacheKey key = cache.sourceKeyOf(input);
    EXPECT_FALSE(cache.loadSource(key));
    const std::string text = "#line 3 1\nfloat4 frag() : SV_Target { return 1; }\n";
    ASSERT_TRUE(cache.storeSource(key, text).ok());
    EXPECT_EQ(cache.loadSource(key), text);
    // A source and a program never answer for each other, even under the same key.
    EXPECT_FALSE(cache.load(key));
    const std::string path = pathOf(key, ".source");
    const std::string good = readAll(path);
    for (size_t at = 0; at < good.size(); at += 7) {
        std::string bad = good;
        bad[at] = static_cast<char>(bad[at] ^ 0x40);
        writeAll(path, bad);
        EXPECT_FALSE(cache.loadSource(key)) << "byte changed at " << at;
    }
    // Every input of the key matters.
    SourceCacheInput other = input;
    other.preamble = "#define SPOT 1\n";
    EXPECT_NE(cache.sourceKeyOf(other), key);
    other = input;
    other.passText = ProgramCache::hashText("pass text 2");
    EXPECT_NE(cache.sourceKeyOf(other), key);
    other = input;
    other.pruned = false;
    EXPECT_NE(cache.sourceKeyOf(other), key);
    other = input;
    other.stage = Stage::Vertex;
    EXPECT_NE(cache.sourceKeyOf(other), key);
}

TEST_F(ProgramCacheTest, AnEntryCopiedToAnotherKeyIsNotTrusted) {
    ProgramCache cache = makeCache();
    ProgramCacheKey one = cache.keyOf(input("one")), two = cache.keyOf(input("two"));
    ASSERT_TRUE(cache.store(one, sample()).ok());
    fs::create_directories(fs::path(pathOf(two)).parent_path());
    fs::copy_file(pathOf(one), pathOf(two));
    EXPECT_FALSE(cache.load(two));
}

TEST_F(ProgramCacheTest, AnUnwritableFolderIsAnErrorNamingThePath) {
    fs::create_directories(mDir.parent_path());
    writeAll(mDir.string(), "a file where the cache folder should be");
    ProgramCache cache = makeCache();
    ProgramCacheKey key = cache.keyOf(input("x"));
    Status stored = cache.store(key, sample());
    ASSERT_FALSE(stored.ok());
    EXPECT_NE(stored.error().detail.find(mDir.string()), std::string::npos)
        << stored.error().detail;
    fs::remove(mDir);
}

}  // namespace
}  // namespace varc::driver
