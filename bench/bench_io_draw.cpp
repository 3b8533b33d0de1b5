// bench_io_draw: COLLADA and PLY loading against Assimp, and headless drawing against a bare draw
// of the same buffers (bench/README.md). One (job, impl) per process, so page faults count:
//
//   bench_io_draw --job collada_load_1m_triangles --impl meshedit|assimp [--runs N] [--data DIR]
//   bench_io_draw --job collada_load_1m_polylist  --impl meshedit|assimp [--runs N] [--data DIR]
//   bench_io_draw --job ply_load_1m_binary        --impl meshedit|assimp [--runs N] [--data DIR]
//   bench_io_draw --job stl_load_1m_binary        --impl meshedit|assimp [--runs N] [--data DIR]
//   bench_io_draw --job ply_load_10m_binary       --impl meshedit|assimp [--runs N] [--data DIR]
//   bench_io_draw --job first_frame_10m [--impl meshedit] [--runs N] [--size WxH] [--data DIR]
//   bench_io_draw --job draw_1m_triangles [--impl all] [--runs N] [--size WxH] [--samples S]
//   bench_io_draw --job pick_1m|pick_10m [--impl all] [--positions N] [--size WxH]
//   bench_io_draw --generate [--data DIR]     writes the COLLADA and PLY inputs (untimed,
//                                             idempotent)
//   bench_io_draw --list                      prints "JOB IMPL" per configuration
//
// The inputs are generated, never committed: shapes::torus(1000, 500) (500,000 vertices,
// 1,000,000 triangles) as a COLLADA <triangles> file (~34 MB) and as a <polylist> with one
// normal per face (NORMAL at offset 1, so every corner has two indices), and as a binary
// little-endian PLY as scanners write it (float x y z, `list uchar int vertex_indices`,
// ~18 MB), and as binary STL (each triangle its three corners and its normal, as every STL
// file is: the loaders weld equal corners; ~50 MB); and torus(2500, 2000), 10M triangles, as
// the same binary PLY (~190 MB) for ply_load_10m_binary and first_frame_10m (the read, the
// GPU upload and one shaded 1280x800 frame: opening the file in the viewer). The draw job renders
// the same torus at 1280x800 in one headless context (EGL, else OSMesa): N frames through
// MeshRenderer::draw (smooth Blinn-Phong; back faces culled, as the torus is closed and outward)
// and N through MeshRenderer::draw_bare (transform-only shader, same vertex buffer, back faces
// drawn), and, for reference, N bare draws with back faces culled too; glFinish after each frame,
// and a RESULT line for each of the three. The pick job picks at the same random cursor positions
// on that torus with the ID pass (MeshRenderer::pick) and on the CPU (cpu_pick, a ray into a
// FaceBvh), one position after the other, and prints a RESULT line for each.

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <GL/gl.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "../src/headless/gl_context.h"
#include "bench_util.h"
#include "meshedit/core/face_bvh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/shapes.h"
#include "meshedit/io/io.h"
#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/cpu_pick.h"
#include "meshedit/overlay/shading.h"
#include "meshedit/render/mesh_renderer.h"
#include "meshedit/render/overlay_renderer.h"
#include "meshedit/render/render_target.h"

