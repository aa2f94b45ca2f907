// SPDX-License-Identifier: Apache-2.0
// readStripRules: every field in both forms, each error at its line and column, truncations.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ProjectTestSupport.h"
#include "varc/project/StripRuleFile.h"

namespace varc::project {
namespace {

using test::TempProject;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

constexpr FileId kRulesFileId = 7;

// Reads |text| as `rules.yaml` of a temp folder, the file given kRulesFileId.
struct RuleFile {
    TempProject folder;
    DiagnosticList diagnostics;
    std::vector<std::filesystem::path> idRequests;

    std::optional<std::vector<StripRuleSpec>> read(const std::string& text) {
        folder.write("rules.yaml", text);
        return readPath(folder.root() / "rules.yaml");
    }
    std::optional<std::vector<StripRuleSpec>> readPath(const std::filesystem::path& path) {
        return readStripRules(path, diagnostics, [this](const std::filesystem::path& file) {
            idRequests.push_back(file);
            return kRulesFileId;
        });
    }
    // Each diagnostic as `line:col: severity: message`, after checking it names the file.
    std::vector<std::string> texts() const {
        std::vector<std::string> out;
        for (const Diagnostic& d : diagnostics.diagnostics()) {
            EXPECT_EQ(d.location.file, kRulesFileId) << d.message;
            out.push_back(std::to_string(d.location.line) + ":" +
                          std::to_string(d.location.column) + ": " + severityName(d.severity) +
                          ": " + d.message);
        }
        return out;
    }
};

const std::string kFullFile =
    "# varc strip rules: each rule removes the variants that match it\n"  // 1
    "rules:\n"                                                            // 2
    "  - name: no exp2 fog in add passes\n"                               // 3
    "    shader: \"Custom/*\"\n"                                          // 4
    "    pass: ForwardAdd\n"                                              // 5
    "    stage: fragment\n"                                               // 6
    "    with: [FOG_EXP2]\n"                                              // 7
    "    without: [LIGHTMAP_ON, _SHADOWS_SOFT]\n"                         // 8
    "  - name: no vertex lights\n"                                        // 9
    "    stage: vertex\n"                                                 // 10
    "    with: VERTEXLIGHT_ON\n"                                          // 11
    "  - without:\n"                                                      // 12
    "      - INSTANCING_ON\n"                                             // 13
    "      - DIRLIGHTMAP_COMBINED\n"                                      // 14
    "    name: 'only instanced, directional'\n"                           // 15
    "    shader: Hidden/Internal*Shadow\n"                                // 16
    "    pass:\n";                                                        // 17

TEST(StripRuleFile, ReadsEveryFieldInScalarAndListForms) {
    RuleFile file;
    auto rules = file.read(kFullFile);
    ASSERT_TRUE(rules.has_value()) << ::testing::PrintToString(file.texts());
    EXPECT_THAT(file.texts(), IsEmpty());
    ASSERT_EQ(rules->size(), 3u);

    const StripRuleSpec& fog = (*rules)[0];
    EXPECT_EQ(fog.name, "no exp2 fog in add passes");
    EXPECT_EQ(fog.location, (SourceLocation{kRulesFileId, 3, 5}));
    EXPECT_EQ(fog.shader, "Custom/*");
    EXPECT_EQ(fog.pass, "ForwardAdd");
    EXPECT_EQ(fog.stage, Stage::Fragment);
    EXPECT_THAT(fog.with, ElementsAre("FOG_EXP2"));
    EXPECT_THAT(fog.without, ElementsAre("LIGHTMAP_ON", "_SHADOWS_SOFT"));

    const StripRuleSpec& vertex = (*rules)[1];
    EXPECT_EQ(vertex.name, "no vertex lights");
    EXPECT_EQ(vertex.location, (SourceLocation{kRulesFileId, 9, 5}));
    EXPECT_EQ(vertex.shader, "");
    EXPECT_EQ(vertex.pass, "");
    EXPECT_EQ(vertex.stage, Stage::Vertex);
    EXPECT_THAT(vertex.with, ElementsAre("VERTEXLIGHT_ON"));
    EXPECT_THAT(vertex.without, IsEmpty());

    // Keys in any order; a block list; `pass:` with no value is the default (every pass).
    const StripRuleSpec& instanced = (*rules)[2];
    EXPECT_EQ(instanced.name, "only instanced, directional");
    EXPECT_EQ(instanced.location, (SourceLocation{kRulesFileId, 12, 5}));
    EXPECT_EQ(instanced.shader, "Hidden/Internal*Shadow");
    EXPECT_EQ(instanced.pass, "");
    EXPECT_EQ(instanced.stage, std::nullopt);
    EXPECT_THAT(instanced.with, IsEmpty());
    EXPECT_THAT(instanced.without, ElementsAre("INSTANCING_ON", "DIRLIGHTMAP_COMBINED"));

    // fileIdFor is asked once, for the path given.
    EXPECT_THAT(file.idRequests, ElementsAre(file.folder.root() / "rules.yaml"));
}

TEST(StripRuleFile, EveryStageNameIsAccepted) {
    RuleFile file;
    std::string text = "rules:\n";
    for (Stage stage : kStages) {
        text += std::string("  - {name: ") + stageName(stage) + ", stage: " + stageName(stage) +
                ", with: K}\n";
    }
    auto rules = file.read(text);
    ASSERT_TRUE(rules.has_value());
    ASSERT_EQ(rules->size(), kStageCount);
    for (size_t i = 0; i < kStageCount; ++i) EXPECT_EQ((*rules)[i].stage, kStages[i]);
}

TEST(StripRuleFile, EmptyRulesIsValidAndHasNoRules) {
    RuleFile file;
    auto rules = file.read("# nothing stripped yet\nrules: []\n");
    ASSERT_TRUE(rules.has_value());
    EXPECT_THAT(*rules, IsEmpty());
    EXPECT_THAT(file.texts(), IsEmpty());
}

TEST(StripRuleFile, WithFileIdForUnsetDiagnosticsNameFileZero) {
    DiagnosticList diagnostics;
    TempProject folder;
    folder.write("rules.yaml", "rules: 3\n");
    EXPECT_EQ(readStripRules(folder.root() / "rules.yaml", diagnostics, {}), std::nullopt);
    ASSERT_EQ(diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(diagnostics.diagnostics()[0].location, (SourceLocation{0, 1, 8}));
}

TEST(StripRuleFile, UnreadableFileIsAnErrorOnTheWholeFile) {
    RuleFile file;
    EXPECT_EQ(file.readPath(file.folder.root() / "missing.yaml"), std::nullopt);
    ASSERT_EQ(file.texts().size(), 1u);
    EXPECT_THAT(file.texts()[0], HasSubstr("0:0: error: cannot read strip rules: "));
    EXPECT_THAT(file.texts()[0], HasSubstr("missing.yaml"));
    // A folder is not a file either.
    RuleFile folder;
    EXPECT_EQ(folder.readPath(folder.folder.root()), std::nullopt);
    EXPECT_EQ(folder.diagnostics.errorCount(), 1u);
}

TEST(StripRuleFile, MalformedYamlIsReportedAtYamlCppsMark) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n  - name: a\n    with: [FOG_EXP2\n"), std::nullopt);
    EXPECT_THAT(file.texts(), ElementsAre("4:1: error: malformed YAML: end of sequence flow not "
                                          "found"));
}

TEST(StripRuleFile, TopLevelMustBeAMappingWithRules) {
    RuleFile scalar;
    EXPECT_EQ(scalar.read("# a comment\nFOG_EXP2\n"), std::nullopt);
    EXPECT_THAT(scalar.texts(),
                ElementsAre("2:1: error: expected a mapping with a 'rules:' sequence at the top "
                            "level"));

    RuleFile empty;
    EXPECT_EQ(empty.read("# only a comment\n"), std::nullopt);
    EXPECT_THAT(empty.texts(),
                ElementsAre("0:0: error: no rules: expected a mapping with a 'rules:' sequence"));

    RuleFile misspelt;
    EXPECT_EQ(misspelt.read("version: 1\nrule:\n  - name: a\n    with: A\n"), std::nullopt);
    EXPECT_THAT(misspelt.texts(),
                ElementsAre("1:1: error: unknown key 'version' at the top level (expected rules)",
                            "2:1: error: unknown key 'rule' at the top level (expected rules)",
                            "1:1: error: missing 'rules:' (a sequence of strip rules; 'rules: []' "
                            "for none)"));
}

TEST(StripRuleFile, RulesMustBeASequence) {
    RuleFile mapping;
    EXPECT_EQ(mapping.read("rules:\n  name: a\n  with: A\n"), std::nullopt);
    EXPECT_THAT(mapping.texts(),
                ElementsAre("2:3: error: 'rules' must be a sequence of rules ('rules: []' for "
                            "none)"));
    // With no value the error goes to the key: yaml-cpp marks a null at the next token.
    RuleFile nothing;
    EXPECT_EQ(nothing.read("\nrules:\n\n"), std::nullopt);
    EXPECT_THAT(nothing.texts(),
                ElementsAre("2:1: error: 'rules' must be a sequence of rules ('rules: []' for "
                            "none)"));
}

TEST(StripRuleFile, ARuleMustBeAMapping) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n  - FOG_EXP2\n  - [a, b]\n  - {name: ok, with: A}\n"),
              std::nullopt);
    const std::string expected =
        ": error: a rule must be a mapping (name, shader, pass, stage, with, without)";
    EXPECT_THAT(file.texts(), ElementsAre("2:5" + expected, "3:5" + expected));
}

TEST(StripRuleFile, UnknownAndRepeatedKeysAtTheKey) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n"
                        "  - name: a\n"
                        "    shdaer: Custom/*\n"
                        "    with: A\n"
                        "    with: B\n"
                        "    ? [x]\n"
                        "    : 1\n"),
              std::nullopt);
    EXPECT_THAT(file.texts(),
                ElementsAre("3:5: error: unknown key 'shdaer' in a rule (expected name, shader, "
                            "pass, stage, with, without)",
                            "5:5: error: key 'with' written twice in a rule",
                            "6:7: error: a key in a rule must be a plain name"));
}

