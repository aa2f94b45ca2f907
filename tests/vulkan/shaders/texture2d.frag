#version 450
// Samples a 2D texture at an explicit level of detail given by a push constant.
layout(set = 0, binding = 0) uniform sampler2D uTexture;
layout(push_constant) uniform Push {
    float lod;
} push;
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
    outColor = textureLod(uTexture, inUv, push.lod);
}