namespace {

namespace fs = std::filesystem;
using namespace meshedit;

constexpr int kTorusRing = 1000;  // 1000 x 500 torus: 500,000 vertices, 1,000,000 triangles
constexpr int kTorusTube = 500;

const char* const kTrianglesFile = "torus_1m_triangles.dae";
const char* const kPolylistFile = "torus_1m_polylist.dae";
const char* const kPlyFile = "torus_1m_binary.ply";
// torus(2500, 2000): 5,000,000 vertices, 10,000,000 triangles (~190 MB; issue 38's 10M rows).
const char* const kPly10mFile = "torus_10m_binary.ply";
const char* const kStlFile = "torus_1m_binary.stl";

/// A growing text buffer with fast number formatting (std::to_chars, shortest round trip).
class Writer {
public:
    void text(std::string_view s) { out_.append(s); }
    void number(float v) {
        char buf[32];
        const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
        out_.append(buf, end);
    }
    void number(std::uint32_t v) {
        char buf[16];
        const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
        out_.append(buf, end);
    }
    void space() { out_.push_back(' '); }
    /// Writes the buffer to `tmp`, then renames it to `path` (no partial inputs on a crash).
    void save(const fs::path& path) const {
        const fs::path tmp = path.string() + ".tmp";
        std::FILE* f = std::fopen(tmp.c_str(), "wb");
        if (f == nullptr || std::fwrite(out_.data(), 1, out_.size(), f) != out_.size() ||
            std::fclose(f) != 0) {
            throw std::runtime_error("cannot write " + tmp.string());
        }
        fs::rename(tmp, path);
    }
    std::size_t size() const { return out_.size(); }

private:
    std::string out_;
};

void write_source(Writer& w, std::string_view id, const std::vector<float>& xyz) {
    const auto count = static_cast<std::uint32_t>(xyz.size());
    w.text("        <source id=\"");
    w.text(id);
    w.text("\">\n          <float_array id=\"");
    w.text(id);
    w.text("-array\" count=\"");
    w.number(count);
    w.text("\">");
    for (std::size_t i = 0; i < xyz.size(); ++i) {
        if (i > 0) {
            w.space();
        }
        w.number(xyz[i]);
    }
    w.text("</float_array>\n          <technique_common>\n            <accessor source=\"#");
    w.text(id);
    w.text("-array\" count=\"");
    w.number(count / 3);
    w.text(
        "\" stride=\"3\">\n"
        "              <param name=\"X\" type=\"float\"/>\n"
        "              <param name=\"Y\" type=\"float\"/>\n"
        "              <param name=\"Z\" type=\"float\"/>\n"
        "            </accessor>\n          </technique_common>\n        </source>\n");
}

/// The torus as COLLADA 1.4.1: <triangles> (positions only) or <polylist> (vcount 3, one
/// normal per face at offset 1).
void write_torus(const Mesh& mesh, const fs::path& path, bool polylist) {
    std::vector<float> positions;
    positions.reserve(3 * mesh.n_vertices());
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        positions.insert(positions.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                                           static_cast<float>(p.z)});
    }
    std::vector<std::uint32_t> corners;
    std::vector<float> normals;
    corners.reserve(3 * mesh.n_faces());
    for (Face f : mesh.faces()) {
        const Halfedge h0 = mesh.halfedge(f);
        const Halfedge h1 = mesh.next(h0);
        const Halfedge h2 = mesh.next(h1);
        for (Halfedge h : {h0, h1, h2}) {
            corners.push_back(mesh.to_vertex(h).idx());
        }
        if (polylist) {
            const Vec3 a = mesh.position(mesh.to_vertex(h0));
            const Vec3 n = normalize(cross(mesh.position(mesh.to_vertex(h1)) - a,
                                           mesh.position(mesh.to_vertex(h2)) - a));
            normals.insert(normals.end(), {static_cast<float>(n.x), static_cast<float>(n.y),
                                           static_cast<float>(n.z)});
        }
    }
    const auto n_faces = static_cast<std::uint32_t>(corners.size() / 3);

    Writer w;
    w.text(
        "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
        "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
        "  <asset>\n    <unit name=\"meter\" meter=\"1\"/>\n    <up_axis>Y_UP</up_axis>\n"
        "  </asset>\n  <library_geometries>\n    <geometry id=\"mesh\" name=\"mesh\">\n"
        "      <mesh>\n");
    write_source(w, "mesh-positions", positions);
    if (polylist) {
        write_source(w, "mesh-normals", normals);
    }
    w.text(
        "        <vertices id=\"mesh-vertices\">\n"
        "          <input semantic=\"POSITION\" source=\"#mesh-positions\"/>\n"
        "        </vertices>\n");
    w.text(polylist ? "        <polylist count=\"" : "        <triangles count=\"");
    w.number(n_faces);
    w.text("\">\n          <input semantic=\"VERTEX\" source=\"#mesh-vertices\" offset=\"0\"/>\n");
    if (polylist) {
        w.text(
            "          <input semantic=\"NORMAL\" source=\"#mesh-normals\" offset=\"1\"/>\n"
            "          <vcount>");
        for (std::uint32_t f = 0; f < n_faces; ++f) {
            w.text(f == 0 ? "3" : " 3");
        }
        w.text("</vcount>\n");
    }
    w.text("          <p>");
    for (std::size_t i = 0; i < corners.size(); ++i) {
        if (i > 0) {
            w.space();
        }
        w.number(corners[i]);
        if (polylist) {
            w.space();
            w.number(static_cast<std::uint32_t>(i / 3));
        }
    }
    w.text(polylist ? "</p>\n        </polylist>\n" : "</p>\n        </triangles>\n");
    w.text(
        "      </mesh>\n    </geometry>\n  </library_geometries>\n"
        "  <library_visual_scenes>\n    <visual_scene id=\"scene\" name=\"scene\">\n"
        "      <node id=\"node\" name=\"mesh\">\n        <instance_geometry url=\"#mesh\"/>\n"
        "      </node>\n    </visual_scene>\n  </library_visual_scenes>\n"
        "  <scene>\n    <instance_visual_scene url=\"#scene\"/>\n  </scene>\n</COLLADA>\n");
    w.save(path);
    std::fprintf(stderr, "bench_io_draw: wrote %s (%.1f MB)\n", path.c_str(),
                 static_cast<double>(w.size()) / 1e6);
}