TEST(StripRuleFile, MissingEmptyAndDuplicateNames) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n"
                        "  - with: A\n"           // 2: no name
                        "  - name: ''\n"          // 3: empty
                        "    with: A\n"           //
                        "  - name:\n"             // 5: no value
                        "    with: A\n"           //
                        "  - name: fog\n"         // 7
                        "    with: FOG_EXP2\n"    //
                        "  - name: fog\n"         // 9: duplicate
                        "    with: FOG_LINEAR\n"  //
                        "  - name: [fog]\n"       // 11: not a string
                        "    with: A\n"),
              std::nullopt);
    EXPECT_THAT(file.texts(), ElementsAre("2:5: error: a rule needs a 'name'",
                                          "3:11: error: a rule's 'name' must not be empty",
                                          "5:5: error: a rule's 'name' must not be empty",
                                          "9:11: error: duplicate rule name 'fog'",
                                          "11:11: error: 'name' must be a string"));
    const Diagnostic& duplicate = file.diagnostics.diagnostics()[3];
    ASSERT_EQ(duplicate.notes.size(), 1u);
    EXPECT_EQ(duplicate.notes[0].location, (SourceLocation{kRulesFileId, 7, 11}));
    EXPECT_EQ(duplicate.notes[0].message, "first used here");
}

