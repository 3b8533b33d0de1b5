// Box and lasso selection (region_pick.h).

#include "meshedit/overlay/region_pick.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <thread>

#include "meshedit/core/threads.h"
#include "region_shapes.h"

namespace meshedit {

namespace {

// Every vertex in clip space, once: a face's centre is then the average of its corners'
// clip coordinates (projection is linear before the division by w), so no face needs its
// own matrix product.
// The arrays are kept per thread between calls: a million-face mesh's 14 MB would otherwise
// be fresh pages at every box, whose first touch costs about as much as the pass itself.
struct Projected {
    std::vector<glm::vec4>& clip;
    std::vector<glm::vec3>& screen;     // pixels and NDC depth (when asked for)
    std::vector<std::uint8_t>& placed;  // 1 where to_screen() succeeded
    // Where each vertex lands against the region's bounding box (kFar and kNotInside bits), so that
    // most faces are decided from a byte per corner: the clip array does not fit a cache.
    std::vector<std::uint8_t>& code;
    float w = 1, h = 1;
    glm::mat4 m{1.0f};  // world to clip space

    // Pixels and NDC depth of a clip-space point; false behind the eye or outside the depth
    // range.
    bool to_screen(const glm::vec4& c, glm::vec3& out) const {
        if (c.w <= 0.0f || c.z < -c.w || c.z > c.w) {
            return false;
        }
        out = {(c.x / c.w + 1.0f) * 0.5f * w, (1.0f - c.y / c.w) * 0.5f * h, c.z / c.w};
        return true;
    }

