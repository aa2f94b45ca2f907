// SPDX-License-Identifier: Apache-2.0
// The built-in include folder next to an installed varc, else the source tree's.
#include "BuiltinIncludeDir.h"

#include <filesystem>
#include <system_error>

namespace varc::cli {

std::string defaultBuiltinIncludeDir() {
    std::error_code error;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        // VARC_INSTALLED_BUILTIN_DIR is relative to the installed binary's folder, e.g.
        // "../share/varc/builtin" (cli/CMakeLists.txt).
        std::filesystem::path installed =
            (exe.parent_path() / VARC_INSTALLED_BUILTIN_DIR).lexically_normal();
        if (std::filesystem::is_directory(installed, error)) return installed.string();
    }
    return VARC_DEFAULT_BUILTIN_INCLUDE_DIR;
}

}  // namespace varc::cli
