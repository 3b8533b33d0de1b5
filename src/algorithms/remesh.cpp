// Isotropic remeshing (Botsch and Kobbelt, "A remeshing approach to multiresolution
// modeling", 2004), with boundaries and creases kept as features.
//
// One iteration, L the target length:
//
//   split     every edge longer than 4/3 L at its midpoint (until none is left)
//   collapse  every edge shorter than 4/5 L, shortest first, into one of its ends, unless a
//             new edge would be longer than 4/3 L
//   flip      every edge whose flip brings the four vertices' valences nearer 6 (4 on the
//             boundary), unless the two new triangles bend more than 1.5° past the two old
//             ones or get a smaller smallest angle under 20°
//   smooth    every free vertex toward its neighbours' centroid, in its tangent plane, then
//   project   onto the closest point of the input surface
//
// Feature edges (boundary, crease) are never flipped. A collapse of an edge with one end on a
// feature puts the survivor at that end; a collapse along a feature edge puts it at one of
// the edge's ends (the corner, if one end is a corner: the end of a crease, three or more
// feature edges, or a turn of more than 30 degrees). Feature vertices are not smoothed.
// Splits put new feature vertices at midpoints of feature edges, and collapses keep feature
// vertices where they are, so every feature vertex stays on the input's feature polyline.
// With a feature angle, the edges sharper than it are marked as creases first (CGAL's and
// pmp's "detect sharp edges"): a mesh read from a format without creases (OFF, STL) keeps
// its sharp edges straight instead of rounding them.

#include "meshedit/core/remesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

#include "local_ops/collapse_guard.h"
#include "mesh/parallel.h"
#include "mesh/triangles_only.h"
#include "mesh/unit_scale.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/budget.h"
#include "meshedit/core/closest_point.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/number_text.h"
#include "meshedit/core/validate.h"
#include "remesh_attributes.h"

