// SPDX-License-Identifier: Apache-2.0
// JsonReader: typed reads of scene JSON values that report the first error with its JSON pointer.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>

namespace varc::scene {

// Collects the first error; every read* returns false after reporting it.
class JsonReader {
public:
    explicit JsonReader(std::string path) : mPath(std::move(path)) {}

    bool fail(const std::string& pointer, const std::string& message);
    const std::string& error() const { return mError; }
    const std::string& path() const { return mPath; }

    // Fails when |value| (an object) has a key outside |allowed|.
    bool onlyKeys(const nlohmann::json& value, const std::string& pointer,
                  std::initializer_list<const char*> allowed);

    bool readFloat(const nlohmann::json& value, const std::string& pointer, float& out);

    bool readPositive(const nlohmann::json& value, const std::string& pointer, float& out);

    bool readVec3(const nlohmann::json& value, const std::string& pointer, glm::vec3& out);

    // [r, g, b] (alpha 1) or [r, g, b, a].
    bool readColor(const nlohmann::json& value, const std::string& pointer, glm::vec4& out);

    bool readBool(const nlohmann::json& value, const std::string& pointer, bool& out);

    bool readString(const nlohmann::json& value, const std::string& pointer, std::string& out);

    // A non-negative integer in [lo, hi].
    bool readInt(const nlohmann::json& value, const std::string& pointer, int64_t lo, int64_t hi,
                 int64_t& out);

    static std::string typeName(const nlohmann::json& value) { return value.type_name(); }

    // |value| as JSON for a message, cut to 60 characters ("..." marks the cut).
    static std::string shortDump(const nlohmann::json& value);

    // One of |names| (mapped to the matching entry of |values|).
    template <typename E>
    bool readEnum(const nlohmann::json& value, const std::string& pointer,
                  std::initializer_list<std::pair<const char*, E>> options, E& out) {
        std::string list;
        for (const auto& option : options)
            list += (list.empty() ? "" : ", ") + std::string(option.first);
        if (!value.is_string()) {
            return fail(pointer, "expected one of " + list + ", got " + shortDump(value));
        }
        const std::string text = value.get<std::string>();
        for (const auto& option : options) {
            if (text == option.first) {
                out = option.second;
                return true;
            }
        }
        return fail(pointer, "expected one of " + list + ", got '" + text + "'");
    }

private:
    std::string mPath;
    std::string mError;
};

}  // namespace varc::scene
