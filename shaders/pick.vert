#version 330 core
// ID pass: positions and barycentrics only.

layout(location = 0) in vec3 a_position;
layout(location = 3) in vec4 a_corner;

uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_barycentric;

void main() {
    v_barycentric = a_corner.xyz;
    gl_Position = u_projection * u_view * vec4(a_position, 1.0);
}
