#version 330 core
// ID pass: the element under the pixel as 24-bit RGB: kind (1 vertex, 2 halfedge, 3 face)
// in the top 2 bits, index in the low 22. The per-triangle table holds, at texel 2t, the
// face and the three corner vertices, at 2t+1 the halfedges c0->c1, c1->c2, c2->c0
// (0xffffffff for a fan diagonal, which is no mesh edge).

in vec3 v_barycentric;

uniform usamplerBuffer u_table;
uniform float u_vertex_radius;  // pixels
uniform float u_edge_radius;    // pixels

out vec4 frag_color;

vec4 encode(uint kind, uint index) {
    uint id = (kind << 22) | (index & 0x3fffffu);
    return vec4(float((id >> 16) & 0xffu), float((id >> 8) & 0xffu), float(id & 0xffu), 255.0) /
           255.0;
}

void main() {
    int t = gl_PrimitiveID;
    uvec4 fv = texelFetch(u_table, 2 * t);
    uvec4 hs = texelFetch(u_table, 2 * t + 1);
    vec3 b = v_barycentric;
    vec3 w = max(fwidth(b), vec3(1e-7));

    // Nearest corner, if within the vertex radius.
    int k = b.x > b.y ? (b.x > b.z ? 0 : 2) : (b.y > b.z ? 1 : 2);
    if ((1.0 - b[k]) / w[k] < u_vertex_radius) {
        frag_color = encode(1u, fv[1 + k]);
        return;
    }
    // Side c_j -> c_(j+1) lies opposite corner j+2.
    vec3 d = b / w;
    int j = -1;
    float best = u_edge_radius;
    for (int s = 0; s < 3; ++s) {
        float dist = d[(s + 2) % 3];
        if (hs[s] != 0xffffffffu && dist < best) {
            best = dist;
            j = s;
        }
    }
    if (j >= 0) {
        frag_color = encode(2u, hs[j]);
        return;
    }
    frag_color = encode(3u, fv[0]);
}