TEST(StripRuleFile, WrongTypesAtTheValue) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n"
                        "  - name: a\n"
                        "    shader: [Custom/*]\n"   // 3
                        "    pass: {name: Add}\n"    // 4
                        "    stage: [fragment]\n"    // 5
                        "    with: {FOG_EXP2: 1}\n"  // 6
                        "    without: [[A], ~]\n"),  // 7
              std::nullopt);
    EXPECT_THAT(
        file.texts(),
        ElementsAre("3:13: error: 'shader' must be a string",
                    "4:11: error: 'pass' must be a string", "5:12: error: 'stage' must be a string",
                    "6:11: error: 'with' must be a keyword or a sequence of keywords",
                    "7:15: error: 'without' lists a mapping or sequence where a keyword "
                    "belongs",
                    "7:20: error: 'without' lists an empty value where a keyword belongs"));
}

TEST(StripRuleFile, UnknownStage) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n  - name: a\n    stage: Fragment\n    with: A\n"), std::nullopt);
    EXPECT_THAT(file.texts(), ElementsAre("3:12: error: unknown stage 'Fragment' (expected vertex, "
                                          "fragment, geometry, hull or domain)"));
}

TEST(StripRuleFile, KeywordsMustBeIdentifiers) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n"
                        "  - name: a\n"
                        "    with: FOG_EXP2 LIGHTMAP_ON\n"               // 3: two words, one scalar
                        "    without: [OK_1, 2SIDED, 'FOG-EXP2', '']\n"  // 4
                        "  - name: b\n"
                        "    with:\n"
                        "      - _ÄRGER\n"),  // 7: not ASCII
              std::nullopt);
    const std::string rest =
        "' is not a keyword (ASCII letters, digits and '_', not starting "
        "with a digit)";
    EXPECT_THAT(file.texts(),
                ElementsAre("3:11: error: 'FOG_EXP2 LIGHTMAP_ON" + rest,
                            "4:21: error: '2SIDED" + rest, "4:29: error: 'FOG-EXP2" + rest,
                            "4:41: error: '" + rest, "7:9: error: '_ÄRGER" + rest));
}

