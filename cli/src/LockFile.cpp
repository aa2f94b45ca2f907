// SPDX-License-Identifier: Apache-2.0
// The variant-count lock file: what `varc lock` writes and `varc check` compares against.
#include "varc/cli/LockFile.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "varc/core/KeywordNames.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

Json passToJson(const LockedPass& pass) {
    Json sets = Json::array();
    for (const LockedSet& set : pass.sets) {
        sets.push_back({{"directive", set.directive}, {"keywords", set.keywords}});
    }
    Json json = {{"index", pass.index},       {"name", pass.name}, {"lightmode", pass.lightMode},
                 {"variants", pass.variants}, {"sets", sets},      {"skipped", pass.skipped}};
    if (pass.stages) {
        json["stages"] = {{"declared", pass.stages->declared},
                          {"materials", pass.stages->materials},
                          {"settings", pass.stages->settings},
                          {"rules", pass.stages->rules}};
    }
    return json;
}

LockedPass passFromJson(const Json& json) {
    LockedPass pass;
    pass.index = json.at("index").get<size_t>();
    pass.name = json.at("name").get<std::string>();
    pass.lightMode = json.at("lightmode").get<std::string>();
    pass.variants = json.at("variants").get<uint64_t>();
    for (const Json& set : json.at("sets")) {
        pass.sets.push_back({set.at("directive").get<std::string>(),
                             set.at("keywords").get<std::vector<std::string>>()});
    }
    pass.skipped = json.at("skipped").get<std::vector<std::string>>();
    if (auto stages = json.find("stages"); stages != json.end()) {
        pass.stages = LockedStages{stages->at("declared").get<uint64_t>(),
                                   stages->at("materials").get<uint64_t>(),
                                   stages->at("settings").get<uint64_t>(),
                                   stages->at("rules").get<uint64_t>()};
    }
    return pass;
}

LockedShader shaderFromJson(const Json& json) {
    LockedShader shader;
    shader.name = json.at("name").get<std::string>();
    shader.file = json.at("file").get<std::string>();
    shader.variants = json.at("variants").get<uint64_t>();
    for (const Json& pass : json.at("passes")) shader.passes.push_back(passFromJson(pass));
    return shader;
}

}  // namespace

LockedPass makeLockedPass(const frontend::LoadedPass& pass) {
    LockedPass locked;
    locked.index = pass.index;
    locked.name = pass.pass->name;
    locked.lightMode = pass.pass->lightMode();
    locked.variants = pass.variantCount();
    if (pass.plan) {
        const frontend::VariantStageCounts& counts = pass.plan->counts;
        locked.stages = LockedStages{counts.declared, counts.materials, counts.settings,
                                     counts.rules};
    }
    for (const variants::KeywordSetDecl& set : pass.keywords.sets) {
        locked.sets.push_back({set.directive, displayKeywords(set.keywords)});
    }
    locked.skipped = pass.keywords.skipped;
    std::sort(locked.skipped.begin(), locked.skipped.end());
    return locked;
}

LockFile makeLock(const std::vector<frontend::LoadedShader>& shaders,
                  const std::string& lockDirectory) {
    namespace fs = std::filesystem;
    LockFile lock;
    for (const frontend::LoadedShader& shader : shaders) {
        LockedShader locked;
        locked.name = shader.ast.name;
        fs::path base = lockDirectory.empty() ? fs::current_path() : fs::absolute(lockDirectory);
        locked.file = fs::absolute(shader.path).lexically_relative(base).generic_string();
        locked.variants = shader.variantCount();
        for (const frontend::LoadedPass& pass : shader.passes) {
            locked.passes.push_back(makeLockedPass(pass));
        }
        lock.shaders.push_back(std::move(locked));
    }
    std::stable_sort(lock.shaders.begin(), lock.shaders.end(),
                     [](const LockedShader& a, const LockedShader& b) { return a.name < b.name; });
    return lock;
}

std::string serializeLock(const LockFile& lock) {
    Json shaders = Json::array();
    for (const LockedShader& shader : lock.shaders) {
        Json passes = Json::array();
        for (const LockedPass& pass : shader.passes) passes.push_back(passToJson(pass));
        shaders.push_back({{"name", shader.name},
                           {"file", shader.file},
                           {"variants", shader.variants},
                           {"passes", passes}});
    }
    Json root = {{"version", LockFile::kVersion}, {"shaders", shaders}};
    return root.dump(2) + "\n";
}

Result<LockFile> parseLock(const std::string& text, const std::string& path) {
    Json root = Json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (root.is_discarded() || !root.is_object()) {
        return makeError(ErrorCode::InvalidInput, path + ": not a varc lock file (invalid JSON)");
    }
    auto version = root.find("version");
    if (version == root.end() || !version->is_number_integer() ||
        version->get<int>() != LockFile::kVersion) {
        return makeError(ErrorCode::Unsupported,
                         path + ": unsupported lock file version (expected 1)");
    }
    LockFile lock;
    try {
        for (const Json& shader : root.at("shaders"))
            lock.shaders.push_back(shaderFromJson(shader));
    } catch (const Json::exception& e) {
        return makeError(ErrorCode::InvalidInput, path + ": malformed lock file: " + e.what());
    }
    return lock;
}

}  // namespace varc::cli
