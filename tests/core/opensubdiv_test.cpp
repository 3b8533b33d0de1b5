// MeshEdit's subdivision against an independent implementation: OpenSubdiv's Far refinement
// (Catmark and Loop schemes, VTX_BOUNDARY_EDGE_ONLY, crease edges infinitely sharp). Three
// levels of each case; at every level each MeshEdit vertex is matched to the OpenSubdiv
// vertex refined from the same parent element (GetVertexChildVertex, GetEdgeChildVertex,
// GetFaceChildVertex), and then positions agree to 1e-12, faces agree as oriented vertex
// cycles and crease edges agree with OpenSubdiv's infinitely sharp edges.

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "opensubdiv_test_util.h"
#include "subdivision_test_util.h"
#include "support/fixtures.h"

namespace meshedit {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

constexpr int kLevels = 3;

using test::canonical;
using test::Cycle;
using test::Point;

enum class Scheme { CatmullClark, Loop };

// OpenSubdiv's refinement of `mesh` (dense indices): the refiner and every level's points.
struct Reference {
    std::unique_ptr<Far::TopologyRefiner> refiner;
    std::vector<std::vector<Point>> points;  // per level
};

Reference refine_with_opensubdiv(const Mesh& mesh, Scheme scheme) {
    std::vector<int> sizes, corners, crease_ends;
    for (Face f : mesh.faces()) {
        sizes.push_back(static_cast<int>(mesh.valence(f)));
        for (Vertex v : mesh.vertices(f)) {
            corners.push_back(static_cast<int>(v.idx()));
        }
    }
    for (const auto& [a, b] : test::crease_pairs(mesh)) {
        crease_ends.push_back(static_cast<int>(a));
        crease_ends.push_back(static_cast<int>(b));
    }
    const std::vector<float> sharpness(crease_ends.size() / 2, Sdc::Crease::SHARPNESS_INFINITE);
    Far::TopologyDescriptor desc;
    desc.numVertices = static_cast<int>(mesh.n_vertices());
    desc.numFaces = static_cast<int>(mesh.n_faces());
    desc.numVertsPerFace = sizes.data();
    desc.vertIndicesPerFace = corners.data();
    desc.numCreases = static_cast<int>(sharpness.size());
    desc.creaseVertexIndexPairs = crease_ends.data();
    desc.creaseWeights = sharpness.data();
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    Reference out;
    out.refiner.reset(Factory::Create(
        desc, Factory::Options(scheme == Scheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK,
                               options)));
    Far::TopologyRefiner::UniformOptions uniform(kLevels);
    uniform.fullTopologyInLastLevel = true;
    out.refiner->RefineUniform(uniform);
    out.points.resize(kLevels + 1);
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        out.points[0].push_back({p.x, p.y, p.z});
    }
    Far::PrimvarRefinerReal<double> primvar(*out.refiner);
    for (int level = 1; level <= kLevels; ++level) {
        out.points[level].resize(out.refiner->GetLevel(level).GetNumVertices());
        Point* src = out.points[level - 1].data();
        Point* dst = out.points[level].data();
        primvar.Interpolate(level, src, dst);
    }
    return out;
}

// Subdivides `mesh` kLevels times beside OpenSubdiv and compares every level.
void expect_equal_to_opensubdiv(Mesh mesh, Scheme scheme) {
    mesh.garbage_collection();  // OpenSubdiv numbers vertices densely
    const Reference ref = refine_with_opensubdiv(mesh, scheme);
    // MeshEdit's vertex and face indices at the current level → OpenSubdiv's.
    std::vector<int> vmap(mesh.n_vertices());
    std::vector<int> fmap(mesh.n_faces());
    for (std::size_t i = 0; i < vmap.size(); ++i) {
        vmap[i] = static_cast<int>(i);
    }
    for (std::size_t i = 0; i < fmap.size(); ++i) {
        fmap[i] = static_cast<int>(i);
    }
    for (int level = 1; level <= kLevels; ++level) {
        SCOPED_TRACE("level " + std::to_string(level));
        const Far::TopologyLevel& parent = ref.refiner->GetLevel(level - 1);
        const Far::TopologyLevel& child = ref.refiner->GetLevel(level);
        const Mesh before = mesh;
        if (scheme == Scheme::Loop) {
            LoopOptions options;
            options.weights = LoopWeights::Loop;
            loop_subdivide(mesh, options);
        } else {
            quad_subdivide(mesh);
        }
        ASSERT_EQ(mesh.n_vertices(), static_cast<std::size_t>(child.GetNumVertices()));
        ASSERT_EQ(mesh.n_faces(), static_cast<std::size_t>(child.GetNumFaces()));

        // The layout: old v, then V + e, then (Catmull-Clark) V + E + f.
        ASSERT_TRUE(test::next_vertex_map(before, parent, scheme == Scheme::CatmullClark, vmap,
                                          fmap, mesh.vertices_size()));

        // Positions, to 1e-12.
        for (Vertex v : mesh.vertices()) {
            const Point& q = ref.points[level][vmap[v.idx()]];
            ASSERT_TRUE(test::near(mesh.position(v), {q.x, q.y, q.z}))
                << "vertex " << v.idx() << " (OpenSubdiv " << vmap[v.idx()] << ")";
        }
        // Faces as oriented cycles; remember which OpenSubdiv face each of ours is.
        const std::map<Cycle, int> osd_faces = test::faces_by_cycle(child);
        fmap.assign(mesh.faces_size(), -1);
        for (Face f : mesh.faces()) {
            Cycle c;
            for (Vertex v : mesh.vertices(f)) {
                c.push_back(vmap[v.idx()]);
            }
            const auto found = osd_faces.find(canonical(c));
            ASSERT_NE(found, osd_faces.end()) << "face " << f.idx() << " is not an OpenSubdiv face";
            fmap[f.idx()] = found->second;
        }
        // Crease edges: exactly OpenSubdiv's infinitely sharp interior edges.
        std::vector<std::pair<int, int>> ours, theirs;
        for (const auto& [a, b] : test::crease_pairs(mesh)) {
            ours.emplace_back(std::min(vmap[a], vmap[b]), std::max(vmap[a], vmap[b]));
        }
        for (int e = 0; e < child.GetNumEdges(); ++e) {
            // OpenSubdiv makes boundary edges infinitely sharp too; MeshEdit flags creases only.
            if (Sdc::Crease::IsInfinite(child.GetEdgeSharpness(e)) && !child.IsEdgeBoundary(e)) {
                const auto ends = child.GetEdgeVertices(e);
                theirs.emplace_back(std::min(ends[0], ends[1]), std::max(ends[0], ends[1]));
            }
        }
        std::sort(ours.begin(), ours.end());
        std::sort(theirs.begin(), theirs.end());
        EXPECT_EQ(ours, theirs);
    }
}