    // Vertex v in clip space: kept, or computed again (a box through the mesh keeps none:
    // the few faces its codes leave undecided cost less than writing every vertex's).
    glm::vec4 clip_of(const Mesh& mesh, std::uint32_t v) const {
        if (!clip.empty()) {
            return clip[v];
        }
        const Vec3& x = mesh.position(Vertex(v));
        return m * glm::vec4(static_cast<float>(x.x), static_cast<float>(x.y),
                             static_cast<float>(x.z), 1.0f);
    }
};

// A corner's code: the low four bits say on which sides it lies more than kFarPixels outside
// the box (all corners of a face sharing one: the face, its centre included, lies beyond the
// box and its depth window); the high four on which sides it is not kInsidePixels inside.
// A corner that cannot be placed has only high bits: its face is decided the exact way.
constexpr float kFarPixels = 2.0f;
constexpr float kInsidePixels = 0.01f;  // far above float rounding of a centre in pixels
constexpr std::uint8_t kFar = 0x0f, kNotInside = 0xf0;

std::uint8_t code_of(bool placed, const glm::vec3& s, glm::vec2 lo, glm::vec2 hi) {
    if (!placed) {
        return kNotInside;
    }
    const auto sides = [&](float margin) {
        return static_cast<std::uint8_t>(
            (s.x < lo.x - margin ? 1 : 0) | (s.x > hi.x + margin ? 2 : 0) |
            (s.y < lo.y - margin ? 4 : 0) | (s.y > hi.y + margin ? 8 : 0));
    };
    return static_cast<std::uint8_t>(sides(kFarPixels) | (sides(-kInsidePixels) << 4));
}

Projected project_all(const Mesh& mesh, const Camera& camera, int width, int height, bool screen,
                      bool keep_clip, glm::vec2 lo, glm::vec2 hi) {
    thread_local std::vector<glm::vec4> clip;
    thread_local std::vector<glm::vec3> pixels;
    thread_local std::vector<std::uint8_t> placed;
    thread_local std::vector<std::uint8_t> code;
    Projected p{clip, pixels, placed, code};
    p.w = static_cast<float>(std::max(width, 1));
    p.h = static_cast<float>(std::max(height, 1));
    p.m = camera.projection(p.w / p.h) * camera.view();
    const glm::mat4& m = p.m;
    p.clip.resize(keep_clip ? mesh.vertices_size() : 0);
    p.code.resize(mesh.vertices_size());
    if (screen) {
        p.screen.resize(mesh.vertices_size());
        p.placed.assign(mesh.vertices_size(), 0);
    }
    for (const Vertex v : mesh.vertices()) {
        const Vec3& x = mesh.position(v);
        const glm::vec4 c = m * glm::vec4(static_cast<float>(x.x), static_cast<float>(x.y),
                                          static_cast<float>(x.z), 1.0f);
        if (keep_clip) {
            p.clip[v.idx()] = c;
        }
        glm::vec3 s;
        const bool ok = p.to_screen(c, s);
        p.code[v.idx()] = code_of(ok, s, lo, hi);
        if (screen) {
            p.screen[v.idx()] = s;
            p.placed[v.idx()] = ok ? 1 : 0;
        }
    }
    return p;
}

// The AND (low byte) and OR (high byte) of face f's corner codes.
std::uint16_t face_code(const Mesh& mesh, const Projected& p, Face f) {
    std::uint8_t all = 0xff, any = 0;
    for (const Halfedge h : mesh.halfedges(f)) {
        const std::uint8_t c = p.code[mesh.to_vertex(h).idx()];
        all &= c;
        any |= c;
    }
    return static_cast<std::uint16_t>(all | (any << 8));
}

// Runs body(first, last, k) on consecutive ranges of [0, n), one per thread k (thread_count(),
// fewer for small meshes), and returns how many ranges ran.
template <class Body>
unsigned in_ranges(std::size_t n, const Body& body) {
    const unsigned threads =
        static_cast<unsigned>(std::clamp<std::size_t>(n / 100000, 1, std::max(1u, thread_count())));
    std::vector<std::thread> pool;
    for (unsigned k = 1; k < threads; ++k) {
        pool.emplace_back([&, k] { body(n * k / threads, n * (k + 1) / threads, k); });
    }
    body(0, n / threads, 0u);
    for (std::thread& t : pool) {
        t.join();
    }
    return threads;
}

// The faces the view shows in a window of the image (the region's bounding box): for each
// pixel the nearest face at its centre and that face's depth plane in screen space (the
// triangle drawn there), as a GPU's depth and ID passes would hold them.
// What the depth pass saw of a face on its way (DepthBuffer's `look`): the sum of its corners
// in clip space, whether every corner could be placed, and its signed area on the screen
// (below zero: counter-clockwise with pixels running down, so it turns toward the eye, as
// the renderer's culling decides).
struct FaceSeen {
    glm::vec4 clip{0.0f};
    float corners = 0.0f;
    bool placed = true;
    float area = 0.0f;
};

class DepthBuffer {
public:
    /// Draws every face of the window; `look(k, f, seen)` is called for each face not beyond
    /// it and, with `cull`, not turned away (k: the thread's range), so that a caller needs no
    /// second pass over the corners.
    template <class Look>
    DepthBuffer(const Mesh& mesh, const Projected& p, glm::vec2 lo, glm::vec2 hi, bool cull,
                const Look& look)
        : x0_(std::max(0, static_cast<int>(std::floor(lo.x)))),
          y0_(std::max(0, static_cast<int>(std::floor(lo.y)))),
          x1_(std::min(static_cast<int>(p.w) - 1, static_cast<int>(std::ceil(hi.x)))),
          y1_(std::min(static_cast<int>(p.h) - 1, static_cast<int>(std::ceil(hi.y)))) {
        const std::size_t size =
            x1_ < x0_ || y1_ < y0_ ? 0 : static_cast<std::size_t>(x1_ - x0_ + 1) * (y1_ - y0_ + 1);
        // Each thread draws its range of faces into its own buffer; the nearest wins.
        // Kept per calling thread between boxes (fresh pages cost as much as drawing).
        thread_local std::vector<std::vector<Pixel>> cache;
        cache.resize(std::max<std::size_t>(cache.size(), std::max(1u, thread_count())));
        std::vector<std::vector<Pixel>>& parts = cache;  // this thread's, named in the workers
        ranges_ = in_ranges(mesh.faces_size(), [&](std::size_t first, std::size_t last,
                                                   unsigned k) {
            std::vector<Pixel>& buffer = parts[k];
            buffer.assign(size, Pixel{});
            std::vector<std::uint32_t> ids;
            for (std::size_t i = first; i < last; ++i) {
                const Face f(static_cast<std::uint32_t>(i));
                if (mesh.is_deleted(f)) {
                    continue;
                }
                const Halfedge h0 = mesh.halfedge(f), h1 = mesh.next(h0), h2 = mesh.next(h1);
                if (mesh.next(h2) == h0) {
                    // A triangle, most faces of a big mesh: the steps below without
                    // the walk and the list (the same arithmetic, in the same order).
                    const std::uint32_t a = mesh.to_vertex(h0).idx(), b = mesh.to_vertex(h1).idx(),
                                        c = mesh.to_vertex(h2).idx();
                    if ((p.code[a] & p.code[b] & p.code[c] & kFar) != 0) {
                        continue;
                    }
                    FaceSeen seen;
                    seen.corners = 3.0f;
                    seen.placed = (p.placed[a] & p.placed[b] & p.placed[c]) != 0;
                    if (seen.placed) {
                        const glm::vec3 &sa = p.screen[a], &sb = p.screen[b], &sc = p.screen[c];
                        seen.area = (sb.x - sa.x) * (sc.y - sa.y) - (sc.x - sa.x) * (sb.y - sa.y);
                        draw(buffer, f, sa, sb, sc, seen.area, cull);
                        if (cull && seen.area >= 0.0f) {
                            continue;
                        }
                    }
                    seen.clip = p.clip[a] + p.clip[b] + p.clip[c];
                    look(k, f, seen);
                    continue;
                }
                ids.clear();
                std::uint8_t all = 0xff;
                for (const Halfedge h : mesh.halfedges(f)) {
                    ids.push_back(mesh.to_vertex(h).idx());
                    all &= p.code[ids.back()];
                }
                if ((all & kFar) != 0) {
                    continue;  // beyond the window: no pixel of it to draw
                }
                FaceSeen seen;
                glm::vec3 start{}, previous{};
                for (const std::uint32_t v : ids) {
                    seen.placed = seen.placed && p.placed[v] != 0;
                    const glm::vec3& q = p.screen[v];
                    // A fan (start, previous, q); a face across the eye's plane hides
                    // nothing we can place: not drawn from there on.
                    if (seen.corners == 0.0f) {
                        start = q;
                    } else if (seen.corners >= 2.0f && seen.placed) {
                        seen.area += (previous.x - start.x) * (q.y - start.y) -
                                     (q.x - start.x) * (previous.y - start.y);
                        draw(buffer, f, start, previous, q,
                             (previous.x - start.x) * (q.y - start.y) -
                                 (q.x - start.x) * (previous.y - start.y),
                             cull);
                    }
                    previous = q;
                    seen.corners += 1.0f;
                }
                if (cull && seen.placed && seen.area >= 0.0f) {
                    continue;  // turned away where that hides it: nothing to look at
                }
                for (const std::uint32_t v : ids) {
                    seen.clip += p.clip[v];
                }
                look(k, f, seen);
            }
        });
        pixels_ = parts[0].data();
        if (ranges_ > 1) {  // the merge too by ranges (of pixels), in the same order of buffers
            in_ranges(size, [&](std::size_t first, std::size_t last, unsigned) {
                for (unsigned k = 1; k < ranges_; ++k) {
                    for (std::size_t i = first; i < last; ++i) {
                        if (parts[k][i].face != kEmpty &&
                            (pixels_[i].face == kEmpty ||
                             depth_at(parts[k][i], i) < depth_at(pixels_[i], i))) {
                            pixels_[i] = parts[k][i];
                        }
                    }
                }
            });
        }
    }

