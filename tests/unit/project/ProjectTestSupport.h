// SPDX-License-Identifier: Apache-2.0
// A Unity project written to a temporary folder by a test, and diagnostic helpers.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/project/Project.h"

namespace varc::project::test {

namespace fs = std::filesystem;

// A folder under the system temp dir, unique per test, removed at the end.
class TempProject {
public:
    TempProject() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        mRoot = fs::temp_directory_path() /
                ("varc-project-" + std::string(info->test_suite_name()) + "-" + info->name());
        fs::remove_all(mRoot);
        fs::create_directories(mRoot);
    }
    ~TempProject() {
        std::error_code ignored;
        fs::remove_all(mRoot, ignored);
    }
    TempProject(const TempProject&) = delete;
    TempProject& operator=(const TempProject&) = delete;

    const fs::path& root() const { return mRoot; }

    // Writes |contents| to |relative| (folders created as needed).
    TempProject& write(const std::string& relative, const std::string& contents) {
        fs::path file = mRoot / relative;
        fs::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << contents;
        return *this;
    }
    TempProject& folder(const std::string& relative) {
        fs::create_directories(mRoot / relative);
        return *this;
    }

private:
    fs::path mRoot;
};

// The UnityYAML header every text asset starts with.
inline const std::string kUnityHeader = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n";

inline std::string shaderMeta(const std::string& guid) {
    return "fileFormatVersion: 2\nguid: " + guid + "\nShaderImporter:\n  userData: \n";
}

// A material naming |shaderLine| (the text after `m_Shader: `) with extra |fields| lines.
inline std::string materialYaml(const std::string& name, const std::string& shaderLine,
                                const std::string& fields = "  m_ShaderKeywords: \n") {
    return kUnityHeader +
           "--- !u!21 &2100000\nMaterial:\n  serializedVersion: 6\n  m_Name: " + name +
           "\n  m_Shader: " + shaderLine + "\n" + fields;
}

inline std::string projectShaderRef(const std::string& guid) {
    return "{fileID: 4800000, guid: " + guid + ", type: 3}";
}
inline std::string builtinRef(int fileId) {
    return "{fileID: " + std::to_string(fileId) +
           ", guid: 0000000000000000f000000000000000, type: 0}";
}

// Each warning as `describe(location): message`, for assertions on text.
inline std::vector<std::string> warningTexts(const Project& project, const DiagnosticList& list) {
    std::vector<std::string> texts;
    for (const Diagnostic& d : list.diagnostics()) {
        texts.push_back(project.describe(d.location) + ": " + severityName(d.severity) + ": " +
                        d.message);
    }
    return texts;
}

}  // namespace varc::project::test
