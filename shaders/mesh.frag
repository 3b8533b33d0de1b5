#version 330 core
// Shading modes 0-9 (include/meshedit/overlay/shading.h is the table) and the wireframe.
// Lights are fixed in view space, so every camera angle is lit the same way.
//
// MeshRenderer compiles one variant per mode and wireframe switch (MESHEDIT_MODE,
// MESHEDIT_WIREFRAME): the compiler then drops every other branch, which on a software
// rasteriser (llvmpipe) is most of the per-fragment cost.
#ifndef MESHEDIT_MODE
#define MESHEDIT_MODE 1
#endif
#ifndef MESHEDIT_WIREFRAME
#define MESHEDIT_WIREFRAME 0
#endif

in vec3 v_position_view;
in vec3 v_normal_view;
in vec3 v_normal_world;
in vec3 v_flat_normal_view;
in vec3 v_barycentric;
flat in int v_edge_mask;

uniform vec3 u_base_color;
uniform mat4 u_view;          // mode 7: back to world space (a rotation and a translation)
uniform sampler2D u_envmap;   // the environment, equirectangular, texture unit 1, linear
uniform samplerCube u_envcube; // mode 7: the same as a cube map, unit 2
uniform float u_exposure;     // mode 7: stops
uniform bool u_field;         // colour by a scalar field (v_color), lit by Blinn-Phong
uniform bool u_edge_field;    // and draw the real sides in their edge field's colours
in vec3 v_color;
flat in vec3 v_side_color[3];
// Where the lit colour comes from (overlay/shading.h SurfaceColor): 0 u_base_color, 1 the
// face's material colour, 2 the vertex colours, 3 the material's texture, 4 a UV checker.
uniform int u_surface;
uniform sampler2DArray u_textures;  // every material's base-colour texture, sRGB, unit 3
in vec2 v_uv;
in vec4 v_vertex_color;
flat in vec4 v_material_color;
flat in float v_layer;
uniform float u_wire_width;   // pixels
uniform vec4 u_wire_color;
uniform vec2 u_depth_range;   // view-space distance of the nearest and farthest scene point
// Blinn-Phong (mode 1): the viewer's shading panel edits these; the defaults in
// include/meshedit/overlay/shading.h reproduce the fixed look of the golden images.
uniform float u_ambient;      // scales the sky-to-ground ambient term
uniform float u_diffuse;
uniform float u_specular;
uniform float u_shininess;
uniform vec3 u_light_dir;     // view space, towards the light
uniform vec3 u_light_color;

out vec4 frag_color;

const vec3 kKeyDir = normalize(vec3(-0.45, 0.65, 0.62));  // upper left, in front
const vec3 kFillDir = normalize(vec3(0.7, 0.1, 0.5));     // right
const vec3 kRimDir = normalize(vec3(0.2, 0.5, -0.85));    // behind

vec3 blinn_phong(vec3 n, vec3 v, vec3 base) {
    // Key light with a specular highlight, a weak cool fill from the right so faces turned
    // away from the key keep their shape, and a sky-to-ground ambient.
    vec3 l = normalize(u_light_dir);
    float key = max(dot(n, l), 0.0);
    float fill = max(dot(n, kFillDir), 0.0);
    vec3 h = normalize(l + v);
    float specular = pow(max(dot(n, h), 0.0), u_shininess) * step(0.0, dot(n, l));
    float ambient = u_ambient * mix(0.2, 0.3, 0.5 + 0.5 * n.y);
    return base * ambient + u_light_color * base * (u_diffuse * key) +
           vec3(0.62, 0.68, 0.78) * base * 0.3 * fill + u_light_color * (u_specular * specular);
}

vec3 studio(vec3 n, vec3 v, vec3 base) {
    vec3 key = vec3(1.0, 0.94, 0.86) * max(dot(n, kKeyDir), 0.0) * 0.75;
    vec3 fill = vec3(0.55, 0.63, 0.78) * max(dot(n, kFillDir), 0.0) * 0.45;
    float rim = pow(1.0 - max(dot(n, v), 0.0), 3.0) * max(dot(n, kRimDir) + 0.6, 0.0) * 0.5;
    vec3 h = normalize(kKeyDir + v);
    float specular = pow(max(dot(n, h), 0.0), 64.0) * 0.3;
    return base * (0.16 + key + fill) + vec3(rim) + vec3(specular);
}

