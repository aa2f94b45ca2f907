// SPDX-License-Identifier: Apache-2.0
// Source paths as CI tools want them: relative to the current folder where possible.
#pragma once

#include <string>

#include "varc/core/SourceLocation.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// |path| relative to the current folder when it lies inside it ("/w/s/a.shader" from /w ->
// "s/a.shader"); other paths are returned normalised, as they are.
std::string pathForCi(const std::string& path);

// "path:line:col" as SourceMap::format writes it, with the path from pathForCi; "" when the
// location is unknown.
std::string formatForCi(SourceLocation location, const includes::SourceMap& sourceMap);

// A URI reference for |path| (after pathForCi): a relative reference for a relative path, a
// file:// URI for an absolute one, with every byte outside RFC 3986's unreserved set and '/'
// percent-encoded. Example: "shaders/my lit.shader" -> "shaders/my%20lit.shader".
std::string pathUri(const std::string& path);

}  // namespace varc::cli
