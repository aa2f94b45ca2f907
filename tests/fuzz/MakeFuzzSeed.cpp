// SPDX-License-Identifier: Apache-2.0
// Writes seed packs for PackReaderFuzzer: `varc_pack_fuzz_seed <corpus-dir>`.
#include <cstdio>
#include <string>

#include "PackTestData.h"
#include "varc/packwriter/PackWriter.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s <corpus-dir>\n", argv[0]);
        return 2;
    }
    varc::pack::PackContents contents = varc::packtest::makeSampleContents();
    const std::string dir = argv[1];
    using varc::packwriter::PackDictionary;
    bool ok = varc::packwriter::writePack(dir + "/sample-dict.vpk", contents,
                                          {.dictionary = PackDictionary::Always})
                  .ok() &&
              varc::packwriter::writePack(dir + "/sample-plain.vpk", contents,
                                          {.dictionary = PackDictionary::Never})
                  .ok() &&
              varc::packwriter::writePack(dir + "/empty.vpk", varc::pack::PackContents{}).ok();
    if (!ok) std::fprintf(stderr, "cannot write seeds to %s\n", dir.c_str());
    return ok ? 0 : 1;
}
