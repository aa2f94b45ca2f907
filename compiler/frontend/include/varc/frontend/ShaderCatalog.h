// SPDX-License-Identifier: Apache-2.0
// Shaders by name, for the references between shaders: `UsePass "Shader/PASS"` and `Fallback`.
#pragma once

#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "varc/includes/FileSystem.h"
#include "varc/includes/SourceMap.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::frontend {

// Where the shaders a reference may name are found, in this order (Unity finds any shader of
// the project by name):
//   1. the build's own input files (a user's `Fallback "Toon/Basic"` names another input);
//   2. |searchFiles|: the other shaders of the project (the CLI passes the `.shader` files
//      under the include folders);
//   3. varc's built-in shaders, `<builtin include dir>/fallback/*.shader` (the legacy
//      fallbacks people name: VertexLit, Diffuse, Transparent/Cutout/VertexLit, ...).
// Unity renamed its old built-in shaders to "Legacy Shaders/..." and still finds them by the old
// name; so does the catalog ("VertexLit" finds "Legacy Shaders/VertexLit").
// Each group of files is parsed on the first lookup that reaches it; a file that does not parse
// is skipped here (loading it as an input reports the error). Not thread-safe.
class ShaderCatalog {
public:
    ShaderCatalog(const includes::FileSystem& fileSystem, includes::SourceMap& sourceMap,
                  std::vector<std::string> inputFiles, std::vector<std::string> searchFiles,
                  std::string builtinDir);

    // The shader named |name| (exact, case-sensitive as in Unity), or nullptr.
    const shaderlab::ShaderFile* find(std::string_view name);

    // The folder of the built-in shaders, "" without a built-in include folder.
    const std::string& builtinShaderDir() const { return mBuiltinShaderDir; }

private:
    // One group of files searched in turn, parsed when a lookup first reaches it.
    struct Group {
        std::vector<std::string> files;
        bool parsed = false;
        std::deque<shaderlab::ShaderFile> shaders;  // deque: pointers stay valid
    };
    void parse(Group& group);
    const shaderlab::ShaderFile* findInGroups(std::string_view name);

    const includes::FileSystem& mFileSystem;
    includes::SourceMap& mSourceMap;
    std::string mBuiltinShaderDir;
    Group mGroups[3];  // inputs, search files, built-in shaders (listed when first parsed)
};

}  // namespace varc::frontend