/// The torus as binary little-endian PLY: float x y z, `list uchar int vertex_indices`.
void write_ply_torus(const Mesh& mesh, const fs::path& path) {
    Writer w;
    w.text("ply\nformat binary_little_endian 1.0\ncomment bench_io_draw torus\nelement vertex ");
    w.number(static_cast<std::uint32_t>(mesh.n_vertices()));
    w.text("\nproperty float x\nproperty float y\nproperty float z\nelement face ");
    w.number(static_cast<std::uint32_t>(mesh.n_faces()));
    w.text("\nproperty list uchar int vertex_indices\nend_header\n");
    auto put = [&w](const auto& value) {  // the host is little-endian (x86-64, arm64)
        w.text(std::string_view(reinterpret_cast<const char*>(&value), sizeof value));
    };
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        put(static_cast<float>(p.x));
        put(static_cast<float>(p.y));
        put(static_cast<float>(p.z));
    }
    for (Face f : mesh.faces()) {
        put(std::uint8_t{3});
        const Halfedge h0 = mesh.halfedge(f);
        for (Halfedge h : {h0, mesh.next(h0), mesh.next(mesh.next(h0))}) {
            put(static_cast<std::int32_t>(mesh.to_vertex(h).idx()));
        }
    }
    w.save(path);
    std::fprintf(stderr, "bench_io_draw: wrote %s (%.1f MB)\n", path.c_str(),
                 static_cast<double>(w.size()) / 1e6);
}

/// The torus as binary STL: an 80-byte header, the count, then per triangle its normal, its
/// three corners (float) and a zero attribute word.
void write_stl_torus(const Mesh& mesh, const fs::path& path) {
    Writer w;
    w.text(std::string(80, ' '));
    auto put = [&w](const auto& value) {  // the host is little-endian (x86-64, arm64)
        w.text(std::string_view(reinterpret_cast<const char*>(&value), sizeof value));
    };
    put(static_cast<std::uint32_t>(mesh.n_faces()));
    const auto put_vec = [&](const Vec3& p) {
        put(static_cast<float>(p.x));
        put(static_cast<float>(p.y));
        put(static_cast<float>(p.z));
    };
    for (Face f : mesh.faces()) {
        put_vec(face_normal(mesh, f));
        const Halfedge h0 = mesh.halfedge(f);
        for (Halfedge h : {h0, mesh.next(h0), mesh.next(mesh.next(h0))}) {
            put_vec(mesh.position(mesh.to_vertex(h)));
        }
        put(std::uint16_t{0});
    }
    w.save(path);
    std::fprintf(stderr, "bench_io_draw: wrote %s (%.1f MB)\n", path.c_str(),
                 static_cast<double>(w.size()) / 1e6);
}

