// SPDX-License-Identifier: Apache-2.0
// parseCommandLine: each command's flags decoded into its typed options, the defaults, and each
// value or combination refused as a usage error at parse time.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include "varc/cli/Options.h"

namespace varc::cli {
namespace {

class OptionsTest : public ::testing::Test {
protected:
    void SetUp() override {
        for (const char* name : {"VARC_CACHE", "VARC_CACHE_DIR", "VARC_BUILTIN_INCLUDE_DIR"})
            ::unsetenv(name);
    }
    void TearDown() override { SetUp(); }

    // Parses `varc ARGS...`, keeping what was printed.
    ParsedCommandLine parse(std::initializer_list<std::string> args) {
        std::vector<std::string> words = {"varc"};
        words.insert(words.end(), args);
        std::vector<const char*> argv;
        for (const std::string& word : words) argv.push_back(word.c_str());
        mOut.str("");
        mErr.str("");
        return parseCommandLine(static_cast<int>(argv.size()), argv.data(), mOut, mErr);
    }

    // The options of the one command |args| parse to; fails the test when parsing ended the run.
    template <typename T>
    T parseAs(std::initializer_list<std::string> args) {
        ParsedCommandLine parsed = parse(args);
        EXPECT_TRUE(parsed.command) << "exit " << parsed.exitCode << ": " << mErr.str();
        if (!parsed.command) return T{};
        const T* options = std::get_if<T>(&*parsed.command);
        EXPECT_NE(options, nullptr) << "another command, index " << parsed.command->index();
        return options ? *options : T{};
    }

    // Expects |args| to be a usage error whose message holds |message|.
    void expectUsageError(std::initializer_list<std::string> args, const std::string& message) {
        ParsedCommandLine parsed = parse(args);
        EXPECT_FALSE(parsed.command);
        EXPECT_EQ(parsed.exitCode, kExitUsage);
        EXPECT_NE(mErr.str().find(message), std::string::npos) << mErr.str();
    }

