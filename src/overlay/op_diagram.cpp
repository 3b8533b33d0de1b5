// The rewiring diagram (op_diagram.h): which faces to show, where to put their vertices
// in the plane, what changed, and the picture. GL-free.

#include "meshedit/overlay/op_diagram.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

namespace meshedit {
namespace {

using op_diagram_detail::Names;
using Layout = std::unordered_map<std::uint32_t, Vec3>;  // vertex index -> z = 0 point

// ---------------------------------------------------------------------------- regions

struct Region {
    std::vector<Face> faces;
    std::vector<Vertex> vertices;  // of the faces, in the order met
};

void add_face(const Mesh& mesh, Face f, Region& r, std::unordered_set<std::uint32_t>& seen) {
    if (!f.is_valid() || mesh.is_deleted(f) || !seen.insert(f.idx()).second) {
        return;
    }
    r.faces.push_back(f);
    for (Vertex v : mesh.vertices(f)) {
        if (std::find(r.vertices.begin(), r.vertices.end(), v) == r.vertices.end()) {
            r.vertices.push_back(v);
        }
    }
}

void add_faces_around(const Mesh& mesh, Vertex v, Region& r,
                      std::unordered_set<std::uint32_t>& seen) {
    if (mesh.is_isolated(v)) {
        return;
    }
    for (Face f : mesh.faces(v)) {
        add_face(mesh, f, r, seen);
    }
}

Region region_before(const Mesh& mesh, CodeNames names, ElementRef input) {
    Region r;
    std::unordered_set<std::uint32_t> seen;
    switch (input.kind) {
        case ElementRef::Kind::Vertex:
            add_faces_around(mesh, Vertex(input.index), r, seen);
            break;
        case ElementRef::Kind::Halfedge:
        case ElementRef::Kind::Edge: {
            const Edge e = input.kind == ElementRef::Kind::Edge ? Edge(input.index)
                                                                : Mesh::edge(Halfedge(input.index));
            if (names == CodeNames::Collapse) {
                add_faces_around(mesh, mesh.vertex(e, 0), r, seen);
                add_faces_around(mesh, mesh.vertex(e, 1), r, seen);
            } else {
                add_face(mesh, mesh.face(e, 0), r, seen);
                add_face(mesh, mesh.face(e, 1), r, seen);
            }
            break;
        }
        case ElementRef::Kind::Face: {
            const Face f(input.index);
            add_face(mesh, f, r, seen);
            for (Halfedge h : mesh.halfedges(f)) {
                add_face(mesh, mesh.face(Mesh::twin(h)), r, seen);
            }
            break;
        }
        case ElementRef::Kind::None:
            break;
    }
    return r;
}

bool live(const Mesh& mesh, Halfedge h) {
    return h.idx() < mesh.halfedges_size() && !mesh.is_deleted(h);
}
bool live(const Mesh& mesh, Vertex v) {
    return v.idx() < mesh.vertices_size() && !mesh.is_deleted(v);
}
bool live(const Mesh& mesh, Face f) {
    return f.idx() < mesh.faces_size() && !mesh.is_deleted(f);
}

// The loop of f as halfedge indices.
std::vector<std::uint32_t> loop_of(const Mesh& mesh, Face f) {
    std::vector<std::uint32_t> out;
    for (Halfedge h : mesh.halfedges(f)) {
        out.push_back(h.idx());
    }
    return out;
}

// After: the faces on the region's vertices (and new vertices) that are new, were shown
// before, or changed their loop.
Region region_after(const Mesh& before, const Mesh& after, const Region& old) {
    std::unordered_set<std::uint32_t> allowed, shown;
    for (Vertex v : old.vertices) {
        allowed.insert(v.idx());
    }
    for (auto v = static_cast<std::uint32_t>(before.vertices_size()); v < after.vertices_size();
         ++v) {
        allowed.insert(v);
    }
    for (Face f : old.faces) {
        shown.insert(f.idx());
    }
    std::vector<std::uint32_t> candidates(allowed.begin(), allowed.end());
    std::sort(candidates.begin(), candidates.end());  // no hash order in the picture
    std::vector<Face> faces;
    std::unordered_set<std::uint32_t> seen;
    for (const std::uint32_t v : candidates) {
        if (!live(after, Vertex(v)) || after.is_isolated(Vertex(v))) {
            continue;
        }
        for (Face f : after.faces(Vertex(v))) {
            bool inside = true;
            for (Vertex w : after.vertices(f)) {
                inside = inside && allowed.count(w.idx()) != 0;
            }
            const bool fresh = !live(before, f);
            if (inside && seen.insert(f.idx()).second &&
                (fresh || shown.count(f.idx()) != 0 || loop_of(before, f) != loop_of(after, f))) {
                faces.push_back(f);
            }
        }
    }
    std::sort(faces.begin(), faces.end());
    Region r;
    seen.clear();
    for (Face f : faces) {
        add_face(after, f, r, seen);
    }
    return r;
}

// ---------------------------------------------------------------------------- layout

// The halfedges of the region's faces whose twins lie outside it, as one loop in order, or
// empty when the region is not a disk (several loops, a pinched vertex, closed).
std::vector<Halfedge> outline(const Mesh& mesh, const Region& r) {
    std::unordered_set<std::uint32_t> faces;
    for (Face f : r.faces) {
        faces.insert(f.idx());
    }
    std::unordered_map<std::uint32_t, Halfedge> leaving;
    for (Face f : r.faces) {
        for (Halfedge h : mesh.halfedges(f)) {
            const Face across = mesh.face(Mesh::twin(h));
            if (!across.is_valid() || faces.count(across.idx()) == 0) {
                if (!leaving.emplace(mesh.from_vertex(h).idx(), h).second) {
                    return {};
                }
            }
        }
    }
    if (leaving.empty()) {
        return {};
    }
    // Start at the smallest vertex index: the same outline gives the same loop.
    std::uint32_t start = leaving.begin()->first;
    for (const auto& [v, h] : leaving) {
        start = std::min(start, v);
    }
    std::vector<Halfedge> loop;
    std::uint32_t v = start;
    do {
        const auto it = leaving.find(v);
        if (it == leaving.end() || loop.size() > leaving.size()) {
            return {};
        }
        loop.push_back(it->second);
        v = mesh.to_vertex(it->second).idx();
    } while (v != start);
    return loop.size() == leaving.size() ? loop : std::vector<Halfedge>{};
}

// The plane the diagram is drawn in: x along `x_hint` (the input edge), z the region's
// normal, in the mesh's coordinates.
struct Frame {
    Vec3 origin, x, y;
    Vec3 flat(const Vec3& p) const { return {dot(p - origin, x), dot(p - origin, y), 0.0}; }
};

Frame frame_of(const Mesh& mesh, const Region& r, const Vec3& x_hint) {
    Vec3 normal, centre;
    for (Face f : r.faces) {
        std::vector<Vec3> p;
        for (Vertex v : mesh.vertices(f)) {
            p.push_back(mesh.position(v));
        }
        for (std::size_t i = 1; i + 1 < p.size(); ++i) {
            normal += cross(p[i] - p[0], p[i + 1] - p[0]);
        }
    }
    for (Vertex v : r.vertices) {
        centre += mesh.position(v);
    }
    Frame frame;
    frame.origin = r.vertices.empty() ? Vec3{} : centre / static_cast<double>(r.vertices.size());
    const Vec3 n = normalize(normal);
    Vec3 x = normalize(x_hint - dot(x_hint, n) * n);
    if (norm(x) == 0.0) {
        x = normalize(cross(n, std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    }
    frame.x = x;
    frame.y = cross(n, x);
    return frame;
}

// Vertex neighbours along the region's edges.
std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> neighbours(const Mesh& mesh,
                                                                         const Region& r) {
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> out;
    for (Face f : r.faces) {
        for (Halfedge h : mesh.halfedges(f)) {
            auto& list = out[mesh.from_vertex(h).idx()];
            const std::uint32_t w = mesh.to_vertex(h).idx();
            if (std::find(list.begin(), list.end(), w) == list.end()) {
                list.push_back(w);
                out[w].push_back(mesh.from_vertex(h).idx());
            }
        }
    }
    for (auto& [v, list] : out) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return out;
}

// A Tutte embedding: the outline on the unit circle (evenly spaced, turned to match the
// flattened mesh), inner vertices at the average of their neighbours. Vertices already in
// `fixed` keep their places (the "after" picture reuses the "before" outline). Not a disk:
// the flattened mesh, scaled into the unit circle.
Layout layout(const Mesh& mesh, const Region& r, const Frame& frame, const Layout* fixed) {
    Layout out;
    const std::vector<Halfedge> loop = outline(mesh, r);
    if (loop.empty()) {
        double radius = 0.0;
        for (Vertex v : r.vertices) {
            out[v.idx()] = frame.flat(mesh.position(v));
            radius = std::max(radius, norm(out[v.idx()]));
        }
        for (auto& [v, p] : out) {
            p = radius > 0.0 ? p / radius : p;
        }
        return out;
    }
    std::unordered_set<std::uint32_t> pinned;
    if (fixed != nullptr) {
        for (Halfedge h : loop) {
            const auto it = fixed->find(mesh.from_vertex(h).idx());
            if (it != fixed->end()) {
                out[it->first] = it->second;
                pinned.insert(it->first);
            }
        }
    }
    if (pinned.empty()) {
        // Evenly spaced: the clearest picture, whatever the edges' lengths.
        const double total = static_cast<double>(loop.size());
        std::vector<double> at;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            at.push_back(static_cast<double>(i));
        }
        // The turn that best matches the flattened positions (a 2-D Procrustes rotation).
        double s = 0.0, c = 0.0;
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const double angle = 2.0 * std::numbers::pi * at[i] / total;
            const Vec3 q = frame.flat(mesh.position(mesh.from_vertex(loop[i])));
            c += std::cos(angle) * q.x + std::sin(angle) * q.y;
            s += std::cos(angle) * q.y - std::sin(angle) * q.x;
        }
        const double turn = std::atan2(s, c);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const double angle = 2.0 * std::numbers::pi * at[i] / total + turn;
            out[mesh.from_vertex(loop[i]).idx()] = {std::cos(angle), std::sin(angle), 0.0};
            pinned.insert(mesh.from_vertex(loop[i]).idx());
        }
    } else {
        // New outline vertices (a split boundary edge's m): between their placed neighbours.
        for (std::size_t round = 0; round < loop.size(); ++round) {
            for (std::size_t i = 0; i < loop.size(); ++i) {
                const std::uint32_t v = mesh.from_vertex(loop[i]).idx();
                const std::uint32_t prev =
                    mesh.from_vertex(loop[(i + loop.size() - 1) % loop.size()]).idx();
                const std::uint32_t next = mesh.to_vertex(loop[i]).idx();
                if (pinned.count(v) == 0 && pinned.count(prev) != 0 && pinned.count(next) != 0) {
                    out[v] = 0.5 * (out[prev] + out[next]);
                    pinned.insert(v);
                }
            }
        }
    }
    const auto adjacent = neighbours(mesh, r);
    for (Vertex v : r.vertices) {
        out.try_emplace(v.idx(), Vec3{});
    }
    for (int iteration = 0; iteration < 500; ++iteration) {
        for (Vertex v : r.vertices) {
            if (pinned.count(v.idx()) != 0) {
                continue;
            }
            Vec3 sum;
            const auto& list = adjacent.at(v.idx());
            for (const std::uint32_t w : list) {
                sum += out[w];
            }
            out[v.idx()] = sum / static_cast<double>(list.size());
        }
    }
    return out;
}

// ---------------------------------------------------------------------------- changes

enum class Status { Unchanged, Created, Deleted, Relinked };

struct Diff {
    const Mesh& before;
    const Mesh& after;

