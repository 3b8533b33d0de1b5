// numpy in and out: Mesh.from_arrays() with its checks, the V view, faces() and edges().
#include <cmath>
#include <cstdint>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "meshedit/core/build.h"
#include "py_arrays.h"
#include "py_mesh.h"

namespace py = pybind11;

namespace meshedit::python {
namespace {

std::string shape_text(const py::array& a) {
    std::string out = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) {
        out += (i > 0 ? ", " : "") + std::to_string(a.shape(i));
    }
    return out + (a.ndim() == 1 ? ",)" : ")");
}

// `value` as an array of numbers of `kinds` (numpy dtype kinds: "fiu", "iu"), else a
// TypeError naming the argument.
py::array numbers(const py::object& value, const char* name, const char* kinds,
                  const char* wanted) {
    py::array a;
    try {
        a = py::array::ensure(value);
    } catch (const py::error_already_set&) {
        a = py::array();
    }
    // An empty list is float64 to numpy: any empty array of numbers will do.
    const bool empty_numbers =
        a && a.size() == 0 && std::string("fiu").find(a.dtype().kind()) != std::string::npos;
    if (!a || (!empty_numbers && std::string(kinds).find(a.dtype().kind()) == std::string::npos)) {
        const std::string got =
            a ? "dtype " + std::string(py::str(a.dtype())) : std::string(py::str(value.get_type()));
        throw py::type_error(std::string(name) + ": expected " + wanted + ", got " + got);
    }
    return a;
}

// Indices as int64, checked against [0, n_vertices); the message names the argument and the
// first bad entry.
py::array_t<std::int64_t, py::array::c_style> indices_of(const py::object& value, const char* name,
                                                         std::size_t n_vertices) {
    auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(
        numbers(value, name, "iu", "integers"));
    const std::int64_t* p = a.data();
    for (py::ssize_t i = 0; i < a.size(); ++i) {
        if (p[i] < 0 || static_cast<std::uint64_t>(p[i]) >= n_vertices) {
            std::string where = std::string(name) + "[";
            if (a.ndim() == 2) {
                where += std::to_string(i / a.shape(1)) + ", " + std::to_string(i % a.shape(1));
            } else {
                where += std::to_string(i);
            }
            throw py::index_error(where + "] = " + std::to_string(p[i]) +
                                  " is out of range (V has " + std::to_string(n_vertices) +
                                  " rows)");
        }
    }
    return a;
}

}  // namespace