/// Writes the missing inputs into `data`.
void generate(const fs::path& data) {
    fs::create_directories(data);
    if (!fs::exists(data / kPly10mFile)) {
        write_ply_torus(shapes::torus(2500, 2000), data / kPly10mFile);
    }
    const bool need_tri = !fs::exists(data / kTrianglesFile);
    const bool need_poly = !fs::exists(data / kPolylistFile);
    const bool need_ply = !fs::exists(data / kPlyFile);
    const bool need_stl = !fs::exists(data / kStlFile);
    if (!need_tri && !need_poly && !need_ply && !need_stl) {
        return;
    }
    const Mesh torus = shapes::torus(kTorusRing, kTorusTube);
    if (need_tri) {
        write_torus(torus, data / kTrianglesFile, false);
    }
    if (need_poly) {
        write_torus(torus, data / kPolylistFile, true);
    }
    if (need_ply) {
        write_ply_torus(torus, data / kPlyFile);
    }
    if (need_stl) {
        write_stl_torus(torus, data / kStlFile);
    }
}

/// The input of a load job.
const char* input_of(const std::string& job) {
    return job == "collada_load_1m_triangles" ? kTrianglesFile
           : job == "ply_load_1m_binary"      ? kPlyFile
           : job == "ply_load_10m_binary"     ? kPly10mFile
           : job == "first_frame_10m"         ? kPly10mFile
           : job == "stl_load_1m_binary"      ? kStlFile
                                              : kPolylistFile;
}

void bench_load(const std::string& job, const std::string& impl, int runs, const fs::path& data) {
    const fs::path file = data / input_of(job);
    if (!fs::exists(file)) {
        // Generating here inflates this process's peak RSS; run_bench.py runs --generate first.
        std::fprintf(stderr, "bench_io_draw: %s missing, generating (peak RSS includes it)\n",
                     file.c_str());
        generate(data);
    }
    const double file_mb = static_cast<double>(fs::file_size(file)) / 1e6;
    double faces_out = 0;
    double vertices_out = 0;
    double bytes_moved = 0;
    double extra_rss_per_face = 0;
    std::vector<double> ms;
    if (impl == "meshedit") {
        std::optional<LoadedMesh> loaded;
        ms = bench::time_runs(
            runs, [&] { loaded.reset(); }, [&] { loaded.emplace(read_mesh(file)); });
        faces_out = static_cast<double>(loaded->mesh.n_faces());
        vertices_out = static_cast<double>(loaded->mesh.n_vertices());
        // The compulsory traffic (the report's bandwidth section): the file's bytes read once,
        // the mesh's arrays written once.
        bytes_moved = static_cast<double>(fs::file_size(file) + loaded->mesh.bytes());
        // The process's peak over the faces: what a face costs once loaded (and while loading).
        extra_rss_per_face = bench::peak_rss_mb() * 1e6 / faces_out;
    } else if (impl == "assimp") {
        std::unique_ptr<Assimp::Importer> importer;
        const aiScene* scene = nullptr;
        ms = bench::time_runs(
            runs, [&] { importer = std::make_unique<Assimp::Importer>(); },
            [&] {
                scene = importer->ReadFile(file.string(),
                                           aiProcess_JoinIdenticalVertices | aiProcess_Triangulate);
            });
        if (scene == nullptr) {
            throw std::runtime_error("Assimp: " + std::string(importer->GetErrorString()));
        }
        for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
            faces_out += scene->mMeshes[i]->mNumFaces;
            vertices_out += scene->mMeshes[i]->mNumVertices;
        }
    } else {
        throw std::invalid_argument("unknown impl '" + impl + "' for " + job +
                                    " (meshedit, assimp)");
    }
    std::map<std::string, double> extra = {{"peak_rss_mb", bench::peak_rss_mb()},
                                           {"faces_out", faces_out},
                                           {"vertices_out", vertices_out},
                                           {"file_mb", file_mb},
                                           {"mb_per_s", file_mb / (bench::median_of(ms) / 1000.0)}};
    if (bytes_moved > 0) {
        extra["bytes_moved"] = bytes_moved;
    }
    if (extra_rss_per_face > 0) {
        extra["peak_rss_bytes_per_face"] = extra_rss_per_face;
    }
    bench::print_result(job, impl, ms, extra);
}

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

