#version 330 core
// Benchmark baseline: a constant colour.

out vec4 frag_color;

void main() {
    frag_color = vec4(0.8, 0.8, 0.8, 1.0);
}
