// SPDX-License-Identifier: Apache-2.0
// The "Property checks" section of the `varc validate --report` page (docs/PROPERTIES.md).
#pragma once

#include <iosfwd>
#include <vector>

#include "varc/properties/PropertyRunner.h"

namespace varc::cli {

// Writes the section for |reports| (one per shader checked, in check order): a table with per
// shader its model, each relation's verdict (an n/a or FAIL cell carries the relation's detail
// as its title), the lit variants drawn and any render error; then per failing relation each
// failing case with its finding (the worst pixels), the variants drawn and the PNGs the run
// wrote (FailedCase::images), embedded as data: URLs; an image that cannot be read is named in
// text instead. Rows carry data-shader and data-result ("pass" or "FAIL"), failing relations
// data-relation, for tests. Every string is HTML-escaped. Writes nothing when |reports| is empty.
void writePropertySection(std::ostream& out, const std::vector<properties::ShaderReport>& reports);

}  // namespace varc::cli