namespace meshedit {
namespace {

// A collapse may not turn a face by more than 60 degrees (cos 60° = 0.5), nor a flip.
constexpr double kCosLimit = 0.5;
// A flip may bend its two triangles this much more than they were (1.5°), and may not make
// their smallest angle smaller than it was where the result is under kKeepAngle (20°): the
// balance measured between the share of valence 6 and the distance to the input
// (docs/performance.md, "Remeshing: valence against distance").
constexpr double kBendSlack = 1.5 * 3.14159265358979323846 / 180.0;
constexpr double kKeepAngle = 20.0 * 3.14159265358979323846 / 180.0;
// The scratch face property of a region remesh (removed before it returns).
constexpr const char* kRegionProperty = "f:remesh_region";
// The scratch edge property marking the attributes' seams, carried as a crease is (removed
// before it returns): a flag read at every feature test, where comparing corners cost a
// quarter of the remesh.
constexpr const char* kSeamProperty = "e:remesh_seam";
// More than this many passes of splits means the target is absurd for the mesh (each pass
// halves every long edge): check_remesh() refuses such targets first.
constexpr int kMaxSplitPasses = 40;
// What one face of the growing mesh costs at the peak, with everything the remesher keeps
// per vertex, the input's copy and search tree and the caller's buffers beside it (measured:
// `meshedit convert dae/torus.dae r.off --ops remesh:0.004,1` peaks at 3.3 GB of resident
// memory for 11.7M faces, 284 bytes a face with the writer's buffers).
constexpr double kBytesPerFace = 300.0;
// The growth guard looks at the mesh's size every this many splits.
constexpr std::size_t kSplitsPerGuard = 4096;
// Smoothing runs on several threads from this many vertices, in chunks of kChunk.
constexpr std::size_t kParallelVertices = 50'000;
constexpr std::size_t kChunk = 4096;

// Both in the units of the mesh scaled by 2^exponent (unit_scale.h), so that huge or tiny
// coordinates neither overflow nor underflow when squared.
double mean_edge_length(const Mesh& mesh, int exponent = 0) {
    double sum = 0.0;
    for (Edge e : mesh.edges()) {
        sum += distance(scaled_point(mesh.position(mesh.vertex(e, 0)), exponent),
                        scaled_point(mesh.position(mesh.vertex(e, 1)), exponent));
    }
    return mesh.n_edges() > 0 ? sum / static_cast<double>(mesh.n_edges()) : 0.0;
}

// How many triangles remeshing toward `length` makes, from the faces' areas and from the
// splits their edges need: an equilateral triangle of side L has area √3/4 · L², and a
// face whose longest edge needs n pieces becomes about n² triangles however little area it
// has (a needle, or three corners on a line, has almost none).
double estimated_triangles(const Mesh& mesh, int exponent, double length) {
    const double high = 4.0 / 3.0 * length;
    double triangles = 0.0;
    for (Face f : mesh.faces()) {
        Vec3 c[3];
        int i = 0;
        for (Vertex v : mesh.vertices(f)) {
            c[i++] = scaled_point(mesh.position(v), exponent);
        }
        const double area = 0.5 * norm(cross(c[1] - c[0], c[2] - c[0]));
        const double longest =
            std::max({distance(c[0], c[1]), distance(c[1], c[2]), distance(c[2], c[0])});
        const double pieces = std::ceil(longest / high);
        triangles +=
            std::max({1.0, area / (std::sqrt(3.0) / 4.0 * length * length), pieces * pieces});
    }
    return triangles;
}

class Remesher {
public:
    /// `source`: the input as it is now, unscaled, for its attributes (null: none to project).
    Remesher(Mesh& mesh, const RemeshOptions& options, const Mesh* source)
        : mesh_(mesh),
          options_(options),
          input_(mesh),
          crease_(mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)),
          source_(source) {
        if (const remeshing::AttributeSeams seams(mesh); seams.any()) {
            seam_ = mesh.add_property<Edge, std::uint8_t>(kSeamProperty, 0);
            mesh.set_carry<Edge>(kSeamProperty, Carry::Any);
            for (const Edge e : mesh.edges()) {
                seam_[e] = seams.is_seam(e) ? 1 : 0;
            }
        }
        if (!options.faces.empty()) {
            // Carried by every split (a face cut copies its value), so what the region's
            // faces become stays in it.
            region_ = mesh.add_property<Face, std::uint8_t>(kRegionProperty, 0);
            for (const Face f : options.faces) {
                region_[f] = 1;
            }
        }
        report_.target_length =
            options.target_length > 0.0 ? options.target_length : mean_edge_length(mesh);
        high_ = 4.0 / 3.0 * report_.target_length;
        low_ = 4.0 / 5.0 * report_.target_length;
    }

    RemeshReport run() {
        const double steps = 4.0 * options_.iterations;
        double done = 0.0;
        const auto report = [&] {
            if (options_.progress) {
                options_.progress(std::min(1.0, ++done / steps));
            }
        };
        for (int i = 0; i < options_.iterations; ++i) {
            split_long_edges();
            report();
            collapse_short_edges();
            report();
            flip_toward_valence_six();
            report();
            smooth_and_project();
            report();
        }
        if (source_ != nullptr) {
            remeshing::project_attributes(
                mesh_, *source_, input_, [this](Face f) { return in_region(f); },
                [this](Vertex v) { return !frozen(v); }, hint_);
        }
        if (region_) {
            mesh_.remove_property(region_);
        }
        if (seam_) {
            mesh_.remove_property(seam_);
        }
        mesh_.garbage_collection();
        return report_;
    }

private:
    // A region remesh (RemeshOptions::faces): an edge may change when both its faces are in
    // the region, a vertex move when every face around it is.
    bool in_region(Face f) const { return !region_ || (f.is_valid() && region_[f] != 0); }
    bool free_edge(Edge e) const {
        return !region_ || (in_region(mesh_.face(e, 0)) && in_region(mesh_.face(e, 1)));
    }
    bool frozen(Vertex v) const {
        if (!region_) {
            return false;
        }
        for (const Halfedge h : mesh_.halfedges(v)) {
            if (!in_region(mesh_.face(h))) {
                return true;
            }
        }
        return false;
    }
    // Boundaries, creases and the attributes' seams (texture coordinates, split normals,
    // materials): a face never spans two charts, so its corners can be projected from one.
    bool is_feature(Edge e) const {
        return mesh_.is_boundary(e) || (crease_ && crease_[e] != 0) || (seam_ && seam_[e] != 0);
    }
    int features_at(Vertex v) const {
        int n = 0;
        for (Edge e : mesh_.edges(v)) {
            n += is_feature(e);
        }
        return n;
    }
    // A feature vertex that must not move: the end of a crease, three or more feature edges,
    // or two that turn by more than 30 degrees (a corner of a boundary or a crease).
    bool is_corner(Vertex v) const {
        return is_feature_corner(mesh_, v, [this](Edge e) { return is_feature(e); });
    }
    double length(Edge e) const {
        return distance(mesh_.position(mesh_.vertex(e, 0)), mesh_.position(mesh_.vertex(e, 1)));
    }