PolygonSoup soup_from_arrays(const py::object& v, const py::object& f, const py::object& indices) {
    auto positions = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(
        numbers(v, "V", "fiu", "numbers"));
    if (positions.ndim() != 2 || positions.shape(1) != 3) {
        throw py::value_error("V: expected shape (n, 3), got " + shape_text(positions));
    }
    const auto nv = static_cast<std::size_t>(positions.shape(0));
    if (nv > kInvalidIndex - 1) {
        throw py::value_error("V: too many vertices (" + std::to_string(nv) + ")");
    }
    PolygonSoup soup;
    soup.positions.resize(nv);
    const double* xyz = positions.data();
    for (std::size_t i = 0; i < nv; ++i) {
        const Vec3 p{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw py::value_error("V: row " + std::to_string(i) + " is not finite (" +
                                  std::string(py::str(py::make_tuple(p.x, p.y, p.z))) + ")");
        }
        soup.positions[i] = p;
    }

    if (indices.is_none()) {
        // F: (n, 3) or (n, 4)
        const auto faces = indices_of(f, "F", nv);
        if (faces.ndim() != 2 || (faces.shape(1) != 3 && faces.shape(1) != 4)) {
            throw py::value_error("F: expected shape (n, 3) or (n, 4), got " + shape_text(faces));
        }
        const auto k = static_cast<std::size_t>(faces.shape(1));
        const auto nf = static_cast<std::size_t>(faces.shape(0));
        soup.indices.assign(faces.data(), faces.data() + nf * k);
        soup.face_offsets.resize(nf + 1);
        for (std::size_t i = 0; i <= nf; ++i) {
            soup.face_offsets[i] = static_cast<std::uint32_t>(i * k);
        }
        return soup;
    }

    // offsets (n + 1,) into indices: face i is indices[offsets[i]:offsets[i + 1]]
    const auto corners = indices_of(indices, "indices", nv);
    if (corners.ndim() != 1) {
        throw py::value_error("indices: expected one dimension, got " + shape_text(corners));
    }
    auto offsets = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(
        numbers(f, "offsets", "iu", "integers"));
    if (offsets.ndim() != 1 || offsets.size() < 1) {
        throw py::value_error("offsets: expected shape (faces + 1,), got " + shape_text(offsets));
    }
    const std::int64_t* o = offsets.data();
    if (o[0] != 0 || o[offsets.size() - 1] != corners.size()) {
        throw py::value_error(
            "offsets: must start at 0 and end at len(indices) = " + std::to_string(corners.size()) +
            " (got " + std::to_string(o[0]) + " … " + std::to_string(o[offsets.size() - 1]) + ")");
    }
    soup.face_offsets.resize(static_cast<std::size_t>(offsets.size()));
    for (py::ssize_t i = 0; i < offsets.size(); ++i) {
        if (i > 0 && o[i] < o[i - 1]) {
            throw py::value_error("offsets[" + std::to_string(i) + "] = " + std::to_string(o[i]) +
                                  " is below offsets[" + std::to_string(i - 1) + "]");
        }
        soup.face_offsets[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(o[i]);
    }
    soup.indices.assign(corners.data(), corners.data() + corners.size());
    return soup;
}

py::array positions_view(const py::object& owner, PyMesh& self) {
    const Mesh& mesh = self.mesh;
    const std::size_t n = mesh.vertices_size();
    if (n == 0) {
        return py::array_t<double>(std::vector<py::ssize_t>{0, 3});
    }
    static_assert(sizeof(Vec3) == 3 * sizeof(double));
    // A view of the mesh's own array, based on the pin that keeps the Python Mesh alive.
    py::object pin = self.pin ? py::object(self.pin()) : py::object(py::none());
    if (pin.is_none()) {
        pin = py::cast(PositionsPin{owner, {}});
        self.pin = py::weakref(pin);
    }
    auto* data = const_cast<double*>(&mesh.position_vector().data()->x);
    return py::array_t<double>({static_cast<py::ssize_t>(n), py::ssize_t{3}},
                               {py::ssize_t{sizeof(Vec3)}, py::ssize_t{sizeof(double)}}, data, pin);
}

void release_views(PyMesh& self) {
    if (!self.pin) {
        return;
    }
    py::object pin = self.pin();
    self.pin = py::weakref();
    if (pin.is_none()) {
        return;
    }
    auto& p = pin.cast<PositionsPin&>();
    memory::Array<Vec3>& positions = self.mesh.position_vector();
    p.detached = std::move(positions);
    positions = p.detached;
    p.mesh = py::none();
}

// Each face from the start of its anchor halfedge: a mesh built from arrays gives its faces
// back as they went in.
py::object faces_of(const Mesh& mesh) {
    std::size_t degree = 0;
    bool uniform = true;
    for (const Face f : mesh.faces()) {
        const std::size_t k = mesh.valence(f);
        uniform = uniform && (degree == 0 || k == degree);
        degree = k;
    }
    if (uniform && degree > 0) {
        py::array_t<std::int64_t> out(
            {static_cast<py::ssize_t>(mesh.n_faces()), static_cast<py::ssize_t>(degree)});
        std::int64_t* p = out.mutable_data();
        for (const Face f : mesh.faces()) {
            for (const Halfedge h : mesh.halfedges(f)) {
                *p++ = mesh.from_vertex(h).idx();
            }
        }
        return out;
    }
    py::list out;
    for (const Face f : mesh.faces()) {
        py::list corners;
        for (const Halfedge h : mesh.halfedges(f)) {
            corners.append(mesh.from_vertex(h).idx());
        }
        out.append(corners);
    }
    return out;
}

py::array edges_of(const Mesh& mesh) {
    py::array_t<std::int64_t> out({static_cast<py::ssize_t>(mesh.n_edges()), py::ssize_t{2}});
    std::int64_t* p = out.mutable_data();
    for (const Edge e : mesh.edges()) {
        const Halfedge h = mesh.halfedge(e, 0);
        *p++ = mesh.from_vertex(h).idx();
        *p++ = mesh.to_vertex(h).idx();
    }
    return out;
}

}  // namespace meshedit::python
