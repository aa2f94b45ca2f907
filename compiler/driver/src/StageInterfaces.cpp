// SPDX-License-Identifier: Apache-2.0
// Every fragment input must be written by the stage before rasterisation, in every variant.
#include "varc/driver/StageInterfaces.h"

#include "varc/pack/PartialPack.h"

namespace varc::driver {

bool checkVariantInterfaces(const std::vector<pack::PackVariant>& variants,
                            const std::vector<pack::PackProgram>& programs,
                            std::set<std::pair<uint32_t, uint32_t>>& checked,
                            const InterfaceMismatchReport& report) {
    bool ok = true;
    for (const pack::PackVariant& variant : variants) {
        Stage producer = Stage::Vertex;
        for (Stage stage : {Stage::Domain, Stage::Geometry}) {
            if (variant.programs[stageIndex(stage)] != pack::kNoProgram) producer = stage;
        }
        uint32_t feeding = variant.programs[stageIndex(producer)];
        uint32_t fragment = variant.programs[stageIndex(Stage::Fragment)];
        if (feeding == pack::kNoProgram || fragment == pack::kNoProgram ||
            pack::isPlaceholderSpirv(programs[feeding].spirv) ||
            pack::isPlaceholderSpirv(programs[fragment].spirv) ||
            !checked.insert({feeding, fragment}).second) {
            continue;
        }
        const auto& outputs = programs[feeding].reflection.outputs;
        for (const pack::StageVariable& input : programs[fragment].reflection.inputs) {
            bool matched = false;
            for (const pack::StageVariable& output : outputs) {
                matched =
                    matched || (output.location == input.location && output.type == input.type);
            }
            if (matched) continue;
            report(variant, producer, input);
            ok = false;
        }
    }
    return ok;
}

}  // namespace varc::driver