    void split_long_edges() {
        for (int pass = 0; pass < kMaxSplitPasses; ++pass) {
            bool any = false;
            const std::size_t n = mesh_.edges_size();
            for (std::size_t i = 0; i < n; ++i) {
                const Edge e(static_cast<std::uint32_t>(i));
                if (!mesh_.is_deleted(e) && free_edge(e) && length(e) > high_ &&
                    is_split_ok(mesh_, e)) {
                    const Vertex a = mesh_.vertex(e, 0);
                    const OpResult<Vertex> v = split(mesh_, e);
                    // The midpoint's projection starts from its end's triangle.
                    if (v && a.idx() < hint_.size()) {
                        hint_.resize(std::max<std::size_t>(hint_.size(), (*v).idx() + 1),
                                     kInvalidIndex);
                        hint_[(*v).idx()] = hint_[a.idx()];
                    }
                    ++report_.splits;
                    any = true;
                    if (report_.splits % kSplitsPerGuard == 0) {
                        guard_growth();
                    }
                }
            }
            if (!any) {
                return;
            }
        }
    }

    void collapse_short_edges() {
        const std::size_t n = mesh_.edges_size();
        // Shortest first, as CGAL's queue: a collapse lengthens the edges around it, so the
        // shortest go and their neighbours stay (in index order 20% fewer faces were left).
        std::vector<std::pair<double, std::uint32_t>> order;
        for (std::size_t i = 0; i < n; ++i) {
            const Edge e(static_cast<std::uint32_t>(i));
            if (!mesh_.is_deleted(e)) {
                if (const double l = length(e); l < low_) {
                    order.emplace_back(l, static_cast<std::uint32_t>(i));
                }
            }
        }
        std::sort(order.begin(), order.end());
        for (const auto& [shorter, index] : order) {
            const Edge e(index);
            if (mesh_.is_deleted(e) || !free_edge(e) || length(e) >= low_) {
                continue;
            }
            const Vertex a = mesh_.vertex(e, 0), b = mesh_.vertex(e, 1);
            // A vertex on the region's border holds as a feature vertex does.
            const int fa = features_at(a) + (frozen(a) ? 1 : 0);
            const int fb = features_at(b) + (frozen(b) ? 1 : 0);
            Vec3 p;
            if (is_feature(e)) {
                // Along a feature the survivor takes an end's place (a midpoint would leave a
                // curved feature), the corner's if there is one.
                const bool ca = is_corner(a), cb = is_corner(b);
                if (ca && cb) {
                    continue;
                }
                p = cb ? mesh_.position(b) : mesh_.position(a);
            } else {
                if (fa > 0 && fb > 0) {
                    continue;  // a chord between two feature vertices would pinch the surface
                }
                // An end, not the midpoint: the survivor stays on the input surface.
                p = fa > 0 ? mesh_.position(a) : mesh_.position(b);
            }
            if (makes_a_long_edge(a, b, p) || !is_collapse_ok(mesh_, e) ||
                collapse_turns_a_face(mesh_, e, p, kCosLimit)) {
                continue;
            }
            const Vertex s = *collapse(mesh_, e);
            mesh_.position(s) = p;
            ++report_.collapses;
        }
    }