/// What opening a file in the viewer costs until its first frame is on screen, headless: the
/// read (parse and halfedge build), the upload of the GPU buffers and one shaded frame, with
/// glFinish. The GL context is made once, before (a window's, not the file's, cost).
void bench_first_frame(const std::string& job, const std::string& impl, int runs, int width,
                       int height, const fs::path& data) {
    if (impl != "meshedit") {
        throw std::invalid_argument("unknown impl '" + impl + "' for " + job + " (meshedit)");
    }
    const fs::path file = data / input_of(job);
    if (!fs::exists(file)) {
        throw std::runtime_error(file.string() + " missing: run bench_io_draw --generate");
    }
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const auto gl = headless::make_context({.width = width, .height = height});
    const headless::GlContext& context = *gl;
    RenderTarget target(width, height, 1);
    target.bind();
    BackgroundRenderer background;
    std::optional<LoadedMesh> loaded;
    std::optional<MeshRenderer> renderer;
    double faces = 0;
    const std::vector<double> ms = bench::time_runs(
        runs,
        [&] {
            renderer.reset();
            loaded.reset();
        },
        [&] {
            loaded.emplace(read_mesh(file));
            Camera camera;
            camera.frame_mesh(loaded->mesh, aspect);
            renderer.emplace();
            renderer->upload(loaded->mesh);
            background.draw(kBackgroundTop, kBackgroundBottom);
            renderer->draw(camera, aspect, RenderOptions{});
            context.finish();
        });
    faces = static_cast<double>(loaded->mesh.n_faces());
    if (glGetError() != GL_NO_ERROR) {
        throw std::runtime_error("GL error in the first frame");
    }
    bench::print_result(job, impl, ms,
                        {{"faces", faces},
                         {"peak_rss_mb", bench::peak_rss_mb()},
                         {"peak_rss_bytes_per_face", bench::peak_rss_mb() * 1e6 / faces}});
}

