// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for the scene parser: any bytes give a Scene or an error naming the JSON
// pointer, within the limits of docs/SECURITY.md.
#include "FuzzInput.h"
#include "varc/scene/Scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)varc::scene::parseScene(varc::fuzz::asText(data, size), "fuzz.json");
    return 0;
}
