#version 330 core
// Overlay points: one instance per point, a 4-vertex strip pushed out in pixels.

layout(location = 0) in vec3 a_center;
layout(location = 1) in vec4 a_color;
layout(location = 2) in float a_size;  // diameter in pixels

uniform mat4 u_view_projection;
uniform vec2 u_viewport;    // pixels
uniform float u_depth_bias; // fraction of w

out vec2 v_coord;  // -1..1 across the disc, a pixel of margin beyond
out vec4 v_color;
out float v_radius_px;

void main() {
    vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1)) * 2.0 - 1.0;
    float radius = 0.5 * a_size + 1.0;  // one pixel of margin for the smooth rim
    vec4 clip = u_view_projection * vec4(a_center, 1.0);
    clip.xy += corner * radius * 2.0 / u_viewport * clip.w;
    clip.z -= u_depth_bias * 4.0 * clip.w;  // discs sit above lines
    gl_Position = clip;
    v_coord = corner * radius;
    v_color = a_color;
    v_radius_px = 0.5 * a_size;
}