void bench_draw(const std::string& job, const std::string& impl, int runs, int width, int height,
                int samples) {
    if (impl != "all" && impl != "meshedit" && impl != "bare") {
        throw std::invalid_argument("unknown impl '" + impl + "' for " + job +
                                    " (all, meshedit, bare: one run measures both)");
    }
    const Mesh mesh = shapes::torus(kTorusRing, kTorusTube);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    Camera camera;
    camera.azimuth_deg = 30.0f;
    camera.elevation_deg = 20.0f;
    camera.frame_mesh(mesh, aspect);

    const auto gl = headless::make_context({.width = width, .height = height});
    const headless::GlContext& context = *gl;
    RenderTarget target(width, height, samples);
    target.bind();
    BackgroundRenderer background;
    MeshRenderer renderer;
    RenderOptions options;  // smooth Blinn-Phong ("phong", mode 1)
    const auto upload_start = std::chrono::steady_clock::now();
    renderer.upload(mesh);
    context.finish();
    const double upload_ms = ms_since(upload_start);
    std::printf("INFO gl_renderer: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));

    auto shaded = [&] {
        background.draw(kBackgroundTop, kBackgroundBottom);
        renderer.draw(camera, aspect, options);
        context.finish();
    };
    auto bare = [&] {
        background.draw(kBackgroundTop, kBackgroundBottom);
        renderer.draw_bare(camera, aspect);
        context.finish();
    };
    // For reference: the bare draw with back faces culled as draw() culls them here.
    const bool culls = renderer.culls_back_faces(camera);
    auto bare_culled = [&] {
        background.draw(kBackgroundTop, kBackgroundBottom);
        renderer.draw_bare(camera, aspect, culls);
        context.finish();
    };
    // One warm-up frame each (shader compilation, first-touch of the buffers), then the
    // timed frames interleaved so drift in machine load hits both alike.
    shaded();
    bare();
    bare_culled();
    std::vector<double> shaded_ms, bare_ms, bare_culled_ms;
    for (int i = 0; i < runs; ++i) {
        auto start = std::chrono::steady_clock::now();
        shaded();
        shaded_ms.push_back(ms_since(start));
        start = std::chrono::steady_clock::now();
        bare();
        bare_ms.push_back(ms_since(start));
        start = std::chrono::steady_clock::now();
        bare_culled();
        bare_culled_ms.push_back(ms_since(start));
    }
    if (glGetError() != GL_NO_ERROR) {
        throw std::runtime_error("GL error while drawing");
    }
    const auto triangles = static_cast<double>(renderer.triangle_count());
    const std::map<std::string, double> common = {{"triangles", triangles},
                                                  {"width", static_cast<double>(width)},
                                                  {"height", static_cast<double>(height)},
                                                  {"samples", target.samples()}};
    auto with = [&](std::map<std::string, double> extra) {
        extra.insert(common.begin(), common.end());
        extra["peak_rss_mb"] = bench::peak_rss_mb();
        return extra;
    };
    bench::print_result(job, "meshedit", shaded_ms,
                        with({{"upload_ms", upload_ms}, {"culls_back_faces", culls ? 1.0 : 0.0}}));
    bench::print_result(job, "bare", bare_ms, with({}));
    bench::print_result(job, "bare_culled", bare_culled_ms,
                        with({{"culls_back_faces", culls ? 1.0 : 0.0}}));
}

/// The nearest-rank percentile `q` (0 … 1) of `v`.
double percentile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
    return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

void bench_pick(const std::string& job, const std::string& impl, int positions, int width,
                int height) {
    if (impl != "all" && impl != "id_pass" && impl != "bvh") {
        throw std::invalid_argument("unknown impl '" + impl + "' for " + job +
                                    " (all, id_pass, bvh: one run measures both)");
    }
    const Mesh mesh =
        job == "pick_10m" ? shapes::torus(2500, 2000) : shapes::torus(kTorusRing, kTorusTube);
    Camera camera;
    camera.azimuth_deg = 30.0f;
    camera.elevation_deg = 20.0f;
    camera.frame_mesh(mesh, static_cast<float>(width) / static_cast<float>(height));

    const auto gl = headless::make_context({.width = width, .height = height});
    const headless::GlContext& context = *gl;
    RenderTarget target(width, height, 1);  // the viewer's pick target: one sample
    target.bind();
    MeshRenderer renderer;
    renderer.upload(mesh);
    context.finish();
    std::printf("INFO gl_renderer: %s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)));
    const bool cull = renderer.culls_back_faces(camera);

    // The BVH: built 5 times (a fresh object each time), the last one kept.
    std::vector<double> build_ms;
    std::optional<FaceBvh> bvh;
    for (int i = 0; i < 5; ++i) {
        bvh.reset();
        const auto start = std::chrono::steady_clock::now();
        bvh.emplace(mesh);
        build_ms.push_back(ms_since(start));
    }

    // Random pixels on the torus (where the CPU pick finds something), fixed seed.
    std::mt19937 rng(20);
    std::uniform_int_distribution<int> px(0, width - 1), py(0, height - 1);
    std::vector<std::pair<int, int>> at;
    while (static_cast<int>(at.size()) < positions) {
        const int x = px(rng), y = py(rng);
        if (!cpu_pick(*bvh, mesh, camera, width, height, x, y, cull).is_none()) {
            at.emplace_back(x, y);
        }
    }
    (void)renderer.pick(camera, width, height, at[0].first, at[0].second);  // compiles pick.frag
    std::vector<double> id_ms, bvh_ms;
    int same = 0;
    for (const auto& [x, y] : at) {
        auto start = std::chrono::steady_clock::now();
        const ElementRef gpu = renderer.pick(camera, width, height, x, y);  // reads back: waits
        id_ms.push_back(ms_since(start));
        start = std::chrono::steady_clock::now();
        const ElementRef cpu = cpu_pick(*bvh, mesh, camera, width, height, x, y, cull);
        bvh_ms.push_back(ms_since(start));
        same += gpu == cpu ? 1 : 0;
    }
    if (glGetError() != GL_NO_ERROR) {
        throw std::runtime_error("GL error while picking");
    }
    const auto extras = [&](const std::vector<double>& ms) {
        return std::map<std::string, double>{
            {"p50_ms", percentile(ms, 0.5)},
            {"p99_ms", percentile(ms, 0.99)},
            {"max_ms", percentile(ms, 1.0)},
            {"positions", static_cast<double>(at.size())},
            {"triangles", static_cast<double>(renderer.triangle_count())},
            {"width", static_cast<double>(width)},
            {"height", static_cast<double>(height)},
            {"culls_back_faces", cull ? 1.0 : 0.0},
            {"peak_rss_mb", bench::peak_rss_mb()}};
    };
    bench::print_result(job, "id_pass", id_ms, extras(id_ms));
    auto bvh_extras = extras(bvh_ms);
    bvh_extras["build_ms"] = bench::median_of(build_ms);
    bvh_extras["build_min_ms"] = bench::min_of(build_ms);
    bvh_extras["same_answer"] = same;
    bench::print_result(job, "bvh", bvh_ms, bvh_extras);
}

struct Args {
    std::string job;
    std::string impl;
    int runs = 5;
    fs::path data;
    bool generate = false;
    bool list = false;
    int width = 1280;
    int height = 800;
    int samples = 4;      // meshedit-render's default
    int positions = 200;  // the pick job's cursor positions
};

int to_int(const std::string& s, const char* what) {
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size()) {
        throw std::invalid_argument(std::string("bad ") + what + " '" + s + "'");
    }
    return v;
}

Args parse(int argc, char** argv) {
    Args a;
    a.data = fs::path(argv[0]).parent_path() / "data";
    std::vector<std::string> args(argv + 1, argv + argc);
    auto value = [&](std::size_t& i) -> const std::string& {
        if (i + 1 >= args.size()) {
            throw std::invalid_argument(args[i] + " needs a value");
        }
        return args[++i];
    };
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& s = args[i];
        if (s == "--job") {
            a.job = value(i);
        } else if (s == "--impl") {
            a.impl = value(i);
        } else if (s == "--runs") {
            a.runs = to_int(value(i), "run count");
        } else if (s == "--data") {
            a.data = value(i);
        } else if (s == "--generate") {
            a.generate = true;
        } else if (s == "--list") {
            a.list = true;
        } else if (s == "--size") {
            const std::string& v = value(i);
            const auto x = v.find('x');
            if (x == std::string::npos) {
                throw std::invalid_argument("--size wants WxH");
            }
            a.width = to_int(v.substr(0, x), "width");
            a.height = to_int(v.substr(x + 1), "height");
        } else if (s == "--samples") {
            a.samples = to_int(value(i), "samples");
        } else if (s == "--positions") {
            a.positions = to_int(value(i), "position count");
        } else {
            throw std::invalid_argument("unknown argument '" + s + "'");
        }
    }
    if (a.runs < 1 || a.positions < 1) {
        throw std::invalid_argument("--runs and --positions must be positive");
    }
    return a;
}

}  // namespace

