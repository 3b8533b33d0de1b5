// Polygon soup -> halfedge mesh. The only place where input topology is diagnosed.
//
// Outline (all passes are linear except the per-vertex bucket scans: O(valence²) for the
// usual small buckets, sorted first when big, so O(n log n) whatever the input):
//   1. drop degenerate faces; check indices and positions;
//   2. pair each face halfedge u->v with the one v->u, bucketing halfedges by their smaller
//      endpoint; an edge used by more than two faces, or twice in one direction, is cut:
//      all its halfedges stay unpaired and become boundary;
//   3. group the corners around each vertex into fans (walks over corners linked through
//      paired edges); every fan after the first gets a copy of the vertex; the two sides of a
//      cut edge that still join the same two vertices are glued (no doubled edges);
//   4. assign edges in order of first appearance, add boundary twins, link boundary loops.
#include "meshedit/core/build.h"

#include <algorithm>
#include <sstream>

#include "mesh/parallel.h"
#include "meshedit/core/memory.h"

namespace meshedit {
namespace {

constexpr std::uint32_t kNone = kInvalidIndex;

// Pairwise for the small faces files are made of; sorted for big polygons, so that a
// 1,000,000-corner face costs O(k log k), not O(k²).
bool has_repeated_corner(const std::uint32_t* c, std::size_t k) {
    if (k > 32) {
        std::vector<std::uint32_t> sorted(c, c + k);
        std::sort(sorted.begin(), sorted.end());
        return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    }
    for (std::size_t i = 0; i < k; ++i) {
        for (std::size_t j = i + 1; j < k; ++j) {
            if (c[i] == c[j]) {
                return true;
            }
        }
    }
    return false;
}

// Face halfedges of the kept faces, in CSR order: halfedge h runs from corner[h] to
// corner[next[h]], and face f owns [first[f], first[f + 1]). When no face is dropped,
// `corner` and `first` are the soup's own arrays, not copies.
struct SoupHalfedges {
    const std::uint32_t* corner = nullptr;
    const std::uint32_t* first = nullptr;
    std::uint32_t n_halfedges = 0;
    std::uint32_t n_faces = 0;
    memory::Array<std::uint32_t> next;
    memory::Array<std::uint32_t> kept_corner;  // storage when faces were dropped
    memory::Array<std::uint32_t> kept_first;

