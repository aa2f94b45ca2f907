// SPDX-License-Identifier: Apache-2.0
// `build --skip-failing-shaders`: which shaders are left out, and what is reported about them.
#include <gtest/gtest.h>

#include "varc/cli/SkipFailingShaders.h"

namespace varc::cli {
namespace {

std::vector<frontend::LoadedShader> shadersAt(const std::vector<std::string>& paths) {
    std::vector<frontend::LoadedShader> shaders;
    for (const std::string& path : paths) {
        shaders.emplace_back();
        shaders.back().path = path;
    }
    return shaders;
}

Diagnostic errorAt(uint32_t line, std::string message) {
    return {Severity::Error, SourceLocation{0, line, 1}, std::move(message), {}};
}

// A build step that fails whenever a shader whose path starts with "bad" is in the set, reporting
// "broken <path>" at line 1 and, for "bad-late", a second error only its own build finds.
struct FakeBuild {
    std::vector<std::vector<std::string>> calls;  // the paths of each call's shaders

    std::optional<BuiltPack> operator()(const std::vector<frontend::LoadedShader>& shaders,
                                        DiagnosticSink& sink) {
        calls.emplace_back();
        bool failed = false;
        for (const frontend::LoadedShader& shader : shaders) {
            calls.back().push_back(shader.path);
            if (shader.path.rfind("bad", 0) != 0) continue;
            failed = true;
            sink.report(errorAt(1, "broken " + shader.path));
            if (shader.path == "bad-late") sink.report(errorAt(2, "late check of bad-late"));
        }
        if (failed) return std::nullopt;
        return BuiltPack{};
    }
};

TEST(SkipFailingShaders, LeavesOutWhatFailsAloneAndBuildsTheRestTogether) {
    auto shaders = shadersAt({"a", "bad-x", "b", "bad-late"});
    FakeBuild fake;
    DiagnosticList reported;
    reported.report(errorAt(1, "broken bad-x"));  // the first build found these
    reported.report(errorAt(1, "broken bad-late"));
    std::vector<std::string> leftOut;
    auto built = buildWithoutFailingShaders(
        shaders, [&](const auto& s, DiagnosticSink& sink) { return fake(s, sink); }, leftOut,
        reported);
    ASSERT_TRUE(built.has_value());
    EXPECT_EQ(leftOut, (std::vector<std::string>{"bad-x", "bad-late"}));
    ASSERT_EQ(shaders.size(), 2u);
    EXPECT_EQ(shaders[0].path, "a");
    EXPECT_EQ(shaders[1].path, "b");
    // Each shader alone, then the survivors together, in input order.
    ASSERT_EQ(fake.calls.size(), 5u);
    EXPECT_EQ(fake.calls[4], (std::vector<std::string>{"a", "b"}));
    // Only the problem the first build had not reported is added.
    ASSERT_EQ(reported.diagnostics().size(), 3u);
    EXPECT_EQ(reported.diagnostics()[2].message, "late check of bad-late");
}

TEST(SkipFailingShaders, NothingLeftIsAFailure) {
    auto shaders = shadersAt({"bad-1", "bad-2"});
    FakeBuild fake;
    DiagnosticList reported;
    std::vector<std::string> leftOut;
    auto built = buildWithoutFailingShaders(
        shaders, [&](const auto& s, DiagnosticSink& sink) { return fake(s, sink); }, leftOut,
        reported);
    EXPECT_FALSE(built.has_value());
    EXPECT_EQ(leftOut.size(), 2u);
    EXPECT_TRUE(shaders.empty());
    EXPECT_EQ(fake.calls.size(), 2u);  // no build of an empty set
}

TEST(SkipFailingShaders, ARestThatFailsTogetherReportsWhy) {
    auto shaders = shadersAt({"a", "b"});
    DiagnosticList reported;
    std::vector<std::string> leftOut;
    auto built = buildWithoutFailingShaders(
        shaders,
        [](const std::vector<frontend::LoadedShader>& s,
           DiagnosticSink& sink) -> std::optional<BuiltPack> {
            if (s.size() == 1) return BuiltPack{};
            sink.report(errorAt(7, "a and b clash"));
            return std::nullopt;
        },
        leftOut, reported);
    EXPECT_FALSE(built.has_value());
    EXPECT_TRUE(leftOut.empty());
    ASSERT_EQ(reported.diagnostics().size(), 1u);
    EXPECT_EQ(reported.diagnostics()[0].message, "a and b clash");
}

}  // namespace
}  // namespace varc::cli