    // The estimate of check_remesh() can be wrong (a surface that folds onto itself as it is
    // projected); the mesh's real size is checked as it grows, before memory runs out.
    void guard_growth() const {
        const std::size_t faces = mesh_.faces_size();
        if (const auto over = over_budget(kBytesPerFace * static_cast<double>(faces))) {
            throw BudgetError("cannot remesh: stopped at " + std::to_string(faces) +
                              " faces, which " + *over + "; nothing changed");
        }
    }

    bool makes_a_long_edge(Vertex a, Vertex b, const Vec3& p) const {
        for (const Vertex v : {a, b}) {
            for (Vertex w : mesh_.vertices(v)) {
                if (w != a && w != b && distance(p, mesh_.position(w)) > high_) {
                    return true;
                }
            }
        }
        return false;
    }

    int target_valence(Vertex v) const { return mesh_.is_boundary(v) ? 4 : 6; }

    void flip_toward_valence_six() {
        // Valences counted once and kept as the flips change them: walking around four
        // vertices for every edge cost most of the pass.
        valence_.assign(mesh_.vertices_size(), 0);
        for (const Halfedge h : mesh_.halfedges()) {
            ++valence_[mesh_.to_vertex(h).idx()];
        }
        const std::size_t n = mesh_.edges_size();
        for (std::size_t i = 0; i < n; ++i) {
            const Edge e(static_cast<std::uint32_t>(i));
            if (mesh_.is_deleted(e) || !free_edge(e) || is_feature(e)) {
                continue;
            }
            const Halfedge h = mesh_.halfedge(e, 0), t = Mesh::twin(h);
            const Vertex a = mesh_.from_vertex(h), b = mesh_.to_vertex(h);
            const Vertex c = mesh_.to_vertex(mesh_.next(h)), d = mesh_.to_vertex(mesh_.next(t));
            const auto off = [&](Vertex v, int change) {
                const int x = valence_[v.idx()] + change - target_valence(v);
                return x * x;
            };
            const int before = off(a, 0) + off(b, 0) + off(c, 0) + off(d, 0);
            const int after = off(a, -1) + off(b, -1) + off(c, 1) + off(d, 1);
            if (after >= before || !is_flip_ok(mesh_, e) || folds(a, b, c, d)) {
                continue;
            }
            flip(mesh_, e);
            --valence_[a.idx()];
            --valence_[b.idx()];
            ++valence_[c.idx()];
            ++valence_[d.idx()];
            ++report_.flips;
        }
    }

    // Whether the flipped triangles (c, a, d) and (d, b, c) would turn by more than 60° from
    // the quad's normal (the pair (a, b, c), (b, a, d) before).
    bool folds(Vertex a, Vertex b, Vertex c, Vertex d) const {
        const Vec3 &pa = mesh_.position(a), &pb = mesh_.position(b), &pc = mesh_.position(c),
                   &pd = mesh_.position(d);
        const Vec3 n1 = cross(pb - pa, pc - pa), n2 = cross(pa - pb, pd - pb);
        const Vec3 before = n1 + n2;
        const Vec3 m1 = cross(pa - pc, pd - pc), m2 = cross(pb - pd, pc - pd);
        for (const Vec3& after : {m1, m2}) {
            const double scale = norm(before) * norm(after);
            if (!(scale > 0.0) || dot(before, after) < kCosLimit * scale) {
                return true;
            }
        }
        // Nor bend the pair more than it was bent, but for kBendSlack: a flip across a ridge
        // would cut the ridge off (on a 208k-triangle scan this rule took the Hausdorff
        // distance to the input from 0.122% to 0.081% of the diagonal), while on a curved
        // surface half the flips toward valence 6 bend a little more (with none allowed, 59%
        // of the inner vertices had valence 6 against CGAL's 71%).
        const double bend_before = dot(n1, n2) / (norm(n1) * norm(n2));
        const double bend_after = dot(m1, m2) / (norm(m1) * norm(m2));
        // Nor make the pair's smallest angle smaller where it is small: flips toward valence
        // 6 on an anisotropic surface (a torus) otherwise leave slivers.
        const double old_min = std::min(smallest_angle(pa, pb, pc), smallest_angle(pb, pa, pd));
        const double new_min = std::min(smallest_angle(pc, pa, pd), smallest_angle(pd, pb, pc));
        if (new_min < old_min && new_min < kKeepAngle) {
            return true;
        }
        return std::acos(std::clamp(bend_after, -1.0, 1.0)) >
               std::acos(std::clamp(bend_before, -1.0, 1.0)) + kBendSlack;
    }

