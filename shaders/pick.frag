#version 330 core
// ID pass: the element under the pixel. RGB holds a 24-bit index, alpha the kind (1 vertex,
// 2 edge, 3 halfedge, 4 face; 0 is the cleared "nothing"). The per-triangle table holds, at
// texel 2t, the face and the three corner vertices, at 2t+1 the halfedges c0->c1, c1->c2,
// c2->c0 (0xffffffff for a fan diagonal, which is no mesh edge).
//
// Within a triangle, as in CS184: near a corner the vertex; within u_edge_radius pixels of
// a real side the edge; in the band just inside it (where the halfedge arrow is drawn) the
// halfedge of that side in this face; elsewhere the face.

in vec3 v_barycentric;

uniform usamplerBuffer u_table;
uniform float u_vertex_radius;  // pixels
uniform float u_edge_radius;    // pixels
uniform float u_halfedge_band;  // barycentric: the inner band's width relative to the face

out vec4 frag_color;

vec4 encode(uint kind, uint index) {
    return vec4(float((index >> 16) & 0xffu), float((index >> 8) & 0xffu),
                float(index & 0xffu), float(kind)) / 255.0;
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
    // Side c_j -> c_(j+1) lies opposite corner j+2: its barycentric is 0 on the side.
    int j = -1;
    float best = 1e9;
    for (int s = 0; s < 3; ++s) {
        float bs = b[(s + 2) % 3];
        if (hs[s] != 0xffffffffu && bs < best) {
            best = bs;
            j = s;
        }
    }
    if (j >= 0) {
        float pixels = best / w[(j + 2) % 3];
        if (pixels < u_edge_radius) {
            frag_color = encode(2u, hs[j] >> 1);  // edge e holds halfedges 2e and 2e+1
            return;
        }
        if (best < u_halfedge_band || pixels < 2.5 * u_edge_radius) {
            frag_color = encode(3u, hs[j]);
            return;
        }
    }
    frag_color = encode(4u, fv[0]);
}