// A clay matcap computed from the view-space normal instead of looked up in a texture.
vec3 matcap(vec3 n) {
    vec2 uv = n.xy;
    float shade = smoothstep(-0.9, 1.0, 0.45 * uv.y - 0.25 * uv.x + 0.6 * n.z);
    vec3 color = mix(vec3(0.23, 0.19, 0.17), vec3(0.86, 0.76, 0.68), shade);
    float spot = 1.0 - smoothstep(0.0, 0.38, length(uv - vec2(-0.32, 0.42)));
    color += vec3(0.45) * spot * spot;
    float rim = smoothstep(0.75, 1.0, length(uv));
    return mix(color, vec3(0.55, 0.5, 0.52), rim * 0.5);
}

// Mode 7: the mirror reflection of the view direction about the normal, looked up in the
// environment. The equirectangular image (u = theta/2pi, v = phi/pi as in the CS184 handout) was
// resampled through that mapping into a cube map when it was loaded (environment.h): the same
// picture, with no seam at theta = +-pi and no arc tangent or arc cosine per pixel.
vec3 envmap_reflection(vec3 n, vec3 v) {
    vec3 r = transpose(mat3(u_view)) * reflect(-v, n);
    vec3 c = texture(u_envcube, r).rgb * exp2(u_exposure);
    // Highlights above 0.8 roll off towards 1 instead of clipping; then about sRGB (gamma 2).
    c = mix(c, 0.8 + 0.2 * (1.0 - exp(-(c - 0.8) / 0.2)), step(0.8, c));
    return sqrt(clamp(c, 0.0, 1.0));
}

vec3 material_color() {
    return v_material_color.a > 0.0 ? v_material_color.rgb : u_base_color;
}

