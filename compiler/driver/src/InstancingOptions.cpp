// SPDX-License-Identifier: Apache-2.0
// The macros `#pragma instancing_options` switches define, as Unity's shader compiler does.
#include "varc/driver/InstancingOptions.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <utility>

#include "varc/core/AsciiCase.h"

namespace varc::driver {

namespace {

bool isName(std::string_view text) {
    if (text.empty() || std::isdigit(static_cast<unsigned char>(text[0]))) return false;
    return std::all_of(text.begin(), text.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    });
}

bool isCount(std::string_view text) {
    return !text.empty() && text.size() <= 6 && std::all_of(text.begin(), text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
    }) && text.find_first_not_of('0') != std::string_view::npos;
}

}  // namespace

std::vector<PredefinedMacro> instancingOptionMacros(const std::vector<std::string>& options) {
    std::vector<PredefinedMacro> macros;
    auto define = [&macros](std::string name, std::string value) {
        macros.push_back({PredefinedMacro::Kind::Define, std::move(name), std::move(value)});
    };
    for (const std::string& option : options) {
        size_t colon = option.find(':');
        std::string key = toAsciiLower(option.substr(0, colon));
        std::string_view value = colon == std::string::npos
                                     ? std::string_view()
                                     : std::string_view(option).substr(colon + 1);
        if (key == "procedural" && isName(value)) {
            define("UNITY_INSTANCING_PROCEDURAL_FUNC", std::string(value));
        } else if (key == "maxcount" && isCount(value)) {
            define("UNITY_MAX_INSTANCE_COUNT", std::string(value));
        } else if (key == "forcemaxcount" && isCount(value)) {
            define("UNITY_FORCE_MAX_INSTANCE_COUNT", std::string(value));
        } else if (colon == std::string::npos) {
            static const std::pair<const char*, const char*> kFlags[] = {
                {"assumeuniformscaling", "UNITY_ASSUME_UNIFORM_SCALING"},
                {"nomatrices", "UNITY_DONT_INSTANCE_OBJECT_MATRICES"},
                {"lodfade", "UNITY_INSTANCED_LOD_FADE"},
                {"renderinglayer", "UNITY_INSTANCED_RENDERING_LAYER"}};
            for (const auto& [flag, macro] : kFlags) {
                if (key == flag) define(macro, "1");
            }
        }
    }
    // A macro defined twice keeps the last value (as `#define` would, without the warning).
    std::vector<PredefinedMacro> unique;
    for (auto it = macros.rbegin(); it != macros.rend(); ++it) {
        bool seen = std::any_of(unique.begin(), unique.end(),
                                [&](const PredefinedMacro& m) { return m.name == it->name; });
        if (!seen) unique.insert(unique.begin(), *it);
    }
    return unique;
}

}  // namespace varc::driver
