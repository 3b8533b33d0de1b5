// The rewiring diagram: the names it gives land on the elements the ASCII diagrams in
// flip_split.cpp and collapse.cpp show, its list of changes is exact, and both pictures are
// embeddings (every face turns counter-clockwise, no two vertices meet).

#include "meshedit/render/op_diagram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

using op_diagram_detail::code_names;
using op_diagram_detail::Names;

template <typename Handle>
Handle named(const std::vector<std::pair<std::uint32_t, std::string>>& names,
             const std::string& name) {
    for (const auto& [index, n] : names) {
        if (n == name) {
            return Handle(index);
        }
    }
    ADD_FAILURE() << "no element named " << name;
    return Handle();
}

// The names, on the mesh before and after the operation, hold the relations the source's
// diagrams draw.
TEST(OpDiagramNames, FlipMatchesItsDiagram) {
    // Before: e = b-c between f0 = (a,b,c) and f1 = (c,b,d). After: h0 runs d -> a.
    Mesh mesh = shapes::icosahedron();
    const Edge e(7);
    const Names n = code_names(mesh, CodeNames::Flip, ElementRef::edge(e));
    const auto h = [&](const char* s) { return named<Halfedge>(n.halfedges, s); };
    const auto v = [&](const char* s) { return named<Vertex>(n.vertices, s); };
    EXPECT_EQ(mesh.from_vertex(h("h0")), v("b"));
    EXPECT_EQ(mesh.to_vertex(h("h0")), v("c"));
    EXPECT_EQ(mesh.to_vertex(h("h1")), v("a"));
    EXPECT_EQ(mesh.to_vertex(h("t1")), v("d"));
    ASSERT_TRUE(flip(mesh, e));
    ASSERT_TRUE(!validate(mesh).has_value());
    EXPECT_EQ(mesh.from_vertex(h("h0")), v("d"));
    EXPECT_EQ(mesh.to_vertex(h("h0")), v("a"));
    EXPECT_EQ(mesh.next(h("h0")), h("h2"));  // f0 = (a, b, d): h0 -> h2 -> t1
    EXPECT_EQ(mesh.next(h("h2")), h("t1"));
    EXPECT_EQ(mesh.face(h("t1")), named<Face>(n.faces, "f0"));
}

TEST(OpDiagramNames, SplitMatchesItsDiagram) {
    Mesh mesh = shapes::icosahedron();
    const Edge e(7);
    const Names n = code_names(mesh, CodeNames::Split, ElementRef::edge(e));
    const auto h = [&](const char* s) { return named<Halfedge>(n.halfedges, s); };
    const auto v = [&](const char* s) { return named<Vertex>(n.vertices, s); };
    const auto m = split(mesh, e);
    ASSERT_TRUE(m);
    ASSERT_TRUE(!validate(mesh).has_value());
    EXPECT_EQ(*m, v("m"));
    // s0 = b -> m, u0 = m -> a, w0 = m -> d, h0 = m -> c; f2 = s0 -> u0 -> h2.
    EXPECT_EQ(mesh.from_vertex(h("s0")), v("b"));
    EXPECT_EQ(mesh.to_vertex(h("s0")), v("m"));
    EXPECT_EQ(mesh.to_vertex(h("u0")), v("a"));
    EXPECT_EQ(mesh.to_vertex(h("w0")), v("d"));
    EXPECT_EQ(mesh.from_vertex(h("h0")), v("m"));
    EXPECT_EQ(mesh.to_vertex(h("h0")), v("c"));
    EXPECT_EQ(mesh.next(h("s0")), h("u0"));
    EXPECT_EQ(mesh.next(h("u0")), h("h2"));
    EXPECT_EQ(mesh.face(h("s0")), named<Face>(n.faces, "f2"));
    EXPECT_EQ(mesh.face(h("s1")), named<Face>(n.faces, "f3"));
}

TEST(OpDiagramNames, CollapseMatchesItsDiagram) {
    Mesh mesh = shapes::icosahedron();
    const Edge e(7);
    const Names n = code_names(mesh, CodeNames::Collapse, ElementRef::edge(e));
    const auto h = [&](const char* s) { return named<Halfedge>(n.halfedges, s); };
    const auto v = [&](const char* s) { return named<Vertex>(n.vertices, s); };
    EXPECT_LT(v("v0").idx(), v("v1").idx());
    EXPECT_EQ(mesh.from_vertex(h("h0")), v("v0"));
    EXPECT_EQ(mesh.to_vertex(h("h1")), v("a"));
    EXPECT_EQ(h("o1"), Mesh::twin(h("h1")));
    EXPECT_EQ(h("q2"), Mesh::twin(h("t2")));
    const auto survivor = collapse(mesh, e);
    ASSERT_TRUE(survivor);
    ASSERT_TRUE(!validate(mesh).has_value());
    EXPECT_EQ(*survivor, v("v0"));
    EXPECT_TRUE(mesh.is_deleted(v("v1")));
    EXPECT_TRUE(mesh.is_deleted(h("o1")));
    // h2 (a -> v0) took o1's place: its next is what followed o1.
    EXPECT_EQ(mesh.to_vertex(h("h2")), v("v0"));
    EXPECT_FALSE(mesh.is_deleted(h("o2")));
    EXPECT_EQ(Mesh::twin(h("h2")), h("o2"));
}

// The names the verb table gives each verb (ops::Verb::names; tests/ops checks the table).
CodeNames names_of(const std::string& verb) {
    return verb == "flip"       ? CodeNames::Flip
           : verb == "split"    ? CodeNames::Split
           : verb == "collapse" ? CodeNames::Collapse
                                : CodeNames::ByIndex;
}