    /// How many ranges of faces (threads) the looks came from.
    unsigned ranges() const { return ranges_; }

    // Whether the view shows a point at screen position `s` (NDC depth s.z): its pixel is
    // empty, or the face nearest there is one of `own` (the point's face, a vertex's faces),
    // or that face's plane, taken at the point itself, is not nearer than the point.
    template <class Own>
    bool shows(const glm::vec3& s, const Own& own) const {
        const int x = static_cast<int>(std::floor(s.x)), y = static_cast<int>(std::floor(s.y));
        if (x < x0_ || x > x1_ || y < y0_ || y > y1_) {
            return true;
        }
        const Pixel& px = pixels_[static_cast<std::size_t>(y - y0_) * (x1_ - x0_ + 1) + (x - x0_)];
        if (px.face == kEmpty || own(Face(px.face))) {
            return true;
        }
        const float there = px.z0 + px.gx * s.x + px.gy * s.y;
        return s.z <= there + 1e-6f * (1.0f + std::abs(s.z));
    }

private:
    static constexpr std::uint32_t kEmpty = 0xffffffffu;
    struct Pixel {
        float z0 = 0, gx = 0, gy = 0;  // the plane z0 + gx x + gy y of the triangle drawn
        std::uint32_t face = kEmpty;
    };
    // The depth of the triangle drawn at pixel i of the window, at its centre.
    float depth_at(const Pixel& px, std::size_t i) const {
        const auto row = static_cast<std::size_t>(x1_ - x0_ + 1);
        const float x = static_cast<float>(x0_ + static_cast<int>(i % row)) + 0.5f;
        const float y = static_cast<float>(y0_ + static_cast<int>(i / row)) + 0.5f;
        return px.z0 + px.gx * x + px.gy * y;
    }

