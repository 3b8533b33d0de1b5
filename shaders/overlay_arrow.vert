#version 330 core
// Overlay arrowheads: one instance per head, a triangle whose point is at a_tip and whose
// length and width are in pixels (so it reads at every zoom), pointing along a_tail → a_tip
// on screen. The head never reaches past the tail.
//
//            left
//              |\
//   a_tail ----+ \ a_tip        vertex 0 = a_tip, 1 = left, 2 = right
//              | /
//              |/
//            right
//
// The corners' depths come from the plane the head lies in (the axis and a_across): a head
// flat on screen at the tip's depth would sink into a face seen at a slant. The pixel offset
// of a corner is mapped back to that plane through the projection linearised at the tip.

layout(location = 0) in vec3 a_tip;
layout(location = 1) in vec3 a_tail;
layout(location = 2) in vec3 a_across;  // unit, perpendicular to the axis; zero if unknown
layout(location = 3) in vec4 a_color;
layout(location = 4) in vec2 a_size;  // length, half-width in pixels

uniform mat4 u_view_projection;
uniform vec2 u_viewport;
uniform float u_depth_bias;

out vec4 v_color;

vec2 screen_of(vec4 clip) {
    return clip.xy / clip.w * 0.5 * u_viewport;
}

void main() {
    vec4 clip_tip = u_view_projection * vec4(a_tip, 1.0);
    vec4 clip_tail = u_view_projection * vec4(a_tail, 1.0);
    vec2 screen_tip = screen_of(clip_tip);
    vec2 axis = screen_tip - screen_of(clip_tail);
    float axis_px = length(axis);
    vec2 dir = axis_px > 1e-6 ? axis / axis_px : vec2(1.0, 0.0);
    vec2 normal = vec2(-dir.y, dir.x);
    float scale = axis_px > 1e-6 ? min(1.0, axis_px / a_size.x) : 0.0;

    vec2 offset = vec2(0.0);
    if (gl_VertexID != 0) {
        float side = gl_VertexID == 1 ? 1.0 : -1.0;
        offset = (-dir * a_size.x + normal * side * a_size.y) * scale;
    }

    // World point in the head's plane under the corner: solve offset = a·s_back + b·s_across,
    // s_* being the screen steps of small world steps from the tip.
    vec3 back = a_tail - a_tip;
    float h = 0.05;
    vec3 step_across = a_across * length(back);
    vec2 s_back = (screen_of(u_view_projection * vec4(a_tip + h * back, 1.0)) - screen_tip) / h;
    vec2 s_across =
        (screen_of(u_view_projection * vec4(a_tip + h * step_across, 1.0)) - screen_tip) / h;
    float det = s_back.x * s_across.y - s_back.y * s_across.x;
    vec4 clip_depth = clip_tip;
    if (abs(det) > 1e-3 * (dot(s_back, s_back) + dot(s_across, s_across))) {
        float a = (offset.x * s_across.y - offset.y * s_across.x) / det;
        float b = (s_back.x * offset.y - s_back.y * offset.x) / det;
        clip_depth = u_view_projection * vec4(a_tip + a * back + b * step_across, 1.0);
    }

    vec4 clip = clip_tip;
    clip.xy += offset * 2.0 / u_viewport * clip.w;
    clip.z = (clip_depth.z / clip_depth.w - 2.0 * u_depth_bias) * clip.w;
    gl_Position = clip;
    v_color = a_color;
}