    // The smallest angle of triangle p, q, r, in radians.
    static double smallest_angle(const Vec3& p, const Vec3& q, const Vec3& r) {
        const auto at = [](const Vec3& x, const Vec3& y, const Vec3& z) {
            const Vec3 u = y - x, v = z - x;
            return std::atan2(norm(cross(u, v)), dot(u, v));
        };
        return std::min({at(p, q, r), at(q, r, p), at(r, p, q)});
    }

    // Jacobi: every new place from the old ones, so the vertices are independent and run in
    // chunks on several threads for big meshes (the same result on any number).
    void smooth_and_project() {
        compute_vertex_normals(mesh_, normals_);
        const std::size_t n = mesh_.vertices_size();
        moved_.resize(n);
        hint_.resize(n, kInvalidIndex);  // split vertices have no triangle yet
        // The ends of feature edges, in one pass over the edges rather than a walk around
        // every vertex.
        on_feature_.assign(n, 0);
        for (const Edge e : mesh_.edges()) {
            if (is_feature(e)) {
                on_feature_[mesh_.vertex(e, 0).idx()] = 1;
                on_feature_[mesh_.vertex(e, 1).idx()] = 1;
            }
        }
        const unsigned threads = parallel::thread_count(n, kParallelVertices);
        parallel::for_chunks(n, kChunk, threads, [&](std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const Vertex v(static_cast<std::uint32_t>(i));
                if (mesh_.is_deleted(v)) {
                    continue;
                }
                const Vec3& p = mesh_.position(v);
                moved_[i] = p;
                if (mesh_.is_isolated(v) || on_feature_[i] != 0 || frozen(v)) {
                    continue;
                }
                Vec3 centroid;
                double count = 0;
                for (Vertex w : mesh_.vertices(v)) {
                    centroid += mesh_.position(w);
                    count += 1;
                }
                const Vec3 normal = normals_[i];
                Vec3 step = centroid * (1.0 / count) - p;
                step = step - normal * dot(normal, step);  // tangential only
                // The triangle it was projected onto last time bounds the search.
                const TriangleTree::Hit hit = input_.closest(p + step, hint_[i]);
                moved_[i] = hit.point;
                hint_[i] = hit.triangle;
            }
        });
        for (Vertex v : mesh_.vertices()) {
            mesh_.position(v) = moved_[v.idx()];
        }
    }

    Mesh& mesh_;
    const RemeshOptions& options_;
    const TriangleTree input_;
    EdgeProperty<std::uint8_t> crease_;
    EdgeProperty<std::uint8_t> seam_;  // null: no attribute with seams
    const Mesh* source_;
    FaceProperty<std::uint8_t> region_;  // null: the whole mesh
    double high_ = 0.0, low_ = 0.0;
    std::vector<Vec3> normals_, moved_;
    std::vector<std::uint32_t> hint_;  // per vertex: the input triangle it was last projected on
    std::vector<int> valence_;         // per vertex, during the flips
    std::vector<std::uint8_t> on_feature_;  // per vertex, while smoothing: an end of a feature
    RemeshReport report_;
};

