// SPDX-License-Identifier: Apache-2.0
// Writes a file so that readers see either the old contents or the complete new contents.
#pragma once

#include <string>
#include <string_view>

#include "varc/core/Result.h"

namespace varc {

// Whether writeFileAtomically waits for the data to reach the disk before the rename. Unsynced
// is for caches whose entries carry their own checksum: after a power loss such an entry may be
// empty or torn (a miss), never half-visible to a running reader; it saves an fsync per entry.
enum class Durability { Synced, Unsynced };

// Writes |contents| to a temporary file next to |path| (unique per process and call, created
// exclusively), flushes it (fsync, unless Durability::Unsynced), then renames it over |path|.
// On failure the temporary is removed and |path| is untouched; the error names the path and the
// system's reason.
//
// Only regular files are ever replaced: when |path| is a character device, FIFO or socket
// (`-o /dev/null`), |contents| are written into it and it stays what it was; a symbolic link
// stays a link and the file it names is replaced; a directory is an error.
Status writeFileAtomically(const std::string& path, std::string_view contents,
                           Durability durability = Durability::Synced);

// For programs (the varc CLI; libraries never install handlers): SIGINT, SIGTERM and SIGHUP
// first remove the temporaries of writes in progress, then end the process with that signal as
// before. So an interrupted `varc build` leaves neither a partial output nor a stray temporary.
void removeTemporariesOnTerminationSignals();

}  // namespace varc