OpDiagram diagram_of(Mesh mesh, const std::string& verb, ElementRef input,
                     const std::function<bool(Mesh&)>& op) {
    const Mesh before = mesh;
    EXPECT_TRUE(op(mesh));
    EXPECT_TRUE(!validate(mesh).has_value());
    return op_diagram(before, mesh, verb, names_of(verb), input);
}

TEST(OpDiagram, FlipListsExactlyWhatItRelinked) {
    // two_triangles: faces (0,1,2) and (0,2,3) share edge 0-2; flip makes 1-3.
    const Mesh mesh = test::two_triangles();
    const Edge e = mesh.find_edge(Vertex(0), Vertex(2));
    const OpDiagram d = diagram_of(mesh, "flip", ElementRef::edge(e),
                                   [e](Mesh& m) { return static_cast<bool>(flip(m, e)); });
    EXPECT_EQ(d.title, "flip of " + describe(mesh, ElementRef::edge(e)));
    // Every halfedge of both triangles moved to another loop or end; the outside ones and
    // the vertices did not change.
    ASSERT_EQ(d.changes.size(), 8u);
    for (const char* name : {"h0", "t0", "h1", "h2", "t1", "t2"}) {
        EXPECT_EQ(std::count_if(d.changes.begin(), d.changes.end(),
                                [&](const std::string& line) {
                                    return line.rfind(std::string(name) + " #", 0) == 0;
                                }),
                  1)
            << name;
    }
    const auto has = [&](const std::string& start, const std::string& end) {
        return std::any_of(d.changes.begin(), d.changes.end(), [&](const std::string& l) {
            return l.rfind(start, 0) == 0 && l.size() >= end.size() &&
                   l.compare(l.size() - end.size(), end.size(), end) == 0;
        });
    };
    EXPECT_TRUE(has("h0 #", "next h1 → h2, to c → a"));
    EXPECT_TRUE(has("t0 #", "next t1 → t2, to b → d"));
    EXPECT_TRUE(has("face f0 #", ": (h0 h1 h2) → (h0 h2 t1)") ||
                has("face f0 #", ": (h1 h2 h0) → (h0 h2 t1)") ||
                has("face f0 #", ": (h2 h0 h1) → (h0 h2 t1)"));
}

// Twice the signed area of triangle (a, b, c) in the plane.
double area2(const Vec3& a, const Vec3& b, const Vec3& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

void expect_embedding(const OpDiagram& d) {
    // Face tints are fans from each face's centre: all counter-clockwise.
    ASSERT_FALSE(d.picture.triangles.empty());
    for (const auto& t : d.picture.triangles) {
        EXPECT_GT(area2(t.a, t.b, t.c), 1e-6);
    }
    for (std::size_t i = 0; i < d.picture.points.size(); ++i) {
        for (std::size_t j = i + 1; j < d.picture.points.size(); ++j) {
            EXPECT_GT(distance(d.picture.points[i].p, d.picture.points[j].p), 1e-3);
        }
        EXPECT_GE(d.picture.points[i].p.x, d.min.x);
        EXPECT_LE(d.picture.points[i].p.x, d.max.x);
    }
}

TEST(OpDiagram, PicturesAreEmbeddingsEvenOnBentNeighbourhoods) {
    // The cube's corners are bent 90°, the torus's saddles, the bowl's rim open.
    for (const auto& [name, mesh] :
         std::vector<std::pair<std::string, Mesh>>{{"cube", shapes::cube()},
                                                   {"torus", shapes::torus(6, 5)},
                                                   {"grid", shapes::grid(3, 3)}}) {
        SCOPED_TRACE(name);
        for (Edge e : mesh.edges()) {
            if (is_flip_ok(mesh, e)) {
                expect_embedding(diagram_of(mesh, "flip", ElementRef::edge(e), [e](Mesh& m) {
                    return static_cast<bool>(flip(m, e));
                }));
            }
            if (is_split_ok(mesh, e)) {
                expect_embedding(diagram_of(mesh, "split", ElementRef::edge(e), [e](Mesh& m) {
                    return static_cast<bool>(split(m, e));
                }));
            }
            if (is_collapse_ok(mesh, e)) {
                expect_embedding(diagram_of(mesh, "collapse", ElementRef::edge(e), [e](Mesh& m) {
                    return static_cast<bool>(collapse(m, e));
                }));
            }
        }
    }
}

TEST(OpDiagram, OperationsWithoutNamesLabelByIndexAndColourWhatTheyMade) {
    const Mesh mesh = shapes::cube();
    const Face f(3);
    const OpDiagram d = diagram_of(mesh, "poke", ElementRef::face(f),
                                   [f](Mesh& m) { return static_cast<bool>(poke(m, f)); });
    const OpDiagramStyle style;
    // The new vertex (index 8) is green; the new faces are listed as new.
    EXPECT_TRUE(std::any_of(d.picture.points.begin(), d.picture.points.end(),
                            [&](const auto& p) { return p.color == style.created; }));
    EXPECT_TRUE(std::any_of(d.picture.labels.begin(), d.picture.labels.end(),
                            [](const auto& l) { return l.text == "#8"; }));
    EXPECT_EQ(std::count_if(d.changes.begin(), d.changes.end(),
                            [](const std::string& l) { return l.find(": new (") != l.npos; }),
              2);
}

}  // namespace
}  // namespace meshedit
