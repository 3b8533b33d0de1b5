// The surface colours of the mesh renderer (mesh_renderer.h): texture coordinates, vertex and
// face colours and material colours per triangle corner, and the materials' base-colour
// textures in one texture array, so one draw call shows every material.

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "gl.h"
#include "mesh_gpu.h"
#include "meshedit/core/attributes.h"
#include "meshedit/render/mesh_renderer.h"

namespace meshedit {
namespace {

namespace OIIO = OIIO_NAMESPACE;

// The texture array's layers are square and of one size: the largest texture's longer side,
// at most this, halved until all layers fit the memory cap (textures are resampled to it).
constexpr int kMaxTextureSide = 2048;
constexpr std::size_t kMaxTextureBytes = std::size_t{256} << 20;
// Larger images are not read at all (a 100000 × 100000 texture would need 40 GB; this many
// pixels take 256 MB as RGBA8, twice while they are converted).
constexpr long long kMaxTexturePixels = 8192LL * 8192LL;

std::uint8_t byte_of(double x) {
    return static_cast<std::uint8_t>(
        std::lround(255.0 * std::clamp(std::isnan(x) ? 0.0 : x, 0.0, 1.0)));
}

// OpenImageIO's message as one line.
std::string one_line(std::string message) {
    for (char& c : message) {
        c = c == '\n' ? ';' : c;
    }
    return message;
}

// Reads `path` (or, for an image a file embedded, its `bytes`; the path only names it) as
// RGBA8, rows top first; empty with `why` set when it cannot.
OIIO::ImageBuf read_rgba(const std::string& path, const std::string& bytes, std::string& why) {
    std::error_code ec;
    if (bytes.empty() && !std::filesystem::is_regular_file(path, ec)) {
        why = std::filesystem::exists(path, ec) ? "is not a file" : "was not found";
        return {};
    }
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::open(path, nullptr, bytes.empty() ? nullptr : &memory);
    if (!in) {
        why = "is not an image OpenImageIO reads (" + one_line(OIIO::geterror()) + ")";
        return {};
    }
    const OIIO::ImageSpec spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 ||
        static_cast<long long>(spec.width) * spec.height > kMaxTexturePixels) {
        why = "is " + std::to_string(spec.width) + " × " + std::to_string(spec.height) +
              " pixels, more than MeshEdit shows (8192 × 8192)";
        return {};
    }
    const int channels = std::clamp(spec.nchannels, 1, 4);
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data())) {
        const std::string error = one_line(in->geterror());
        why = "could not be read (" + (error.empty() ? "its pixels end early" : error) + ")";
        return {};
    }
    // Grey, grey + alpha, RGB, RGBA: all to RGBA bytes in one pass.
    const std::size_t n = static_cast<std::size_t>(spec.width) * spec.height;
    std::vector<std::uint8_t> out(4 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint8_t* p = &pixels[i * channels];
        out[4 * i] = p[0];
        out[4 * i + 1] = channels >= 3 ? p[1] : p[0];
        out[4 * i + 2] = channels >= 3 ? p[2] : p[0];
        out[4 * i + 3] = channels == 4 ? p[3] : channels == 2 ? p[1] : 255;
    }
    OIIO::ImageBuf rgba(OIIO::ImageSpec(spec.width, spec.height, 4, OIIO::TypeDesc::UINT8));
    rgba.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, out.data());
    return rgba;
}

}  // namespace

SurfaceColor MeshRenderer::shown_color(SurfaceColor wanted) const {
    switch (wanted) {
        case SurfaceColor::Auto:
            if (has_texture_ && has_texcoords_) {
                return SurfaceColor::Texture;
            }
            if (has_colours_) {
                return SurfaceColor::Vertex;
            }
            return several_material_colours_ ? SurfaceColor::Material : SurfaceColor::Single;
        case SurfaceColor::Material:
            return has_materials_ ? wanted : SurfaceColor::Single;
        case SurfaceColor::Vertex:
            return has_colours_ ? wanted : SurfaceColor::Single;
        case SurfaceColor::Texture:
            // Without a texture the texture mode shows the material colours, as Blender's.
            return has_texcoords_ && has_texture_ ? wanted
                   : has_materials_               ? SurfaceColor::Material
                                                  : SurfaceColor::Single;
        case SurfaceColor::Checker:
            return has_texcoords_ ? wanted : SurfaceColor::Single;
        case SurfaceColor::Single:
            break;
    }
    return SurfaceColor::Single;
}

