#version 450
// Each sixth of the target's width samples the centre of one cube face, in Vulkan's layer
// order +X, -X, +Y, -Y, +Z, -Z (a 6-pixel-wide target gives one pixel per face).
layout(set = 0, binding = 0) uniform samplerCube uCube;
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

const vec3 kFaceDirections[6] = vec3[](vec3(1.0, 0.0, 0.0), vec3(-1.0, 0.0, 0.0),
                                       vec3(0.0, 1.0, 0.0), vec3(0.0, -1.0, 0.0),
                                       vec3(0.0, 0.0, 1.0), vec3(0.0, 0.0, -1.0));

void main() {
    int face = clamp(int(inUv.x * 6.0), 0, 5);
    outColor = texture(uCube, kFaceDirections[face]);
}
