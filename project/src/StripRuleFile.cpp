// SPDX-License-Identifier: Apache-2.0
// readStripRules: yaml-cpp behind a no-throw boundary, then a strict walk of `rules:`.
#include "varc/project/StripRuleFile.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string_view>

#include "UnityYaml.h"
#include "varc/core/AsciiIdentifier.h"
#include "varc/core/FileRead.h"

namespace varc::project {

namespace {

// A rule file is a few lines written by hand; the bound keeps a wrong path (a pack, a video)
// from being read whole into memory.
constexpr size_t kMaxRuleFileBytes = size_t{4} << 20;

constexpr std::array<std::string_view, 1> kTopKeys = {"rules"};
constexpr std::array<std::string_view, 6> kRuleKeys = {"name",  "shader", "pass",
                                                       "stage", "with",   "without"};

template <size_t N>
std::string keyListText(const std::array<std::string_view, N>& keys) {
    std::string text;
    for (std::string_view key : keys) text += (text.empty() ? "" : ", ") + std::string(key);
    return text;
}

bool isKeyword(std::string_view text) {
    return !text.empty() && isAsciiIdentifierStart(text[0]) &&
           std::all_of(text.begin(), text.end(), isAsciiIdentifierChar);
}

std::optional<Stage> stageNamed(std::string_view name) {
    for (Stage stage : kStages) {
        if (name == stageName(stage)) return stage;
    }
    return std::nullopt;
}

// A key of a mapping and its value: errors about a value with no position (a null) go to the key.
struct Field {
    YAML::Node key;
    YAML::Node value;
};
using Fields = std::map<std::string, Field>;

// The walk over one parsed file. Errors are counted here, not read back from the sink, which may
// already hold the caller's earlier diagnostics.
class RuleFileReader {
public:
    RuleFileReader(DiagnosticSink& sink, FileId file) : mSink(sink), mFile(file) {}

    SourceLocation locationOf(const YAML::Node& node) const {
        auto [line, column] = positionOf(node);
        return {mFile, line, column};
    }
    void error(SourceLocation location, std::string message) {
        ++mErrors;
        mSink.error(location, std::move(message));
    }
    void error(const YAML::Node& at, std::string message) {
        error(locationOf(at), std::move(message));
    }
    size_t errorCount() const { return mErrors; }

    // The rules of the one document of the file.
    std::vector<StripRuleSpec> readDocument(const YAML::Node& document);

private:
    // The value of each key of |map| that is one of |keys|; reports unknown and repeated keys.
    template <size_t N>
    Fields knownFields(const YAML::Node& map, const std::array<std::string_view, N>& keys,
                       std::string_view where);
    std::optional<StripRuleSpec> readRule(const YAML::Node& item);
    bool readName(const YAML::Node& rule, const Fields& fields, StripRuleSpec& spec);
    // A scalar's text into |out|; false after an error for a mapping or sequence.
    bool readText(const YAML::Node& value, std::string_view key, std::string& out);
    bool readStage(const YAML::Node& value, std::optional<Stage>& out);
    // A keyword or a sequence of keywords into |out|; false after one error or more.
    bool readKeywords(const YAML::Node& value, std::string_view key, std::vector<std::string>& out);
    bool readKeyword(const YAML::Node& item, std::string_view key, std::vector<std::string>& out);
    void warnContradictions(const StripRuleSpec& spec);

