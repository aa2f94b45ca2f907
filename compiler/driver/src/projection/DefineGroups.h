// SPDX-License-Identifier: Apache-2.0
// Conditional groups whose only effect is to define macros: which branch a variant takes there
// matters only if something the stage keeps uses one of those macros (Reachability.h).
#pragma once

#include <vector>

#include "ConditionalText.h"

namespace varc::driver::projection {

// Sets PpLine::definesOnly and PpLine::defines on each #if/#ifdef/#ifndef of |lines| (linked by
// ConditionalText) whose branches hold only #define/#undef lines, blank text and such groups.
// (Whether another definition of those names makes the choice there matter is the walk's to
// see: Reachability.h.)
void markDefineGroups(std::vector<PpLine>& lines);

}  // namespace varc::driver::projection
