#version 330 core
// Overlay lines: one instance per segment, a screen-space quad `a_width` pixels wide (core
// profile has no wide lines), extended by half the width at both ends so polylines join.

layout(location = 0) in vec3 a_from;
layout(location = 1) in vec3 a_to;
layout(location = 2) in vec4 a_color;
layout(location = 3) in float a_width;

uniform mat4 u_view_projection;
uniform vec2 u_viewport;
uniform float u_depth_bias;

out vec4 v_color;
noperspective out float v_across;  // signed pixels from the centre line
noperspective out float v_half_width;

void main() {
    float end = float(gl_VertexID & 1);                      // 0 at a_from, 1 at a_to
    float side = float((gl_VertexID >> 1) & 1) * 2.0 - 1.0;  // -1 or +1
    vec4 clip_a = u_view_projection * vec4(a_from, 1.0);
    vec4 clip_b = u_view_projection * vec4(a_to, 1.0);
    vec2 screen_a = clip_a.xy / clip_a.w * 0.5 * u_viewport;
    vec2 screen_b = clip_b.xy / clip_b.w * 0.5 * u_viewport;
    vec2 dir = screen_b - screen_a;
    dir = dot(dir, dir) > 1e-12 ? normalize(dir) : vec2(1.0, 0.0);
    vec2 normal = vec2(-dir.y, dir.x);

    float half_width = 0.5 * a_width;
    float extent = half_width + 1.0;  // a pixel of margin for the smooth sides
    vec2 offset = normal * side * extent + dir * (end * 2.0 - 1.0) * half_width;
    vec4 clip = end < 0.5 ? clip_a : clip_b;
    clip.xy += offset * 2.0 / u_viewport * clip.w;
    // The caps reach half a width past each end, so extrapolate depth along the segment
    // there: keeping the endpoint's depth would tilt the depth ramp, and the line would sink
    // behind the surface near its nearer end.
    float z_a = clip_a.z / clip_a.w;
    float z_b = clip_b.z / clip_b.w;
    float length_px = length(screen_b - screen_a);
    float reach = length_px > 1e-6 ? half_width / length_px : 0.0;
    float z = end < 0.5 ? z_a - (z_b - z_a) * reach : z_b + (z_b - z_a) * reach;
    clip.z = (z - 2.0 * u_depth_bias) * clip.w;
    gl_Position = clip;
    v_color = a_color;
    v_across = side * extent;
    v_half_width = half_width;
}
