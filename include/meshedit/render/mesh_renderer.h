#pragma once
/// \file
/// Draws a core Mesh with GL 3.3 core: shaded triangles (polygons fan-triangulated), an
/// optional crisp wireframe, and an ID pass for picking.
///
/// Every triangle corner is its own GPU vertex (24 bytes: position, smooth and flat normals
/// packed 10-10-10-2, a one-hot barycentric plus a mask of which triangle sides are real
/// mesh edges). That costs 3 vertices per triangle instead of ~0.5, but it lets one buffer
/// serve smooth and flat shading (a uniform switches), and it gives the fragment shader
/// barycentrics for a wireframe that is crisp at any zoom and hides fan diagonals. A
/// 1M-triangle mesh is 72 MB of vertex data.

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/pod_array.h"
#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/colormap.h"
#include "meshedit/overlay/overlay.h"
#include "meshedit/overlay/shading.h"
#include "meshedit/render/environment.h"
#include "meshedit/render/shader_program.h"

namespace meshedit {

/// One GPU vertex (a triangle corner). Public so tests can check the packing.
struct MeshGpuVertex {
    float position[3];
    std::uint32_t smooth_normal;  ///< GL_INT_2_10_10_10_REV, normalised
    std::uint32_t flat_normal;    ///< GL_INT_2_10_10_10_REV, normalised
    std::uint8_t corner[4];       ///< one-hot barycentric (xyz), real-edge mask (w)
};

/// The shaded mesh. Needs a current GL 3.3 core context for everything but construction;
/// GL objects are created lazily on the first upload and freed in the destructor (with the
/// same context current).
class MeshRenderer {
public:
    MeshRenderer() = default;
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;
    ~MeshRenderer();

    /// Uploads `mesh` (after any topology change). Reuses the CPU staging arrays and the GL
    /// buffer (glBufferSubData when the size does not grow), so repeated uploads allocate
    /// nothing once the largest size has been seen. \throws GlError on a GL failure.
    void upload(const Mesh& mesh);

    /// After a local edit, or its undo or redo, recorded as a MeshChange (core/mesh_change.h):
    /// redraws only what changed. `faces` and `vertices` are the change's region() (indices
    /// may be deleted or out of range). Each face keeps a slot of triangles in the buffers
    /// from upload(): a face that still fits is rewritten in place (the rest of its slot
    /// degenerate), a grown or new face gets a slot at the end, a deleted face's slot turns
    /// degenerate; vertex normals are brought up to date around the region bit for bit as
    /// upload() computes them (update_vertex_normals), and only the triangles written go to
    /// the GPU (glBufferSubData). Falls back to upload() — returning false — when nothing was
    /// uploaded yet or some edge splits the normals (creases, Auto Smooth), whose wedges are
    /// not updated locally. \pre the mesh was uploaded, then changed only by such changes
    /// (no garbage collection). A field shown is cleared, as by upload().
    bool update(const Mesh& mesh, std::span<const Face> faces, std::span<const Vertex> vertices);

    /// Re-uploads positions and normals only, for geometry-only edits (a vertex drag); the
    /// triangle list must be unchanged since upload(). Cheaper than upload(): no
    /// re-triangulation and no pick table rebuild.
    void update_geometry(const Mesh& mesh);

    /// Draws the surface into the current framebuffer and viewport (depth test on).
    /// \param aspect viewport width / height.
    void draw(const Camera& camera, float aspect, const RenderOptions& options);

    /// The ID pass: writes element ids into the current (single-sample, RGBA8!) framebuffer,
    /// clearing it first: index in RGB (24 bits), kind in alpha. Near a corner
    /// (`vertex_radius_px`) the vertex; within `edge_radius_px` of a real edge the edge; in
    /// the band just inside it (2.5 × the edge radius, or 15% of the face's height, where
    /// the halfedge arrow is drawn) the halfedge of that side in this face; elsewhere the
    /// face. Alpha 0 is "nothing".
    void draw_ids(const Camera& camera, float aspect, float vertex_radius_px = 6.0f,
                  float edge_radius_px = 4.0f);

    /// Decodes an RGBA pixel of the ID pass.
    static ElementRef decode_id(const std::uint8_t* rgba);

    /// Runs draw_ids() on the pixel at (x, y) alone (origin top-left, like window
    /// coordinates) of a `width` × `height` viewport and reads it back.
    ElementRef pick(const Camera& camera, int width, int height, int x, int y,
                    float vertex_radius_px = 6.0f, float edge_radius_px = 4.0f);