int main(int argc, char** argv) {
    meshedit::bench::take_common_flags(argc, argv);
    try {
        const Args a = parse(argc, argv);
        if (a.list) {
            for (const char* job :
                 {"collada_load_1m_triangles", "collada_load_1m_polylist", "ply_load_1m_binary",
                  "stl_load_1m_binary", "ply_load_10m_binary"}) {
                std::printf("%s meshedit\n%s assimp\n", job, job);
            }
            std::printf(
                "draw_1m_triangles all\npick_1m all\npick_10m all\n"
                "first_frame_10m meshedit\n");
            return 0;
        }
        if (a.generate) {
            generate(a.data);
            return 0;
        }
        if (a.job == "collada_load_1m_triangles" || a.job == "collada_load_1m_polylist" ||
            a.job == "ply_load_1m_binary" || a.job == "stl_load_1m_binary" ||
            a.job == "ply_load_10m_binary") {
            bench_load(a.job, a.impl, a.runs, a.data);
        } else if (a.job == "first_frame_10m") {
            bench_first_frame(a.job, a.impl.empty() ? "meshedit" : a.impl, a.runs, a.width,
                              a.height, a.data);
        } else if (a.job == "draw_1m_triangles") {
            bench_draw(a.job, a.impl.empty() ? "all" : a.impl, a.runs, a.width, a.height,
                       a.samples);
        } else if (a.job == "pick_1m" || a.job == "pick_10m") {
            bench_pick(a.job, a.impl.empty() ? "all" : a.impl, a.positions, a.width, a.height);
        } else {
            throw std::invalid_argument(
                "unknown job '" + a.job +
                "' (collada_load_1m_triangles, collada_load_1m_polylist, "
                "ply_load_1m_binary, stl_load_1m_binary, "
                "ply_load_10m_binary, draw_1m_triangles, pick_1m, pick_10m, "
                "first_frame_10m; or --list, --generate)");
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_io_draw: %s\n", e.what());
        return 2;
    }
    return 0;
}