    // No prev array: inside a face it is h - 1; a face's first halfedge walks its face once.
    std::uint32_t prev(std::uint32_t h) const {
        if (h > 0 && next[h - 1] == h) {
            return h - 1;
        }
        std::uint32_t x = h;
        while (next[x] != h) {
            x = next[x];
        }
        return x;
    }
};

// Scratch storage of two words per face halfedge, used twice so that its memory is faulted
// in once (fresh pages dominate the cost of big builds): pair_halfedges() sorts {other
// endpoint, halfedge} entries in it, then build_mesh() keeps each face halfedge's {fan vertex,
// mesh halfedge} there.
struct TwoWords {
    std::uint32_t first;
    std::uint32_t second;
};

void collect_faces(const PolygonSoup& soup, SoupHalfedges& fh, BuildReport& report) {
    const std::uint32_t* off = soup.face_offsets.data();
    for (std::uint32_t f = 0; f < soup.n_faces(); ++f) {
        const std::size_t k = off[f + 1] - off[f];
        if (k < 3 || has_repeated_corner(soup.indices.data() + off[f], k)) {
            report.dropped_faces.push_back(f);
        }
    }
    if (report.dropped_faces.empty()) {
        fh.corner = soup.indices.data();
        fh.first = off;
        fh.n_halfedges = static_cast<std::uint32_t>(soup.indices.size());
        fh.n_faces = static_cast<std::uint32_t>(soup.n_faces());
    } else {
        fh.kept_corner.reserve(soup.indices.size());
        fh.kept_first.reserve(soup.face_offsets.size());
        fh.kept_first.push_back(0);
        std::size_t d = 0;  // next dropped face
        for (std::uint32_t f = 0; f < soup.n_faces(); ++f) {
            if (d < report.dropped_faces.size() && report.dropped_faces[d] == f) {
                ++d;
                continue;
            }
            fh.kept_corner.insert(fh.kept_corner.end(), soup.indices.begin() + off[f],
                                  soup.indices.begin() + off[f + 1]);
            fh.kept_first.push_back(static_cast<std::uint32_t>(fh.kept_corner.size()));
        }
        fh.corner = fh.kept_corner.data();
        fh.first = fh.kept_first.data();
        fh.n_halfedges = static_cast<std::uint32_t>(fh.kept_corner.size());
        fh.n_faces = static_cast<std::uint32_t>(fh.kept_first.size() - 1);
    }
    fh.next.resize(fh.n_halfedges);
    for (std::uint32_t f = 0; f < fh.n_faces; ++f) {
        const std::uint32_t b = fh.first[f];
        const std::uint32_t e = fh.first[f + 1];
        for (std::uint32_t h = b; h + 1 < e; ++h) {
            fh.next[h] = h + 1;
        }
        fh.next[e - 1] = b;
    }
}

// mate[h] = the opposite face halfedge, or kNone for an unpaired (boundary or cut) one.
// Meshes this big pair their halfedges on several threads; the result is the same.
constexpr std::size_t kParallelHalfedges = std::size_t{1} << 18;
// Buckets with more entries than this are sorted before they are scanned.
constexpr std::uint32_t kSortedBucket = 32;
constexpr std::size_t kVerticesPerChunk = std::size_t{1} << 14;

// `n_pairs` counts the pairs made; `bucket` is scratch.
memory::Array<std::uint32_t> pair_halfedges(const SoupHalfedges& fh, std::size_t n_vertices,
                                            memory::Array<TwoWords>& bucket, std::uint32_t& n_pairs,
                                            BuildReport& report) {
    const std::uint32_t nh = fh.n_halfedges;
    const std::uint32_t* corner = fh.corner;
    const std::uint32_t* next = fh.next.data();
    const unsigned threads = parallel::thread_count(nh, kParallelHalfedges);

    // Bucket halfedges by their smaller endpoint: a counting sort, stable in h, whose count
    // and fill passes each thread runs over its own part of the halfedges (part p's entries
    // go after those of parts < p in every bucket, which keeps it stable). Each entry is
    // {other endpoint, h}, so that scanning a bucket reads one small contiguous range instead
    // of chasing corner[next[h]] for every candidate; `other` becomes kNone once handled.
    const std::size_t part = (std::size_t{nh} + threads - 1) / threads;
    std::vector<memory::Array<std::uint32_t>> fill(threads);
    parallel::for_chunks(nh, part, threads, [&](std::size_t begin, std::size_t end) {
        memory::Array<std::uint32_t>& count = fill[begin / part];
        count.assign(n_vertices, 0);
        for (std::size_t h = begin; h < end; ++h) {
            ++count[std::min(corner[h], corner[next[h]])];
        }
    });
    memory::Array<std::uint32_t> start(n_vertices + 1);
    std::uint32_t sum = 0;
    for (std::size_t a = 0; a < n_vertices; ++a) {
        start[a] = sum;
        for (memory::Array<std::uint32_t>& count : fill) {
            const std::uint32_t n = count.empty() ? 0 : count[a];
            if (!count.empty()) {
                count[a] = sum;  // from counts to this part's first slot in bucket a
            }
            sum += n;
        }
    }
    start[n_vertices] = sum;
    bucket.resize(nh);
    parallel::for_chunks(nh, part, threads, [&](std::size_t begin, std::size_t end) {
        memory::Array<std::uint32_t>& slot = fill[begin / part];
        for (std::size_t h = begin; h < end; ++h) {
            const std::uint32_t u = corner[h];
            const std::uint32_t v = corner[next[h]];
            bucket[slot[std::min(u, v)]++] = {std::max(u, v), static_cast<std::uint32_t>(h)};
        }
    });
    fill = {};

    // Buckets are independent: chunks of vertices scan theirs on any thread, and their
    // reports are joined in vertex order. A bucket is scanned pairwise when it is small (the
    // usual few edges per vertex); a big one (the hub of a fan of a million triangles) is
    // first sorted by other endpoint, so each group is contiguous and the scan linear.
    memory::Array<std::uint32_t> mate(nh, kNone);
    const std::size_t n_chunks = (n_vertices + kVerticesPerChunk - 1) / kVerticesPerChunk;
    std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> cut(n_chunks);
    std::vector<std::uint32_t> pairs(n_chunks, 0);
    parallel::for_chunks(n_vertices, kVerticesPerChunk, threads,
                         [&](std::size_t first, std::size_t last) {
                             const std::size_t c = first / kVerticesPerChunk;
                             for (std::size_t a = first; a < last; ++a) {
                                 const std::uint32_t end = start[a + 1];
                                 if (end - start[a] > kSortedBucket) {
                                     // Stable in h within each group, as the scan expects.
                                     std::sort(bucket.begin() + start[a], bucket.begin() + end,
                                               [](const TwoWords& x, const TwoWords& y) {
                                                   return x.first != y.first ? x.first < y.first
                                                                             : x.second < y.second;
                                               });
                                 }
                                 for (std::uint32_t i = start[a]; i < end; ++i) {
                                     const std::uint32_t b = bucket[i].first;
                                     if (b == kNone) {
                                         continue;
                                     }
                                     // All halfedges of the bucket joining a and b; forward ones
                                     // run like bucket[i].
                                     const std::uint32_t h = bucket[i].second;
                                     std::uint32_t count = 0, forward = 0, backward = 0;
                                     std::uint32_t h_fwd = kNone, h_bwd = kNone;
                                     // Sorted buckets: the group ends at the first other b.
                                     const bool sorted = end - start[a] > kSortedBucket;
                                     for (std::uint32_t j = i; j < end; ++j) {
                                         if (sorted && bucket[j].first != b) {
                                             break;
                                         }
                                         if (bucket[j].first == b) {
                                             bucket[j].first = kNone;
                                             const std::uint32_t g = bucket[j].second;
                                             ++count;
                                             if (corner[g] == corner[h]) {
                                                 ++forward;
                                                 h_fwd = g;
                                             } else {
                                                 ++backward;
                                                 h_bwd = g;
                                             }
                                         }
                                     }
                                     if (forward == 1 && backward == 1) {
                                         mate[h_fwd] = h_bwd;
                                         mate[h_bwd] = h_fwd;
                                         ++pairs[c];
                                     } else if (count > 1) {
                                         cut[c].emplace_back(static_cast<std::uint32_t>(a), b);
                                     }
                                 }
                             }
                         });
    for (std::size_t c = 0; c < n_chunks; ++c) {
        n_pairs += pairs[c];
        report.nonmanifold_edges.insert(report.nonmanifold_edges.end(), cut[c].begin(),
                                        cut[c].end());
    }
    return mate;
}

// The vertex each corner belongs to. Corner h is where halfedge h arrives (at
// corner[next[h]]). The corners around a vertex are linked through paired edges, h to
// mate[next[h]]; each linked group is one fan, and every fan after the first gets a copy of
// the vertex. A corner has at most one link out and one in, so a fan is a path or a cycle and
// one walk each way labels it. Fans are numbered in order of their smallest corner.
// Writes slots[h].first; the slots start as kNone.
void label_fans(const SoupHalfedges& fh, const memory::Array<std::uint32_t>& mate,
                const std::vector<Vec3>& positions, memory::Array<TwoWords>& slots,
                std::vector<Vec3>& extra_positions, BuildReport& report) {
    const std::uint32_t nh = fh.n_halfedges;
    const std::size_t nv_in = positions.size();
    auto fan_vertex = [&](std::uint32_t h) -> std::uint32_t& { return slots[h].first; };
    memory::Array<std::uint8_t> used(nv_in, 0);
    for (std::uint32_t h = 0; h < nh; ++h) {
        if (fan_vertex(h) != kNone) {
            continue;
        }
        const std::uint32_t v = fh.corner[fh.next[h]];
        std::uint32_t label = v;
        if (!used[v]) {
            used[v] = 1;
        } else {
            if (used[v] == 1) {
                report.split_vertices.push_back(v);
                used[v] = 2;
            }
            label = static_cast<std::uint32_t>(nv_in + extra_positions.size());
            extra_positions.push_back(positions[v]);
        }
        fan_vertex(h) = label;
        // Forward (out-links) until the fan ends or closes into a cycle back at h.
        std::uint32_t c = mate[fh.next[h]];
        while (c != kNone && c != h) {
            fan_vertex(c) = label;
            c = mate[fh.next[c]];
        }
        if (c == h) {
            continue;
        }
        // An open fan: also backward (in-links) from h.
        for (std::uint32_t m = mate[h]; m != kNone;) {
            c = fh.prev(m);
            fan_vertex(c) = label;
            m = mate[c];
        }
    }
    std::sort(report.split_vertices.begin(), report.split_vertices.end());
    report.added_vertices = extra_positions.size();
    report.isolated_vertices =
        static_cast<std::size_t>(std::count(used.begin(), used.end(), std::uint8_t{0}));
}

// A cut edge whose sides still end at the same two fan vertices after label_fans() would
// become two edges joining the same two vertices: a slit, a boundary loop of two edges that
// no face-list file can describe. (The smallest case: faces (0,1,2), (0,2,1), (0,1,3); edge
// 0-1 is cut, the third face gets copies of 0 and 1, and the first two still share both.)
// Such sides are glued back into one edge. Within one fan a corner is linked out only through
// a paired halfedge, so the fan at either end has exactly one unpaired side leaving and one
// arriving: at most one u->v and one v->u side share their fan vertices, and gluing them
// closes both fans into cycles without changing any fan label. \return the pairs made.
std::uint32_t glue_slits(const SoupHalfedges& fh, memory::Array<std::uint32_t>& mate,
                         const memory::Array<TwoWords>& slots) {
    struct Side {
        std::uint32_t lo, hi, h;  // fan vertices (smaller first) and the halfedge
    };
    std::vector<Side> sides;
    for (std::uint32_t h = 0; h < fh.n_halfedges; ++h) {
        if (mate[h] == kNone) {
            const std::uint32_t from = slots[fh.prev(h)].first;
            const std::uint32_t to = slots[h].first;
            sides.push_back({std::min(from, to), std::max(from, to), h});
        }
    }
    std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
        return a.lo != b.lo ? a.lo < b.lo : a.hi != b.hi ? a.hi < b.hi : a.h < b.h;
    });
    std::uint32_t glued = 0;
    for (std::size_t i = 0; i + 1 < sides.size(); ++i) {
        if (sides[i].lo == sides[i + 1].lo && sides[i].hi == sides[i + 1].hi &&
            slots[sides[i].h].first != slots[sides[i + 1].h].first) {  // opposite directions
            mate[sides[i].h] = sides[i + 1].h;
            mate[sides[i + 1].h] = sides[i].h;
            ++glued;
            ++i;
        }
    }
    return glued;
}

}  // namespace

