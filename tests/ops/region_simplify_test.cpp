// simplify_region and remesh_region through the edit language: only the region's inner vertices
// move or go, so its border and everything outside it stay bit for bit; a selection grown by
// select_more names the same region; refusals name their reason and leave the mesh.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <set>
#include <string>

#include "meshedit/core/shapes.h"
#include "meshedit/core/smoothing.h"
#include "meshedit/ops/ops.h"
#include "support/mesh_compare.h"

namespace meshedit::ops {
namespace {

// The faces with every corner within `r` of the sphere's point (0, 0, 1): a cap.
std::string cap(const Mesh& mesh, double r) {
    std::string out;
    for (const Face f : mesh.faces()) {
        bool inside = true;
        for (const Vertex v : mesh.vertices(f)) {
            inside = inside && distance(mesh.position(v), Vec3{0, 0, 1}) <= r;
        }
        if (inside) {
            out += (out.empty() ? "f" : "+f") + std::to_string(f.idx());
        }
    }
    return out;
}

TEST(SimplifyRegion, OnlyTheInsideOfTheRegionChanges) {
    const Mesh sphere = shapes::icosphere(4);  // 5120 triangles
    const std::string region = cap(sphere, 0.6);
    const Step step = parse_step("simplify_region:" + region + ":0.25");
    const std::vector<Face> faces = named_faces(sphere, step);
    ASSERT_GT(faces.size(), 200u);
    const std::vector<Vertex> inner = region_inner_vertices(sphere, faces);
    std::vector<bool> is_inner(sphere.vertices_size(), false);
    for (const Vertex v : inner) {
        is_inner[v.idx()] = true;
    }
    Mesh mesh = sphere;
    const StepResult result = run_step(mesh, step);
    EXPECT_VALID(mesh);
    // About a quarter of the region's faces are left, the rest of the mesh as it was.
    const std::size_t removed = sphere.n_faces() - mesh.n_faces();
    EXPECT_NEAR(static_cast<double>(removed), 0.75 * static_cast<double>(faces.size()), 2.0);
    EXPECT_EQ(result.message.rfind(
                  "simplified the region of " + std::to_string(faces.size()) + " faces to ", 0),
              0u)
        << result.message;
    for (const Vertex v : sphere.vertices()) {
        if (!is_inner[v.idx()]) {
            ASSERT_FALSE(mesh.is_deleted(v)) << v.idx();
            EXPECT_EQ(mesh.position(v), sphere.position(v)) << v.idx();
        }
    }
    std::size_t outside = 0, kept = 0;
    for (const Face f : sphere.faces()) {
        bool in_region = false;
        for (const Face g : faces) {
            in_region = in_region || g == f;
        }
        if (!in_region) {
            ++outside;
            ASSERT_FALSE(mesh.is_deleted(f)) << f.idx();
            for (const Halfedge h : sphere.halfedges(f)) {
                EXPECT_EQ(mesh.to_vertex(h), sphere.to_vertex(h)) << f.idx();
            }
        } else {
            kept += mesh.is_deleted(f) ? 0 : 1;
        }
    }
    EXPECT_EQ(outside, sphere.n_faces() - faces.size());
    EXPECT_EQ(result.selected_too.size() + 1, kept);  // what is left of the region, selected
}

// remesh_region refines a cap toward a shorter length; every face outside the cap comes out
// with the same corners (remesh renumbers, so they are matched by position) and the cap's
// border vertices stay where they were.
TEST(RemeshRegion, OnlyTheRegionIsRemeshed) {
    const Mesh sphere = shapes::icosphere(3);
    const std::string region = cap(sphere, 0.6);
    const Step step = parse_step("remesh_region:" + region + ":0.04");
    const std::vector<Face> faces = named_faces(sphere, step);
    std::vector<bool> in_region(sphere.faces_size(), false);
    for (const Face f : faces) {
        in_region[f.idx()] = true;
    }
    Mesh mesh = sphere;
    const StepResult result = run_step(mesh, step);
    EXPECT_VALID(mesh);
    EXPECT_GT(mesh.n_faces(), sphere.n_faces()) << result.message;
    EXPECT_EQ(result.message.rfind("remeshed the region of " + std::to_string(faces.size()) +
                                       " faces to edge length 0.04: ",
                                   0),
              0u)
        << result.message;
    using Corners = std::array<std::array<double, 3>, 3>;
    const auto corners_of = [](const Mesh& m, Face f) {
        Corners c{};
        std::size_t i = 0;
        for (const Vertex v : m.vertices(f)) {
            const Vec3 p = m.position(v);
            c[i++] = {p.x, p.y, p.z};
        }
        std::sort(c.begin(), c.end());
        return c;
    };
    std::set<Corners> after;
    for (const Face f : mesh.faces()) {
        after.insert(corners_of(mesh, f));
    }
    for (const Face f : sphere.faces()) {
        if (!in_region[f.idx()]) {
            EXPECT_EQ(after.count(corners_of(sphere, f)), 1u) << "face " << f.idx();
        }
    }
}

TEST(SimplifyRegion, RefusalsNameTheirReasonAndLeaveTheMesh) {
    const Mesh sphere = shapes::icosphere(2);
    const auto refusal = [&](const Mesh& before, const std::string& text) {
        Mesh mesh = before;
        try {
            run_step(mesh, parse_step(text));
        } catch (const OpError& e) {
            EXPECT_TRUE(test::identical(mesh, before)) << text;
            return std::string(e.what());
        }
        ADD_FAILURE() << text << " ran";
        return std::string();
    };
    EXPECT_NE(
        refusal(sphere, "simplify_region:f3")
            .find("cannot simplify the region: every vertex of the 1 face is on their border"),
        std::string::npos);
    EXPECT_NE(refusal(sphere, "simplify_region:f0..100:1.5").find("above 0 and below 1, not 1.5"),
              std::string::npos);
    const Mesh quads = shapes::quad_grid(4, 4);
    EXPECT_NE(refusal(quads, "simplify_region:f0..15").find("triangle"), std::string::npos);
}

}  // namespace
}  // namespace meshedit::ops
