#version 450
// Passes positions through (already in clip space) with a flat per-vertex colour, so HDR
// targets receive the exact colour without interpolation rounding.
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColor;
layout(location = 0) flat out vec4 outColor;

void main() {
    gl_Position = vec4(inPosition, 1.0);
    outColor = inColor;
}