void check_polygon_soup(const PolygonSoup& soup) {
    const auto& off = soup.face_offsets;
    if (off.empty() || off.front() != 0 || off.back() != soup.indices.size()) {
        throw TopologyError("polygon soup: face offsets do not cover the index list");
    }
    for (std::size_t f = 0; f + 1 < off.size(); ++f) {
        if (off[f + 1] < off[f]) {
            throw TopologyError("polygon soup: face offsets decrease at face " + std::to_string(f));
        }
        for (std::uint32_t i = off[f]; i < off[f + 1]; ++i) {
            if (soup.indices[i] >= soup.positions.size()) {
                throw TopologyError("face " + std::to_string(f) + " uses vertex " +
                                    std::to_string(soup.indices[i]) + ", but there are only " +
                                    std::to_string(soup.positions.size()) + " vertices");
            }
        }
    }
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        if (!is_finite(soup.positions[v])) {
            throw TopologyError("vertex " + std::to_string(v) + " has a non-finite coordinate");
        }
    }
}

Mesh build_mesh(const PolygonSoup& soup, BuildReport* report_out) {
    check_polygon_soup(soup);
    BuildReport report;
    const std::size_t nv_in = soup.positions.size();
    SoupHalfedges fh;
    collect_faces(soup, fh, report);
    std::uint32_t n_pairs = 0;
    memory::Array<TwoWords> slots;
    memory::Array<std::uint32_t> mate = pair_halfedges(fh, nv_in, slots, n_pairs, report);
    const std::uint32_t nh = fh.n_halfedges;
    const std::uint32_t nf = fh.n_faces;

    std::vector<Vec3> extra_positions;
    // From here on slots[h] = {fan vertex, mesh halfedge} of face halfedge h.
    std::fill(slots.begin(), slots.end(), TwoWords{kNone, kNone});
    label_fans(fh, mate, soup.positions, slots, extra_positions, report);
    if (!report.nonmanifold_edges.empty()) {
        n_pairs += glue_slits(fh, mate, slots);
    }
    auto fan_vertex = [&](std::uint32_t h) { return slots[h].first; };
    auto mesh_halfedge = [&](std::uint32_t h) -> std::uint32_t& { return slots[h].second; };

    Mesh mesh;
    mesh.resize(nv_in + extra_positions.size(), nh - n_pairs, nf);
    std::copy(soup.positions.begin(), soup.positions.end(), mesh.position_vector().begin());
    std::copy(extra_positions.begin(), extra_positions.end(),
              mesh.position_vector().begin() + static_cast<std::ptrdiff_t>(nv_in));

    // Edges in order of first appearance: a paired edge is (h, mate); an unpaired one is
    // (h, boundary twin). A face's halfedges are numbered before its corners pick their
    // vertex's halfedge (the first corner in order wins), as both only look back.
    std::uint32_t n_edges = 0;
    for (std::uint32_t f = 0; f < nf; ++f) {
        const std::uint32_t begin = fh.first[f];
        const std::uint32_t end = fh.first[f + 1];
        for (std::uint32_t h = begin; h < end; ++h) {
            if (mesh_halfedge(h) == kNone) {
                mesh_halfedge(h) = 2 * n_edges;
                if (mate[h] != kNone) {
                    mesh_halfedge(mate[h]) = 2 * n_edges + 1;
                }
                ++n_edges;
            }
        }
        for (std::uint32_t h = begin; h < end; ++h) {
            const Vertex v(fan_vertex(h));
            if (!mesh.halfedge(v).is_valid()) {
                mesh.set_halfedge(v, Halfedge(mesh_halfedge(h + 1 < end ? h + 1 : begin)));
            }
        }
    }
    // The links touch each mesh halfedge, face and boundary vertex from one face halfedge
    // only, so chunks of faces write them on any thread. A fan has at most one unpaired
    // corner (its start), so a vertex has at most one outgoing boundary halfedge.
    constexpr std::size_t kFacesPerChunk = std::size_t{1} << 14;
    const unsigned threads = parallel::thread_count(nh, kParallelHalfedges);
    std::vector<std::vector<std::uint32_t>> unpaired((nf + kFacesPerChunk - 1) / kFacesPerChunk);
    memory::Array<Halfedge> out_boundary(mesh.vertices_size());
    parallel::for_chunks(nf, kFacesPerChunk, threads, [&](std::size_t first, std::size_t last) {
        std::vector<std::uint32_t>& chunk_unpaired = unpaired[first / kFacesPerChunk];
        for (std::size_t f = first; f < last; ++f) {
            const std::uint32_t begin = fh.first[f];
            const std::uint32_t end = fh.first[f + 1];
            mesh.set_halfedge(Face(static_cast<std::uint32_t>(f)), Halfedge(mesh_halfedge(begin)));
            for (std::uint32_t h = begin; h < end; ++h) {
                const Halfedge mh(mesh_halfedge(h));
                const Vertex v(fan_vertex(h));
                mesh.set_vertex(mh, v);
                mesh.set_face(mh, Face(static_cast<std::uint32_t>(f)));
                mesh.set_next(mh, Halfedge(mesh_halfedge(h + 1 < end ? h + 1 : begin)));
                if (mate[h] == kNone) {
                    // Boundary twin: runs from v back to where h starts; v's outgoing boundary.
                    const Halfedge b = Mesh::twin(mh);
                    mesh.set_vertex(b, Vertex(fan_vertex(h > begin ? h - 1 : end - 1)));
                    mesh.set_face(b, Face());
                    out_boundary[v.idx()] = b;
                    chunk_unpaired.push_back(h);
                }
            }
        }
    });
    // Boundary loops, in order of the unpaired face halfedges.
    for (const std::vector<std::uint32_t>& chunk_unpaired : unpaired) {
        for (const std::uint32_t h : chunk_unpaired) {
            const Halfedge b = Mesh::twin(Halfedge(mesh_halfedge(h)));
            mesh.set_next(b, out_boundary[mesh.to_vertex(b).idx()]);
        }
    }
    for (std::uint32_t v = 0; v < out_boundary.size(); ++v) {
        if (out_boundary[v].is_valid()) {
            mesh.set_halfedge(Vertex(v), out_boundary[v]);  // boundary-anchor rule
        }
    }
    if (report_out != nullptr) {
        *report_out = std::move(report);
    }
    return mesh;
}

