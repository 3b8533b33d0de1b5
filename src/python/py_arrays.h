#pragma once
// numpy in and out (arrays.cpp).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "meshedit/core/build.h"
#include "meshedit/core/mesh.h"
#include "py_mesh.h"

namespace meshedit::python {

/// The soup of Mesh.from_arrays(V, F) (`indices` None) or (V, offsets, indices), checked: a
/// TypeError for non-numbers, a ValueError for a bad shape or a NaN, an IndexError for an
/// index out of range, each naming the argument and the entry.
PolygonSoup soup_from_arrays(const pybind11::object& v, const pybind11::object& f,
                             const pybind11::object& indices);
/// V: an (n, 3) float64 view of the positions, n = vertices_size(), that keeps `owner` alive.
pybind11::array positions_view(const pybind11::object& owner, PyMesh& mesh);
/// The live faces: an (n, k) int64 array when all have k corners, else a list of lists.
pybind11::object faces_of(const Mesh& mesh);
/// The live edges as an (n, 2) int64 array of vertex indices.
pybind11::array edges_of(const Mesh& mesh);

}  // namespace meshedit::python