    std::ostringstream mOut, mErr;
};

TEST_F(OptionsTest, VariantsDefaults) {
    VariantsOptions options = parseAs<VariantsOptions>({"variants", "a.shader", "dir"});
    EXPECT_EQ(options.input.inputs, (std::vector<std::string>{"a.shader", "dir"}));
    EXPECT_TRUE(options.input.includeDirs.empty());
    EXPECT_EQ(options.input.projectRoot, "");
    EXPECT_FALSE(options.input.builtinIncludeDir.empty()) << "the installed or source default";
    EXPECT_EQ(options.input.diagnosticsFormat, DiagnosticsFormat::Clang);
    EXPECT_FALSE(options.json);
    EXPECT_FALSE(options.list);
    EXPECT_EQ(options.maxVariants, frontend::kDefaultMaxVariantsPerPass);
}

TEST_F(OptionsTest, VariantsFlags) {
    VariantsOptions options = parseAs<VariantsOptions>(
        {"variants", "--json", "--list", "--max-variants", "5", "--diagnostics-format", "sarif",
         "-I", "inc1", "--include-dir", "inc2", "--project-root", "root", "--builtin-include-dir",
         "builtin", "a.shader"});
    EXPECT_TRUE(options.json);
    EXPECT_TRUE(options.list);
    EXPECT_EQ(options.maxVariants, 5u);
    EXPECT_EQ(options.input.diagnosticsFormat, DiagnosticsFormat::Sarif);
    EXPECT_EQ(options.input.includeDirs, (std::vector<std::string>{"inc1", "inc2"}));
    EXPECT_EQ(options.input.projectRoot, "root");
    EXPECT_EQ(options.input.builtinIncludeDir, "builtin");
}

TEST_F(OptionsTest, BuiltinIncludeDirComesFromTheEnvironmentWhenNotGiven) {
    ::setenv("VARC_BUILTIN_INCLUDE_DIR", "/from/env", 1);
    EXPECT_EQ(parseAs<LockOptions>({"lock", "-o", "x.lock", "a"}).input.builtinIncludeDir,
              "/from/env");
    EXPECT_EQ(parseAs<LockOptions>({"lock", "-o", "x.lock", "--builtin-include-dir", "flag", "a"})
                  .input.builtinIncludeDir,
              "flag");
}

TEST_F(OptionsTest, DiagnosticsFormatsDecode) {
    EXPECT_EQ(parseAs<CheckOptions>({"check", "--lock", "l", "--diagnostics-format", "json", "a"})
                  .input.diagnosticsFormat,
              DiagnosticsFormat::Json);
    EXPECT_EQ(
        parseAs<BuildCommandOptions>({"build", "-o", "p", "--diagnostics-format", "github", "a"})
            .input.diagnosticsFormat,
        DiagnosticsFormat::Github);
    expectUsageError({"variants", "--diagnostics-format", "xml", "a"},
                     "--diagnostics-format: xml not in {clang,json,github,sarif}");
}

TEST_F(OptionsTest, ShaderCommandsNeedPathsAndPositiveLimits) {
    expectUsageError({"variants"}, "no shaders to read");
    expectUsageError({"build", "-o", "p"}, "or a Unity project with --project DIR");
    expectUsageError({"variants", "--project-shaders", "s", "a"}, "needs --project");
    expectUsageError({"variants", "--max-variants", "0", "a"}, "--max-variants");
    expectUsageError({"lock", "a"}, "--output is required");
}

TEST_F(OptionsTest, AProjectStandsInForPaths) {
    VariantsOptions options = parseAs<VariantsOptions>(
        {"variants", "--project", "game", "--project-shaders", "src", "--project-shaders", "src2",
         "--builtin-shaders", "b1", "--builtin-shaders", "b2"});
    EXPECT_TRUE(options.input.inputs.empty());
    EXPECT_EQ(options.input.projectDir, "game");
    EXPECT_EQ(options.input.projectShaders, (std::vector<std::string>{"src", "src2"}));
    EXPECT_EQ(options.input.builtinShaderDirs, (std::vector<std::string>{"b1", "b2"}));
}

TEST_F(OptionsTest, LockTakesItsFileAndLimit) {
    LockOptions options =
        parseAs<LockOptions>({"lock", "-o", "v.lock", "--max-variants", "9", "a"});
    EXPECT_EQ(options.lockPath, "v.lock");
    EXPECT_EQ(options.maxVariants, 9u);
    EXPECT_EQ(parseAs<LockOptions>({"lock", "-o", "v.lock", "a"}).maxVariants,
              frontend::kDefaultMaxVariantsPerPass);
}

TEST_F(OptionsTest, CheckDecodesGrowthAndBudget) {
    CheckOptions plain = parseAs<CheckOptions>({"check", "--lock", "v.lock", "a"});
    EXPECT_EQ(plain.lockPath, "v.lock");
    EXPECT_FALSE(plain.maxGrowth);
    EXPECT_FALSE(plain.budget);
    CheckOptions count = parseAs<CheckOptions>({"check", "--lock", "l", "--max-growth", "12", "a"});
    EXPECT_EQ(count.maxGrowth, (GrowthLimit{12, false}));
    CheckOptions percent =
        parseAs<CheckOptions>({"check", "--lock", "l", "--max-growth", "2.5%", "a"});
    EXPECT_EQ(percent.maxGrowth, (GrowthLimit{2.5, true}));
    EXPECT_EQ(parseAs<CheckOptions>({"check", "--lock", "l", "--budget", "40", "a"}).budget, 40u);
}

TEST_F(OptionsTest, CheckRefusesBadGrowthAndGrowthWithBudget) {
    expectUsageError({"check", "--lock", "l", "--max-growth", "many", "a"},
                     "varc: error: --max-growth expects N or N%, got 'many'");
    expectUsageError({"check", "--lock", "l", "--max-growth", "%", "a"},
                     "--max-growth expects N or N%, got '%'");
    expectUsageError({"check", "--lock", "l", "--max-growth", "3%%", "a"},
                     "--max-growth expects N or N%, got '3%%'");
    expectUsageError({"check", "--lock", "l", "--budget", "3", "--max-growth", "2", "a"},
                     "excludes");
    expectUsageError({"check", "a"}, "--lock is required");
}

TEST_F(OptionsTest, BuildDefaults) {
    BuildCommandOptions options = parseAs<BuildCommandOptions>({"build", "-o", "out.svpack", "a"});
    EXPECT_EQ(options.outputPath, "out.svpack");
    EXPECT_EQ(options.depfilePath, "");
    EXPECT_FALSE(options.json);
    EXPECT_EQ(options.compressionLevel, kDefaultCompressionLevel);
    EXPECT_EQ(options.compressionLevel, 19);
    const CompileOptions& compile = options.compile;
    EXPECT_EQ(compile.jobs, kAllCores);
    EXPECT_EQ(compile.maxVariants, frontend::kDefaultMaxVariantsPerPass);
    EXPECT_EQ(compile.optimization, driver::OptimizationLevel::Performance);
    EXPECT_FALSE(compile.keepGoing);
    EXPECT_FALSE(compile.debugNames);
    EXPECT_TRUE(compile.shard.whole());
    EXPECT_TRUE(compile.cacheLevels.empty());
    EXPECT_TRUE(compile.filePrefixMaps.empty());
}

TEST_F(OptionsTest, BuildFlags) {
    BuildCommandOptions options = parseAs<BuildCommandOptions>(
        {"build", "-o", "p", "-j", "3", "--depfile", "p.d", "--json", "--keep-going", "-g",
         "--compression-level", "3", "--max-variants", "100", "--file-prefix-map", "/opt/sdk=sdk",
         "a"});
    EXPECT_EQ(options.compile.jobs, 3u);
    EXPECT_EQ(options.depfilePath, "p.d");
    EXPECT_TRUE(options.json);
    EXPECT_TRUE(options.compile.keepGoing);
    EXPECT_TRUE(options.compile.debugNames);
    EXPECT_EQ(options.compressionLevel, 3);
    EXPECT_EQ(options.compile.maxVariants, 100u);
    EXPECT_EQ(options.compile.filePrefixMaps, (std::vector<std::string>{"/opt/sdk=sdk"}));
    EXPECT_TRUE(parseAs<BuildCommandOptions>({"build", "-o", "p", "--debug-names", "a"})
                    .compile.debugNames);
}

TEST_F(OptionsTest, BuildDecodesTheOptimisationLevel) {
    using driver::OptimizationLevel;
    auto levelOf = [&](std::initializer_list<std::string> args) {
        return parseAs<BuildCommandOptions>(args).compile.optimization;
    };
    EXPECT_EQ(levelOf({"build", "-O0", "-o", "p", "a"}), OptimizationLevel::None);
    EXPECT_EQ(levelOf({"build", "-Os", "-o", "p", "a"}), OptimizationLevel::Size);
    EXPECT_EQ(levelOf({"build", "-O", "-o", "p", "a"}), OptimizationLevel::Performance);
    EXPECT_EQ(levelOf({"build", "--optimization=-Os", "-o", "p", "a"}), OptimizationLevel::Size);
    expectUsageError({"build", "--optimization", "fast", "-o", "p", "a"}, "--optimization");
    expectUsageError({"build", "-O3", "-o", "p", "a"}, "-O3");
    expectUsageError({"build", "-O0", "-Os", "-o", "p", "a"},
                     "--optimization: At Most 1 required but received 2");
}

TEST_F(OptionsTest, BuildDecodesTheShard) {
    driver::ShardSpec shard =
        parseAs<BuildCommandOptions>({"build", "--shard", "2/3", "-o", "p", "a"}).compile.shard;
    EXPECT_EQ(shard.index, 2u);
    EXPECT_EQ(shard.count, 3u);
    expectUsageError({"build", "--shard", "3/2", "-o", "p", "a"},
                     "expected K/N with 1 <= K <= N <= 4096, got '3/2'");
    expectUsageError({"build", "--shard", "0/2", "-o", "p", "a"}, "got '0/2'");
    expectUsageError({"build", "--shard", "half", "-o", "p", "a"}, "got 'half'");
}

TEST_F(OptionsTest, BuildRefusesACompressionLevelOutOfRange) {
    EXPECT_EQ(parseAs<BuildCommandOptions>({"build", "--compression-level", "22", "-o", "p", "a"})
                  .compressionLevel,
              22);
    expectUsageError({"build", "--compression-level", "30", "-o", "p", "a"},
                     "--compression-level: Value 30 not in range 1 to 22");
    expectUsageError({"build", "--compression-level", "0", "-o", "p", "a"},
                     "--compression-level: Value 0 not in range 1 to 22");
}

TEST_F(OptionsTest, BuildRefusesABadPrefixMapAndAMissingOutput) {
    expectUsageError({"build", "--file-prefix-map", "nothing", "-o", "p", "a"},
                     "expected OLD=NEW, got 'nothing'");
    expectUsageError({"build", "a"}, "--output is required");
}

TEST_F(OptionsTest, CacheDirIsOneFolderLevelTakenWhole) {
    auto levels =
        parseAs<BuildCommandOptions>({"build", "--cache-dir", "/tmp/c|read-only", "-o", "p", "a"})
            .compile.cacheLevels;
    ASSERT_EQ(levels.size(), 1u);
    EXPECT_EQ(levels[0].kind, cache::CacheSpec::Kind::Directory);
    EXPECT_EQ(levels[0].directory, "/tmp/c|read-only") << "the folder name is not parsed";
    EXPECT_FALSE(levels[0].readOnly);
    EXPECT_EQ(levels[0].url, "file:/tmp/c|read-only");
}

TEST_F(OptionsTest, CacheDirComesFirstThenTheCacheUrls) {
    auto levels = parseAs<BuildCommandOptions>({"build", "--cache", "redis://h:7000/2", "--cache",
                                                "file:/shared|read-only", "--cache-dir", "local",
                                                "-o", "p", "a"})
                      .compile.cacheLevels;
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_EQ(levels[0].directory, "local");
    EXPECT_EQ(levels[1].kind, cache::CacheSpec::Kind::Redis);
    EXPECT_EQ(levels[1].host, "h");
    EXPECT_EQ(levels[1].port, 7000);
    EXPECT_EQ(levels[1].database, 2u);
    EXPECT_EQ(levels[2].directory, "/shared");
    EXPECT_TRUE(levels[2].readOnly);
}

TEST_F(OptionsTest, CacheLevelsComeFromTheEnvironmentWhenNotGiven) {
    ::setenv("VARC_CACHE_DIR", "envdir", 1);
    ::setenv("VARC_CACHE", "file:one  redis://127.0.0.1", 1);
    auto levels = parseAs<BuildCommandOptions>({"build", "-o", "p", "a"}).compile.cacheLevels;
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_EQ(levels[0].directory, "envdir");
    EXPECT_EQ(levels[1].directory, "one");
    EXPECT_EQ(levels[2].kind, cache::CacheSpec::Kind::Redis);
    // A --cache flag replaces VARC_CACHE; --cache-dir replaces VARC_CACHE_DIR.
    levels = parseAs<BuildCommandOptions>(
                 {"build", "--cache-dir", "flagdir", "--cache", "file:two", "-o", "p", "a"})
                 .compile.cacheLevels;
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_EQ(levels[0].directory, "flagdir");
    EXPECT_EQ(levels[1].directory, "two");
}

TEST_F(OptionsTest, AMalformedCacheUrlIsAUsageError) {
    expectUsageError({"build", "--cache", "redis://127.0.0.1:99999/0", "-o", "p", "a"},
                     "varc: error: cache URL 'redis://127.0.0.1:99999/0': port 99999 is not "
                     "1-65535");
    ::setenv("VARC_CACHE", "ftp://somewhere", 1);
    expectUsageError({"cache", "stats"}, "cache URL 'ftp://somewhere'");
}

TEST_F(OptionsTest, MergeInfoExtract) {
    MergeOptions merge = parseAs<MergeOptions>({"merge", "-o", "all.svpack", "p1", "p2"});
    EXPECT_EQ(merge.outputPath, "all.svpack");
    EXPECT_EQ(merge.parts, (std::vector<std::string>{"p1", "p2"}));
    InfoOptions info = parseAs<InfoOptions>({"info", "--json", "x.svpack"});
    EXPECT_EQ(info.packPath, "x.svpack");
    EXPECT_TRUE(info.json);
    EXPECT_FALSE(parseAs<InfoOptions>({"info", "x.svpack"}).json);
    ExtractOptions extract = parseAs<ExtractOptions>({"extract", "x.svpack", "-o", "dir"});
    EXPECT_EQ(extract.packPath, "x.svpack");
    EXPECT_EQ(extract.outputDir, "dir");
    expectUsageError({"merge", "p1"}, "--output is required");
    expectUsageError({"extract", "x.svpack"}, "--output is required");
}

TEST_F(OptionsTest, LookupByKeywords) {
    LookupOptions options = parseAs<LookupOptions>(
        {"lookup", "x.svpack", "--shader", "S", "--pass", "ForwardAdd", "--keywords", " A  B "});
    EXPECT_EQ(options.packPath, "x.svpack");
    EXPECT_EQ(options.shader, "S");
    EXPECT_EQ(options.pass, "ForwardAdd");
    EXPECT_EQ(options.keywords, (std::vector<std::string>{"A", "B"}));
    EXPECT_FALSE(options.light);
    EXPECT_EQ(options.policy, variants::SelectionPolicy::Closest);
    EXPECT_FALSE(options.json);
}

TEST_F(OptionsTest, LookupByLight) {
    LookupOptions options = parseAs<LookupOptions>(
        {"lookup", "x.svpack", "--shader", "S", "--pass", "1", "--light", "point", "--cookie",
         "--shadows", "soft", "--vertex-lights", "2", "--hdr", "--policy", "strict", "--json"});
    ASSERT_TRUE(options.light);
    EXPECT_EQ(options.light->type, variants::LightType::Point);
    EXPECT_TRUE(options.light->cookie);
    EXPECT_EQ(options.light->shadows, variants::ShadowMode::Soft);
    EXPECT_EQ(options.light->vertexLightCount, 2);
    EXPECT_TRUE(options.light->hdr);
    EXPECT_TRUE(options.keywords.empty());
    EXPECT_EQ(options.policy, variants::SelectionPolicy::Strict);
    EXPECT_TRUE(options.json);
    LookupOptions plain = parseAs<LookupOptions>(
        {"lookup", "x.svpack", "--shader", "S", "--pass", "1", "--light", "spot"});
    ASSERT_TRUE(plain.light);
    EXPECT_EQ(plain.light->type, variants::LightType::Spot);
    EXPECT_EQ(plain.light->shadows, variants::ShadowMode::None);
    EXPECT_FALSE(plain.light->cookie);
}

TEST_F(OptionsTest, LookupPolicies) {
    for (auto [name, policy] : {std::pair{"exact", variants::SelectionPolicy::Exact},
                                std::pair{"first", variants::SelectionPolicy::First},
                                std::pair{"closest", variants::SelectionPolicy::Closest}}) {
        EXPECT_EQ(parseAs<LookupOptions>({"lookup", "x", "--shader", "S", "--pass", "0",
                                          "--keywords", "A", "--policy", name})
                      .policy,
                  policy)
            << name;
    }
}

TEST_F(OptionsTest, LookupRefusesBadValuesAtParseTime) {
    // The pack need not exist: the values are refused before anything is opened.
    expectUsageError({"lookup", "missing.svpack", "--shader", "S", "--pass", "0", "--keywords", "A",
                      "--policy", "nearest"},
                     "varc: error: --policy expects exact, closest, first or strict, got "
                     "'nearest'");
    expectUsageError({"lookup", "missing.svpack", "--shader", "S", "--pass", "0", "--light", "sun"},
                     "varc: error: --light expects directional, point or spot, got 'sun'");
    expectUsageError({"lookup", "missing.svpack", "--shader", "S", "--pass", "0", "--light",
                      "point", "--shadows", "blurry"},
                     "varc: error: --shadows expects none, hard or soft, got 'blurry'");
}

TEST_F(OptionsTest, LookupRefusesMissingOrConflictingFlags) {
    expectUsageError({"lookup", "x", "--shader", "S", "--pass", "0"},
                     "lookup needs --keywords or --light");
    expectUsageError({"lookup", "x", "--shader", "S", "--pass", "0", "--keywords", "A", "--cookie"},
                     "--cookie requires --light");
    expectUsageError({"lookup", "x", "--shader", "S", "--pass", "0", "--keywords", "A", "--hdr"},
                     "--hdr requires --light");
    expectUsageError({"lookup", "x", "--pass", "0", "--keywords", "A"}, "--shader is required");
}

TEST_F(OptionsTest, ExplainOptions) {
    ExplainOptions options = parseAs<ExplainOptions>(
        {"explain", "--shader", "S", "--pass", "ForwardBase", "--variant", "A B", "--diff", "A",
         "B C", "-j", "2", "--max-variants", "7", "--json", "a.shader"});
    EXPECT_EQ(options.shader, "S");
    EXPECT_EQ(options.pass, "ForwardBase");
    EXPECT_EQ(options.variant, "A B");
    ASSERT_TRUE(options.diff);
    EXPECT_EQ(options.diff->first, "A");
    EXPECT_EQ(options.diff->second, "B C");
    EXPECT_EQ(options.compile.jobs, 2u);
    EXPECT_EQ(options.compile.maxVariants, 7u);
    EXPECT_TRUE(options.json);
    EXPECT_EQ(options.input.inputs, (std::vector<std::string>{"a.shader"}));
    // Explain has no flag for the rest: the driver's defaults.
    EXPECT_EQ(options.compile.optimization, driver::OptimizationLevel::Performance);
    EXPECT_TRUE(options.compile.cacheLevels.empty());
    EXPECT_TRUE(options.compile.shard.whole());
}

TEST_F(OptionsTest, ExplainVariantMayBeEmptyAndDiffNeedsTwo) {
    ExplainOptions none =
        parseAs<ExplainOptions>({"explain", "--shader", "S", "--pass", "0", "--variant", "", "a"});
    EXPECT_EQ(none.variant, "") << "\"\" is the variant without keywords";
    EXPECT_FALSE(none.diff);
    ExplainOptions bare = parseAs<ExplainOptions>({"explain", "--shader", "S", "--pass", "0", "a"});
    EXPECT_FALSE(bare.variant);
    EXPECT_EQ(bare.compile.maxVariants, frontend::kDefaultMaxVariantsPerPass);
    expectUsageError({"explain", "--shader", "S", "--pass", "0", "--diff", "A"}, "--diff");
}

TEST_F(OptionsTest, RenderOptions) {
    RenderOptions options = parseAs<RenderOptions>(
        {"render", "a.svpack", "b.svpack", "--scene", "s.json", "-o", "out.png", "--reference",
         "r.png", "--diff", "d.png", "--pipeline-cache", "pc.bin"});
    EXPECT_EQ(options.session.packPaths, (std::vector<std::string>{"a.svpack", "b.svpack"}));
    EXPECT_EQ(options.session.pipelineCachePath, "pc.bin");
    EXPECT_EQ(options.scenePath, "s.json");
    EXPECT_EQ(options.outputPath, "out.png");
    EXPECT_EQ(options.referencePath, "r.png");
    EXPECT_EQ(options.diffPath, "d.png");
    expectUsageError({"render", "a.svpack", "-o", "out.png"}, "--scene is required");
    EXPECT_EQ(options.variantPolicy, variants::SelectionPolicy::Closest);
    EXPECT_EQ(options.usageLogPath, "");
}

TEST_F(OptionsTest, RenderVariantPolicyAndUsageLog) {
    RenderOptions options =
        parseAs<RenderOptions>({"render", "a.svpack", "--scene", "s.json", "-o", "out.png",
                                "--variant-policy", "strict", "--usage-log", "usage.jsonl"});
    EXPECT_EQ(options.variantPolicy, variants::SelectionPolicy::Strict);
    EXPECT_EQ(options.usageLogPath, "usage.jsonl");
    options = parseAs<RenderOptions>(
        {"render", "a.svpack", "--scene", "s.json", "-o", "o.png", "--variant-policy", "closest"});
    EXPECT_EQ(options.variantPolicy, variants::SelectionPolicy::Closest);
    expectUsageError(
        {"render", "a.svpack", "--scene", "s.json", "-o", "o.png", "--variant-policy", "first"},
        "--variant-policy");
}

TEST_F(OptionsTest, ValidateDefaultsAndFlags) {
    ValidateOptions defaults = parseAs<ValidateOptions>({"validate", "--pack", "a.svpack"});
    EXPECT_EQ(defaults.scenesDir, "tests/scenes/forward");
    EXPECT_EQ(defaults.outputDir, "validate-out");
    EXPECT_EQ(defaults.reportPath, "");
    EXPECT_FALSE(defaults.properties);
    EXPECT_FALSE(defaults.listUncovered);
    EXPECT_EQ(parseAs<ValidateOptions>({"validate", "--pack", "a", "--scenes", ""}).scenesDir,
              kDefaultScenesDir)
        << "an empty folder is the default, as before";
    ValidateOptions options = parseAs<ValidateOptions>(
        {"validate", "--pack", "a", "--pack", "b", "--properties", "--out", "o", "--report",
         "r.html", "--list-uncovered", "--pipeline-cache", "pc"});
    EXPECT_EQ(options.session.packPaths, (std::vector<std::string>{"a", "b"}));
    EXPECT_TRUE(options.properties);
    EXPECT_EQ(options.outputDir, "o");
    EXPECT_EQ(options.reportPath, "r.html");
    EXPECT_TRUE(options.listUncovered);
    EXPECT_EQ(options.session.pipelineCachePath, "pc");
    expectUsageError({"validate", "--properties", "--pack", "a", "--scenes", "s"}, "excludes");
    expectUsageError({"validate"}, "--pack is required");
}

TEST_F(OptionsTest, CacheStatsAndClear) {
    CacheOptions stats = parseAs<CacheOptions>({"cache", "stats", "--cache", "file:d", "--json"});
    EXPECT_EQ(stats.action, CacheOptions::Action::Stats);
    EXPECT_TRUE(stats.json);
    ASSERT_EQ(stats.levels.size(), 1u);
    EXPECT_EQ(stats.levels[0].directory, "d");
    CacheOptions clear = parseAs<CacheOptions>({"cache", "clear", "--cache", "redis://h"});
    EXPECT_EQ(clear.action, CacheOptions::Action::Clear);
    ASSERT_EQ(clear.levels.size(), 1u);
    EXPECT_EQ(clear.levels[0].kind, cache::CacheSpec::Kind::Redis);
    EXPECT_TRUE(parseAs<CacheOptions>({"cache", "stats"}).levels.empty());
    ParsedCommandLine bare = parse({"cache"});
    EXPECT_FALSE(bare.command);
    EXPECT_EQ(bare.exitCode, kExitUsage);
}

TEST_F(OptionsTest, HelpVersionAndUnknownCommands) {
    ParsedCommandLine help = parse({"--help"});
    EXPECT_FALSE(help.command);
    EXPECT_EQ(help.exitCode, kExitOk);
    EXPECT_NE(mOut.str().find("lookup"), std::string::npos) << mOut.str();
    ParsedCommandLine buildHelp = parse({"build", "--help"});
    EXPECT_EQ(buildHelp.exitCode, kExitOk);
    EXPECT_NE(mOut.str().find("zstd level of the pack's blobs, 1-22 (default 19;"),
              std::string::npos)
        << mOut.str();
    EXPECT_NE(mOut.str().find("(default 10000000)"), std::string::npos) << mOut.str();
    ParsedCommandLine version = parse({"--version"});
    EXPECT_EQ(version.exitCode, kExitOk);
    EXPECT_NE(mOut.str().find("built-in includes: "), std::string::npos) << mOut.str();
    expectUsageError({"frobnicate"}, "A subcommand is required");
    ParsedCommandLine nothing = parse({});
    EXPECT_FALSE(nothing.command);
    EXPECT_EQ(nothing.exitCode, kExitUsage);
}

TEST_F(OptionsTest, GenerateWritesTheManPageAndRunsNothing) {
    const std::filesystem::path file =
        std::filesystem::path(::testing::TempDir()) / "varc-options-test.1";
    std::filesystem::remove(file);
    ParsedCommandLine parsed = parse({"_generate", "man", "-o", file.string()});
    EXPECT_FALSE(parsed.command);
    EXPECT_EQ(parsed.exitCode, kExitOk) << mErr.str();
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("lookup"), std::string::npos);
    std::filesystem::remove(file);
    expectUsageError({"_generate", "pdf", "-o", file.string()}, "pdf");
}

}  // namespace
}  // namespace varc::cli
