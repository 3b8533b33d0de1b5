#pragma once
// The Python module's shared pieces: the Mesh as Python holds it, and the exception types.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"

namespace meshedit::python {

/// A mesh as `meshedit.Mesh` holds it: the halfedge mesh, what reading or building it said,
/// and a count of the edits made through Python (a Document notices edits made behind it).
struct PyMesh {
    Mesh mesh;
    std::vector<std::string> notices;
    std::uint64_t version = 0;
    /// The PositionsPin that the live `V` views of the current position array share (a weak
    /// reference; null or dead when there are none).
    pybind11::weakref pin;

    PyMesh() = default;
    PyMesh(Mesh m, std::vector<std::string> n) : mesh(std::move(m)), notices(std::move(n)) {}
    /// A copy of the mesh and its notices: views and history stay with the original.
    PyMesh(const PyMesh& other) : mesh(other.mesh), notices(other.notices) {}
    PyMesh(PyMesh&&) = default;
    PyMesh& operator=(const PyMesh&) = delete;
};

/// The base object of `V` views: while attached it keeps the Python Mesh alive; before an edit
/// that might reallocate, release_views() moves the position array it shows into `detached`
/// and gives the mesh a copy, so a view kept across an edit shows the positions as they were
/// instead of freed memory.
struct PositionsPin {
    pybind11::object mesh;
    memory::Array<Vec3> detached;
};

/// What a step selected, as the Python methods return it: a vertex or face index, an edge as
/// its two vertex indices, or None.
pybind11::object element_of(const Mesh& mesh, const ElementRef& element);

/// Detaches the live `V` views of `mesh` (see PositionsPin). Call before every edit.
void release_views(PyMesh& mesh);

/// meshedit.Refused: the operation said no (ops::OpError with refused()); the mesh is as it was.
class Refused : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};
/// meshedit.BadStep: a step names an element the mesh does not have (a ValueError).
class BadStep : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Parses `text` (a comma list, or a session file's text when `session`) and runs it on
/// `mesh` as one edit: all steps or none (a failing list leaves the mesh as it was).
/// \return the notices, each prefixed with its step; `last` receives what the last step
/// selected. \throws ops::SyntaxError, Refused, BadStep.
std::vector<std::string> apply_text(PyMesh& mesh, const std::string& text, bool session,
                                    ElementRef* last = nullptr);

}  // namespace meshedit::python