    Status of(Halfedge h) const {
        const bool was = live(before, h), is = live(after, h);
        if (was != is) {
            return is ? Status::Created : Status::Deleted;
        }
        const bool same = before.next(h) == after.next(h) &&
                          before.to_vertex(h) == after.to_vertex(h) &&
                          before.face(h) == after.face(h);
        return same ? Status::Unchanged : Status::Relinked;
    }
    Status of(Vertex v) const {
        const bool was = live(before, v), is = live(after, v);
        if (was != is) {
            return is ? Status::Created : Status::Deleted;
        }
        return before.position(v) == after.position(v) ? Status::Unchanged : Status::Relinked;
    }
    Status of(Face f) const {
        const bool was = live(before, f), is = live(after, f);
        if (was != is) {
            return is ? Status::Created : Status::Deleted;
        }
        return loop_of(before, f) == loop_of(after, f) ? Status::Unchanged : Status::Relinked;
    }
};

const Color& color_of(Status s, const OpDiagramStyle& style) {
    switch (s) {
        case Status::Created:
            return style.created;
        case Status::Deleted:
            return style.deleted;
        case Status::Relinked:
            return style.relinked;
        case Status::Unchanged:
            break;
    }
    return style.unchanged;
}

// "#12" (GCC 12 warns, wrongly, on "#" + std::to_string()).
std::string index_text(std::uint32_t i) {
    std::string out = "#";
    out += std::to_string(i);
    return out;
}

struct Labeller {
    const Names& names;
    // Local meshes (op_diagram_change.cpp) print the indices of the mesh they were cut from.
    const op_diagram_detail::Originals* originals = nullptr;
    std::string halfedge_index(std::uint32_t h) const {
        return index_text(originals ? 2 * originals->edges[h >> 1] + (h & 1u) : h);
    }
    std::string vertex_index(std::uint32_t v) const {
        return index_text(originals ? originals->vertices[v] : v);
    }
    std::string face_index(std::uint32_t f) const {
        return index_text(originals ? originals->faces[f] : f);
    }
    std::string halfedge(Halfedge h) const {
        const std::string* n = names.halfedge(h);
        return n ? *n : halfedge_index(h.idx());
    }
    std::string vertex(Vertex v) const {
        const std::string* n = names.vertex(v);
        return n ? *n + " " + vertex_index(v.idx()) : vertex_index(v.idx());
    }
    std::string vertex_short(Vertex v) const {
        const std::string* n = names.vertex(v);
        return n ? *n : vertex_index(v.idx());
    }
    std::string face(Face f) const {
        if (!f.is_valid()) {
            return "a hole";
        }
        const std::string* n = names.face(f);
        return n ? *n + " " + face_index(f.idx()) : face_index(f.idx());
    }
    // In the picture: a named face by its name only (the changes list gives its index).
    std::string face_short(Face f) const {
        const std::string* n = names.face(f);
        return n ? *n : face_index(f.idx());
    }
};

std::string loop_text(const Mesh& mesh, Face f, const Labeller& l) {
    std::string out = "(";
    for (Halfedge h : mesh.halfedges(f)) {
        if (out.size() > 1) {
            out += ' ';
        }
        out += l.halfedge(h);
    }
    return out + ")";
}

std::vector<std::string> change_lines(const Diff& d, const Region& old, const Region& now,
                                      const Labeller& l) {
    std::vector<std::string> lines;
    std::vector<std::uint32_t> halfedges;
    for (const Region* r : {&old, &now}) {
        const Mesh& mesh = r == &old ? d.before : d.after;
        for (Face f : r->faces) {
            for (Halfedge h : mesh.halfedges(f)) {
                halfedges.push_back(h.idx());
                halfedges.push_back(Mesh::twin(h).idx());
            }
        }
    }
    std::sort(halfedges.begin(), halfedges.end());
    halfedges.erase(std::unique(halfedges.begin(), halfedges.end()), halfedges.end());
    for (const std::uint32_t i : halfedges) {
        const Halfedge h(i);
        std::string name = l.halfedge(h);
        if (l.names.halfedge(h) != nullptr) {
            name += ' ';
            name += l.halfedge_index(i);
        }
        switch (d.of(h)) {
            case Status::Created:
                lines.push_back(name + ": new, " + l.vertex_short(d.after.from_vertex(h)) + " → " +
                                l.vertex_short(d.after.to_vertex(h)) + " in " +
                                l.face(d.after.face(h)) + ", next " + l.halfedge(d.after.next(h)));
                break;
            case Status::Deleted:
                lines.push_back(name + ": deleted");
                break;
            case Status::Relinked: {
                std::string what;
                const auto field = [&](const char* key, const std::string& a,
                                       const std::string& b) {
                    if (a != b) {
                        what += std::string(what.empty() ? "" : ", ") + key + " " + a + " → " + b;
                    }
                };
                field("next", l.halfedge(d.before.next(h)), l.halfedge(d.after.next(h)));
                field("to", l.vertex_short(d.before.to_vertex(h)),
                      l.vertex_short(d.after.to_vertex(h)));
                field("face", l.face(d.before.face(h)), l.face(d.after.face(h)));
                lines.push_back(name + ": " + what);
                break;
            }
            case Status::Unchanged:
                break;
        }
    }
    std::vector<std::uint32_t> faces;
    for (Face f : old.faces) {
        faces.push_back(f.idx());
    }
    for (Face f : now.faces) {
        faces.push_back(f.idx());
    }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    for (const std::uint32_t i : faces) {
        const Face f(i);
        switch (d.of(f)) {
            case Status::Created:
                lines.push_back("face " + l.face(f) + ": new " + loop_text(d.after, f, l));
                break;
            case Status::Deleted:
                lines.push_back("face " + l.face(f) + ": deleted");
                break;
            case Status::Relinked:
                lines.push_back("face " + l.face(f) + ": " + loop_text(d.before, f, l) + " → " +
                                loop_text(d.after, f, l));
                break;
            case Status::Unchanged:
                break;
        }
    }
    return lines;
}

// ---------------------------------------------------------------------------- picture

struct Painter {
    const Mesh& mesh;
    const Region& region;
    const Layout& layout;
    const Diff& diff;
    const Labeller& labels;
    const OpDiagramStyle& style;
    double dx;  // this state's offset along x
    OverlayBatch& out;

