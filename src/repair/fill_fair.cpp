// fill_holes_fair() and fill_hole_fair() (repair.h): Liepa's hole filling (2003), as CGAL's
// triangulate_refine_and_fair_hole and pmp's fill_hole + fair do it —
//
//   1. cover the hole with triangles (hole_triangles.h: minimum weight, or ears when large,
//      then flipped to Delaunay),
//   2. refine: poke each triangle whose centroid lies farther than its corners' edge lengths
//      allow (σ: a corner's mean edge length, a new vertex's the mean of its triangle's),
//      flipping the poked triangle's sides toward Delaunay at once and the whole patch's
//      after each round, until no triangle is poked; then dissolve the new vertices left
//      with three edges (a poke no flip reached: fairing pulls such a vertex onto the side
//      its clamped cotangent weights favour, a 179° cap),
//   3. fair: the new vertices solve the bi-Laplacian with everything else fixed (fair(),
//      smoothing.h), so the patch continues the surface around it; then flip toward
//      Delaunay once more, on the faired shape (its worst caps lean on the hole's border).
//
// Every change goes through the local operations (fill_hole, triangulate, flip, poke,
// dissolve), so attributes are carried by each operation's rule and the result is valid after
// each step.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "hole_triangles.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/smoothing.h"
#include "meshedit/repair/repair.h"
#include "soup_edit.h"