// The quad cube with creases: the bottom square (two creases at each of its corners), and
// the three edges at vertex 6 (a corner); vertex 2's third edge 2-6 makes 2 a corner too,
// and vertex 7 (on 6-7 only) is a dart.
Mesh creased_quad_cube() {
    Mesh mesh = test::quad_cube();
    for (auto [a, b] : test::Pairs{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {6, 2}, {6, 5}, {6, 7}}) {
        test::mark_crease(mesh, a, b);
    }
    return mesh;
}

// A 3 × 2 open grid of quads with one quad cut into two triangles and one poked: triangles,
// quads, a boundary with corners of valence 2.
Mesh open_mixed_grid() {
    std::vector<Vec3> p;
    for (int j = 0; j <= 2; ++j) {
        for (int i = 0; i <= 3; ++i) {
            p.push_back({static_cast<double>(i), static_cast<double>(j), 0.1 * i * j});
        }
    }
    const auto id = [](int i, int j) { return static_cast<std::uint32_t>(j * 4 + i); };
    std::vector<std::vector<std::uint32_t>> faces;
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 3; ++i) {
            if (i == 1 && j == 0) {
                faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
                faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            }
        }
    }
    Mesh mesh = test::mesh_from_faces(p, faces);
    poke(mesh, Face(static_cast<std::uint32_t>(mesh.n_faces() - 1)));
    return mesh;
}

TEST(OpenSubdivCatmark, QuadCube) {
    expect_equal_to_opensubdiv(test::quad_cube(), Scheme::CatmullClark);
}
TEST(OpenSubdivCatmark, MixedTrianglesQuadsAndAPentagon) {
    Mesh mesh = test::quad_cube();
    poke(mesh, Face(1));                                        // four triangles
    dissolve_edge(mesh, mesh.find_edge(Vertex(2), Vertex(6)));  // a hexagon
    expect_equal_to_opensubdiv(mesh, Scheme::CatmullClark);
}
TEST(OpenSubdivCatmark, OpenGrid) {
    expect_equal_to_opensubdiv(open_mixed_grid(), Scheme::CatmullClark);
}
TEST(OpenSubdivCatmark, CreasedCube) {
    expect_equal_to_opensubdiv(creased_quad_cube(), Scheme::CatmullClark);
}
TEST(OpenSubdivCatmark, TriangleMeshes) {
    expect_equal_to_opensubdiv(shapes::icosahedron(), Scheme::CatmullClark);
    expect_equal_to_opensubdiv(test::creased_cube(), Scheme::CatmullClark);
}

TEST(OpenSubdivLoop, IcosahedronWithLoopsOwnWeights) {
    expect_equal_to_opensubdiv(shapes::icosahedron(), Scheme::Loop);
}
TEST(OpenSubdivLoop, CreasedTriangleCube) {
    expect_equal_to_opensubdiv(test::creased_cube(), Scheme::Loop);
}
TEST(OpenSubdivLoop, OpenGridAndDisk) {
    expect_equal_to_opensubdiv(shapes::grid(4, 3), Scheme::Loop);
    expect_equal_to_opensubdiv(shapes::disk(7), Scheme::Loop);
}
TEST(OpenSubdivLoop, Torus) {
    expect_equal_to_opensubdiv(shapes::torus(8, 5), Scheme::Loop);
}

}  // namespace
}  // namespace meshedit