    Vec3 at(Vertex v) const { return layout.at(v.idx()) + Vec3{dx, 0.0, 0.0}; }
    Vec3 centre(Face f) const {
        Vec3 sum;
        double n = 0.0;
        for (Vertex v : mesh.vertices(f)) {
            sum += at(v);
            n += 1.0;
        }
        return sum / n;
    }
    bool shown(Face f) const {
        return f.is_valid() &&
               std::find(region.faces.begin(), region.faces.end(), f) != region.faces.end();
    }

    // A halfedge inside its face (a gap's: mirrored to the outside), with its name.
    void arrow(Halfedge h, const Vec3& toward) {
        const Vec3 p = at(mesh.from_vertex(h)), q = at(mesh.to_vertex(h));
        const Vec3 a = lerp(p, toward, 0.16), b = lerp(q, toward, 0.16);
        const Vec3 tail = lerp(a, b, 0.14), tip = lerp(a, b, 0.86);
        const Color& color = color_of(diff.of(h), style);
        out.lines.push_back({tail, tip, color, 2.0f});
        const Vec3 axis = normalize(tip - tail);
        const Vec3 left{-axis.y, axis.x, 0.0};  // into the loop's side (faces run CCW)
        out.arrowheads.push_back({tip, tail, left, color, 11.0f, 4.5f});
        out.labels.push_back({lerp(tail, tip, 0.5) + 0.09 * left, labels.halfedge(h), color,
                              OverlayBatch::Label::Side::Centre});
    }