    // Draws triangle (a, b, c) of face f, whose signed area on the screen is `area`.
    void draw(std::vector<Pixel>& pixels, Face f, const glm::vec3& a, const glm::vec3& b,
              const glm::vec3& c, float area, bool cull) const {
        // Pixels run down the screen: a counter-clockwise (front) triangle has area < 0.
        if (area == 0.0f || !std::isfinite(area) || (cull && area > 0.0f)) {
            return;
        }
        const int xa = std::max(x0_, static_cast<int>(std::ceil(std::min({a.x, b.x, c.x}) - 0.5f)));
        const int xb =
            std::min(x1_, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}) - 0.5f)));
        const int ya = std::max(y0_, static_cast<int>(std::ceil(std::min({a.y, b.y, c.y}) - 0.5f)));
        const int yb =
            std::min(y1_, static_cast<int>(std::floor(std::max({a.y, b.y, c.y}) - 0.5f)));
        if (xa > xb || ya > yb) {
            return;  // no pixel centre inside (a sub-pixel triangle), or outside the window
        }
        // The plane z = z0 + gx x + gy y through the three corners.
        const float gx = ((b.z - a.z) * (c.y - a.y) - (c.z - a.z) * (b.y - a.y)) / area;
        const float gy = ((c.z - a.z) * (b.x - a.x) - (b.z - a.z) * (c.x - a.x)) / area;
        const float z0 = a.z - gx * a.x - gy * a.y;
        const float sign = area > 0.0f ? 1.0f : -1.0f;
        for (int y = ya; y <= yb; ++y) {
            const float py = static_cast<float>(y) + 0.5f;
            for (int x = xa; x <= xb; ++x) {
                const float px = static_cast<float>(x) + 0.5f;
                // Inside when the pixel centre is on the inner side of all three edges.
                const float e0 = sign * ((b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x));
                const float e1 = sign * ((c.x - b.x) * (py - b.y) - (c.y - b.y) * (px - b.x));
                const float e2 = sign * ((a.x - c.x) * (py - c.y) - (a.y - c.y) * (px - c.x));
                if (e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) {
                    continue;
                }
                const float z = z0 + gx * px + gy * py;
                Pixel& d = pixels[static_cast<std::size_t>(y - y0_) * (x1_ - x0_ + 1) + (x - x0_)];
                if (d.face == kEmpty || z < d.z0 + d.gx * px + d.gy * py) {
                    d = {z0, gx, gy, f.idx()};
                }
            }
        }
    }

    int x0_, y0_, x1_, y1_;
    unsigned ranges_ = 1;
    Pixel* pixels_ = nullptr;  // the first thread's buffer, the others merged into it
};