    DiagnosticSink& mSink;
    FileId mFile;
    size_t mErrors = 0;
    std::map<std::string, SourceLocation> mNames;  // rule name -> where first used
};

template <size_t N>
Fields RuleFileReader::knownFields(const YAML::Node& map,
                                   const std::array<std::string_view, N>& keys,
                                   std::string_view where) {
    Fields fields;
    for (const auto& entry : map) {
        const YAML::Node& key = entry.first;
        if (!key.IsScalar()) {
            error(key, "a key " + std::string(where) + " must be a plain name");
            continue;
        }
        const std::string& name = key.Scalar();
        if (std::find(keys.begin(), keys.end(), name) == keys.end()) {
            error(key, "unknown key '" + name + "' " + std::string(where) + " (expected " +
                           keyListText(keys) + ")");
        } else if (!fields.emplace(name, Field{key, entry.second}).second) {
            error(key, "key '" + name + "' written twice " + std::string(where));
        }
    }
    return fields;
}

std::vector<StripRuleSpec> RuleFileReader::readDocument(const YAML::Node& document) {
    std::vector<StripRuleSpec> rules;
    if (!document.IsMap()) {
        error(document, "expected a mapping with a 'rules:' sequence at the top level");
        return rules;
    }
    auto fields = knownFields(document, kTopKeys, "at the top level");
    auto found = fields.find("rules");
    if (found == fields.end()) {
        error(document, "missing 'rules:' (a sequence of strip rules; 'rules: []' for none)");
        return rules;
    }
    const YAML::Node& sequence = found->second.value;
    if (!sequence.IsSequence()) {
        error(sequence.IsNull() ? found->second.key : sequence,
              "'rules' must be a sequence of rules ('rules: []' for none)");
        return rules;
    }
    for (const YAML::Node& item : sequence) {
        if (auto rule = readRule(item)) rules.push_back(std::move(*rule));
    }
    return rules;
}

std::optional<StripRuleSpec> RuleFileReader::readRule(const YAML::Node& item) {
    if (!item.IsMap()) {
        error(item, "a rule must be a mapping (" + keyListText(kRuleKeys) + ")");
        return std::nullopt;
    }
    size_t errorsBefore = mErrors;
    StripRuleSpec spec;
    spec.location = locationOf(item);
    auto fields = knownFields(item, kRuleKeys, "in a rule");
    readName(item, fields, spec);
    auto present = [&](const char* key) -> const YAML::Node* {
        auto found = fields.find(key);
        return found == fields.end() || found->second.value.IsNull() ? nullptr
                                                                     : &found->second.value;
    };
    if (const YAML::Node* shader = present("shader")) readText(*shader, "shader", spec.shader);
    if (const YAML::Node* pass = present("pass")) readText(*pass, "pass", spec.pass);
    if (const YAML::Node* stage = present("stage")) readStage(*stage, spec.stage);
    bool keywordsRead = true;
    if (const YAML::Node* with = present("with")) {
        keywordsRead = readKeywords(*with, "with", spec.with) && keywordsRead;
    }
    if (const YAML::Node* without = present("without")) {
        keywordsRead = readKeywords(*without, "without", spec.without) && keywordsRead;
    }
    // Only when the lists were read: a list with a bad keyword already has its error.
    if (keywordsRead && spec.with.empty() && spec.without.empty()) {
        error(item, "a rule without 'with' or 'without' would remove every variant");
    }
    if (mErrors != errorsBefore) return std::nullopt;
    warnContradictions(spec);
    return spec;
}

bool RuleFileReader::readName(const YAML::Node& rule, const Fields& fields, StripRuleSpec& spec) {
    auto found = fields.find("name");
    if (found == fields.end()) {
        error(rule, "a rule needs a 'name'");
        return false;
    }
    const YAML::Node& value = found->second.value;
    if (!value.IsNull() && !readText(value, "name", spec.name)) return false;
    if (spec.name.empty()) {
        error(value.IsNull() ? found->second.key : value, "a rule's 'name' must not be empty");
        return false;
    }
    SourceLocation here = locationOf(value);
    auto [first, added] = mNames.emplace(spec.name, here);
    if (!added) {
        ++mErrors;
        mSink.report({Severity::Error,
                      here,
                      "duplicate rule name '" + spec.name + "'",
                      {{first->second, "first used here"}}});
        return false;
    }
    return true;
}

bool RuleFileReader::readText(const YAML::Node& value, std::string_view key, std::string& out) {
    if (!value.IsScalar()) {
        error(value, "'" + std::string(key) + "' must be a string");
        return false;
    }
    out = value.Scalar();
    return true;
}

bool RuleFileReader::readStage(const YAML::Node& value, std::optional<Stage>& out) {
    std::string name;
    if (!readText(value, "stage", name)) return false;
    out = stageNamed(name);
    if (!out) {
        error(value,
              "unknown stage '" + name + "' (expected vertex, fragment, geometry, hull or domain)");
        return false;
    }
    return true;
}

bool RuleFileReader::readKeywords(const YAML::Node& value, std::string_view key,
                                  std::vector<std::string>& out) {
    if (value.IsScalar()) return readKeyword(value, key, out);
    if (!value.IsSequence()) {
        error(value, "'" + std::string(key) + "' must be a keyword or a sequence of keywords");
        return false;
    }
    bool ok = true;
    for (const YAML::Node& item : value) ok = readKeyword(item, key, out) && ok;
    return ok;
}

bool RuleFileReader::readKeyword(const YAML::Node& item, std::string_view key,
                                 std::vector<std::string>& out) {
    if (!item.IsScalar()) {
        // A plain `~` or `null` item is YAML's null, which no keyword is.
        error(item, "'" + std::string(key) + "' lists " +
                        (item.IsNull() ? "an empty value" : "a mapping or sequence") +
                        " where a keyword belongs");
        return false;
    }
    const std::string& keyword = item.Scalar();
    if (!isKeyword(keyword)) {
        error(item, "'" + keyword +
                        "' is not a keyword (ASCII letters, digits and '_', not starting with a "
                        "digit)");
        return false;
    }
    out.push_back(keyword);
    return true;
}

void RuleFileReader::warnContradictions(const StripRuleSpec& spec) {
    std::set<std::string_view> with(spec.with.begin(), spec.with.end());
    for (const std::string& keyword : spec.without) {
        if (with.count(keyword) != 0) {
            mSink.warning(spec.location, "rule '" + spec.name + "' has '" + keyword +
                                             "' in both 'with' and 'without': it can never match");
        }
    }
}

// The parsed documents of |text|, or nullopt after an error at yaml-cpp's mark.
std::optional<std::vector<YAML::Node>> parse(const std::string& text, RuleFileReader& reader,
                                             FileId file) {
    try {
        return YAML::LoadAll(text);
    } catch (const YAML::Exception& failure) {
        SourceLocation at{file, 0, 0};
        if (!failure.mark.is_null()) {
            at.line = static_cast<uint32_t>(std::max(failure.mark.line, 0) + 1);
            at.column = static_cast<uint32_t>(std::max(failure.mark.column, 0) + 1);
        }
        reader.error(at, "malformed YAML: " + failure.msg);
    } catch (const std::exception& failure) {
        reader.error({file, 0, 0}, std::string("malformed YAML: ") + failure.what());
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::vector<StripRuleSpec>> readStripRules(
    const std::filesystem::path& file, DiagnosticSink& sink,
    const std::function<FileId(const std::filesystem::path&)>& fileIdFor) {
    FileId id = fileIdFor ? fileIdFor(file) : FileId{0};
    RuleFileReader reader(sink, id);
    Result<std::string> text = readFile(file.string(), kMaxRuleFileBytes);
    if (!text) {
        reader.error({id, 0, 0}, "cannot read strip rules: " + text.error().detail);
        return std::nullopt;
    }
    std::vector<StripRuleSpec> rules;
    try {  // the boundary: yaml-cpp's accessors throw on input the checks above did not foresee
        auto documents = parse(*text, reader, id);
        if (!documents) return std::nullopt;
        if (documents->empty()) {
            reader.error({id, 0, 0}, "no rules: expected a mapping with a 'rules:' sequence");
            return std::nullopt;
        }
        if (documents->size() > 1) {
            reader.error((*documents)[1], "a strip-rule file holds one YAML document");
        }
        rules = reader.readDocument(documents->front());
    } catch (const std::exception& failure) {
        reader.error({id, 0, 0}, std::string("strip rules not read: ") + failure.what());
    }
    if (reader.errorCount() != 0) return std::nullopt;
    return rules;
}

}  // namespace varc::project