void MeshRenderer::fill_surface(const Mesh& mesh) {
    const auto& [uv, vertex_colour, face_colour, material, uv1] = surface_sources(mesh);
    has_texcoords_ = uv || uv1;
    has_colours_ = vertex_colour || face_colour;
    has_materials_ = material && !mesh.materials().empty();
    several_material_colours_ = false;
    if (has_materials_) {
        const std::vector<Material>& m = mesh.materials();
        for (std::size_t i = 1; i < m.size(); ++i) {
            several_material_colours_ =
                several_material_colours_ ||
                (m[i].has_base_colour && m[i].base_colour != m[0].base_colour);
        }
    }
    if (!has_texcoords_ && !has_colours_ && !has_materials_) {
        surface_.clear();
        surface_.shrink_to_fit();  // an attribute-free mesh carries none of it
        has_texture_ = false;
        texture_notes_.clear();
        return;
    }
    load_textures(has_materials_ ? mesh.materials() : std::vector<Material>{});
    surface_.resize(3 * triangle_count_);
    const SurfaceSources sources = surface_sources(mesh);
    for (std::size_t t = 0; t < triangle_count_; ++t) {
        write_surface_triangle(mesh, sources, t);
    }
    glBindBuffer(GL_ARRAY_BUFFER, surface_vbo_);
    upload_buffer(GL_ARRAY_BUFFER, surface_capacity_, surface_.data(),
                  surface_.size() * sizeof(SurfaceCorner));
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

MeshRenderer::SurfaceSources MeshRenderer::surface_sources(const Mesh& mesh) {
    return {mesh.get_property<Halfedge, Vec2>(kTexCoordProperty),
            mesh.get_property<Vertex, Vec4>(kColorProperty),
            mesh.get_property<Face, Vec4>(kFaceColorProperty),
            mesh.get_property<Face, std::uint32_t>(kMaterialProperty),
            mesh.get_property<Halfedge, Vec2>(kTexCoord1Property)};
}

void MeshRenderer::write_surface_triangle(const Mesh& mesh, const SurfaceSources& sources,
                                          std::size_t t) {
    const auto& [uv0, vertex_colour, face_colour, material, uv1] = sources;
    // The set the face's texture reads (its material's), else the one the mesh has.
    bool second = !uv0;
    const std::uint32_t f = triangle_faces_[t];
    const bool live = f < mesh.faces_size() && !mesh.is_deleted(Face(f));
    std::uint8_t material_colour[4] = {0, 0, 0, 0};  // alpha 0: none, the base colour
    float layer = -1.0f;
    if (live && material && !mesh.materials().empty()) {
        const std::uint32_t m = material[Face(f)];
        if (m < mesh.materials().size()) {
            const Material& mat = mesh.materials()[m];
            if (mat.has_base_colour) {
                material_colour[0] = byte_of(mat.base_colour.x);
                material_colour[1] = byte_of(mat.base_colour.y);
                material_colour[2] = byte_of(mat.base_colour.z);
                material_colour[3] = 255;
            }
            layer = m < material_layers_.size() ? material_layers_[m] : -1.0f;
            second = second || (mat.base_colour_texcoord == 1 && uv1);
        }
    }
    for (std::size_t k = 0; k < 3; ++k) {
        SurfaceCorner& out = surface_[3 * t + k];
        const std::uint32_t v = triangle_corners_[3 * t + k];
        const Halfedge h(corner_halfedges_[3 * t + k]);
        const HalfedgeProperty<Vec2>& uv = second ? uv1 : uv0;
        const Vec2 at = live && uv ? uv[h] : Vec2{};
        out.uv[0] = static_cast<float>(at.x);
        out.uv[1] = static_cast<float>(at.y);
        Vec4 c{1.0, 1.0, 1.0, 1.0};
        if (live && vertex_colour) {
            c = vertex_colour[Vertex(v)];
        } else if (live && face_colour) {
            c = face_colour[Face(f)];
        }
        out.colour[0] = byte_of(c.x);
        out.colour[1] = byte_of(c.y);
        out.colour[2] = byte_of(c.z);
        out.colour[3] = byte_of(c.w);
        std::copy_n(material_colour, 4, out.material);
        out.layer = layer;
    }
}

void MeshRenderer::load_textures(const std::vector<Material>& materials) {
    std::vector<std::string> paths;  // an embedded image by its size too: a cheap key
    for (const Material& m : materials) {
        paths.push_back(m.base_colour_texture +
                        (m.base_colour_texture_bytes.empty()
                             ? ""
                             : "#" + std::to_string(m.base_colour_texture_bytes.size())));
    }
    if (paths == texture_paths_ && texture_array_ != 0) {
        return;  // the same textures: an edit does not reload them
    }
    texture_paths_ = paths;
    texture_notes_.clear();
    material_layers_.assign(materials.size(), -1.0f);
    // One layer per distinct readable file.
    std::vector<std::string> files;
    std::vector<OIIO::ImageBuf> images;
    int side = 1;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const std::string& path = materials[i].base_colour_texture;
        if (path.empty()) {
            continue;
        }
        const auto known = std::find(files.begin(), files.end(), paths[i]);
        if (known != files.end()) {
            material_layers_[i] = static_cast<float>(known - files.begin());
            continue;
        }
        std::string why;
        OIIO::ImageBuf image = read_rgba(path, materials[i].base_colour_texture_bytes, why);
        if (!image.initialized()) {
            texture_notes_.push_back("the texture " + path + " of material '" + materials[i].name +
                                     "' " + why + ": its faces show the material's colour");
            continue;
        }
        side = std::max({side, image.spec().width, image.spec().height});
        material_layers_[i] = static_cast<float>(files.size());
        files.push_back(paths[i]);
        images.push_back(std::move(image));
    }
    has_texture_ = !images.empty();
    if (!has_texture_) {
        return;
    }
    side = std::min(side, kMaxTextureSide);
    while (side > 64 && images.size() * side * side * 4 > kMaxTextureBytes) {
        side /= 2;
    }
    std::vector<std::uint8_t> texels(images.size() * side * side * 4);
    for (std::size_t i = 0; i < images.size(); ++i) {
        OIIO::ImageBuf resized = images[i];
        if (resized.spec().width != side || resized.spec().height != side) {
            resized = OIIO::ImageBufAlgo::resize(images[i], "", 0.0f,
                                                 OIIO::ROI(0, side, 0, side, 0, 1, 0, 4));
        }
        resized.get_pixels(OIIO::ROI(0, side, 0, side, 0, 1, 0, 4), OIIO::TypeDesc::UINT8,
                           texels.data() + i * side * side * 4);
    }
    if (texture_array_ == 0) {
        glGenTextures(1, &texture_array_);
    }
    glBindTexture(GL_TEXTURE_2D_ARRAY, texture_array_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // sRGB texels: filtered and mipmapped in linear light, as the image meant them.
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_SRGB8_ALPHA8, side, side,
                 static_cast<GLsizei>(images.size()), 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    check_gl("MeshRenderer::load_textures");
}

void MeshRenderer::bind_surface(const ShaderProgram& shader, SurfaceColor color) {
    const SurfaceColor shown = surface_.empty() ? SurfaceColor::Single : shown_color(color);
    shader.set_int("u_surface", static_cast<int>(shown) - 1);  // Single is 0
    for (GLuint k = 8; k < 12; ++k) {
        if (surface_.empty()) {
            glDisableVertexAttribArray(k);
        } else {
            glEnableVertexAttribArray(k);
        }
    }
    if (shown == SurfaceColor::Texture) {
        glActiveTexture(GL_TEXTURE3);
        glBindTexture(GL_TEXTURE_2D_ARRAY, texture_array_);
        glActiveTexture(GL_TEXTURE0);
        shader.set_int("u_textures", 3);
    }
}

}  // namespace meshedit
