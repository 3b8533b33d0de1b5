// Meshes near the top of the double range (coordinates around 1e308): every operation that
// makes new positions keeps them finite, and gives exactly the result of the same mesh at an
// ordinary scale, scaled by the same power of two. (A fuzzing campaign found Loop writing
// infinities for a .bez patch at 1e308.)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/subdivision.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

constexpr int kExponent = 1024;  // [0.5, 1) to [2^1023, 2^1024): near DBL_MAX, 1.8e308

// Every position, deleted vertices' too (identical() compares whole arrays).
Mesh scaled(Mesh mesh, int exponent) {
    for (std::uint32_t i = 0; i < mesh.vertices_size(); ++i) {
        Vec3& p = mesh.position(Vertex(i));
        p = Vec3{std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
    }
    return mesh;
}

// `mesh` scaled by a power of two so that its largest coordinate lies in [0.5, 1): scaled
// by 2^kExponent, it then just fits the double range, and a sum of two may not.
Mesh normalised(const Mesh& mesh) {
    double largest = 0.0;
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    }
    int exponent = 0;
    std::frexp(largest, &exponent);
    return scaled(mesh, -exponent);
}

// An edge whose endpoints' coordinates add up to 2^1024 or more when scaled.
Edge same_sign_edge(const Mesh& mesh) {
    for (Edge e : mesh.edges()) {
        const Vec3& a = mesh.position(mesh.vertex(e, 0));
        const Vec3& b = mesh.position(mesh.vertex(e, 1));
        for (int c = 0; c < 3; ++c) {
            if (std::abs(a[c] + b[c]) >= 1.0) {  // scaled, the sum is 2^1024 or more: inf
                return e;
            }
        }
    }
    return Edge();
}

TEST(HugeCoordinates, LoopMatchesTheOrdinaryScaleBitForBit) {
    for (const Mesh& any : {shapes::icosahedron(), shapes::grid(3, 2), shapes::torus(6, 4)}) {
        const Mesh small = normalised(any);
        Mesh expected = small;
        loop_subdivide(expected);
        expected = scaled(expected, kExponent);
        Mesh huge = scaled(small, kExponent);
        loop_subdivide(huge);
        EXPECT_VALID(huge);
        EXPECT_TRUE(test::identical(huge, expected));
    }
}

TEST(HugeCoordinates, SplitAndCollapsePutTheMidpointInRange) {
    const Mesh small = normalised(shapes::icosahedron());
    const Edge e = same_sign_edge(small);
    ASSERT_TRUE(e.is_valid());
    for (const bool splitting : {true, false}) {
        Mesh expected = small;
        Mesh huge = scaled(small, kExponent);
        if (splitting) {
            ASSERT_TRUE(split(expected, e).ok());
            ASSERT_TRUE(split(huge, e).ok());
        } else {
            ASSERT_TRUE(collapse(expected, e).ok());
            ASSERT_TRUE(collapse(huge, e).ok());
        }
        EXPECT_VALID(huge);
        EXPECT_TRUE(test::identical(huge, scaled(expected, kExponent)));
    }
}

}  // namespace
}  // namespace meshedit

namespace meshedit {
namespace {

Mesh scaled_by_power_of_two(Mesh mesh, int exponent) {
    for (Vertex v : mesh.vertices()) {
        Vec3& p = mesh.position(v);
        p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
    }
    return mesh;
}

// QEM and remeshing square coordinates; near 1e300 that overflows and near 1e-300 underflows.
// Both work on the mesh scaled by a power of two, so the huge and tiny spheres come out as
// the unit sphere's result, scaled, bit for bit.
TEST(HugeCoordinates, SimplifyAndRemeshDoNotDependOnScale) {
    const Mesh unit = shapes::icosphere(3);
    SimplifyOptions half;
    half.target_faces = 640;
    RemeshOptions remesh_with;
    remesh_with.target_length = 0.15;
    Mesh simplified = unit, remeshed = unit;
    simplify(simplified, half);
    simplified.garbage_collection();
    remesh(remeshed, remesh_with);
    for (const int exponent : {990, -1000}) {
        SCOPED_TRACE(exponent);
        Mesh a = scaled_by_power_of_two(unit, exponent);
        ASSERT_EQ(check_simplify(a, half), "");
        simplify(a, half);
        a.garbage_collection();
        EXPECT_TRUE(test::identical(a, scaled_by_power_of_two(simplified, exponent)));
        Mesh b = scaled_by_power_of_two(unit, exponent);
        RemeshOptions scaled = remesh_with;
        scaled.target_length = std::ldexp(0.15, exponent);
        ASSERT_EQ(check_remesh(b, scaled), "");
        remesh(b, scaled);
        EXPECT_TRUE(test::identical(b, scaled_by_power_of_two(remeshed, exponent)));
    }
    // The default length (the mean) is measured without overflow too.
    EXPECT_EQ(check_remesh(scaled_by_power_of_two(unit, 1000), RemeshOptions{}), "");
}

}  // namespace
}  // namespace meshedit
