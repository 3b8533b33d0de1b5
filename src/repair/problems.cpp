// What is wrong with a mesh (problems.h): each kind found in one pass over what it needs,
// each problem with the element that shows it.

#include "meshedit/repair/problems.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "meshedit/core/normals.h"
#include "soup_edit.h"

namespace meshedit {
namespace {

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

struct Collector {
    ProblemReport& report;
    const ProblemOptions& options;
    void add(ProblemKind kind, ElementRef where, std::size_t size, std::string text) {
        const std::size_t k = static_cast<std::size_t>(kind);
        if (report.counts[k]++ < options.listed) {
            report.problems.push_back({kind, where, size, std::move(text)});
        }
    }
};

void load_cuts(const Mesh& mesh, const BuildReport& load, Collector& out) {
    const auto vertex = [&](std::uint32_t v) {
        return v < mesh.vertices_size() ? ElementRef::vertex(Vertex(v)) : ElementRef{};
    };
    for (const auto& [a, b] : load.nonmanifold_edges) {
        out.add(ProblemKind::LoadCut, vertex(a), 1,
                "edge " + std::to_string(a) + "-" + std::to_string(b) +
                    " cut apart on load (more than two faces, or two that disagree on direction)");
    }
    for (const std::uint32_t v : load.split_vertices) {
        out.add(ProblemKind::LoadCut, vertex(v), 1,
                "vertex " + std::to_string(v) + " split on load (its faces formed separate fans)");
    }
    for (const std::uint32_t f : load.dropped_faces) {
        out.add(ProblemKind::LoadCut, ElementRef{}, 1,
                "face " + std::to_string(f) + " of the file dropped on load (a repeated corner)");
    }
}

void holes(const Mesh& mesh, Collector& out) {
    std::vector<bool> seen(mesh.halfedges_size(), false);
    for (const Halfedge h : mesh.halfedges()) {
        if (seen[h.idx()] || !mesh.is_boundary(h)) {
            continue;
        }
        std::size_t n = 0;
        for (const Halfedge x : mesh.loop(h)) {
            seen[x.idx()] = true;
            ++n;
        }
        const Vertex at = mesh.from_vertex(h);
        out.add(ProblemKind::Hole, ElementRef::edge(Mesh::edge(h)), n,
                "hole of " + plural(n, "edge", "edges") + " at vertex " + std::to_string(at.idx()));
    }
}

void degenerate_faces(const Mesh& mesh, Collector& out) {
    for (const Face f : mesh.faces()) {
        double longest = 0.0;
        bool repeated = false;
        for (const Halfedge h : mesh.halfedges(f)) {
            const Vec3 a = mesh.position(mesh.from_vertex(h));
            const Vec3 b = mesh.position(mesh.to_vertex(h));
            longest = std::max(longest, sqrnorm(b - a));
            repeated = repeated || a == b;
        }
        const double area = 0.5 * norm(face_area_vector(mesh, f));
        if (repeated || area <= 1e-12 * longest) {
            out.add(ProblemKind::DegenerateFace, ElementRef::face(f), 1,
                    "face " + std::to_string(f.idx()) +
                        (repeated ? " has two corners at one point" : " has no area"));
        }
    }
}

// Parts joined across edges: small ones, and closed ones that enclose a negative volume (not a
// flat one: a double-sided sheet has no inside, Enclosure).
void parts(const Mesh& mesh, Collector& out, const ProblemOptions& options) {
    std::vector<std::int32_t> part(mesh.faces_size(), -1);
    std::vector<std::vector<Face>> members;
    for (const Face seed : mesh.faces()) {
        if (part[seed.idx()] >= 0) {
            continue;
        }
        const auto id = static_cast<std::int32_t>(members.size());
        std::vector<Face>& faces = members.emplace_back(1, seed);
        part[seed.idx()] = id;
        for (std::size_t i = 0; i < faces.size(); ++i) {
            for (const Halfedge h : mesh.halfedges(faces[i])) {
                const Face g = mesh.face(Mesh::twin(h));
                if (g.is_valid() && part[g.idx()] < 0) {
                    part[g.idx()] = id;
                    faces.push_back(g);
                }
            }
        }
    }
    for (const std::vector<Face>& faces : members) {
        bool closed = true;
        repair_detail::Enclosure inside;
        const Vec3 origin = mesh.position(mesh.to_vertex(mesh.halfedge(faces[0])));
        for (const Face f : faces) {
            const Halfedge h0 = mesh.halfedge(f);
            const Vec3 p0 = mesh.position(mesh.from_vertex(h0)) - origin;
            for (const Halfedge h : mesh.halfedges(f)) {
                closed = closed && !mesh.is_boundary(Mesh::twin(h));
            }
            for (Halfedge h = mesh.next(h0); mesh.next(h) != h0; h = mesh.next(h)) {
                inside.add(p0, mesh.position(mesh.from_vertex(h)) - origin,
                           mesh.position(mesh.to_vertex(h)) - origin);
            }
        }
        const ElementRef where = ElementRef::face(faces[0]);
        if (closed && inside.faces_inward()) {
            out.add(ProblemKind::InsideOut, where, faces.size(),
                    "closed part of " + plural(faces.size(), "face", "faces") + " at face " +
                        std::to_string(faces[0].idx()) + " faces inward (negative volume)");
        }
        if (members.size() > 1 && faces.size() < options.small_part_faces) {
            out.add(ProblemKind::SmallPart, where, faces.size(),
                    "part of " + plural(faces.size(), "face", "faces") + " at face " +
                        std::to_string(faces[0].idx()));
        }
    }
}

}  // namespace

const char* problem_kind_name(ProblemKind kind) {
    switch (kind) {
        case ProblemKind::LoadCut:
            return "load cut";
        case ProblemKind::Hole:
            return "hole";
        case ProblemKind::DegenerateFace:
            return "degenerate face";
        case ProblemKind::InsideOut:
            return "inside out";
        case ProblemKind::SmallPart:
            return "small part";
        case ProblemKind::SelfIntersection:
            return "self-intersection";
    }
    return "?";
}

bool ProblemReport::empty() const {
    return std::all_of(counts.begin(), counts.end(), [](std::size_t n) { return n == 0; });
}

std::string ProblemReport::summary() const {
    static constexpr const char* kMany[] = {"load cuts",  "holes",       "degenerate faces",
                                            "inside out", "small parts", "self-intersections"};
    std::string text;
    for (std::size_t k = 0; k < kProblemKinds; ++k) {
        if (counts[k] > 0) {
            const char* one = problem_kind_name(static_cast<ProblemKind>(k));
            text += (text.empty() ? "" : ", ") +
                    (k == static_cast<std::size_t>(ProblemKind::InsideOut)
                         ? plural(counts[k], "part inside out", "parts inside out")
                         : plural(counts[k], one, kMany[k]));
        }
    }
    return text.empty() ? "no problems" : text;
}

ProblemReport find_problems(const Mesh& mesh, const BuildReport* load,
                            const ProblemOptions& options) {
    ProblemReport report;
    Collector out{report, options};
    if (load != nullptr) {
        load_cuts(mesh, *load, out);
    }
    holes(mesh, out);
    degenerate_faces(mesh, out);
    parts(mesh, out, options);
    if (options.self_intersections) {
        for (const auto& [f, g] : self_intersections(mesh)) {
            out.add(ProblemKind::SelfIntersection, ElementRef::face(f), 1,
                    "faces " + std::to_string(f.idx()) + " and " + std::to_string(g.idx()) +
                        " pass through each other");
        }
    }
    std::stable_sort(report.problems.begin(), report.problems.end(),
                     [](const Problem& a, const Problem& b) { return a.kind < b.kind; });
    return report;
}

}  // namespace meshedit
