// SPDX-License-Identifier: Apache-2.0
// Decomposes keyword directive names: base, `_local`, stage suffix, or a shortcut name.
#include "pragma/DirectiveForm.h"

#include <array>
#include <utility>

namespace varc::variants {

namespace {

struct Base {
    std::string_view name;
    DirectiveKind kind;
};
constexpr std::array<Base, 3> kBases = {{{"multi_compile", DirectiveKind::MultiCompile},
                                         {"shader_feature", DirectiveKind::ShaderFeature},
                                         {"dynamic_branch", DirectiveKind::DynamicBranch}}};

constexpr std::array<std::pair<std::string_view, StageMask>, 6> kStageSuffixes = {{
    {"vertex", stageBit(Stage::Vertex)},
    {"fragment", stageBit(Stage::Fragment)},
    {"hull", stageBit(Stage::Hull)},
    {"domain", stageBit(Stage::Domain)},
    {"geometry", stageBit(Stage::Geometry)},
    {"raytracing", kRaytracingStages},
}};

// Reads "[local][_stage]" from |rest| into |form|; false if anything else is left over.
bool parseSuffixes(std::string_view rest, DirectiveForm& form) {
    if (rest == "local" || rest.starts_with("local_")) {
        form.local = true;
        rest.remove_prefix(rest.size() == 5 ? 5 : 6);
        if (rest.empty()) return true;
    }
    for (const auto& [suffix, bit] : kStageSuffixes) {
        if (rest == suffix) {
            form.stages = bit;
            return true;
        }
    }
    return false;
}

}  // namespace

DirectiveForm classifyDirective(std::string_view name) {
    DirectiveForm form;
    for (const Base& base : kBases) {
        if (!name.starts_with(base.name)) continue;
        std::string_view rest = name.substr(base.name.size());
        form.kind = base.kind;
        if (rest.empty()) {
            form.status = FormStatus::Set;
        } else if (rest[0] != '_' || rest.size() == 1) {
            continue;  // "multi_compilefoo" is some other pragma
        } else if (parseSuffixes(rest.substr(1), form)) {
            bool staged = form.stages != kEverySetStage;
            form.status = base.kind == DirectiveKind::DynamicBranch && staged
                              ? FormStatus::StageOnDynamicBranch
                              : FormStatus::Set;
        } else if (base.kind == DirectiveKind::MultiCompile) {
            form = DirectiveForm{FormStatus::Shortcut, base.kind, false, kEverySetStage,
                                 rest.substr(1)};
        } else {
            form = DirectiveForm{FormStatus::UnknownSuffix, base.kind, false, kEverySetStage, {}};
        }
        return form;
    }
    return DirectiveForm{};
}

std::vector<std::string> keywordDirectiveSpellings() {
    std::vector<std::string> spellings;
    for (const Base& base : kBases) {
        std::string name(base.name);
        spellings.push_back(name);
        spellings.push_back(name + "_local");
        if (base.kind == DirectiveKind::DynamicBranch) continue;
        for (const auto& [suffix, bit] : kStageSuffixes) {
            spellings.push_back(name + "_" + std::string(suffix));
            spellings.push_back(name + "_local_" + std::string(suffix));
        }
    }
    return spellings;
}

}  // namespace varc::variants
