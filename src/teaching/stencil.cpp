// Subdivision stencils (stencil.h): the weights of loop_rules.h and catmark_rules.h for one
// element, gathered term by term so the viewer can label every contributing vertex. The
// tests check each stencil's position against what loop_subdivide() and quad_subdivide()
// compute, and its weights against the formulas in docs/teaching.md.

#include "meshedit/core/stencil.h"

#include <cstdio>
#include <numbers>

#include "algorithms/catmark_rules.h"
#include "algorithms/loop_rules.h"
#include "meshedit/core/attributes.h"

namespace meshedit {
namespace {

std::string num(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", x);
    return buffer;
}

std::string point(const Vec3& p) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "(%.6g, %.6g, %.6g)", p.x, p.y, p.z);
    return buffer;
}

// Accumulates weights per vertex in the order vertices are first met.
class Terms {
public:
    void add(Vertex v, double weight) {
        for (StencilTerm& term : terms_) {
            if (term.vertex == v) {
                term.weight += weight;
                return;
            }
        }
        terms_.push_back({v, weight});
    }
    // A face point's share: `weight` spread evenly over the face's corners.
    void add_face(const Mesh& mesh, Face f, double weight) {
        const double share = weight / static_cast<double>(mesh.valence(f));
        for (Vertex v : mesh.vertices(f)) {
            add(v, share);
        }
    }
    std::vector<StencilTerm> take() { return std::move(terms_); }

private:
    std::vector<StencilTerm> terms_;
};

// What a vertex's one-ring holds, gathered clockwise as the subdivision passes do.
struct Ring {
    std::vector<Vertex> neighbours;
    std::vector<Face> faces;
    std::vector<Vertex> sharp_ends;  // far ends of boundary and crease edges
    bool all_sharp_on_boundary = true;
};

bool edge_is_crease(const Mesh& mesh, Edge e) {
    const auto crease = loop_rules::crease_property(mesh);
    return crease && crease[e] != 0;
}

Ring ring_of(const Mesh& mesh, Vertex v) {
    Ring ring;
    const Halfedge start = mesh.halfedge(v);
    if (!start.is_valid()) {
        return ring;
    }
    Halfedge h = start;
    do {
        const Vertex q = mesh.to_vertex(h);
        ring.neighbours.push_back(q);
        if (!mesh.is_boundary(h)) {
            ring.faces.push_back(mesh.face(h));
        }
        const Edge e = Mesh::edge(h);
        const bool boundary = mesh.is_boundary(e);
        if (loop_rules::is_sharp(boundary, edge_is_crease(mesh, e) ? 1 : 0)) {
            ring.sharp_ends.push_back(q);
            ring.all_sharp_on_boundary = ring.all_sharp_on_boundary && boundary;
        }
        h = mesh.cw_rotated(h);
    } while (h != start);
    return ring;
}

std::string vertex_rule(const Ring& ring) {
    if (ring.neighbours.empty()) {
        return "isolated vertex";
    }
    switch (loop_rules::classify(ring.sharp_ends.size())) {
        case loop_rules::VertexRule::Smooth:
            return ring.sharp_ends.empty() ? "interior vertex" : "dart";
        case loop_rules::VertexRule::Crease:
            return ring.all_sharp_on_boundary ? "boundary vertex" : "crease vertex";
        case loop_rules::VertexRule::Corner:
            break;
    }
    return "corner";
}

