#version 330 core
// Shaded mesh: one GPU vertex per triangle corner (see mesh_renderer.h).

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_smooth_normal;  // packed 10-10-10-2, normalised
layout(location = 2) in vec4 a_flat_normal;
layout(location = 3) in vec4 a_corner;         // one-hot barycentric, real-edge mask / 255
layout(location = 4) in vec4 a_color;          // a scalar field's colour (when u_field)
layout(location = 5) in vec4 a_side_color0;    // an edge field's colour of the side opposite
layout(location = 6) in vec4 a_side_color1;    // corner 0, 1, 2 (when u_edge_field)
layout(location = 7) in vec4 a_side_color2;
layout(location = 8) in vec2 a_uv;             // the corner's texture coordinate
layout(location = 9) in vec4 a_vertex_color;   // its vertex (or face) colour
layout(location = 10) in vec4 a_material_color; // its face's material colour (alpha 0: none)
layout(location = 11) in float a_layer;         // its material's texture layer, or -1

uniform mat4 u_view;
uniform mat4 u_projection;
uniform bool u_smooth;

out vec3 v_position_view;
out vec3 v_normal_view;
out vec3 v_normal_world;
out vec3 v_flat_normal_view;
out vec3 v_barycentric;
flat out int v_edge_mask;
out vec3 v_color;
flat out vec3 v_side_color[3];
out vec2 v_uv;
out vec4 v_vertex_color;
flat out vec4 v_material_color;
flat out float v_layer;

void main() {
    vec4 p = u_view * vec4(a_position, 1.0);
    v_position_view = p.xyz;
    // The view matrix is a rotation plus translation, so it transforms normals directly.
    vec3 n = u_smooth ? a_smooth_normal.xyz : a_flat_normal.xyz;
    // A vertex whose faces cancel has a zero smooth normal: fall back to the face normal.
    if (dot(n, n) < 1e-8) n = a_flat_normal.xyz;
    v_normal_world = n;
    v_normal_view = mat3(u_view) * n;
    v_flat_normal_view = mat3(u_view) * a_flat_normal.xyz;
    v_barycentric = a_corner.xyz;
    v_edge_mask = int(a_corner.w * 255.0 + 0.5);
    v_color = a_color.rgb;
    v_side_color[0] = a_side_color0.rgb;
    v_side_color[1] = a_side_color1.rgb;
    v_side_color[2] = a_side_color2.rgb;
    v_uv = a_uv;
    v_vertex_color = a_vertex_color;
    v_material_color = a_material_color;
    v_layer = a_layer;
    gl_Position = u_projection * p;
}
