// SPDX-License-Identifier: Apache-2.0
// JsonReader: typed reads of scene JSON values that report the first error with its JSON pointer.
#include "JsonReader.h"

#include <cmath>

namespace varc::scene {

using nlohmann::json;

bool JsonReader::fail(const std::string& pointer, const std::string& message) {
    if (mError.empty()) mError = mPath + ": " + (pointer.empty() ? "/" : pointer) + ": " + message;
    return false;
}

bool JsonReader::onlyKeys(const json& value, const std::string& pointer,
                          std::initializer_list<const char*> allowed) {
    if (!value.is_object()) return fail(pointer, "expected an object, got " + typeName(value));
    for (const auto& [key, unused] : value.items()) {
        bool known = false;
        for (const char* name : allowed) known = known || key == name;
        if (!known) {
            std::string list;
            for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
            return fail(pointer + "/" + key, "unknown key (expected one of " + list + ")");
        }
    }
    return true;
}

bool JsonReader::readFloat(const json& value, const std::string& pointer, float& out) {
    if (!value.is_number()) return fail(pointer, "expected a number, got " + typeName(value));
    const double d = value.get<double>();
    if (!std::isfinite(d)) return fail(pointer, "expected a finite number");
    out = static_cast<float>(d);
    return true;
}

bool JsonReader::readPositive(const json& value, const std::string& pointer, float& out) {
    if (!readFloat(value, pointer, out)) return false;
    if (!(out > 0.0f)) return fail(pointer, "expected a number > 0, got " + shortDump(value));
    return true;
}

bool JsonReader::readVec3(const json& value, const std::string& pointer, glm::vec3& out) {
    if (!value.is_array() || value.size() != 3) {
        return fail(pointer, "expected an array of 3 numbers, got " + shortDump(value));
    }
    for (size_t i = 0; i < 3; ++i) {
        if (!readFloat(value[i], pointer + "/" + std::to_string(i), out[static_cast<int>(i)])) {
            return false;
        }
    }
    return true;
}

bool JsonReader::readColor(const json& value, const std::string& pointer, glm::vec4& out) {
    if (!value.is_array() || value.size() < 3 || value.size() > 4) {
        return fail(pointer,
                    "expected a colour [r, g, b] or [r, g, b, a], got " + shortDump(value));
    }
    out = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    for (size_t i = 0; i < value.size(); ++i) {
        if (!readFloat(value[i], pointer + "/" + std::to_string(i), out[static_cast<int>(i)])) {
            return false;
        }
    }
    return true;
}

bool JsonReader::readBool(const json& value, const std::string& pointer, bool& out) {
    if (!value.is_boolean())
        return fail(pointer, "expected true or false, got " + shortDump(value));
    out = value.get<bool>();
    return true;
}

bool JsonReader::readString(const json& value, const std::string& pointer, std::string& out) {
    if (!value.is_string()) return fail(pointer, "expected a string, got " + typeName(value));
    out = value.get<std::string>();
    return true;
}

bool JsonReader::readInt(const json& value, const std::string& pointer, int64_t lo, int64_t hi,
                         int64_t& out) {
    if (!value.is_number_integer()) {
        return fail(pointer, "expected an integer, got " + shortDump(value));
    }
    out = value.get<int64_t>();
    if (out < lo || out > hi) {
        return fail(pointer, "expected an integer in [" + std::to_string(lo) + ", " +
                                 std::to_string(hi) + "], got " + shortDump(value));
    }
    return true;
}

std::string JsonReader::shortDump(const json& value) {
    std::string text = value.dump();
    return text.size() <= 60 ? text : text.substr(0, 57) + "...";
}

}  // namespace varc::scene
