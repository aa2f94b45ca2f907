// SPDX-License-Identifier: Apache-2.0
// Opening a pack for the pack-reading commands, with the error printed the CLI's way.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "varc/reader/Pack.h"

namespace varc::cli {

// The opened pack, or nullopt after printing "varc: error: <why>" to |err|.
inline std::optional<reader::Pack> openPackOrReport(const std::string& path, std::ostream& err) {
    Result<reader::Pack> pack = reader::Pack::open(path);
    if (!pack) {
        err << "varc: error: " << pack.error().detail << "\n";
        return std::nullopt;
    }
    return std::move(pack).value();
}

}  // namespace varc::cli