// A UV checker in the manner of Blender's colour grid: 8 × 8 cells per unit square, each
// cell's hue set by its place (so a mirrored or rotated chart reads differently), light and
// dark alternating, thin lines between cells. Stretch, flips and seams show at a glance.
vec3 uv_checker(vec2 uv) {
    vec2 cell = floor(uv * 8.0);
    float hue = fract((cell.x + 3.0 * cell.y) / 8.0 + 0.02 * cell.y);
    vec3 tint = clamp(abs(mod(hue * 6.0 + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
    float parity = mod(cell.x + cell.y, 2.0);
    vec3 color = mix(vec3(0.25), vec3(0.92), parity) * mix(vec3(1.0), tint, 0.55);
    vec2 line = abs(fract(uv * 8.0 + 0.5) - 0.5) / max(fwidth(uv * 8.0), vec2(1e-6));
    return mix(vec3(0.05), color, clamp(min(line.x, line.y) - 0.5, 0.0, 1.0));
}

// The colour the shading lights (its albedo), from u_surface.
vec3 surface_color() {
    if (u_surface == 1) {
        return material_color();
    } else if (u_surface == 2) {
        return v_vertex_color.rgb;
    } else if (u_surface == 3) {
        if (v_layer < 0.0) {
            return material_color();
        }
        // The texture is filtered in linear light; the shading works on display values.
        vec3 linear = texture(u_textures, vec3(v_uv.x, 1.0 - v_uv.y, v_layer)).rgb;
        return pow(linear, vec3(1.0 / 2.2));
    } else if (u_surface == 4) {
        return uv_checker(v_uv);
    }
    return u_base_color;
}

// The on-screen length in pixels of the side between corners j and k, from the screen
// gradients of their barycentrics (a, b: corner j's d/dx, d/dy; c, d: corner k's): going
// from corner j to corner k changes them by (-1, 1).
float side_pixels(float a, float b, float c, float d) {
    float det = a * d - b * c;
    return length(vec2(-(b + d), a + c)) / max(abs(det), 1e-12);
}

void main() {
    vec3 n = normalize(v_normal_view);
    vec3 v = normalize(-v_position_view);
    // Two-sided: the back of an open surface is lit like its front, slightly darker so an
    // inside-out mesh remains recognisable.
    float side = 1.0;
    if (!gl_FrontFacing) {
        n = -n;
        side = 0.82;
    }

    vec3 base = surface_color();
    vec3 color;
    if (MESHEDIT_MODE == 7 && !u_field) {
        color = envmap_reflection(n, v);
    } else if (u_field) {
        color = blinn_phong(n, v, v_color) * side;
    } else if (MESHEDIT_MODE == 0) {
        color = 0.5 + 0.5 * normalize(v_normal_world);
    } else if (MESHEDIT_MODE == 2) {
        vec3 fn = normalize(v_flat_normal_view) * (gl_FrontFacing ? 1.0 : -1.0);
        color = vec3(0.62) * (0.72 + 0.28 * max(dot(fn, kKeyDir), 0.0)) * side;
    } else if (MESHEDIT_MODE == 3) {
        color = studio(n, v, base) * side;
    } else if (MESHEDIT_MODE == 4) {
        color = matcap(n) * side;
    } else if (MESHEDIT_MODE == 5) {
        float t = clamp((-v_position_view.z - u_depth_range.x) /
                            max(u_depth_range.y - u_depth_range.x, 1e-6), 0.0, 1.0);
        color = vec3(mix(0.92, 0.18, t));
    } else if (MESHEDIT_MODE == 6) {
        float up = 0.5 + 0.5 * normalize(v_normal_world).y * (gl_FrontFacing ? 1.0 : -1.0);
        vec3 light = mix(vec3(0.42, 0.36, 0.30), vec3(1.0, 0.98, 0.95), up);
        color = base * light * side;
    } else {
        // 1 and the reserved aliases 8-9.
        color = blinn_phong(n, v, base) * side;
    }

    if (u_edge_field) {
        // The nearest real side within 1.5 px takes its edge's colour (as the wireframe).
        vec3 d = v_barycentric / max(fwidth(v_barycentric), vec3(1e-7));
        float dist = 1e9;
        int side = -1;
        if ((v_edge_mask & 1) != 0 && d.x < dist) { dist = d.x; side = 0; }
        if ((v_edge_mask & 2) != 0 && d.y < dist) { dist = d.y; side = 1; }
        if ((v_edge_mask & 4) != 0 && d.z < dist) { dist = d.z; side = 2; }
        if (side >= 0) {
            float coverage = clamp(2.0 - dist, 0.0, 1.0);
            color = mix(color, v_side_color[side], coverage);
        }
    }

#if MESHEDIT_WIREFRAME
    {
        // Distance in pixels to each real side (a side's barycentric is 0 on it).
        vec3 w = fwidth(v_barycentric);
        vec3 d = v_barycentric / max(w, vec3(1e-7));
        // Each side fades out by its own length on screen (a dense mesh would otherwise turn
        // solid wire colour): gone below 3 px, full from 8 px. The length is the side's, not
        // the triangle's, so the two triangles along an edge fade it alike and a mesh of mixed
        // sizes fades evenly instead of in speckles (issue 40).
        vec3 gx = dFdx(v_barycentric);
        vec3 gy = dFdy(v_barycentric);
        vec3 fade = vec3(side_pixels(gx.y, gy.y, gx.z, gy.z), side_pixels(gx.z, gy.z, gx.x, gy.x),
                         side_pixels(gx.x, gy.x, gx.y, gy.y));
        fade = clamp((fade - 3.0) / 5.0, 0.0, 1.0);
        // A sliver under 2 px high draws none of its sides: its neighbours draw them, and its
        // inside would otherwise be all wire.
        float height_px = 1.0 / max(max(w.x, w.y), max(w.z, 1e-7));
        fade *= clamp(height_px - 1.0, 0.0, 1.0);
        vec3 cover = clamp(vec3(0.5 * u_wire_width + 0.5) - d, 0.0, 1.0) * fade;
        float coverage = 0.0;
        if ((v_edge_mask & 1) != 0) coverage = max(coverage, cover.x);
        if ((v_edge_mask & 2) != 0) coverage = max(coverage, cover.y);
        if ((v_edge_mask & 4) != 0) coverage = max(coverage, cover.z);
        color = mix(color, u_wire_color.rgb, coverage * u_wire_color.a);
    }
#endif
    frag_color = vec4(color, 1.0);
}
