// SPDX-License-Identifier: Apache-2.0
#include "varc/render/ShaderValues.h"

#include <glm/gtc/type_ptr.hpp>

namespace varc::render {

void ShaderValues::set(std::string name, float value) { mValues[std::move(name)] = {1, {value}}; }

void ShaderValues::set(std::string name, const glm::vec4& value) {
    mValues[std::move(name)] = {4, {value.x, value.y, value.z, value.w}};
}

void ShaderValues::set(std::string name, const glm::vec3& value, float w) {
    set(std::move(name), glm::vec4(value, w));
}

void ShaderValues::set(std::string name, const glm::mat4& value) {
    const float* floats = glm::value_ptr(value);
    mValues[std::move(name)] = {16, std::vector<float>(floats, floats + 16)};
}

void ShaderValues::setArray(std::string name, std::span<const glm::vec4> values) {
    ShaderValue value{4, {}};
    for (const glm::vec4& v : values) value.data.insert(value.data.end(), {v.x, v.y, v.z, v.w});
    mValues[std::move(name)] = std::move(value);
}

void ShaderValues::setArray(std::string name, std::span<const glm::mat4> values) {
    ShaderValue value{16, {}};
    for (const glm::mat4& m : values) {
        const float* floats = glm::value_ptr(m);
        value.data.insert(value.data.end(), floats, floats + 16);
    }
    mValues[std::move(name)] = std::move(value);
}

const ShaderValue* ShaderValues::find(std::string_view name) const {
    auto it = mValues.find(name);
    return it == mValues.end() ? nullptr : &it->second;
}

void ShaderValues::merge(const ShaderValues& other) {
    for (const auto& [name, value] : other.mValues) mValues[name] = value;
}

}  // namespace varc::render
