#version 330 core
// A disc with a smooth rim and a darker outline.

in vec2 v_coord;
in vec4 v_color;
in float v_radius_px;

uniform float u_alpha;  // 1; less for the hidden parts of x-ray marks

out vec4 frag_color;

void main() {
    float r = length(v_coord);
    float alpha = clamp(v_radius_px + 0.5 - r, 0.0, 1.0);
    if (alpha <= 0.0) discard;
    float outline = clamp(r - (v_radius_px - 1.5) + 0.5, 0.0, 1.0);
    vec3 rgb = mix(v_color.rgb, v_color.rgb * 0.45, outline);
    frag_color = vec4(rgb, v_color.a * alpha * u_alpha);
}