    void draw() {
        std::unordered_set<std::uint32_t> edges_done;
        for (Face f : region.faces) {
            const Color& c = color_of(diff.of(f), style);
            const Color tint{c[0], c[1], c[2], style.face_alpha};
            const Vec3 mid = centre(f);
            for (Halfedge h : mesh.halfedges(f)) {
                out.triangles.push_back(
                    {mid, at(mesh.from_vertex(h)), at(mesh.to_vertex(h)), tint});
                if (edges_done.insert(Mesh::edge(h).idx()).second) {
                    out.lines.push_back(
                        {at(mesh.from_vertex(h)), at(mesh.to_vertex(h)), style.edge, 1.5f});
                }
            }
        }
        for (Face f : region.faces) {
            const Vec3 mid = centre(f);
            for (Halfedge h : mesh.halfedges(f)) {
                arrow(h, mid);
                const Halfedge t = Mesh::twin(h);
                if (mesh.is_boundary(t)) {
                    arrow(t, at(mesh.from_vertex(h)) + at(mesh.to_vertex(h)) - mid);
                }
            }
            out.labels.push_back({mid, labels.face_short(f), color_of(diff.of(f), style),
                                  OverlayBatch::Label::Side::Centre});
        }
        for (Vertex v : region.vertices) {
            const Color& c = color_of(diff.of(v), style);
            out.points.push_back({at(v), c, 9.0f});
            out.labels.push_back({at(v), labels.vertex(v), c});
        }
    }
};

}  // namespace

