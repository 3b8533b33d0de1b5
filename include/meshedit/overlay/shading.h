#pragma once
/// \file
/// Shading modes and render options. The mode table is the single source for the
/// `--shading` flag of `meshedit render` and the viewer's 0–9 keys.

#include <array>
#include <optional>
#include <string_view>

namespace meshedit {

/// A shading mode: number (the viewer key), name (the CLI word), one-line description.
struct ShadingMode {
    int number;
    std::string_view name;
    std::string_view description;
};

/// Modes 0–9. The number is also MESHEDIT_MODE, the variant of the mesh fragment shader.
inline constexpr std::array<ShadingMode, 10> kShadingModes{{
    {0, "normals", "world-space normal as colour (0.5 + 0.5 n)"},
    {1, "phong", "Blinn-Phong: key light and highlight, cool fill (smooth or flat)"},
    {2, "grey", "flat grey: unlit-ish grey with a little face shading"},
    {3, "studio", "two-light studio: warm key, cool fill, rim light"},
    {4, "matcap", "matcap-like clay lookup by view-space normal (procedural, no texture)"},
    {5, "depth", "grey by view depth (near light, far dark)"},
    {6, "hemisphere", "sky/ground hemisphere light"},
    {7, "envmap", "mirror reflection of an environment map (default: a procedural studio)"},
    {8, "user8", "your shader: mesh8.frag in the user shader folder (docs/shaders.md)"},
    {9, "user9", "your shader: mesh9.frag in the user shader folder (docs/shaders.md)"},
}};

/// Looks a mode up by name or number ("phong", "1"); nullopt if unknown.
std::optional<ShadingMode> find_shading_mode(std::string_view name_or_number);

/// Where the surface's colour comes from (as Blender's viewport "Color" choice); the shading
/// mode then lights it. `--color` of `meshedit render` and the viewer's Alt+C.
enum class SurfaceColor {
    Auto,      ///< texture, else vertex colours, else several materials' colours, else single
    Single,    ///< RenderOptions::base_color everywhere
    Material,  ///< each face's material base colour (f:material, Mesh::materials())
    Vertex,    ///< the vertex colours (v:color), else the face colours (f:color)
    Texture,   ///< the material's base-colour texture at the corner UVs, times its colour
    Checker,   ///< a UV checker: a numbered-looking grid of the corner UVs (seams show)
};

/// A surface colour: its CLI word and one-line description.
struct SurfaceColorMode {
    SurfaceColor color;
    std::string_view name;
    std::string_view description;
};

inline constexpr std::array<SurfaceColorMode, 6> kSurfaceColors{{
    {SurfaceColor::Auto, "auto", "texture, else vertex colours, else material colours, else one"},
    {SurfaceColor::Single, "single", "one base colour"},
    {SurfaceColor::Material, "material", "each face's material colour"},
    {SurfaceColor::Vertex, "vertex", "vertex colours (else face colours)"},
    {SurfaceColor::Texture, "texture", "base-colour textures at the texture coordinates"},
    {SurfaceColor::Checker, "checker", "a UV checker grid: stretch, flips and seams show"},
}};

/// Looks a surface colour up by its word ("texture"); nullopt if unknown.
std::optional<SurfaceColorMode> find_surface_color(std::string_view name);

/// Blinn-Phong coefficients of shading mode 1 (the viewer's shading panel edits them). The
/// light direction is in view space (x right, y up, z towards the viewer), so the lighting
/// follows the camera.
struct PhongParams {
    float ambient = 1.0f;  ///< scales the sky-to-ground ambient (0.2 below … 0.3 above)
    float diffuse = 0.62f;
    float specular = 0.32f;
    float shininess = 48.0f;
    std::array<float, 3> light_dir{-0.45f, 0.65f, 0.62f};  ///< upper left, in front
    std::array<float, 3> light_color{1.0f, 1.0f, 1.0f};
};

/// What MeshRenderer::draw() draws. A plain struct with defaults.
struct RenderOptions {
    int shading = 1;         ///< index into kShadingModes
    bool smooth = true;      ///< area-weighted vertex normals (else face normals)
    bool wireframe = false;  ///< crisp ~1 px edges over the surface
    float wire_width_px = 1.0f;
    std::array<float, 4> wire_color{0.16f, 0.17f, 0.2f, 1.0f};
    /// Base colour of the surface (a warm white).
    std::array<float, 3> base_color{0.93f, 0.89f, 0.82f};
    /// Where the colour that the shading lights comes from (modes 1, 3, 6 and the users').
    SurfaceColor color = SurfaceColor::Auto;
    PhongParams phong;
    /// Mode 7: the environment's brightness in stops (2^exposure), before the highlights
    /// above 0.8 roll off towards white and the result is encoded as sRGB.
    float exposure = 0.0f;
    /// For user shaders (modes 8, 9): seconds since the start, and the selection's centre.
    float time_s = 0.0f;
    bool has_selection = false;
    std::array<float, 3> selection{};
};

}  // namespace meshedit
