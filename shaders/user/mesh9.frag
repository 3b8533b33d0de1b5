#version 330 core
// A MeshEdit user shader (docs/shaders.md). Edit it, save, press Ctrl+R in the viewer: on a
// compile error the previous picture stays and the error names this file and its line.

// From mesh.vert, per fragment:
in vec3 v_position_view;      // position in view space (the eye at the origin, looking down -z)
in vec3 v_normal_view;        // smooth (or flat, Q) normal in view space
in vec3 v_normal_world;       // the same in world space
in vec3 v_flat_normal_view;   // the face's normal in view space
in vec3 v_barycentric;        // one-hot at the triangle's corners (for a wireframe)
flat in int v_edge_mask;      // which triangle sides are real mesh edges (bits 0-2)
in vec3 v_color;              // a scalar field's colour, when u_field
flat in vec3 v_side_color[3]; // an edge field's side colours, when u_edge_field

uniform mat4 u_view;          // world -> view (a rotation and a translation)
uniform mat4 u_projection;
uniform vec3 u_base_color;    // the surface colour (Shading panel)
uniform vec3 u_light_dir;     // towards the light, view space
uniform vec3 u_light_color;
uniform float u_ambient, u_diffuse, u_specular, u_shininess;
uniform sampler2D u_envmap;   // the environment, equirectangular (u = theta/2pi + 1/2, v = phi/pi), unit 1
uniform float u_exposure;     // stops
uniform float u_time;         // seconds since the viewer started (0 headless)
uniform bool u_has_selection; // something is selected
uniform vec3 u_selection;     // its centre, world space
uniform bool u_field, u_edge_field;

out vec4 frag_color;

// Mode 9: Lambert light with stripes along world y drifting with time.
void main() {
    vec3 n = normalize(v_normal_view);
    if (!gl_FrontFacing) n = -n;
    float light = 0.25 + 0.75 * max(dot(n, normalize(u_light_dir)), 0.0);
    vec3 p = (inverse(u_view) * vec4(v_position_view, 1.0)).xyz;
    float stripe = step(0.5, fract(4.0 * p.y - 0.2 * u_time));
    vec3 color = mix(u_base_color, vec3(0.2, 0.45, 0.8), 0.5 * stripe);
    frag_color = vec4(color * light, 1.0);
}