    /// The same triangles with a transform-only shader and a constant colour: the baseline
    /// that the draw benchmark compares draw() against. Back faces are drawn unless
    /// `cull_back_faces` (draw() culls them when culls_back_faces() says so).
    void draw_bare(const Camera& camera, float aspect, bool cull_back_faces = false);

    /// Triangles of the live faces (after update() the buffers hold some degenerate ones too).
    std::size_t triangle_count() const { return live_triangles_; }

    /// Colours the surface by a scalar field (core/fields.h) of the uploaded mesh: a vertex
    /// field interpolated across the faces, a face field flat per face, an edge field on the
    /// edges (about 3 px wide, as the wireframe is drawn) over a neutral grey surface. Lit by
    /// Blinn-Phong whatever the shading mode. Call after upload(); another upload() clears it.
    void set_field(FieldSite site, std::span<const double> values, const FieldColoring& coloring);
    /// The environment mode 7 reflects (texture unit 1, mipmapped); the default one
    /// (environment.h) is made on the first draw in mode 7 without one. Needs the context.
    void set_environment(const EnvironmentImage& image);

    /// Where modes 8 and 9 load mesh8.frag and mesh9.frag (user_shaders.h); empty: they draw
    /// as mode 1. Takes effect at the next draw in those modes.
    void set_user_shader_dir(const std::filesystem::path& dir);
    const std::filesystem::path& user_shader_dir() const { return user_shader_dir_; }
    /// Why the last draw in mode 8 or 9 fell back to mode 1 (the compiler's message, naming
    /// the file and line), or empty.
    const std::string& user_shader_error() const { return user_shader_error_; }
    /// Recompiles, from disk, every program compiled so far and the user's. A program that
    /// fails keeps the one it had. \return the errors, one per line (empty: all compiled).
    std::string reload_shaders();

    void clear_field() { has_field_ = has_edge_field_ = false; }
    bool has_field() const { return has_field_; }

    /// The surface colour draw() shows when `wanted` is asked for on the uploaded mesh: Auto
    /// resolved (a texture, else vertex or face colours, else the colours of several
    /// materials, else Single); a choice the mesh has no data for (Texture without texture
    /// coordinates or a readable texture, Checker without texture coordinates, Vertex
    /// without colours, Material without materials) is drawn as Single.
    SurfaceColor shown_color(SurfaceColor wanted) const;
    /// One line for each base-colour texture the last upload() could not show (missing,
    /// unreadable, too large), naming the file and the material: those faces are drawn in
    /// their material's colour.
    const std::vector<std::string>& texture_notes() const { return texture_notes_; }

    /// Which edges split smooth shading (core/normals.h; by default crease edges). Takes
    /// effect at the next upload() or update_geometry().
    void set_normal_split(const NormalSplit& split) { normal_split_ = split; }
    const NormalSplit& normal_split() const { return normal_split_; }

    /// Whether draw() and the ID pass skip back faces for this camera: back_faces_hidden()
    /// (camera.h) for the uploaded mesh. The bare draw never culls.
    bool culls_back_faces(const Camera& camera) const;

private:
    /// A triangle corner's surface colour data (attributes 8-11), kept only for a mesh with
    /// texture coordinates, colours or materials.
    struct SurfaceCorner {
        float uv[2];               ///< h:texcoord
        std::uint8_t colour[4];    ///< v:color, else f:color (sRGB bytes as the file had)
        std::uint8_t material[4];  ///< the face's material colour and opacity
        float layer;               ///< its texture's layer in the texture array, or -1
    };

    void ensure_gl_objects();
    /// The surface data of every triangle (after upload's fans), and the textures.
    void fill_surface(const Mesh& mesh);
    /// The properties the surface data comes from, looked up once per pass (by name).
    struct SurfaceSources {
        HalfedgeProperty<Vec2> uv;
        VertexProperty<Vec4> vertex_colour;
        FaceProperty<Vec4> face_colour;
        FaceProperty<std::uint32_t> material;
        HalfedgeProperty<Vec2> uv1;  ///< the second set, for materials whose texture reads it
    };
    static SurfaceSources surface_sources(const Mesh& mesh);
    void write_surface_triangle(const Mesh& mesh, const SurfaceSources& sources, std::size_t t);
    /// Loads the materials' textures into one texture array when their paths changed.
    void load_textures(const std::vector<Material>& materials);
    /// Binds the surface data for draw() (attributes 8-11 and texture unit 3).
    void bind_surface(const ShaderProgram& shader, SurfaceColor color);
    void fill_geometry(const Mesh& mesh);
    /// Appends face f's fan triangles to the staging arrays.
    void append_fan(const Mesh& mesh, Face f);
    /// Writes f's fan into triangles [first, first + slots) of the staging arrays, the rest
    /// degenerate (all of them when f is deleted or out of range).
    void write_fan(const Mesh& mesh, Face f, std::size_t first, std::size_t slots);
    /// Fills triangle t's GPU vertices from the staging arrays and the normals.
    void write_gpu_triangle(const Mesh& mesh, std::size_t t);
    /// The mesh program for a shading mode and wireframe switch, compiled on first use.
    const ShaderProgram& shaded_program(int mode, bool wireframe);
    ShaderProgram build_program(int mode, bool wireframe) const;
    void set_culling(const Camera& camera) const;