// check_remesh()'s reason as text (composed: it names lengths and counts).
std::string why_not_remesh(const Mesh& mesh, const RemeshOptions& options) {
    if (std::string why = refuse_unless_triangles(mesh, "remesh", "remeshing"); !why.empty()) {
        return why;
    }
    for (const Face f : options.faces) {
        if (f.idx() >= mesh.faces_size() || mesh.is_deleted(f)) {
            return "cannot remesh: face " + std::to_string(f.idx()) + " does not exist";
        }
    }
    if (options.iterations < 1 || options.iterations > 100) {
        return "cannot remesh: iterations must be from 1 to 100, not " +
               std::to_string(options.iterations);
    }
    if (options.feature_angle_deg != kNoFeatureAngle &&
        !check_crease_by_angle(options.feature_angle_deg)) {
        return "cannot remesh: the feature angle must be from 0 to 180 degrees (infinity: off), "
               "not " +
               number_text(options.feature_angle_deg);
    }
    if (!(options.target_length >= 0.0) || !std::isfinite(options.target_length)) {
        return "cannot remesh: the target edge length must be a positive number (0: the mean "
               "edge length)";
    }
    // In the scaled units remesh() works in.
    const int exponent = -unit_exponent(mesh);
    const double length = options.target_length > 0.0 ? std::ldexp(options.target_length, exponent)
                                                      : mean_edge_length(mesh, exponent);
    if (!(length > 0.0)) {
        return "cannot remesh: every edge has length 0 (a degenerate mesh), so there is no mean "
               "length to aim for";
    }
    const double triangles = estimated_triangles(mesh, exponent, length);
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.4g", std::ldexp(length, -exponent));
    if (!(triangles < 1e8)) {
        const std::string count =
            triangles < 1e18 ? std::to_string(static_cast<long long>(triangles)) : "1e18 or more";
        return "cannot remesh: an edge length of " + std::string(shown) + " would make about " +
               count + " triangles (at most 100,000,000)";
    }
    if (const auto over = over_budget(triangles * kBytesPerFace)) {
        return "cannot remesh: an edge length of " + std::string(shown) + " " + *over;
    }
    return {};
}

}  // namespace

OpStatus check_remesh(const Mesh& mesh, const RemeshOptions& options) {
    return OpStatus::composed(why_not_remesh(mesh, options));
}

RemeshReport remesh(Mesh& mesh, const RemeshOptions& options) {
    MESHEDIT_ASSERT(check_remesh(mesh, options));
    if (options.progress) {
        options.progress(0.0);
    }
    // On a copy: a remesh stopped by the growth guard leaves the input as it was.
    Mesh work = mesh;
    RemeshOptions region = options;  // the region's faces as the compacted copy numbers them
    std::optional<Mesh> compacted;   // the input without garbage, for its attributes
    if (work.has_garbage()) {
        GarbageCollectionMap map;
        work.garbage_collection(&map);
        for (Face& f : region.faces) {
            f = map.faces[f.idx()];
        }
        if (remeshing::has_projected_attributes(work)) {
            compacted = work;
        }
    }
    const Mesh* source = compacted                                   ? &*compacted
                         : remeshing::has_projected_attributes(mesh) ? &mesh
                                                                     : nullptr;
    RemeshReport report;
    // Sharp edges found become creases, which the remesher keeps as features.
    const std::size_t marked = options.feature_angle_deg == kNoFeatureAngle
                                   ? 0
                                   : crease_by_angle(work, options.feature_angle_deg);
    {
        // Lengths and areas square coordinates: keep them near 1, the target scaled alike.
        const UnitScale unit(work);
        RemeshOptions scaled = region;
        scaled.target_length = unit.scaled(options.target_length);
        report = Remesher(work, scaled, source).run();
        report.target_length = unit.unscaled(report.target_length);
    }
    report.creases_marked = marked;
    MESHEDIT_ASSERT(!validate(work));
    mesh = std::move(work);
    return report;
}

}  // namespace meshedit
