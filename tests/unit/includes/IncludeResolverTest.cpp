// SPDX-License-Identifier: Apache-2.0
// IncludeResolver: splicing, search order, directive syntax and #line mapping.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "IncludeTestSupport.h"
#include "varc/includes/IncludeResolver.h"

namespace varc::includes {
namespace {

using ::testing::ElementsAre;
using testing::Harness;
using testing::lines;

// The mapping checker must be able to fail, or every test built on it proves nothing.
TEST(IncludeTestSupport, LinesMapBackRejectsWrongOrMissingMapping) {
    SourceMap map;
    FileId a = map.addFile("a.h", lines({"a1", "a2"}));
    FileId b = map.addFile("b.h", lines({"b1"}));
    std::vector<SourceText> roots = {{map.contents(a), {a, 1, 1}}};
    EXPECT_TRUE(testing::linesMapBack(
        lines({"#line 1 0", "a1", "#line 1 1", "b1", "#line 2 0", "a2"}), map, roots));
    EXPECT_FALSE(testing::linesMapBack(lines({"#line 1 0", "a1", "#line 1 1", "b1", "a2"}), map,
                                       roots));  // a2 would be b.h:2
    EXPECT_FALSE(testing::linesMapBack(lines({"#line 2 0", "a1"}), map, roots));
    EXPECT_FALSE(testing::linesMapBack(lines({"a1"}), map, roots));  // no leading #line
    EXPECT_FALSE(testing::linesMapBack(lines({"#line 1 0", "#ifndef VARC_ONCE_1", "a1"}), map,
                                       roots));  // unmapped after a wrapper line
    EXPECT_EQ(b, 1u);
}

TEST(IncludeResolver, SplicesFileInPlaceOfTheIncludeLine) {
    Harness h;
    h.file("a.shader", lines({"line1", "#include \"b.h\"", "line3"}))
        .file("b.h", lines({"b1", "b2"}));
    auto expanded = h.expandFile("a.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text,
              lines({"#line 1 0", "line1", "#line 1 1", "b1", "b2", "#line 3 0", "line3"}));
    EXPECT_THAT(expanded->dependencies, ElementsAre("b.h"));
    EXPECT_TRUE(h.diagnostics.diagnostics().empty());
}

TEST(IncludeResolver, StartsWithLineDirectiveForRootOriginAndOffsetsFirstLineColumns) {
    Harness h;
    std::string shader = lines({"Shader \"X\" {", "    CGPROGRAM #pragma vertex vert",
                                "#include \"b.h\"", "    ENDCG", "}"});
    h.file("s.shader", shader).file("b.h", "B\n");
    // The block starts right after "CGPROGRAM" on line 2 (column 14) and ends before ENDCG.
    auto expanded =
        h.expand({h.root("s.shader", " #pragma vertex vert\n#include \"b.h\"\n", 2, 14)});
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text, lines({"#line 2 0", " #pragma vertex vert", "#line 1 1", "B"}));
    ASSERT_EQ(expanded->pragmas.size(), 1u);
    EXPECT_EQ(expanded->pragmas[0].text, "vertex vert");
    EXPECT_EQ(expanded->pragmas[0].location, (SourceLocation{h.id("s.shader"), 2, 15}));
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, SearchesRelativeThenIncludeDirsThenBuiltin) {
    std::vector<std::string> candidates = {"shaders/x.h", "inc1/x.h", "inc2/x.h", "builtin/x.h"};
    for (size_t first = 0; first < candidates.size(); ++first) {
        SCOPED_TRACE("present from " + candidates[first]);
        Harness h;
        h.includeDir("inc1").includeDir("inc2").builtinDir("builtin");
        h.file("shaders/main.shader", "#include \"x.h\"\n");
        for (size_t i = first; i < candidates.size(); ++i)
            h.file(candidates[i], candidates[i] + "\n");
        auto expanded = h.expandFile("shaders/main.shader");
        ASSERT_TRUE(expanded.has_value());
        EXPECT_THAT(expanded->dependencies, ElementsAre(candidates[first]));
        EXPECT_NE(expanded->text.find("\n" + candidates[first] + "\n"), std::string::npos);
    }
}

TEST(IncludeResolver, SearchesRelativeToTheIncludingFileNotTheRoot) {
    Harness h;
    h.file("shaders/main.shader", "#include \"sub/a.h\"\n")
        .file("shaders/sub/a.h", "#include \"b.h\"\n")
        .file("shaders/sub/b.h", "near\n")
        .file("shaders/b.h", "far\n");
    auto expanded = h.expandFile("shaders/main.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("shaders/sub/a.h", "shaders/sub/b.h"));
    EXPECT_NE(expanded->text.find("near\n"), std::string::npos);
    EXPECT_EQ(expanded->text.find("far\n"), std::string::npos);
}

// Unity resolves "Assets/..." from the project root: the folder above the shader holding Assets/.
TEST(IncludeResolver, FindsProjectRootPathsFromTheNearestFolderAboveThatHasThem) {
    Harness h;
    h.file("repo/Game/Assets/Shaders/main.shader", "#include \"Assets/Lib/Noise.cginc\"\n")
        .file("repo/Game/Assets/Lib/Noise.cginc", "noise\n")
        .file("repo/Assets/Lib/Noise.cginc", "too far\n");
    auto expanded = h.expandFile("repo/Game/Assets/Shaders/main.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("repo/Game/Assets/Lib/Noise.cginc"));
    EXPECT_FALSE(h.diagnostics.hasErrors());
}

TEST(IncludeResolver, AGivenProjectRootIsTheOnlyPlaceForProjectRootPaths) {
    Harness h;
    h.options.projectRoot = "other";
    h.file("game/Assets/main.shader", "#include \"Assets/Lib/Noise.cginc\"\n")
        .file("game/Assets/Lib/Noise.cginc", "near\n")
        .file("other/Assets/Lib/Noise.cginc", "chosen\n");
    auto expanded = h.expandFile("game/Assets/main.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("other/Assets/Lib/Noise.cginc"));

    Harness missing;
    missing.options.projectRoot = "nowhere";
    missing.file("game/main.shader", "#include \"Assets/x.cginc\"\n");
    EXPECT_FALSE(missing.expandFile("game/main.shader").has_value());
    ASSERT_TRUE(missing.diagnostics.hasErrors());
    EXPECT_NE(missing.diagnostics.diagnostics()[0].message.find("nowhere (project root)"),
              std::string::npos)
        << missing.diagnostics.diagnostics()[0].message;
}

// varc --project: "Packages/<name>/..." from the package's folder, "Assets/..." from each
// overlay in order; a miss names every folder tried.
TEST(IncludeResolver, VirtualRootsMapPackagesAndAssetOverlays) {
    Harness h;
    h.options.virtualRoots = {{"Packages/com.example.fx", "cache/com.example.fx@1.2.0"},
                              {"Assets", "project/Assets"},
                              {"Assets", "sources/Assets"}};
    h.file("project/Assets/main.shader",
           "#include \"Packages/com.example.fx/Fx.cginc\"\n#include \"Assets/Lib/Noise.cginc\"\n")
        .file("cache/com.example.fx@1.2.0/Fx.cginc", "fx\n")
        .file("sources/Assets/Lib/Noise.cginc", "noise\n");
    auto expanded = h.expandFile("project/Assets/main.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies,
                ElementsAre("cache/com.example.fx@1.2.0/Fx.cginc", "sources/Assets/Lib/Noise.cginc"));

    Harness missing;
    missing.options.virtualRoots = {{"Packages/com.example.fx", "cache/fx"}};
    missing.file("game/main.shader", "#include \"Packages/com.example.fx/none.cginc\"\n");
    EXPECT_FALSE(missing.expandFile("game/main.shader").has_value());
    ASSERT_TRUE(missing.diagnostics.hasErrors());
    EXPECT_NE(missing.diagnostics.diagnostics()[0].message.find("cache/fx (Packages/com.example.fx)"),
              std::string::npos)
        << missing.diagnostics.diagnostics()[0].message;
}

// Projects made on Windows or macOS include "Autolight.cginc" for AutoLight.cginc.
TEST(IncludeResolver, AFileNameDifferingOnlyInCaseIsFoundWithAWarning) {
    Harness h;
    h.builtinDir("builtin");
    h.file("s/main.shader", "#include \"Autolight.cginc\"\n").file("builtin/AutoLight.cginc", "A\n");
    auto expanded = h.expandFile("s/main.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("builtin/AutoLight.cginc"));
    ASSERT_EQ(h.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(h.diagnostics.diagnostics()[0].severity, Severity::Warning);
    EXPECT_NE(h.diagnostics.diagnostics()[0].message.find("differs in case"), std::string::npos);
}

TEST(IncludeResolver, AnExactNameWinsOverOneDifferingInCase) {
    Harness h;
    h.builtinDir("builtin");
    h.file("s/main.shader", "#include \"x.h\"\n").file("s/X.h", "near\n").file("builtin/x.h", "exact\n");
    auto expanded = h.expandFile("s/main.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("builtin/x.h"));
    EXPECT_TRUE(h.diagnostics.diagnostics().empty());
}

TEST(IncludeResolver, AByteOrderMarkStartingAnIncludeFileIsNotPartOfTheText) {
    Harness h;
    h.file("a.shader", lines({"#include \"b.cginc\"", "a2"}))
        .file("b.cginc", "\xEF\xBB\xBF" + lines({"float b;", "float c;"}));
    auto expanded = h.expandFile("a.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text,
              lines({"#line 1 0", "#line 1 1", "float b;", "float c;", "#line 2 0", "a2"}));
}

TEST(IncludeResolver, AcceptsSpacesInQuotedAndAngledNames) {
    Harness h;
    h.builtinDir("builtin");
    h.file("s/main.shader", lines({"#include \"My Lighting.cginc\"", "#include <Unity Std.cginc>"}))
        .file("s/My Lighting.cginc", "lighting\n")
        .file("builtin/Unity Std.cginc", "std\n");
    auto expanded = h.expandFile("s/main.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies,
                ElementsAre("s/My Lighting.cginc", "builtin/Unity Std.cginc"));
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, AcceptsWhitespaceBetweenHashAndKeyword) {
    Harness h;
    h.file("m.shader",
           lines({"#  include \"a.h\"", "\t#\tinclude\"b.h\"", "  # include <c.h>", "#includes"}))
        .file("a.h", "A\n")
        .file("b.h", "B\n")
        .file("c.h", "C\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("a.h", "b.h", "c.h"));
    EXPECT_EQ(expanded->text.find("include \""), std::string::npos);   // every include replaced
    EXPECT_NE(expanded->text.find("#includes\n"), std::string::npos);  // not an include
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, IgnoresIncludeInComments) {
    Harness h;
    h.file("m.shader",
           lines({"// #include \"missing1.h\"", "/* #include \"missing2.h\" */", "/*",
                  "#include \"missing3.h\"", "*/", "x /* open", "  #include \"missing4.h\"", "*/ y",
                  R"(// continued comment \)", "#include \"missing5.h\"",
                  R"(#include "real.h" // trailing #include "missing6.h")"}))
        .file("real.h", "REAL\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value()) << h.diagnostics.diagnostics().front().message;
    EXPECT_TRUE(h.diagnostics.diagnostics().empty());
    EXPECT_THAT(expanded->dependencies, ElementsAre("real.h"));
    EXPECT_EQ(testing::countOf(expanded->text, "missing"), 5u);  // comments kept verbatim
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, LineContinuationJoinsAnIncludeDirective) {
    Harness h;
    h.file("m.shader", lines({"a", "#include \\", "  \"b.h\"", "c"})).file("b.h", "B\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text, lines({"#line 1 0", "a", "#line 1 1", "B", "#line 4 0", "c"}));
}

TEST(IncludeResolver, KeepsDoubleSlashInsideQuotedNameAndReadsBackslashes) {
    Harness h;
    h.file("m.shader",
           lines({"#include \"dir//b.h\"", "#include <dir//c.h>", R"(#include "dir\d.h")"}))
        .file("dir/b.h", "B\n")
        .file("dir/c.h", "C\n")
        .file("dir/d.h", "D\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("dir/b.h", "dir/c.h", "dir/d.h"));
}

TEST(IncludeResolver, DropsCarriageReturnsAndStillMapsBack) {
    Harness h;
    h.file("m.shader", "a\r\n#include \"b.h\"\r\nc\r\n").file("b.h", "b\r\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text, lines({"#line 1 0", "a", "#line 1 1", "b", "#line 3 0", "c"}));
    EXPECT_TRUE(h.mapsBack(*expanded));
}

TEST(IncludeResolver, KeepsCommentOpenedOnTheIncludeLineOpen) {
    Harness h;
    h.file("m.shader", lines({"#include \"b.h\" /* note", "still comment", "*/", "after"}))
        .file("b.h", "B\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(expanded->text, lines({"#line 1 0", "#line 1 1", "B", "#line 1 0", "/* note",
                                     "still comment", "*/", "after"}));
}

TEST(IncludeResolver, KeepsCommentClosedOnTheIncludeLineClosed) {
    Harness h;
    h.file("m.shader",
           lines({"/* note", "*/ #include \"b.h\"", "after", "x /* c", "*/ #include \"b.h\""}))
        .file("b.h", "B\n");
    auto expanded = h.expandFile("m.shader");
    ASSERT_TRUE(expanded.has_value());
    // The second include follows a token ("x") on its logical line, so it is not a directive.
    EXPECT_EQ(expanded->text, lines({"#line 1 0", "/* note", "*/", "#line 1 1", "B", "#line 3 0",
                                     "after", "x /* c", "*/ #include \"b.h\""}));
}

TEST(IncludeResolver, MapsEveryLineBackThroughNestedIncludes) {
    struct Case {
        const char* name;
        std::map<std::string, std::string> files;  // "m.shader" is the root
    };
    std::vector<Case> cases = {
        {"three levels",
         {{"m.shader", lines({"m1", "#include \"a.h\"", "m3", "#include \"a.h\"", "m5"})},
          {"a.h", lines({"a1", "#include \"sub/b.h\"", "a3"})},
          {"sub/b.h", lines({"#include \"c.h\"", "b2"})},
          {"sub/c.h", "c1 without newline"}}},
        {"includes first and last, empty file",
         {{"m.shader", "#include \"e.h\"\n#include \"a.h\"\nm3\n#include \"a.h\""},
          {"e.h", ""},
          {"a.h", lines({"#include \"e.h\"", "a2", "#include \"e.h\""})}}},
        {"continuations and directives",
         {{"m.shader", lines({"#define X \\", "  1", "#if X", "#include \"a.h\"", "#endif",
                              "float f = \\", "  2;", "#include \"a.h\""})},
          {"a.h",
           lines({"#pragma once", "a2 \\", "a3", "/* a4", "#include \"missing.h\"", "a6 */"})}}},
        {"blank lines and deep chain",
         {{"m.shader", lines({"", "", "#include \"1.h\"", ""})},
          {"1.h", lines({"", "#include \"2.h\"", ""})},
          {"2.h", lines({"#include \"3.h\"", "", "#include \"3.h\""})},
          {"3.h", lines({"", "three", ""})}}},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        Harness h;
        for (const auto& [path, contents] : c.files) h.file(path, contents);
        auto expanded = h.expandFile("m.shader");
        ASSERT_TRUE(expanded.has_value());
        EXPECT_TRUE(h.mapsBack(*expanded)) << expanded->text;
        size_t rootLines = testing::linesFrom(expanded->text, h.sourceMap, "m.shader").size();
        EXPECT_GT(rootLines, 0u);
    }
}

TEST(IncludeResolver, SharesGuardStateAcrossRootsAndMapsEachRoot) {
    Harness h;
    std::string shader = lines({"CGINCLUDE", "#include \"g.h\"", "float shared;", "ENDCG",
                                "CGPROGRAM", "#pragma vertex v", "#include \"g.h\"", "ENDCG"});
    h.file("s.shader", shader).file("g.h", lines({"#pragma once", "G"}));
    auto expanded = h.expand({h.root("s.shader", "\n#include \"g.h\"\nfloat shared;\n", 1, 10),
                              h.root("s.shader", "\n#pragma vertex v\n#include \"g.h\"\n", 5, 10)});
    ASSERT_TRUE(expanded.has_value());
    EXPECT_EQ(testing::linesFrom(expanded->text, h.sourceMap, "g.h").size(), 2u);  // one copy
    EXPECT_EQ(testing::countOf(expanded->text, "\nG\n"), 1u);
    ASSERT_EQ(expanded->pragmas.size(), 1u);
    EXPECT_EQ(expanded->pragmas[0].location, (SourceLocation{h.id("s.shader"), 6, 1}));
    EXPECT_TRUE(h.mapsBack(*expanded)) << expanded->text;
}

TEST(IncludeResolver, ListsDependenciesOnceInFirstReadOrderWithNormalisedPaths) {
    Harness h;
    h.file("s/m.shader", lines({"#include \"./b.h\"", "#include \"c.h\"", "#include \"b.h\""}))
        .file("s/b.h", "#include \"../lib/d.h\"\n")
        .file("s/c.h", lines({"#include \"../lib/d.h\"", "#include \"b.h\""}))
        .file("lib/d.h", "D\n");
    auto expanded = h.expandFile("s/m.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_THAT(expanded->dependencies, ElementsAre("s/b.h", "lib/d.h", "s/c.h"));
}

// Counts reads, to check each file is read once per SourceMap.
class CountingFileSystem final : public FileSystem {
public:
    explicit CountingFileSystem(const FileSystem& inner) : mInner(inner) {}
    std::optional<std::string> read(const std::string& path) const override {
        ++mReads[normalizePath(path)];
        return mInner.read(path);
    }
    bool isFile(const std::string& path) const override { return mInner.isFile(path); }
    std::vector<std::string> fileNames(const std::string& dir) const override {
        return mInner.fileNames(dir);
    }
    int reads(const std::string& path) const {
        auto it = mReads.find(path);
        return it == mReads.end() ? 0 : it->second;
    }

private:
    const FileSystem& mInner;
    mutable std::map<std::string, int> mReads;
};

TEST(IncludeResolver, ReadsEachFileOncePerSourceMap) {
    InMemoryFileSystem files;
    files.add("m.shader", lines({"#include \"u.h\"", "#include \"u.h\""})).add("u.h", "U\n");
    CountingFileSystem counting(files);
    SourceMap sourceMap;
    FileId root = sourceMap.addFile("m.shader", *files.read("m.shader"));
    DiagnosticList diagnostics;
    for (int pass = 0; pass < 2; ++pass) {  // e.g. two passes, each with its own resolver
        IncludeResolver resolver(counting, sourceMap, {});
        auto expanded = resolver.expand({{sourceMap.contents(root), {root, 1, 1}}}, diagnostics);
        ASSERT_TRUE(expanded.has_value());
        EXPECT_EQ(testing::countOf(expanded->text, "U\n"), 2u);  // unguarded: spliced twice
        EXPECT_THAT(expanded->dependencies, ElementsAre("u.h"));
    }
    EXPECT_EQ(counting.reads("u.h"), 1);
}

TEST(IncludeResolver, ExpandsTheMyLightingFixtureFromDisk) {
    namespace fs = std::filesystem;
    std::string fixture = VARC_SHARED_DIR "/fixtures/seed000-multiple-lights/My Lighting.cginc";
    fs::path builtin = fs::temp_directory_path() / "varc-includes-fixture-builtin";
    fs::remove_all(builtin);
    fs::create_directories(builtin);
    auto write = [&](const char* name, const std::string& text) {
        std::ofstream(builtin / name, std::ios::binary) << text;
    };
    write("UnityCG.cginc", lines({"#ifndef UNITY_CG_INCLUDED", "#define UNITY_CG_INCLUDED",
                                  "float4 unity_stub;", "#endif"}));
    write("AutoLight.cginc",
          lines({"#ifndef AUTOLIGHT_INCLUDED", "#define AUTOLIGHT_INCLUDED",
                 "#include \"UnityCG.cginc\"",
                 "#define UNITY_LIGHT_ATTENUATION(a, b, c) float a = 1", "#endif"}));
    write("UnityPBSLighting.cginc", lines({"#pragma once", "#include \"UnityCG.cginc\"",
                                           "struct UnityLight { float3 color; };"}));

    DiskFileSystem disk;
    SourceMap sourceMap;
    std::optional<std::string> text = disk.read(fixture);
    ASSERT_TRUE(text.has_value()) << fixture;
    FileId root = sourceMap.addFile(fixture, *text);
    IncludeOptions options;
    options.builtinDir = builtin.string();
    IncludeResolver resolver(disk, sourceMap, options);
    DiagnosticList diagnostics;
    std::vector<SourceText> roots = {{*text, {root, 1, 1}}};
    auto expanded = resolver.expand(roots, diagnostics);
    ASSERT_TRUE(expanded.has_value());
    std::string dir = normalizePath(builtin.string());
    EXPECT_THAT(expanded->dependencies,
                ElementsAre(dir + "/AutoLight.cginc", dir + "/UnityCG.cginc",
                            dir + "/UnityPBSLighting.cginc"));
    EXPECT_TRUE(testing::linesMapBack(expanded->text, sourceMap, roots)) << expanded->text;
    // Every line of the fixture but its two #include lines, each once; UnityCG spliced once.
    EXPECT_EQ(testing::linesFrom(expanded->text, sourceMap, fixture).size(), 104u - 2u);
    EXPECT_EQ(testing::countOf(expanded->text, "float4 unity_stub;"), 1u);
    EXPECT_TRUE(expanded->pragmas.empty());
    fs::remove_all(builtin);
}

// A chain of distinct files (no cycle) is refused past kMaxIncludeDepth files open at once, at
// the #include that goes one too far; a chain exactly at the limit expands.
TEST(IncludeResolverLimits, IncludeDepthAtTheLimitAndPast) {
    auto chain = [](size_t files) {
        Harness h;
        // f0.shader includes f1.h, which includes f2.h, ... up to f<files-1>.h.
        h.file("f0.shader", "#include \"f1.h\"\n");
        for (size_t i = 1; i < files; ++i) {
            std::string next = i + 1 < files ? "#include \"f" + std::to_string(i + 1) + ".h\"\n"
                                             : std::string("last\n");
            h.file("f" + std::to_string(i) + ".h", next);
        }
        return h;
    };
    Harness atLimit = chain(kMaxIncludeDepth);
    auto expanded = atLimit.expandFile("f0.shader");
    ASSERT_TRUE(expanded.has_value());
    EXPECT_TRUE(atLimit.diagnostics.diagnostics().empty());
    EXPECT_NE(expanded->text.find("last"), std::string::npos);

    Harness past = chain(kMaxIncludeDepth + 1);
    EXPECT_FALSE(past.expandFile("f0.shader").has_value());
    ASSERT_EQ(past.diagnostics.diagnostics().size(), 1u);
    const Diagnostic& error = past.diagnostics.diagnostics().front();
    EXPECT_NE(error.message.find("#include nested too deeply: \"f64.h\" would be file 65"),
              std::string::npos)
        << error.message;
    EXPECT_EQ(error.location.file, past.id("f63.h"));
}

}  // namespace
}  // namespace varc::includes