    std::array<ShaderProgram, 2 * kShadingModes.size()> shaded_programs_;  ///< [2 * mode + wire]
    ShaderProgram pick_shader_;
    ShaderProgram bare_shader_;  ///< loaded on the first draw_bare()
    unsigned vao_ = 0;
    unsigned vbo_ = 0;
    unsigned pick_tbo_buffer_ = 0;
    unsigned pick_tbo_texture_ = 0;
    std::size_t vbo_capacity_ = 0;    ///< bytes allocated in vbo_
    std::size_t pick_capacity_ = 0;   ///< bytes allocated in pick_tbo_buffer_
    std::size_t triangle_count_ = 0;  ///< in the buffers, degenerate slots included
    std::size_t live_triangles_ = 0;
    bool closed_and_outward_ = false;  ///< is_closed_and_outward(), set by upload and
                                       ///< update_geometry
    BoundingBox bounds_;               ///< of the live vertices (same)

    // CPU staging, kept between uploads for their capacity; big arrays grow by moving their
    // pages (memory.h), not by a copy: the first split after loading 10M faces copied them all.
    memory::Array<MeshGpuVertex> vertices_;
    memory::Array<std::uint32_t> pick_table_;  ///< 8 uints per triangle: f, v0..2, h0..2, 0
    std::vector<Vec3> vertex_normals_;
    std::vector<Vec3> face_normals_;
    memory::Array<std::uint32_t> triangle_corners_;  ///< 3 vertex indices per triangle
    /// The halfedge entering each corner in its face (names its corner normal).
    memory::Array<std::uint32_t> corner_halfedges_;
    std::vector<Vec3> corner_normals_;  ///< by halfedge, when some edge splits
    NormalSplit normal_split_;
    unsigned color_vbo_ = 0;                      ///< RGBA8 per corner, attribute 4
    std::size_t color_capacity_ = 0;              ///< bytes allocated in color_vbo_
    memory::Array<std::uint32_t> corner_colors_;  ///< staging, RGBA8 per corner
    bool has_field_ = false;
    unsigned side_color_vbo_ = 0;  ///< an edge field: 3 × RGBA8 per corner, attributes 5-7
    std::size_t side_color_capacity_ = 0;
    memory::Array<std::uint32_t> side_colors_;
    bool has_edge_field_ = false;
    unsigned env_texture_ = 0;  ///< mode 7's environment, 0 until needed
    unsigned env_cube_ = 0;     ///< the same as a cube map (mode 7 samples it)
    std::filesystem::path user_shader_dir_;
    std::string user_shader_error_;
    memory::Array<std::uint32_t> triangle_faces_;  ///< face index per triangle
    /// Each face's slot of triangles (first, count), by face index; count 0 for a deleted face.
    memory::Array<std::uint32_t> face_first_;
    memory::Array<std::uint32_t> face_slots_;
    /// vertices_size() and faces_size() when vertex_normals_ were last brought up to date.
    std::pair<std::size_t, std::size_t> normals_sizes_{0, 0};
    bool split_normals_ = false;  ///< corner normals in use (some edge splits)

    // Surface colours (mesh_surface.cpp).
    memory::Array<SurfaceCorner> surface_;  ///< 3 per triangle; empty without surface data
    unsigned surface_vbo_ = 0;
    std::size_t surface_capacity_ = 0;
    bool has_texcoords_ = false;
    bool has_colours_ = false;  ///< vertex or face colours
    bool several_material_colours_ = false;
    bool has_materials_ = false;
    unsigned texture_array_ = 0;
    std::vector<std::string> texture_paths_;  ///< what texture_array_ holds, by material
    std::vector<float> material_layers_;      ///< each material's layer, or -1
    bool has_texture_ = false;                ///< some layer loaded
    std::vector<std::string> texture_notes_;
};

}  // namespace meshedit
