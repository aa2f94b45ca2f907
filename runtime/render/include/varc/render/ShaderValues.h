// SPDX-License-Identifier: Apache-2.0
// Uniform values by name: what a runtime knows (camera, object, light, material) before it knows
// which program will read it. UniformBlockWriter lays them out by each program's reflection.
#pragma once

#include <glm/glm.hpp>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace varc::render {

// One named value: |elements| elements of |width| floats each (1 = scalar, 4 = vector,
// 16 = a 4x4 matrix in glm's column-major order). Vectors narrower than a member are truncated,
// wider members are zero-filled, so a vec4 serves float, float2, float3 and float4 members.
struct ShaderValue {
    uint32_t width = 4;
    std::vector<float> data;  // elements * width floats
    size_t elements() const { return width ? data.size() / width : 0; }
};

class ShaderValues {
public:
    void set(std::string name, float value);
    void set(std::string name, const glm::vec4& value);
    void set(std::string name, const glm::vec3& value, float w);
    void set(std::string name, const glm::mat4& value);
    void setArray(std::string name, std::span<const glm::vec4> values);
    void setArray(std::string name, std::span<const glm::mat4> values);

    // nullptr when |name| was never set.
    const ShaderValue* find(std::string_view name) const;
    // Copies every value of |other| over this one's (later layers win).
    void merge(const ShaderValues& other);
    size_t size() const { return mValues.size(); }

private:
    std::map<std::string, ShaderValue, std::less<>> mValues;
};

}  // namespace varc::render
