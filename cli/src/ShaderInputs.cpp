// SPDX-License-Identifier: Apache-2.0
// Turns the PATH arguments of varc commands into a sorted list of .shader files.
#include "varc/cli/ShaderInputs.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <set>

#include "varc/pack/PackFormat.h"

namespace varc::cli {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> shadersUnder(const fs::path& dir, DiagnosticSink& sink) {
    std::vector<std::string> found;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && it->path().extension() == ".shader") {
            found.push_back(it->path().generic_string());
        }
    }
    if (ec) sink.error({}, "cannot search directory '" + dir.string() + "': " + ec.message());
    std::sort(found.begin(), found.end());
    return found;
}

// Whether |path| starts with a pack's magic: a pack handed to a command that reads shader
// sources would otherwise be read as text and its bytes quoted as source context.
bool isPack(const std::string& path) {
    std::array<char, pack::kMagic.size()> head{};
    std::ifstream in(path, std::ios::binary);
    return in.read(head.data(), static_cast<std::streamsize>(head.size())) && head == pack::kMagic;
}

}  // namespace

std::vector<std::string> findShaderFiles(const std::vector<std::string>& paths,
                                         DiagnosticSink& sink) {
    std::vector<std::string> files;
    std::set<std::string> seen;
    auto add = [&](const std::string& file) {
        if (seen.insert(fs::path(file).lexically_normal().generic_string()).second) {
            files.push_back(file);
        }
    };
    for (const std::string& path : paths) {
        std::error_code ec;
        if (fs::is_directory(path, ec)) {
            for (const std::string& file : shadersUnder(path, sink)) add(file);
        } else if (fs::is_regular_file(path, ec) && isPack(path)) {
            sink.error({}, "'" + path + "' is a varc pack, not a shader source (varc info " +
                               "shows what a pack holds)");
        } else if (fs::is_regular_file(path, ec)) {
            add(path);
        } else {
            sink.error({}, "no such file or directory: '" + path + "'");
        }
    }
    return files;
}

}  // namespace varc::cli