// The points of what a region selects, in increasing index order, as make(index, at): face
// centres (`faces`) or vertices, at their pixel. `in_region(pixel)` says whether a projected
// point lies inside; [lo, hi] bounds the region; `box`: the region is that box (a face whose
// corners are all inside it has its centre inside too, and is made with `at` left at zero).
// `tile` > 0: faces that the view shows come in the order of the tiles of that many pixels
// (row by row) that hold their centre, not of their index: the depth buffer is then read a
// tile at a time rather than all over.
template <class T, class InRegion, class Make>
std::vector<T> points_inside(const Mesh& mesh, const Camera& camera, int width, int height,
                             bool faces, Reach reach, glm::vec2 lo, glm::vec2 hi, bool box,
                             const InRegion& in_region, const Make& make, int tile = 0) {
    const bool need_points = reach != Reach::Through || !faces;
    const Projected p =
        project_all(mesh, camera, width, height, need_points, need_points || !box, lo, hi);
    const bool cull = reach == Reach::VisibleFrontOnly;
    std::optional<DepthBuffer> depth;
    if (reach != Reach::Through && faces) {
        // The faces whose centre is inside and which turn toward the eye where that counts,
        // found while the depth buffer is drawn; then those the buffer shows.
        struct Candidate {
            glm::vec3 s;
            Face f;
        };
        // Kept per calling thread between boxes, as the other arrays (fresh pages).
        thread_local std::vector<std::vector<Candidate>> kept;
        kept.resize(std::max<std::size_t>(kept.size(), std::max(1u, thread_count())));
        std::vector<std::vector<Candidate>>& candidates = kept;
        for (std::vector<Candidate>& c : candidates) {
            c.clear();
        }
        depth.emplace(mesh, p, lo, hi, cull, [&](unsigned k, Face f, const FaceSeen& seen) {
            glm::vec3 s;
            if (p.to_screen(seen.clip / seen.corners, s) && in_region(glm::vec2(s)) &&
                (!cull || !seen.placed || seen.area < 0.0f)) {
                candidates[k].push_back({s, f});
            }
        });
        std::vector<T> out;
        std::size_t most = 0;
        for (unsigned k = 0; k < depth->ranges(); ++k) {
            most += candidates[k].size();
        }
        out.reserve(most);
        const auto keep_shown = [&](const std::vector<Candidate>& list) {
            for (const Candidate& c : list) {
                if (depth->shows(c.s, [&](Face g) { return g == c.f; })) {
                    out.push_back(make(c.f.idx(), glm::vec2(c.s)));
                }
            }
        };
        if (tile <= 0) {
            for (unsigned k = 0; k < depth->ranges(); ++k) {
                keep_shown(candidates[k]);
            }
            return out;
        }
        // By tile: a counting sort of the candidates (their centres lie in [lo, hi]).
        const int tiles_x = std::max(1, (width + tile - 1) / tile);
        const int tiles_y = std::max(1, (height + tile - 1) / tile);
        const auto tile_of = [&](const glm::vec3& s) {
            const int x = std::clamp(static_cast<int>(s.x) / tile, 0, tiles_x - 1);
            const int y = std::clamp(static_cast<int>(s.y) / tile, 0, tiles_y - 1);
            return static_cast<std::size_t>(y) * tiles_x + x;
        };
        std::vector<std::uint32_t> next(static_cast<std::size_t>(tiles_x) * tiles_y + 1, 0);
        for (unsigned k = 0; k < depth->ranges(); ++k) {
            for (const Candidate& c : candidates[k]) {
                ++next[tile_of(c.s) + 1];
            }
        }
        std::partial_sum(next.begin(), next.end(), next.begin());
        thread_local std::vector<Candidate> sorted;  // kept, as above
        sorted.resize(most);
        for (unsigned k = 0; k < depth->ranges(); ++k) {
            for (const Candidate& c : candidates[k]) {
                sorted[next[tile_of(c.s)]++] = c;
            }
        }
        // The tests by ranges of the sorted list too (the buffer is only read now).
        std::vector<std::vector<T>> shown_parts(std::max(1u, thread_count()));
        const std::vector<Candidate>& list = sorted;  // this thread's, named in the workers
        const unsigned ran = in_ranges(most, [&](std::size_t first, std::size_t last, unsigned k) {
            std::vector<T>& part = k == 0 ? out : shown_parts[k];
            for (std::size_t i = first; i < last; ++i) {
                const Candidate& c = list[i];
                if (depth->shows(c.s, [&](Face g) { return g == c.f; })) {
                    part.push_back(make(c.f.idx(), glm::vec2(c.s)));
                }
            }
        });
        for (unsigned k = 1; k < ran; ++k) {
            out.insert(out.end(), shown_parts[k].begin(), shown_parts[k].end());
        }
        return out;
    }
    if (reach != Reach::Through) {
        depth.emplace(mesh, p, lo, hi, cull, [](unsigned, Face, const FaceSeen&) {});
    }
    std::vector<T> out;
    if (faces) {
        std::vector<std::vector<T>> parts(std::max(1u, thread_count()));
        const unsigned ran =
            in_ranges(mesh.faces_size(), [&](std::size_t first, std::size_t last, unsigned k) {
                parts[k].reserve(last - first);  // address space only: no copies as it grows
                for (std::size_t i = first; i < last; ++i) {
                    const Face f(static_cast<std::uint32_t>(i));
                    if (mesh.is_deleted(f)) {
                        continue;
                    }
                    const std::uint16_t code = face_code(mesh, p, f);
                    if ((code & kFar) != 0) {
                        continue;  // every corner beyond one side: so is the centre
                    }
                    if (box && (code >> 8 & kNotInside) == 0) {
                        parts[k].push_back(make(f.idx(), glm::vec2(0.0f)));  // every corner in
                        continue;
                    }
                    glm::vec4 sum(0.0f);
                    float n = 0.0f;
                    for (const Halfedge h : mesh.halfedges(f)) {
                        sum += p.clip_of(mesh, mesh.to_vertex(h).idx());
                        n += 1.0f;
                    }
                    glm::vec3 s;
                    if (p.to_screen(sum / n, s) && in_region(glm::vec2(s))) {
                        parts[k].push_back(make(f.idx(), glm::vec2(s)));
                    }
                }
            });
        if (ran == 1) {
            return std::move(parts[0]);
        }
        for (unsigned k = 0; k < ran; ++k) {
            out.insert(out.end(), parts[k].begin(), parts[k].end());
        }
        return out;
    }
    for (const Vertex v : mesh.vertices()) {
        const glm::vec3& s = p.screen[v.idx()];
        if (p.placed[v.idx()] == 0 || !in_region(glm::vec2(s))) {
            continue;
        }
        // One of v's faces nearest at its pixel: v is on what the view shows.
        const auto around_v = [&](Face g) {
            if (mesh.is_isolated(v)) {
                return false;
            }
            for (const Halfedge h : mesh.halfedges(v)) {
                if (mesh.face(h) == g) {
                    return true;
                }
            }
            return false;
        };
        if (depth && !depth->shows(s, around_v)) {
            continue;
        }
        out.push_back(make(v.idx(), glm::vec2(s)));
    }
    return out;
}

