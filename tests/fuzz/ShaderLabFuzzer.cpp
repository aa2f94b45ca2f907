// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for the ShaderLab parser: any bytes give a ShaderFile or diagnostics.
#include "FuzzInput.h"
#include "varc/core/Diagnostic.h"
#include "varc/includes/SourceMap.h"
#include "varc/shaderlab/ShaderLabParser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    varc::includes::SourceMap map;
    varc::FileId file = map.addFile("fuzz.shader", std::string(varc::fuzz::asText(data, size)));
    varc::DiagnosticList sink;
    (void)varc::shaderlab::parseShaderLab(map.contents(file), file, sink);
    return 0;
}
