#version 330 core
// Smooth-sided line quad.

in vec4 v_color;
noperspective in float v_across;
noperspective in float v_half_width;

uniform float u_alpha;  // 1; less for the hidden parts of x-ray marks

out vec4 frag_color;

void main() {
    float alpha = clamp(v_half_width + 0.5 - abs(v_across), 0.0, 1.0);
    if (alpha <= 0.0) discard;
    frag_color = vec4(v_color.rgb, v_color.a * alpha * u_alpha);
}