template <class InRegion>
std::vector<ElementRef> elements_inside(const Mesh& mesh, const Camera& camera, int width,
                                        int height, ElementRef::Kind kind, Reach reach,
                                        glm::vec2 lo, glm::vec2 hi, bool box,
                                        const InRegion& in_region) {
    const bool faces = kind == ElementRef::Kind::Face;
    const auto make = [faces](std::uint32_t i, glm::vec2) {
        return faces ? ElementRef::face(Face(i)) : ElementRef::vertex(Vertex(i));
    };
    std::vector<ElementRef> points = points_inside<ElementRef>(mesh, camera, width, height, faces,
                                                               reach, lo, hi, box, in_region, make);
    if (faces || kind == ElementRef::Kind::Vertex) {
        return points;
    }
    std::vector<bool> in(mesh.vertices_size(), false);
    for (const ElementRef& v : points) {
        in[v.index] = true;
    }
    return region::edges_between(mesh, [&](std::uint32_t v) { return in[v]; });
}

}  // namespace

namespace region {

// Even-odd: a ray to the right of q crosses the outline an odd number of times.
bool in_outline(const std::vector<glm::vec2>& outline, glm::vec2 q) {
    bool odd = false;
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const glm::vec2 &a = outline[i], &b = outline[j];
        if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
            odd = !odd;
        }
    }
    return odd;
}

bool in_circle(glm::vec2 centre, float radius, glm::vec2 q) {
    const glm::vec2 d = q - centre;
    return glm::dot(d, d) <= radius * radius;
}

glm::vec2 lower(const std::vector<glm::vec2>& outline) {
    glm::vec2 lo = outline[0];
    for (const glm::vec2& p : outline) {
        lo = glm::min(lo, p);
    }
    return lo;
}

glm::vec2 upper(const std::vector<glm::vec2>& outline) {
    glm::vec2 hi = outline[0];
    for (const glm::vec2& p : outline) {
        hi = glm::max(hi, p);
    }
    return hi;
}

}  // namespace region

