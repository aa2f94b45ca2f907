// SPDX-License-Identifier: Apache-2.0
// Package discovery: package.json names, manifest.json dependencies, the package cache.
#include "PackageLocator.h"

#include <algorithm>
#include <optional>

#include "AssetScanner.h"
#include "UnityYaml.h"

namespace varc::project {

namespace fs = std::filesystem;

namespace {

// The JSON document in |file| (yaml-cpp reads JSON, which is YAML 1.2's flow syntax), or
// nullopt after a warning.
std::optional<YAML::Node> readJson(const fs::path& file, LoadContext& context) {
    auto text = context.readText(file);
    if (!text) return std::nullopt;
    auto documents = parseUnityYaml(*text, file, context);
    if (!documents || documents->empty() || !documents->front().IsMap()) {
        if (documents) context.warn(file, "not a JSON object; not read");
        return std::nullopt;
    }
    return documents->front();
}

std::string packageName(const fs::path& folder, LoadContext& context) {
    fs::path manifest = folder / "package.json";
    std::error_code error;
    if (!fs::is_regular_file(manifest, error)) return folder.filename().string();
    if (auto json = readJson(manifest, context)) {
        if (auto name = field(*json, "name")) {
            std::string text = scalarText(*name).value_or("");
            if (!text.empty()) return text;
        }
        context.warn(manifest, "no \"name\"; the package is named after its folder");
    }
    return folder.filename().string();
}

std::vector<ProjectPackage> embeddedPackages(const fs::path& packagesFolder, bool includeIgnored,
                                             LoadContext& context) {
    std::vector<fs::path> folders;  // sorted first, so warnings come in a stable order
    std::error_code error;
    for (fs::directory_iterator it(packagesFolder, error), end; !error && it != end;
         it.increment(error)) {
        std::error_code typeError;
        std::string name = it->path().filename().string();
        if (!it->is_directory(typeError) || (!includeIgnored && isUnityIgnoredName(name))) continue;
        folders.push_back(it->path());
    }
    std::sort(folders.begin(), folders.end());
    std::vector<ProjectPackage> packages;
    for (const fs::path& folder : folders) {
        packages.push_back({packageName(folder, context), "", PackageSource::Embedded, folder});
    }
    return packages;
}

std::optional<fs::path> cachedPackage(const fs::path& cache, const std::string& name,
                                      const std::string& version) {
    std::error_code error;
    if (fs::is_directory(cache / (name + "@" + version), error))
        return cache / (name + "@" + version);
    std::vector<fs::path> matches;
    for (fs::directory_iterator it(cache, error), end; !error && it != end; it.increment(error)) {
        if (it->path().filename().string().rfind(name + "@", 0) == 0) matches.push_back(it->path());
    }
    if (matches.empty()) return std::nullopt;
    return *std::min_element(matches.begin(), matches.end());
}

std::optional<ProjectPackage> manifestPackage(const fs::path& root, const std::string& name,
                                              const std::string& version) {
    std::error_code error;
    if (version.rfind("file:", 0) == 0) {
        fs::path folder = fs::path(version.substr(5));
        if (folder.is_relative()) folder = root / "Packages" / folder;
        if (!fs::is_directory(folder, error)) return std::nullopt;
        return ProjectPackage{name, version, PackageSource::Local, folder.lexically_normal()};
    }
    auto folder = cachedPackage(root / "Library" / "PackageCache", name, version);
    if (!folder) return std::nullopt;
    return ProjectPackage{name, version, PackageSource::Cache, *folder};
}

}  // namespace

PackageSearch locatePackages(const fs::path& root, bool includeIgnored, LoadContext& context) {
    PackageSearch search;
    search.packages = embeddedPackages(root / "Packages", includeIgnored, context);
    fs::path manifestFile = root / "Packages" / "manifest.json";
    std::error_code error;
    if (fs::is_regular_file(manifestFile, error)) {
        auto manifest = readJson(manifestFile, context);
        auto dependencies = manifest ? field(*manifest, "dependencies") : std::nullopt;
        if (dependencies && dependencies->IsMap()) {
            for (const auto& entry : *dependencies) {
                std::string name = scalarText(entry.first).value_or("");
                std::string version = scalarText(entry.second).value_or("");
                bool embedded =
                    std::any_of(search.packages.begin(), search.packages.end(),
                                [&](const ProjectPackage& p) { return p.name == name; });
                if (name.empty() || embedded) continue;  // an embedded copy wins over the manifest
                if (auto package = manifestPackage(root, name, version)) {
                    search.packages.push_back(std::move(*package));
                } else {
                    search.notOnDisk.push_back(name);
                }
            }
        }
    }
    std::sort(search.packages.begin(), search.packages.end(),
              [](const ProjectPackage& a, const ProjectPackage& b) {
                  return a.name != b.name ? a.name < b.name : a.folder < b.folder;
              });
    std::sort(search.notOnDisk.begin(), search.notOnDisk.end());
    return search;
}

}  // namespace varc::project
