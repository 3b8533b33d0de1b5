#version 330 core
// Overlay triangles (face tints, arrowheads) as they are.

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;

uniform mat4 u_view_projection;
uniform float u_depth_bias;

out vec4 v_color;

void main() {
    vec4 clip = u_view_projection * vec4(a_position, 1.0);
    clip.z -= u_depth_bias * clip.w;
    gl_Position = clip;
    v_color = a_color;
}