double build_bytes(double vertices, double corners, double faces) {
    // Soup: a position (24) and a normal (24) per vertex, an index per corner, an offset per
    // face. Build: about 12 bytes of scratch per corner. Mesh: each corner is a halfedge of
    // 16 bytes, with a twin; an edge byte per corner; 29 bytes per vertex, 5 per face.
    return vertices * (48.0 + 29.0) + corners * (4.0 + 12.0 + 2.0 * 16.0 + 1.0) +
           faces * (4.0 + 5.0);
}

PolygonSoup to_polygon_soup(const Mesh& mesh) {
    PolygonSoup soup;
    soup.positions.assign(mesh.position_vector().begin(), mesh.position_vector().end());
    soup.indices.reserve(3 * mesh.n_faces());
    soup.face_offsets.reserve(mesh.n_faces() + 1);
    for (Face f : mesh.faces()) {
        // Start at from_vertex(halfedge(f)) so that build_mesh() reproduces the mesh exactly.
        for (Halfedge h : mesh.halfedges(f)) {
            soup.indices.push_back(mesh.from_vertex(h).idx());
        }
        soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
    }
    return soup;
}

namespace {

template <class List>
std::string list_some(const List& items, std::size_t limit = 8) {
    std::ostringstream s;
    for (std::size_t i = 0; i < items.size() && i < limit; ++i) {
        s << (i ? ", " : "") << items[i];
    }
    if (items.size() > limit) {
        s << ", …";
    }
    return s.str();
}

}  // namespace

std::string BuildReport::summary() const {
    auto count = [](std::size_t n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    std::ostringstream s;
    if (!dropped_faces.empty()) {
        s << "dropped " << count(dropped_faces.size(), "degenerate face", "degenerate faces")
          << " (fewer than 3 corners or a repeated corner): " << list_some(dropped_faces) << "\n";
    }
    if (!nonmanifold_edges.empty()) {
        std::vector<std::string> names;
        for (const auto& [a, b] : nonmanifold_edges) {
            names.push_back(std::to_string(a) + "-" + std::to_string(b));
        }
        s << "cut "
          << count(nonmanifold_edges.size(), "non-manifold or inconsistently oriented edge",
                   "non-manifold or inconsistently oriented edges")
          << " into boundaries: " << list_some(names) << "\n";
    }
    if (!split_vertices.empty()) {
        s << "split "
          << count(split_vertices.size(), "non-manifold vertex", "non-manifold vertices") << " ("
          << list_some(split_vertices) << ") by adding " << count(added_vertices, "copy", "copies")
          << "\n";
    }
    return s.str();
}

}  // namespace meshedit