OpDiagram op_diagram(const Mesh& before, const Mesh& after, std::string_view verb, CodeNames code,
                     ElementRef input, const OpDiagramStyle& style) {
    return op_diagram_detail::draw(before, after,
                                   std::string(verb) + " of " + describe(before, input), code,
                                   input, nullptr, style);
}

namespace op_diagram_detail {

OpDiagram draw(const Mesh& before, const Mesh& after, std::string title, CodeNames code,
               ElementRef input, const Originals* originals, const OpDiagramStyle& style) {
    OpDiagram diagram;
    diagram.title = std::move(title);
    const Region old = region_before(before, code, input);
    const Region now = region_after(before, after, old);
    const Names names = op_diagram_detail::code_names(before, code, input);
    const Labeller labels{names, originals};
    const Diff diff{before, after};

    Vec3 x_hint{1.0, 0.0, 0.0};
    if (input.kind == ElementRef::Kind::Edge || input.kind == ElementRef::Kind::Halfedge) {
        const Edge e = input.kind == ElementRef::Kind::Edge ? Edge(input.index)
                                                            : Mesh::edge(Halfedge(input.index));
        // Along the code's h0 (flip, split: b -> c; collapse: v0 -> v1), as the diagrams in
        // the source draw it.
        Halfedge h0 = Mesh::halfedge(e, 0);
        for (const auto& [index, name] : names.halfedges) {
            if (name == "h0") {
                h0 = Halfedge(index);
            }
        }
        x_hint = before.position(before.to_vertex(h0)) - before.position(before.from_vertex(h0));
    }
    const Frame frame = frame_of(before, old, x_hint);
    const Layout first = layout(before, old, frame, nullptr);
    const Layout second = layout(after, now, frame, &first);

    Painter{before, old, first, diff, labels, style, 0.0, diagram.picture}.draw();
    Painter{after, now, second, diff, labels, style, OpDiagram::kAfterX, diagram.picture}.draw();
    diagram.picture.labels.push_back(
        {{0.0, 1.3, 0.0}, "before", style.unchanged, OverlayBatch::Label::Side::Centre, true});
    diagram.picture.labels.push_back({{OpDiagram::kAfterX, 1.3, 0.0},
                                      "after",
                                      style.unchanged,
                                      OverlayBatch::Label::Side::Centre,
                                      true});
    diagram.min = {-1.35, -1.3, 0.0};
    diagram.max = {OpDiagram::kAfterX + 1.35, 1.45, 0.0};
    diagram.changes = change_lines(diff, old, now, labels);
    return diagram;
}

}  // namespace op_diagram_detail

}  // namespace meshedit
