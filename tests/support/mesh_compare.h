#pragma once
/// \file
/// Assertions for tests: exact snapshot equality, face-by-face comparison by positions, and
/// validate() with its message.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "meshedit/core/mesh.h"

namespace meshedit::test {

/// Every connectivity array, position, deletion flag and the crease property, compared bit
/// for bit. Use it to check that a refused op left the mesh untouched.
::testing::AssertionResult identical(const Mesh& actual, const Mesh& expected);

/// The live faces of both meshes, each as its cycle of corner positions, match one to one
/// (in any face order, each cycle in any rotation but the same orientation) with positions
/// equal to `tol`; vertex counts must agree too.
::testing::AssertionResult same_faces_by_position(const Mesh& actual, const Mesh& expected,
                                                  double tol = 1e-12);

/// The live faces as corner index cycles, rotated to start at their smallest index, sorted.
std::vector<std::vector<std::uint32_t>> canonical_faces(const Mesh& mesh);

/// validate(mesh) passes; otherwise the assertion message carries its report.
::testing::AssertionResult is_valid(const Mesh& mesh);

}  // namespace meshedit::test

/// Fails the test (and reports the broken invariant) unless `mesh` is valid.
#define EXPECT_VALID(mesh) EXPECT_TRUE(::meshedit::test::is_valid(mesh))
#define ASSERT_VALID(mesh) ASSERT_TRUE(::meshedit::test::is_valid(mesh))