namespace meshedit {
namespace {

using namespace repair_detail;

// A hole refined past this many new vertices stops refining (and says so): a hole as large
// as a scan's outer border would otherwise take the memory of the machine.
constexpr std::size_t kMaxNewVertices = 1'000'000;
// Holes of more sides are left with their reason: a border of 100,000 edges took 50 s and
// 9.8 GB (measured); the fills here are for holes, not for closing a whole scan's border.
constexpr std::size_t kMaxHoleEdges = 20'000;

std::vector<std::vector<Halfedge>> boundary_loops(const Mesh& mesh) {
    std::vector<std::vector<Halfedge>> loops;
    std::vector<bool> seen(mesh.halfedges_size(), false);
    for (const Halfedge h : mesh.halfedges()) {
        if (seen[h.idx()] || !mesh.is_boundary(h)) {
            continue;
        }
        std::vector<Halfedge>& sides = loops.emplace_back();
        for (const Halfedge x : mesh.loop(h)) {
            seen[x.idx()] = true;
            sides.push_back(x);
        }
    }
    return loops;
}

double mean_edge_length(const Mesh& mesh, Vertex v) {
    double sum = 0.0;
    std::size_t n = 0;
    for (const Vertex w : mesh.vertices(v)) {
        sum += norm(mesh.position(w) - mesh.position(v));
        ++n;
    }
    return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

struct Filler {
    Mesh& mesh;
    const FairFillOptions& options;
    // The edge length wanted at a hole's corner (by vertex index: a map, not an array over
    // the mesh, so that a small hole costs its own size); new vertices' in new_sigma.
    std::unordered_map<std::uint32_t, double> corner_sigma;
    double touching = 0.0;          // corners closer than this are one point to repair()
    std::size_t first_vertex = 0;   // the new vertices' indices start here
    std::vector<double> new_sigma;  // of the new vertices, from first_vertex on (most lookups)
    std::vector<Halfedge> sides;    // relax_around()'s scratch

    double& sigma(Vertex v) {
        if (v.idx() < first_vertex) {
            return corner_sigma[v.idx()];
        }
        const std::size_t i = v.idx() - first_vertex;
        if (i >= new_sigma.size()) {
            new_sigma.resize(std::max(2 * new_sigma.size(), i + 1), 0.0);
        }
        return new_sigma[i];
    }

    bool in_patch(Face f, std::size_t first) const { return f.is_valid() && f.idx() >= first; }

    // Whether h's edge lies inside the patch and is not Delaunay: the angles across it sum
    // past π, i.e. cot α + cot β < 0 (no arc functions: this test is most of relax()'s time).
    // Never when the two far corners touch (a pinched border).
    bool wants_flip(Halfedge h, std::size_t first) const {
        const Halfedge t = Mesh::twin(h);
        if (!in_patch(mesh.face(h), first) || !in_patch(mesh.face(t), first)) {
            return false;  // the hole's border stays
        }
        const Vec3 a = mesh.position(mesh.from_vertex(h));
        const Vec3 b = mesh.position(mesh.to_vertex(h));
        const Vec3 c = mesh.position(mesh.to_vertex(mesh.next(h)));
        const Vec3 d = mesh.position(mesh.to_vertex(mesh.next(t)));
        const double dot_c = dot(a - c, b - c), dot_d = dot(a - d, b - d);
        const double sin_c = norm(cross(a - c, b - c)), sin_d = norm(cross(a - d, b - d));
        // sin(α + β) · (the positive lengths): negative past π.
        const double sum = dot_c * sin_d + dot_d * sin_c;
        // Nor when a new vertex would be left with three edges: fairing pulls such a vertex
        // onto a side (see dissolve_threes()).
        const auto keeps_four = [&](Vertex v) {
            return v.idx() < first_vertex || mesh.valence(v) > 4;
        };
        // Nor onto a flat triangle (c, d and an end on a line), as CGAL's flippable().
        const double flat = 1e-12 * sqrnorm(c - d);
        return sum < -1e-9 * (std::abs(dot_c) * sin_d + std::abs(dot_d) * sin_c) &&
               norm(c - d) > touching && keeps_four(mesh.from_vertex(h)) &&
               keeps_four(mesh.to_vertex(h)) && norm(cross(d - c, a - c)) > flat &&
               norm(cross(d - c, b - c)) > flat;
    }

    // Flips the patch's inner edges that are not Delaunay until none is, or a bound of
    // passes. \return the flips made.
    std::size_t relax(std::size_t first) {
        std::size_t total = 0;
        for (int pass = 0; pass < 64; ++pass) {
            std::size_t flipped = 0;
            for (std::size_t fi = first; fi < mesh.faces_size(); ++fi) {
                const Face f(static_cast<std::uint32_t>(fi));
                if (mesh.is_deleted(f)) {
                    continue;
                }
                for (const Halfedge h : mesh.halfedges(f)) {
                    const Halfedge t = Mesh::twin(h);
                    if (t.idx() < h.idx() && in_patch(mesh.face(t), first)) {
                        continue;  // seen from the other side
                    }
                    if (wants_flip(h, first) && flip(mesh, Mesh::edge(h))) {
                        ++flipped;
                        break;  // f changed: its halfedges are another loop now
                    }
                }
            }
            total += flipped;
            if (flipped == 0) {
                break;
            }
        }
        return total;
    }

    // Flips the sides of the triangle poked into v toward Delaunay (Liepa's and CGAL's
    // refinement do it at each poke: the patch's next pokes then see rounder triangles).
    void relax_around(Vertex v, std::size_t first) {
        sides.clear();  // collected first: a flip changes v's ring
        for (const Halfedge h : mesh.halfedges(v)) {
            sides.push_back(mesh.next(h));
        }
        for (const Halfedge h : sides) {
            if (wants_flip(h, first)) {
                flip(mesh, Mesh::edge(h));
            }
        }
    }

    // Dissolves the new vertices (index from `first_vertex` on) that kept three edges, each
    // into the triangle of its neighbours. \return how many.
    std::size_t dissolve_threes() {
        std::size_t gone = 0;
        for (std::size_t vi = first_vertex; vi < mesh.vertices_size(); ++vi) {
            const Vertex v(static_cast<std::uint32_t>(vi));
            if (!mesh.is_deleted(v) && !mesh.is_boundary(v) && mesh.valence(v) == 3 &&
                dissolve_vertex(mesh, v)) {
                ++gone;
            }
        }
        return gone;
    }

    enum class Refined { done, paused, capped };

    // Liepa's refinement of the faces from `first` on: capped when it stopped at
    // kMaxNewVertices, paused when `added` reached `pause_at` first (to be faired while the
    // solve is small enough, then refined on: refine() again).
    Refined refine(std::size_t first, std::size_t& added, std::size_t pause_at) {
        for (int round = 0; round < 256; ++round) {
            std::size_t poked = 0;
            const std::size_t faces = mesh.faces_size();
            for (std::size_t fi = first; fi < faces; ++fi) {
                const Face f(static_cast<std::uint32_t>(fi));
                if (mesh.is_deleted(f) || !mesh.is_triangle(f)) {
                    continue;
                }
                const Vec3 c = face_centroid(mesh, f);
                double sc = 0.0;
                for (const Vertex v : mesh.vertices(f)) {
                    sc += sigma(v) / 3.0;
                }
                bool split = true;
                for (const Vertex v : mesh.vertices(f)) {
                    const double d = options.density * norm(c - mesh.position(v));
                    split = split && d > sc && d > sigma(v);
                }
                if (!split) {
                    continue;
                }
                if (added >= pause_at) {
                    relax(first);
                    return Refined::paused;
                }
                const OpResult<Vertex> v = poke(mesh, f);
                if (!v) {
                    continue;
                }
                sigma(*v) = sc;
                relax_around(*v, first);
                ++poked;
                if (++added >= kMaxNewVertices) {
                    relax(first);
                    return Refined::capped;
                }
            }
            if (poked == 0) {
                return Refined::done;
            }
            relax(first);
        }
        return Refined::done;
    }
};

// The mesh's bounding-box diagonal times the merge tolerance's default (MergeTolerance):
// closer corners are one point to repair().
double touching_distance(const Mesh& mesh) {
    Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    const auto add = [&](const Vec3& p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    };
    if (mesh.n_vertices() == mesh.vertices_size()) {
        // Nothing deleted: one pass over the positions' array, no deleted flags read.
        for (const Vec3& p : mesh.position_vector()) {
            add(p);
        }
    } else {
        for (const Vertex v : mesh.vertices()) {
            add(mesh.position(v));
        }
    }
    return MergeTolerance{}.value * (mesh.n_vertices() > 0 ? norm(hi - lo) : 0.0);
}

// Whether a face of the mesh already has the corners of the 3-sided hole `corner` (two
// triangles back to back, which the builder cut apart): a fill would repeat it.
bool repeats_a_face(const Mesh& mesh, const std::vector<Vertex>& corner) {
    if (corner.size() != 3) {
        return false;
    }
    for (const Face f : mesh.faces(corner[0])) {
        std::size_t shared = 0;
        for (const Vertex v : mesh.vertices(f)) {
            shared += std::count(corner.begin(), corner.end(), v);
        }
        if (shared == 3 && mesh.valence(f) == 3) {
            return true;
        }
    }
    return false;
}

// The first corner whose fan needs no edge the mesh has.
std::optional<std::uint32_t> free_apex(const HoleLoop& hole) {
    const std::size_t n = hole.points.size();
    for (std::size_t i = 0; i < n; ++i) {
        bool free = true;
        for (std::size_t k = 2; free && k + 1 < n; ++k) {
            free = !hole.forbidden(i, (i + k) % n);
        }
        if (free) {
            return static_cast<std::uint32_t>(i);
        }
    }
    return std::nullopt;
}

// Fills the holes `loops` (each a boundary loop's halfedges in order); with `turn`, then
// turns a part the fills closed outward.
RepairResult fill_loops(Mesh& mesh, const FairFillOptions& options,
                        const std::vector<std::vector<Halfedge>>& loops, bool turn) {
    RepairResult result;
    const std::size_t first_face = mesh.faces_size();
    const std::size_t first_vertex = mesh.vertices_size();
    Filler filler{mesh, options, {}, touching_distance(mesh), first_vertex};
    std::size_t large = 0, triangles = 0, added = 0, filled_edges = 0;
    bool capped = false;
    std::optional<std::size_t> paused;  // the first patch whose refinement waits for fairing
    const double touching = filler.touching;
    std::vector<std::string> why;  // of the holes left, in order
    for (const std::vector<Halfedge>& sides : loops) {
        const std::size_t n = sides.size();
        if (options.max_edges > 0 && n > options.max_edges) {
            ++large;
            continue;
        }
        if (n > kMaxHoleEdges) {
            why.push_back("a hole of " + count_of(n, "edge", "edges") + " at vertex " +
                          std::to_string(mesh.from_vertex(sides[0]).idx()) + ": more than " +
                          std::to_string(kMaxHoleEdges) + ", the most this fill takes");
            continue;
        }
        std::vector<Vertex> corner(n);
        HoleLoop hole;
        for (std::size_t i = 0; i < n; ++i) {
            corner[i] = mesh.from_vertex(sides[i]);
            hole.points.push_back(mesh.position(corner[i]));
            hole.outside_normals.push_back(face_normal(mesh, mesh.face(Mesh::twin(sides[i]))));
            filler.sigma(corner[i]) = mean_edge_length(mesh, corner[i]);
        }
        if (repeats_a_face(mesh, corner)) {
            why.push_back("a hole of 3 edges at vertex " + std::to_string(corner[0].idx()) +
                          " whose fill would repeat a face the mesh has");
            continue;
        }
        // Corners that touch (a vertex the loader split where the border pinches, two
        // holes meeting) are never joined: the edge would have no length, and repair()
        // would merge them into faces that repeat a corner.
        hole.forbidden = [&](std::size_t i, std::size_t k) {
            return corner[i] == corner[k] || norm(hole.points[i] - hole.points[k]) <= touching ||
                   mesh.find_edge(corner[i], corner[k]).is_valid();
        };
        const HoleTriangles cover = hole_triangles(hole);
        const std::optional<std::uint32_t> apex = free_apex(hole);
        if (cover.triangles.empty() || !apex || !is_fill_hole_ok(mesh, sides[*apex])) {
            why.push_back("a hole of " + count_of(n, "edge", "edges") + " at vertex " +
                          std::to_string(corner[0].idx()) + ": " +
                          (!cover.triangles.empty() ? "no corner fans it without an edge the "
                                                      "mesh already has"
                                                    : cover.why));
            continue;
        }
        const std::size_t patch = mesh.faces_size();
        const OpResult<Face> face = fill_hole(mesh, sides[*apex]);
        if (!face) {
            why.push_back("a hole at vertex " + std::to_string(corner[0].idx()) + ": " +
                          std::string(face.reason()));
            continue;
        }
        if (n > 3 && triangulate(mesh, *face)) {  // the fan from corner[apex]
            for (const FanFlip& f : flips_from_fan(cover.triangles, n, *apex)) {
                // Each flip's new edge is a diagonal of the planned cover, which the mesh
                // does not have; were one refused, the patch would stay a valid fan.
                const Edge e = mesh.find_edge(corner[*apex], corner[f.z]);
                if (!e.is_valid() || !flip(mesh, e)) {
                    break;
                }
            }
        }
        if (cover.clipped) {
            // Ears flipped to Delaunay: the outline's constrained Delaunay triangulation in
            // its plane (as CGAL's 2D path). Thin ears left as they are put the first new
            // vertices beside the border: a 5° angle on a sphere's cap, 12° flipped.
            filler.relax(patch);
        }
        if (options.refine) {
            // Past what the fairing solves for, the patches are faired part-refined and
            // refined on after, so their new vertices still lie on a faired surface.
            const Filler::Refined r =
                filler.refine(patch, added, options.fair ? options.max_faired : kMaxNewVertices);
            capped = capped || r == Filler::Refined::capped;
            if (r == Filler::Refined::paused && !paused) {
                paused = patch;
            }
        }
        ++result.count;
        filled_edges += n;
        note_first(result, corner[0].idx());
    }
    if (const std::size_t gone = added > 0 ? filler.dissolve_threes() : 0; gone > 0) {
        added -= gone;
        filler.relax(first_face);
    }
    std::size_t faired = 0;
    std::string fair_note;
    if (options.fair && added > 0) {
        std::vector<Face> region;
        for (std::size_t fi = first_face; fi < mesh.faces_size(); ++fi) {
            if (!mesh.is_deleted(Face(static_cast<std::uint32_t>(fi)))) {
                region.push_back(Face(static_cast<std::uint32_t>(fi)));
            }
        }
        FairOptions fo;  // cotangent weights where the faces the solve reads are triangles
        OpStatus ok = check_fair(mesh, region, fo);
        if (!ok) {
            fo.weights = SmoothWeights::Uniform;  // polygons beside the holes
            ok = check_fair(mesh, region, fo);
        }
        if (ok) {
            faired = fair(mesh, region, fo).moved;
            filler.relax(first_face);  // Delaunay on the faired shape
        } else {
            fair_note = "not faired: " + ok.text();
        }
    }
    const std::size_t faired_at = added;
    if (paused) {  // refined on, on the faired surface
        capped =
            filler.refine(*paused, added, kMaxNewVertices) == Filler::Refined::capped || capped;
    }
    std::vector<Face> patches;
    for (std::size_t fi = first_face; fi < mesh.faces_size(); ++fi) {
        if (!mesh.is_deleted(Face(static_cast<std::uint32_t>(fi)))) {
            patches.push_back(Face(static_cast<std::uint32_t>(fi)));
        }
    }
    triangles = patches.size();
    // A part the fills closed had no inside while it was open: inward half the time, and a
    // second repair then turned it (20 of 219 files were not idempotent with --fair).
    std::size_t turned_faces = 0;
    const std::size_t turned = turn ? turn_closed_parts_outward(mesh, patches, turned_faces) : 0;
    result.left = large + why.size();
    std::vector<std::string> parts;
    if (result.count > 0) {
        RepairResult at = result;
        std::string text = "filled " + count_of(result.count, "hole", "holes") + " (" +
                           count_of(filled_edges, "edge", "edges") + " in all) with " +
                           count_of(triangles, "triangle", "triangles");
        if (added > 0) {
            text += " around " + count_of(added, "new vertex", "new vertices");
        }
        if (faired > 0) {
            text += ", faired";
        }
        if (faired > 0 && added > faired_at) {
            text += " at " + count_of(faired_at, "new vertex", "new vertices") +
                    " (the most one fairing solves for) and refined on after";
        }
        parts.push_back(text + "; a vertex of each" + listed(at));
    }
    if (turned > 0) {
        parts.push_back(turned_outward(turned_faces, turned));
    }
    if (capped) {
        parts.push_back("stopped refining at " + std::to_string(kMaxNewVertices) +
                        " new vertices (a hole far larger than its edges)");
    }
    if (!fair_note.empty()) {
        parts.push_back(fair_note);
    }
    if (large > 0) {
        parts.push_back("left " + count_of(large, "hole", "holes") + " of more than " +
                        count_of(options.max_edges, "edge", "edges"));
    }
    for (const std::string& w : why) {
        parts.push_back("left " + w);
    }
    for (std::size_t i = 0; i < parts.size(); ++i) {
        result.sentence += (i == 0 ? "" : "; ") + parts[i];
    }
    return result;
}

}  // namespace

RepairResult fill_holes_fair(Mesh& mesh, const FairFillOptions& options) {
    return fill_loops(mesh, options, boundary_loops(mesh), true);
}

RepairResult fill_hole_fair(Mesh& mesh, Halfedge h, const FairFillOptions& options) {
    if (!mesh.is_valid(h) || mesh.is_deleted(Mesh::edge(h)) || !mesh.is_boundary(h)) {
        RepairResult refused;
        refused.sentence =
            "cannot fill: halfedge " + std::to_string(h.idx()) + " is not on the border of a hole";
        return refused;
    }
    std::vector<std::vector<Halfedge>> loop(1);
    for (const Halfedge x : mesh.loop(h)) {
        loop[0].push_back(x);
    }
    return fill_loops(mesh, options, loop, false);
}

}  // namespace meshedit
