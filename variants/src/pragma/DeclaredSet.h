// SPDX-License-Identifier: Apache-2.0
// A keyword set while the pragmas are read: the declaration plus the column of every keyword.
#pragma once

#include <vector>

#include "varc/core/SourceLocation.h"
#include "varc/variants/PassKeywords.h"

namespace varc::variants {

struct DeclaredSet {
    KeywordSetDecl decl;
    std::vector<SourceLocation> keywordLocations;  // parallel to decl.keywords
    SourceLocation directiveLocation;              // the directive (or shortcut) token
};

}  // namespace varc::variants
