// SPDX-License-Identifier: Apache-2.0
// VariantRequests: misses reported once and counted, strict errors, the usage log's bytes, threads.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "PackTestData.h"
#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/ShaderView.h"
#include "varc/reader/VariantRequests.h"

namespace varc {
namespace {

using reader::Pack;
using reader::PassView;
using reader::VariantMiss;
using reader::VariantRequests;
using variants::SelectionPolicy;
using Names = std::vector<std::string>;

class VariantRequestsTest : public ::testing::Test {
protected:
    void SetUp() override {
        Result<Pack> pack =
            Pack::fromBytes(packwriter::serializePack(packtest::makeSampleContents()));
        ASSERT_TRUE(pack.ok()) << pack.error().detail;
        mPack.emplace(std::move(*pack));
    }
    PassView pass(std::string_view lightMode) {
        return *mPack->findShader("Custom/Lit")->pass(lightMode);
    }

    std::optional<Pack> mPack;
};

TEST_F(VariantRequestsTest, MissIsReportedOnceThenCounted) {
    std::vector<VariantMiss> reported;
    VariantRequests requests([&](const VariantMiss& miss) { reported.push_back(miss); });
    for (int i = 0; i < 3; ++i) {
        auto found =
            requests.resolve(pass("ForwardAdd"), Names{"SPOT", "POINT"}, SelectionPolicy::Closest);
        ASSERT_TRUE(found.ok()) << found.error().detail;
        EXPECT_FALSE(found->exact());
        EXPECT_EQ(found->keywords(), Names{"POINT"});
    }
    ASSERT_EQ(reported.size(), 1u);
    EXPECT_EQ(reported[0].report,
              "shader \"Custom/Lit\" pass 1 (ForwardAdd): no variant with POINT SPOT; using POINT "
              "(closest)");
    EXPECT_EQ(reported[0].requested, (Names{"POINT", "SPOT"}));
    EXPECT_EQ(reported[0].used, Names{"POINT"});
    EXPECT_EQ(reported[0].count, 1u);
    std::vector<VariantMiss> all = requests.misses();
    ASSERT_EQ(all.size(), 1u);
    EXPECT_EQ(all[0].count, 3u);
    // Another keyword set is another miss, reported on its own.
    ASSERT_TRUE(requests.resolve(pass("ForwardBase"), Names{}, SelectionPolicy::Closest).ok());
    ASSERT_EQ(reported.size(), 2u);
    EXPECT_EQ(reported[1].report,
              "shader \"Custom/Lit\" pass 0 (ForwardBase): no variant with no keywords; using "
              "DIRECTIONAL (closest)");
    EXPECT_EQ(requests.requestCount(), 2u);
}

TEST_F(VariantRequestsTest, HitsAndUndeclaredKeywordsAreNotMisses) {
    VariantRequests requests;
    auto found = requests.resolve(pass("ForwardAdd"), Names{"SPOT", "NOT_DECLARED"},
                                  SelectionPolicy::Strict);
    ASSERT_TRUE(found.ok()) << found.error().detail;
    EXPECT_TRUE(found->exact());
    EXPECT_TRUE(requests.takeNewMisses().empty());
    EXPECT_TRUE(requests.misses().empty());
    EXPECT_EQ(requests.requestCount(), 1u);
}

TEST_F(VariantRequestsTest, TakeNewMissesReturnsEachMissOnce) {
    VariantRequests requests;
    ASSERT_TRUE(requests.resolve(pass("ShadowCaster"), Names{}, SelectionPolicy::Closest).ok());
    ASSERT_TRUE(requests.resolve(pass("ShadowCaster"), Names{}, SelectionPolicy::Closest).ok());
    std::vector<VariantMiss> first = requests.takeNewMisses();
    ASSERT_EQ(first.size(), 1u);
    EXPECT_EQ(first[0].report,
              "shader \"Custom/Lit\" pass 2 (ShadowCaster): no variant with no keywords; using "
              "SHADOWS_DEPTH (closest)");
    ASSERT_TRUE(requests.resolve(pass("ShadowCaster"), Names{}, SelectionPolicy::Closest).ok());
    EXPECT_TRUE(requests.takeNewMisses().empty());
    EXPECT_EQ(requests.misses()[0].count, 3u);
}

TEST_F(VariantRequestsTest, StrictMissIsAnErrorNamingTheNearestVariants) {
    VariantRequests requests;
    for (int i = 0; i < 2; ++i) {
        auto found =
            requests.resolve(pass("ForwardAdd"), Names{"SPOT", "POINT"}, SelectionPolicy::Strict);
        ASSERT_FALSE(found.ok());
        EXPECT_EQ(found.error().code, ErrorCode::NotFound);
        // Every strict miss fails with the same text; it is reported once.
        EXPECT_EQ(found.error().detail,
                  "shader \"Custom/Lit\" pass 1 (ForwardAdd): no variant with POINT SPOT "
                  "(strict); nearest: POINT | SPOT | DIRECTIONAL");
    }
    EXPECT_EQ(requests.takeNewMisses().size(), 1u);
    EXPECT_EQ(requests.misses()[0].count, 2u);
    EXPECT_TRUE(requests.misses()[0].used.empty());
}

TEST_F(VariantRequestsTest, LightRequestsRecordTheLightsKeywords) {
    VariantRequests requests;
    variants::LightDescription spot;
    spot.type = variants::LightType::Spot;
    spot.shadows = variants::ShadowMode::Hard;
    auto found = requests.resolve(pass("ForwardAdd"), spot, SelectionPolicy::Closest);
    ASSERT_TRUE(found.ok()) << found.error().detail;
    EXPECT_EQ(found->keywords(), Names{"SPOT"});  // SHADOWS_DEPTH is not declared here
    EXPECT_TRUE(found->exact());
    EXPECT_NE(requests.usageLog().find("\"keywords\":[\"SPOT\"]"), std::string::npos);
}

// The same requests, in two orders: the same bytes, sorted by (shader, pass, keywords).
TEST_F(VariantRequestsTest, UsageLogBytesAreExactAndDeterministic) {
    const std::string expected =
        "{\"varc_usage_log\":1}\n"
        "{\"shader\":\"Custom/Lit\",\"pass\":0,\"lightmode\":\"ForwardBase\",\"keywords\":[]}\n"
        "{\"shader\":\"Custom/Lit\",\"pass\":0,\"lightmode\":\"ForwardBase\","
        "\"keywords\":[\"DIRECTIONAL\",\"FOG_EXP\"]}\n"
        "{\"shader\":\"Custom/Lit\",\"pass\":1,\"lightmode\":\"ForwardAdd\","
        "\"keywords\":[\"POINT\",\"SPOT\"]}\n"
        "{\"shader\":\"Custom/Lit\",\"pass\":2,\"lightmode\":\"ShadowCaster\","
        "\"keywords\":[\"SHADOWS_CUBE\"]}\n"
        "{\"shader\":\"Custom/Unlit\",\"pass\":0,\"lightmode\":\"\",\"keywords\":[]}\n";
    PassView unlit = *mPack->findShader("Custom/Unlit")->pass(size_t{0});
    std::vector<std::pair<PassView, Names>> calls = {
        {pass("ShadowCaster"), {"SHADOWS_CUBE"}},
        {pass("ForwardAdd"), {"SPOT", "POINT"}},
        {unlit, {}},
        {pass("ForwardBase"), {"FOG_EXP", "DIRECTIONAL"}},
        {pass("ForwardBase"), {}},
        {pass("ForwardBase"), {"DIRECTIONAL", "FOG_EXP", "UNDECLARED"}},
    };
    VariantRequests forward, backward;
    for (const auto& [p, names] : calls) {
        ASSERT_TRUE(forward.resolve(p, names, SelectionPolicy::Closest).ok());
    }
    for (auto it = calls.rbegin(); it != calls.rend(); ++it) {
        ASSERT_TRUE(backward.resolve(it->first, it->second, SelectionPolicy::Closest).ok());
    }
    EXPECT_EQ(forward.usageLog(), expected);
    EXPECT_EQ(backward.usageLog(), expected);
    EXPECT_EQ(VariantRequests().usageLog(), "{\"varc_usage_log\":1}\n");
}

TEST_F(VariantRequestsTest, WriteUsageLogWritesTheBytesAndKeepsDevices) {
    VariantRequests requests;
    ASSERT_TRUE(requests.resolve(pass("ForwardAdd"), Names{"SPOT"}, SelectionPolicy::Closest));
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("varc-usage-log-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "usage.jsonl").string();
    ASSERT_TRUE(requests.writeUsageLog(path).ok());
    std::ifstream in(path, std::ios::binary);
    std::stringstream read;
    read << in.rdbuf();
    EXPECT_EQ(read.str(), requests.usageLog());
    // A directory is refused with its name, and left alone.
    Status refused = requests.writeUsageLog(dir.string());
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().detail.find(dir.string()), std::string::npos);
    std::filesystem::remove_all(dir);
    ASSERT_TRUE(requests.writeUsageLog("/dev/null").ok());
    struct stat info {};
    ASSERT_EQ(::stat("/dev/null", &info), 0);
    EXPECT_TRUE(S_ISCHR(info.st_mode));
}

// Two threads ask for the same missing and held variants at once: each miss is reported exactly
// once and every request counted.
TEST_F(VariantRequestsTest, TwoThreadsReportEachMissOnce) {
    std::atomic<int> reports{0};
    VariantRequests requests([&](const VariantMiss&) { ++reports; });
    constexpr int kRounds = 500;
    auto work = [&] {
        for (int i = 0; i < kRounds; ++i) {
            EXPECT_TRUE(requests.resolve(pass("ForwardAdd"), Names{"SPOT", "POINT"},
                                         SelectionPolicy::Closest));
            EXPECT_TRUE(requests.resolve(pass("ShadowCaster"), Names{}, SelectionPolicy::Closest));
            EXPECT_TRUE(
                requests.resolve(pass("ForwardAdd"), Names{"SPOT"}, SelectionPolicy::Closest));
        }
    };
    std::thread a(work), b(work);
    a.join();
    b.join();
    EXPECT_EQ(reports.load(), 2);
    std::vector<VariantMiss> all = requests.misses();
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].count, 2u * kRounds);
    EXPECT_EQ(all[1].count, 2u * kRounds);
    EXPECT_EQ(requests.requestCount(), 3u);
}

}  // namespace
}  // namespace varc
