// The rewiring diagram: the names it gives land on the elements the ASCII diagrams in
// flip_split.cpp and collapse.cpp show, its list of changes is exact, and both pictures are
// embeddings (every face turns counter-clockwise, no two vertices meet).

#include "meshedit/overlay/op_diagram.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
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

// Everything a diagram holds, as text (coordinates to the last bit).
std::string dump(const OpDiagram& d) {
    std::string out = d.title + "\n";
    char buf[128];
    const auto vec = [&](const Vec3& p) {
        std::snprintf(buf, sizeof buf, "(%.17g %.17g %.17g)", p.x, p.y, p.z);
        out += buf;
    };
    const auto colour = [&](const Color& c) {
        std::snprintf(buf, sizeof buf, "[%g %g %g %g]", static_cast<double>(c[0]),
                      static_cast<double>(c[1]), static_cast<double>(c[2]),
                      static_cast<double>(c[3]));
        out += buf;
    };
    for (const auto& p : d.picture.points) {
        vec(p.p);
        colour(p.color);
        out += "\n";
    }
    for (const auto& l : d.picture.lines) {
        vec(l.a);
        vec(l.b);
        colour(l.color);
        out += "\n";
    }
    for (const auto& t : d.picture.triangles) {
        vec(t.a);
        vec(t.b);
        vec(t.c);
        colour(t.color);
        out += "\n";
    }
    for (const auto& a : d.picture.arrowheads) {
        vec(a.tip);
        vec(a.tail);
        colour(a.color);
        out += "\n";
    }
    for (const auto& l : d.picture.labels) {
        vec(l.at);
        out += l.text + "\n";
    }
    for (const std::string& line : d.changes) {
        out += line + "\n";
    }
    vec(d.min);
    vec(d.max);
    return out;
}

// The diagram from a recorded change (no copy of the mesh: the neighbourhood cut out on each
// side) is the diagram from the whole mesh before and after, to the last bit, for every
// operation with a diagram on every element of several meshes; the mesh is left as it was.
TEST(OpDiagram, FromTheRecordedChangeEqualsFromTheWholeMeshes) {
    struct Op {
        const char* verb;
        CodeNames names;
        ElementRef::Kind kind;
        std::function<bool(Mesh&, std::uint32_t)> run;
    };
    const std::vector<Op> ops = {
        {"flip", CodeNames::Flip, ElementRef::Kind::Edge,
         [](Mesh& m, std::uint32_t i) { return static_cast<bool>(flip(m, Edge(i))); }},
        {"split", CodeNames::Split, ElementRef::Kind::Edge,
         [](Mesh& m, std::uint32_t i) { return static_cast<bool>(split(m, Edge(i))); }},
        {"collapse", CodeNames::Collapse, ElementRef::Kind::Edge,
         [](Mesh& m, std::uint32_t i) { return static_cast<bool>(collapse(m, Edge(i))); }},
        {"dissolve", CodeNames::ByIndex, ElementRef::Kind::Vertex,
         [](Mesh& m, std::uint32_t i) { return static_cast<bool>(dissolve_vertex(m, Vertex(i))); }},
        {"poke", CodeNames::ByIndex, ElementRef::Kind::Face,
         [](Mesh& m, std::uint32_t i) { return static_cast<bool>(poke(m, Face(i))); }},
        {"extrude", CodeNames::ByIndex, ElementRef::Kind::Face,
         [](Mesh& m, std::uint32_t i) {
             return static_cast<bool>(extrude_face(m, Face(i), 0.2, 0.3));
         }},
        {"bevel", CodeNames::ByIndex, ElementRef::Kind::Edge,
         [](Mesh& m, std::uint32_t i) { return static_cast<bool>(bevel_edge(m, Edge(i), 0.25)); }},
        {"make_boundary", CodeNames::ByIndex, ElementRef::Kind::Face,
         [](Mesh& m, std::uint32_t i) { return static_cast<bool>(make_boundary(m, Face(i))); }},
    };
    int compared = 0;
    for (const Mesh& start : {test::two_triangles(), shapes::cube(), shapes::icosphere(1),
                              shapes::grid(3, 2), test::one_ring(5), test::quad_strip(3)}) {
        for (const Op& op : ops) {
            const std::size_t n = op.kind == ElementRef::Kind::Edge     ? start.edges_size()
                                  : op.kind == ElementRef::Kind::Vertex ? start.vertices_size()
                                                                        : start.faces_size();
            for (std::uint32_t i = 0; i < n; ++i) {
                const ElementRef input{op.kind, i};
                Mesh mesh = start;
                MeshRecorder recorder(mesh);
                if (!op.run(mesh, i)) {
                    continue;
                }
                const MeshChange change = recorder.finish();
                const Mesh after = mesh;
                const OpDiagram whole = op_diagram(start, after, op.verb, op.names, input);
                const OpDiagram cut =
                    op_diagram(mesh, change, op.verb, op.names, [&](const Mesh&) { return input; });
                ASSERT_EQ(dump(cut), dump(whole)) << op.verb << " " << i;
                ASSERT_TRUE(bitwise_equal(mesh, after)) << op.verb << " " << i;
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 300);
}

}  // namespace
}  // namespace meshedit