std::vector<ElementRef> elements_in_box(const Mesh& mesh, const Camera& camera,
                                        const ScreenBox& box, ElementRef::Kind kind, Reach reach) {
    const glm::vec2 lo = glm::min(box.a, box.b), hi = glm::max(box.a, box.b);
    return elements_inside(mesh, camera, box.width, box.height, kind, reach, lo, hi, true,
                           [&](const glm::vec2& q) {
                               return q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y;
                           });
}

std::vector<ElementRef> elements_in_lasso(const Mesh& mesh, const Camera& camera,
                                          const std::vector<glm::vec2>& outline, int width,
                                          int height, ElementRef::Kind kind, Reach reach) {
    if (outline.size() < 3) {
        return {};
    }
    const glm::vec2 lo = region::lower(outline), hi = region::upper(outline);
    return elements_inside(mesh, camera, width, height, kind, reach, lo, hi, false,
                           [&](const glm::vec2& q) {
                               return q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y &&
                                      region::in_outline(outline, q);
                           });
}

std::vector<ElementRef> elements_in_circle(const Mesh& mesh, const Camera& camera, glm::vec2 centre,
                                           float radius, int width, int height,
                                           ElementRef::Kind kind, Reach reach) {
    const glm::vec2 r(radius, radius);
    return elements_inside(
        mesh, camera, width, height, kind, reach, centre - r, centre + r, false,
        [&](const glm::vec2& q) { return region::in_circle(centre, radius, q); });
}

// ShownPoints -----------------------------------------------------------------------------

ShownPoints::ShownPoints(const Mesh& mesh, const Camera& camera, int width, int height,
                         ElementRef::Kind kind, Reach reach)
    : width_(std::max(width, 1)),
      height_(std::max(height, 1)),
      tiles_x_((width_ + kTile - 1) / kTile),
      tiles_y_((height_ + kTile - 1) / kTile),
      kind_(kind == ElementRef::Kind::Halfedge ? ElementRef::Kind::Edge : kind),
      reach_(reach) {
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    view_projection_ = camera.projection(aspect) * camera.view();
    const bool faces = kind_ == ElementRef::Kind::Face;
    elements_ = faces ? mesh.faces_size() : mesh.vertices_size();
    // Every point in the image: what any region in this view could select.
    const glm::vec2 lo(0.0f), hi(static_cast<float>(width_), static_cast<float>(height_));
    std::vector<Point> found = points_inside<Point>(
        mesh, camera, width_, height_, faces, reach, lo, hi, false,
        [&](const glm::vec2& q) {
            return q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y;
        },
        [](std::uint32_t i, glm::vec2 at) {
            return Point{at, i};
        },
        kTile);
    // Into tiles by a counting sort; a tile holds the points of its closed square.
    const auto tile_of = [&](glm::vec2 at) {
        const int x = std::min(tiles_x_ - 1, static_cast<int>(at.x) / kTile);
        const int y = std::min(tiles_y_ - 1, static_cast<int>(at.y) / kTile);
        return static_cast<std::size_t>(y) * tiles_x_ + x;
    };
    starts_.assign(static_cast<std::size_t>(tiles_x_) * tiles_y_ + 1, 0);
    bool in_order = true;  // the faces the view shows come by tile already (points_inside())
    std::size_t last = 0;
    for (const Point& q : found) {
        const std::size_t t = tile_of(q.at);
        in_order = in_order && t >= last;
        last = t;
        ++starts_[t + 1];
    }
    for (std::size_t t = 1; t < starts_.size(); ++t) {
        starts_[t] += starts_[t - 1];
    }
    if (in_order) {
        points_ = std::move(found);
        return;
    }
    points_.resize(found.size());
    std::vector<std::uint32_t> next(starts_.begin(), starts_.end() - 1);
    for (const Point& q : found) {
        points_[next[tile_of(q.at)]++] = q;
    }
}

bool ShownPoints::fits(const Camera& camera, int width, int height, ElementRef::Kind kind,
                       Reach reach) const {
    if (std::max(width, 1) != width_ || std::max(height, 1) != height_ || reach != reach_ ||
        (kind == ElementRef::Kind::Halfedge ? ElementRef::Kind::Edge : kind) != kind_) {
        return false;
    }
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    return camera.projection(aspect) * camera.view() == view_projection_;
}

}  // namespace meshedit