TEST(StripRuleFile, ARuleWithNeitherWithNorWithoutIsAnError) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n"
                        "  - name: everything in add passes\n"  // 2
                        "    pass: ForwardAdd\n"
                        "  - name: empty lists\n"  // 4
                        "    with: []\n"
                        "    without:\n"
                        "  - name: bad keyword, no second error\n"
                        "    with: [1A]\n"),  // 8
              std::nullopt);
    const std::string message =
        "error: a rule without 'with' or 'without' would remove every "
        "variant";
    EXPECT_THAT(file.texts(), ElementsAre("2:5: " + message, "4:5: " + message,
                                          "8:12: error: '1A' is not a keyword (ASCII letters, "
                                          "digits and '_', not starting with a digit)"));
}

TEST(StripRuleFile, AKeywordInBothListsIsAWarningOnly) {
    RuleFile file;
    auto rules = file.read("rules:\n  - name: never\n    with: [A, B]\n    without: B\n");
    ASSERT_TRUE(rules.has_value());
    EXPECT_EQ(rules->size(), 1u);
    EXPECT_THAT(file.texts(), ElementsAre("2:5: warning: rule 'never' has 'B' in both 'with' and "
                                          "'without': it can never match"));
}

TEST(StripRuleFile, ASecondDocumentIsAnError) {
    RuleFile file;
    EXPECT_EQ(file.read("rules: []\n---\nrules: []\n"), std::nullopt);
    EXPECT_THAT(file.texts(), ElementsAre("3:1: error: a strip-rule file holds one YAML document"));
}

TEST(StripRuleFile, ErrorsInOneRuleDropOnlyThatRuleButTheFileFails) {
    RuleFile file;
    EXPECT_EQ(file.read("rules:\n  - {name: a, with: A}\n  - {name: b, stage: pixel, with: B}\n"),
              std::nullopt);
    EXPECT_EQ(file.diagnostics.errorCount(), 1u);
}

// Every prefix of a valid file either reads without errors or reports at least one error inside
// the file, and nothing throws. A prefix that cuts a rule mid-way may still be valid YAML whose
// rules read (e.g. ending after `with: [FOG_EXP2]`); that is fine, it is a different file.
TEST(StripRuleFile, EveryTruncationReadsOrFailsCleanly) {
    size_t lineCount = static_cast<size_t>(std::count(kFullFile.begin(), kFullFile.end(), '\n'));
    size_t valid = 0;
    for (size_t length = 0; length <= kFullFile.size(); ++length) {
        RuleFile file;
        std::optional<std::vector<StripRuleSpec>> rules;
        ASSERT_NO_THROW(rules = file.read(kFullFile.substr(0, length))) << length;
        EXPECT_EQ(rules.has_value(), !file.diagnostics.hasErrors()) << length;
        for (const Diagnostic& d : file.diagnostics.diagnostics()) {
            EXPECT_LE(d.location.line, lineCount + 1) << length << ": " << d.message;
        }
        if (rules) ++valid;
    }
    EXPECT_GT(valid, 0u);  // at least the whole file
}

}  // namespace
}  // namespace varc::project
