// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for the whole front end down to glslang: a .shader file (plus include files,
// FuzzInput.h) is loaded, and when it has few variants every variant of every pass is
// preprocessed, pruned and compiled (HLSL or GLSL, every stage it declares) and optimised.
#include "FuzzInput.h"
#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/SourceMap.h"

namespace {

// The fuzzer's files, then varc's built-in include library on disk (read-only).
class FuzzFileSystem final : public varc::includes::FileSystem {
public:
    varc::includes::InMemoryFileSystem memory;
    std::optional<std::string> read(const std::string& path) const override {
        if (memory.isFile(path)) return memory.read(path);
        return path.starts_with(VARC_BUILTIN_DIR) ? mDisk.read(path) : std::nullopt;
    }
    bool isFile(const std::string& path) const override {
        return memory.isFile(path) || (path.starts_with(VARC_BUILTIN_DIR) && mDisk.isFile(path));
    }
    std::vector<std::string> fileNames(const std::string& dir) const override {
        return dir.starts_with(VARC_BUILTIN_DIR) ? mDisk.fileNames(dir) : memory.fileNames(dir);
    }

private:
    varc::includes::DiskFileSystem mDisk;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> files = varc::fuzz::splitFiles(varc::fuzz::asText(data, size));
    FuzzFileSystem fileSystem;
    fileSystem.memory.add("fuzz.shader", files[0]);
    for (size_t i = 1; i < files.size(); ++i)
        fileSystem.memory.add(varc::fuzz::includeName(i), files[i]);
    varc::includes::SourceMap map;
    varc::DiagnosticList sink;
    varc::includes::IncludeOptions includes;
    includes.builtinDir = VARC_BUILTIN_DIR;
    auto shader = varc::frontend::loadShader("fuzz.shader", fileSystem, map, includes, sink);
    if (!shader || shader->variantCount() > 8) return 0;
    std::vector<varc::frontend::LoadedShader> shaders;
    shaders.push_back(std::move(*shader));
    varc::driver::BuildOptions build;
    build.jobs = 1;
    (void)varc::driver::buildPrograms(shaders, map, build, sink);
    return 0;
}