// The rules both schemes share: a crease or boundary vertex, a corner, an isolated vertex.
// Returns false for a smooth vertex or a dart (the scheme's own weights; a dart says so).
bool sharp_vertex_stencil(const Vertex v, const Ring& ring, Terms& terms, Stencil& out) {
    if (ring.neighbours.empty() ||
        loop_rules::classify(ring.sharp_ends.size()) == loop_rules::VertexRule::Corner) {
        terms.add(v, 1.0);
        out.formula.push_back(ring.neighbours.empty() ? "no edges: p' = p"
                                                      : std::to_string(ring.sharp_ends.size()) +
                                                            " sharp edges: a corner stays, p' = p");
        return true;
    }
    if (loop_rules::classify(ring.sharp_ends.size()) == loop_rules::VertexRule::Crease) {
        terms.add(v, 0.75);
        terms.add(ring.sharp_ends[0], 0.125);
        terms.add(ring.sharp_ends[1], 0.125);
        out.formula.push_back("two sharp edges, to a = v" +
                              std::to_string(ring.sharp_ends[0].idx()) + " and b = v" +
                              std::to_string(ring.sharp_ends[1].idx()));
        out.formula.push_back("p' = 3/4·p + 1/8·(a + b)");
        return true;
    }
    if (ring.sharp_ends.size() == 1) {
        out.formula.push_back("one sharp edge (a dart): the interior rule");
    }
    return false;
}

// The rule both schemes share for a boundary or crease edge: its midpoint. Returns false for
// a smooth edge (the scheme's own weights).
bool sharp_edge_stencil(const Mesh& mesh, Edge e, Terms& terms, Stencil& out) {
    const bool boundary = mesh.is_boundary(e);
    if (!boundary && !edge_is_crease(mesh, e)) {
        return false;
    }
    out.rule = boundary ? "boundary edge" : "crease edge";
    terms.add(mesh.vertex(e, 1), 0.5);
    terms.add(mesh.vertex(e, 0), 0.5);
    out.formula.push_back("a sharp edge: its midpoint, p' = 1/2·(A + B)");
    return true;
}

void loop_vertex(const Mesh& mesh, Vertex v, LoopWeights weights, Terms& terms, Stencil& out) {
    const Ring ring = ring_of(mesh, v);
    out.rule = vertex_rule(ring);
    out.valence = ring.neighbours.size();
    if (sharp_vertex_stencil(v, ring, terms, out)) {
        return;
    }
    const std::size_t n = ring.neighbours.size();
    const double u = loop_rules::interior_weight(n, weights);
    terms.add(v, 1.0 - static_cast<double>(n) * u);
    for (Vertex q : ring.neighbours) {
        terms.add(q, u);
    }
    const std::string ns = std::to_string(n);
    if (weights == LoopWeights::Warren) {
        out.formula.push_back(n == 3 ? "n = 3: u = 3/16 = " + num(u)
                                     : "n = " + ns + ": u = 3/(8n) = 3/" + std::to_string(8 * n) +
                                           " = " + num(u));
    } else {
        out.formula.push_back("n = " + ns + ": u = (5/8 - (3/8 + 1/4·cos(2pi/n))²)/n = " + num(u));
    }
    out.formula.push_back("p' = (1 - n·u)·p + u·sum(q) = " + num(1.0 - static_cast<double>(n) * u) +
                          "·p + " + num(u) + "·(q1 + … + q" + ns + ")");
}

void loop_edge(const Mesh& mesh, Edge e, Terms& terms, Stencil& out) {
    if (sharp_edge_stencil(mesh, e, terms, out)) {
        return;
    }
    const Vertex a = mesh.vertex(e, 1);
    const Vertex b = mesh.vertex(e, 0);
    for (unsigned i = 0; i < 2; ++i) {
        const Face f = mesh.face(e, i);
        if (!mesh.is_triangle(f)) {
            out.status = OpStatus::composed(
                "Loop needs triangles: face " + std::to_string(f.idx()) + " has " +
                std::to_string(mesh.valence(f)) + " corners (Ctrl+T triangulates)");
            return;
        }
    }
    out.rule = "interior edge";
    terms.add(a, 0.375);
    terms.add(b, 0.375);
    const Vertex c = mesh.to_vertex(mesh.next(Mesh::halfedge(e, 0)));
    const Vertex d = mesh.to_vertex(mesh.next(Mesh::halfedge(e, 1)));
    terms.add(c, 0.125);
    terms.add(d, 0.125);
    out.formula.push_back("ends A, B; opposite corners C = v" + std::to_string(c.idx()) +
                          ", D = v" + std::to_string(d.idx()));
    out.formula.push_back("p' = 3/8·(A + B) + 1/8·(C + D)");
}

