// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for include expansion and the pragma reader on an in-memory file system:
// the input is a root program plus include files f1.h, f2.h, ... (FuzzInput.h), so cycles,
// guards, missing files and deep chains are all reachable.
#include "FuzzInput.h"
#include "varc/core/Diagnostic.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/IncludeResolver.h"
#include "varc/includes/SourceMap.h"
#include "varc/variants/PragmaParser.h"
#include "varc/variants/VariantSpace.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> files = varc::fuzz::splitFiles(varc::fuzz::asText(data, size));
    varc::includes::InMemoryFileSystem fileSystem;
    for (size_t i = 1; i < files.size(); ++i) fileSystem.add(varc::fuzz::includeName(i), files[i]);
    varc::includes::SourceMap map;
    varc::FileId root = map.addFile("root.shader", files[0]);
    varc::DiagnosticList sink;
    varc::includes::IncludeResolver resolver(fileSystem, map, {});
    auto expanded = resolver.expand({{map.contents(root), {root, 1, 1}}}, sink);
    if (!expanded) return 0;
    auto keywords = varc::variants::parsePragmas(expanded->pragmas, sink);
    if (!keywords) return 0;
    auto space = varc::variants::VariantSpace::build(*keywords, sink);
    if (!space) return 0;
    (void)space->count();
    // Enumerate small spaces only: the count says how many there are without enumerating.
    if (space->count() <= 4096) (void)space->enumerate();
    return 0;
}
