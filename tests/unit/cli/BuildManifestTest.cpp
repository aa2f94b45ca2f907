// SPDX-License-Identifier: Apache-2.0
// BuildManifest and RecordingFileSystem: the record `varc build --direct` keeps, round trips,
// damaged text, and which changes to the files make it stale.
#include <gtest/gtest.h>

#include "varc/cli/BuildManifest.h"
#include "varc/cli/RecordingFileSystem.h"

namespace varc::cli {
namespace {

const std::string kKey = "0123456789abcdef0123456789abcdef";

BuildManifest sampleManifest() {
    BuildManifest manifest;
    manifest.key = kKey;
    manifest.packDigest = contentDigest("pack bytes");
    manifest.packBytes = 10;
    manifest.dependencies = {"shaders/a.shader", "inc/My Lighting.cginc"};
    manifest.queries = {{FileQueryKind::Read, "shaders/a.shader", contentDigest("a")},
                        {FileQueryKind::Read, "inc/Missing.cginc", "-"},
                        {FileQueryKind::IsFile, "shaders/My Lighting.cginc", "0"},
                        {FileQueryKind::List, "builtin", contentDigest("x.cginc\n")}};
    return manifest;
}

TEST(BuildManifest, RoundTripsThroughItsText) {
    std::optional<std::string> text = serializeManifest(sampleManifest());
    ASSERT_TRUE(text);
    std::optional<BuildManifest> parsed = parseManifest(*text, kKey);
    ASSERT_TRUE(parsed);
    EXPECT_EQ(*parsed, sampleManifest());
}

TEST(BuildManifest, RefusesAnotherKey) {
    std::string text = *serializeManifest(sampleManifest());
    EXPECT_FALSE(parseManifest(text, "ffffffffffffffffffffffffffffffff"));
}

TEST(BuildManifest, RefusesEveryTruncationAndEveryFlippedByte) {
    std::string text = *serializeManifest(sampleManifest());
    for (size_t size = 0; size < text.size(); ++size) {
        EXPECT_FALSE(parseManifest(text.substr(0, size), kKey)) << "prefix of " << size;
    }
    for (size_t i = 0; i < text.size(); ++i) {
        std::string damaged = text;
        damaged[i] = static_cast<char>(damaged[i] ^ 0x20);
        EXPECT_FALSE(parseManifest(damaged, kKey)) << "byte " << i;
    }
    EXPECT_FALSE(parseManifest(text + "read - extra\n", kKey));
}

TEST(BuildManifest, RefusesUnknownLinesEvenWithAGoodChecksum) {
    BuildManifest manifest = sampleManifest();
    manifest.queries[0].answer = "not a digest";  // written, then refused when read
    std::optional<std::string> text = serializeManifest(manifest);
    ASSERT_TRUE(text);
    EXPECT_FALSE(parseManifest(*text, kKey));
}

TEST(BuildManifest, IsNotWrittenForAPathWithALineBreak) {
    BuildManifest manifest = sampleManifest();
    manifest.queries[0].path = "a\nkey ffff";
    EXPECT_FALSE(serializeManifest(manifest));
}

TEST(BuildManifest, HoldsUntilAFileChangesAppearsOrIsListedDifferently) {
    includes::InMemoryFileSystem before;
    before.add("shaders/a.shader", "a").add("inc/Light.cginc", "light");
    RecordingFileSystem recorder(before);
    recorder.startRecording();
    recorder.read("shaders/a.shader");
    recorder.isFile("shaders/Light.cginc");  // the search tried next to the shader first
    recorder.read("inc/Light.cginc");
    recorder.fileNames("inc");
    BuildManifest manifest{kKey, contentDigest("p"), 1, {}, recorder.queries()};
    EXPECT_EQ(manifest.queries.size(), 4u);
    EXPECT_FALSE(firstChangedQuery(manifest, before));

    includes::InMemoryFileSystem same;  // the same bytes (a touch changes no digest)
    same.add("shaders/a.shader", "a").add("inc/Light.cginc", "light");
    EXPECT_FALSE(firstChangedQuery(manifest, same));

    includes::InMemoryFileSystem changed;
    changed.add("shaders/a.shader", "a").add("inc/Light.cginc", "light 2");
    EXPECT_EQ(firstChangedQuery(manifest, changed), "inc/Light.cginc");

    includes::InMemoryFileSystem shadowed;  // an include created earlier on the search path
    shadowed.add("shaders/a.shader", "a").add("inc/Light.cginc", "light");
    shadowed.add("shaders/Light.cginc", "shadow");
    EXPECT_EQ(firstChangedQuery(manifest, shadowed), "shaders/Light.cginc");

    includes::InMemoryFileSystem listed;  // a new file in a folder the build listed
    listed.add("shaders/a.shader", "a").add("inc/Light.cginc", "light").add("inc/New.cginc", "");
    EXPECT_EQ(firstChangedQuery(manifest, listed), "inc");
}

TEST(RecordingFileSystem, RecordsNothingBeforeStartingAndEachQuestionOnce) {
    includes::InMemoryFileSystem files;
    files.add("a.cginc", "a");
    RecordingFileSystem recorder(files);
    EXPECT_EQ(recorder.read("a.cginc"), "a");
    EXPECT_TRUE(recorder.queries().empty());
    recorder.startRecording();
    recorder.read("a.cginc");
    recorder.read("a.cginc");
    recorder.read("b.cginc");
    std::vector<FileQuery> expected = {{FileQueryKind::Read, "a.cginc", contentDigest("a")},
                                       {FileQueryKind::Read, "b.cginc", "-"}};
    EXPECT_EQ(recorder.queries(), expected);
}

}  // namespace
}  // namespace varc::cli