void catmark_vertex(const Mesh& mesh, Vertex v, Terms& terms, Stencil& out) {
    const Ring ring = ring_of(mesh, v);
    out.rule = vertex_rule(ring);
    out.valence = ring.neighbours.size();
    if (sharp_vertex_stencil(v, ring, terms, out)) {
        return;
    }
    const double n = static_cast<double>(ring.neighbours.size());
    terms.add(v, (n - 2.0) / n);
    for (Vertex q : ring.neighbours) {
        terms.add(q, 1.0 / (n * n));
    }
    for (Face f : ring.faces) {
        terms.add_face(mesh, f, 1.0 / (n * n));
    }
    out.formula.push_back("n = " + std::to_string(ring.neighbours.size()) +
                          ": p' = (n - 2)/n·p + (sum(q) + sum(F))/n²");
    out.formula.push_back("= " + num((n - 2.0) / n) + "·p + " + num(1.0 / (n * n)) +
                          "·(sum(q) + sum(F)), F the face points (corner averages)");
}

void catmark_edge(const Mesh& mesh, Edge e, Terms& terms, Stencil& out) {
    if (sharp_edge_stencil(mesh, e, terms, out)) {
        return;
    }
    const Vertex a = mesh.vertex(e, 1);
    const Vertex b = mesh.vertex(e, 0);
    out.rule = "interior edge";
    terms.add(a, 0.25);
    terms.add(b, 0.25);
    terms.add_face(mesh, mesh.face(e, 0), 0.25);
    terms.add_face(mesh, mesh.face(e, 1), 0.25);
    out.formula.push_back("p' = 1/4·(A + B + F0 + F1), F0, F1 the face points of faces " +
                          std::to_string(mesh.face(e, 0).idx()) + " and " +
                          std::to_string(mesh.face(e, 1).idx()));
}

}  // namespace

const char* scheme_name(StencilScheme scheme) {
    switch (scheme) {
        case StencilScheme::LoopWarren:
            return "Loop (Warren's weights)";
        case StencilScheme::LoopOriginal:
            return "Loop (Loop's weights)";
        case StencilScheme::CatmullClark:
            break;
    }
    return "Catmull-Clark";
}

Stencil subdivision_stencil(const Mesh& mesh, ElementRef element, StencilScheme scheme) {
    Stencil out;
    if (!is_live(mesh, element)) {
        out.status = OpStatus::composed("no stencil: " + describe(mesh, element));
        return out;
    }
    if (element.kind == ElementRef::Kind::Halfedge) {
        element = ElementRef::edge(Mesh::edge(Halfedge(element.index)));
    }
    const bool loop = scheme != StencilScheme::CatmullClark;
    const LoopWeights weights =
        scheme == StencilScheme::LoopOriginal ? LoopWeights::Loop : LoopWeights::Warren;
    Terms terms;
    switch (element.kind) {
        case ElementRef::Kind::Vertex:
            if (loop) {
                loop_vertex(mesh, Vertex(element.index), weights, terms, out);
            } else {
                catmark_vertex(mesh, Vertex(element.index), terms, out);
            }
            break;
        case ElementRef::Kind::Edge:
            if (loop) {
                loop_edge(mesh, Edge(element.index), terms, out);
            } else {
                catmark_edge(mesh, Edge(element.index), terms, out);
            }
            break;
        case ElementRef::Kind::Face:
            if (loop) {
                out.status =
                    OpStatus::refused("Loop makes no face points: hover a vertex or an edge");
                break;
            }
            out.rule = "face";
            terms.add_face(mesh, Face(element.index), 1.0);
            out.formula.push_back("the face point: the average of the " +
                                  std::to_string(mesh.valence(Face(element.index))) + " corners");
            break;
        default:
            break;
    }
    if (!out.ok()) {
        return out;
    }
    out.terms = terms.take();
    for (const StencilTerm& term : out.terms) {
        out.position += term.weight * mesh.position(term.vertex);
    }
    out.formula.push_back("p' = " + point(out.position));
    return out;
}

}  // namespace meshedit
