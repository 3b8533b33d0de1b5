// meshedit.Document: a mesh with undo and redo. A step that names an element (flip, split,
// extrude…) is undone from a recording of what it wrote (MeshRecorder: a few hundred bytes
// whatever the mesh's size); a whole-mesh step (loop, simplify, compact…) from a copy of the
// mesh taken before it.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "meshedit/core/mesh_change.h"
#include "meshedit/ops/ops.h"
#include "py_mesh.h"

namespace py = pybind11;

namespace meshedit::python {
namespace {

class Document {
public:
    explicit Document(py::object mesh) : mesh_object_(std::move(mesh)) {
        if (!py::isinstance<PyMesh>(mesh_object_)) {
            throw py::type_error("Document(mesh): expected a meshedit.Mesh, got " +
                                 std::string(py::str(mesh_object_.get_type())));
        }
        version_ = target().version;
    }

    py::object mesh() const { return mesh_object_; }

    std::vector<std::string> apply(const std::string& text) { return apply_step(text, nullptr); }

    // apply() that also says what the last step selected (for the verb methods).
    py::tuple step(const std::string& text) {
        ElementRef last;
        std::vector<std::string> notices = apply_step(text, &last);
        return py::make_tuple(element_of(target().mesh, last), notices);
    }

    std::vector<std::string> apply_step(const std::string& text, ElementRef* last) {
        check_in_step(false);
        PyMesh& m = target();
        const std::vector<ops::Step> steps = ops::parse(text);
        release_views(m);
        bool local = !steps.empty();
        for (const ops::Step& step : steps) {
            local = local && step.target != ops::Target::None;
        }
        Entry entry;
        entry.text = text;
        std::vector<std::string> notices;
        if (local) {
            MeshRecorder recorder(m.mesh);
            try {
                notices = run(m, steps, last);
            } catch (...) {
                recorder.roll_back();
                throw;
            }
            entry.change = recorder.finish();
        } else {
            entry.other = m.mesh;  // a copy: undo swaps it back in
            notices = apply_text(m, text, false, last);
        }
        ++m.version;
        version_ = m.version;
        undo_.push_back(std::move(entry));
        redo_.clear();
        return notices;
    }

    void undo() {
        check_in_step(true);
        if (undo_.empty()) {
            throw py::index_error("nothing to undo");
        }
        Entry entry = std::move(undo_.back());
        undo_.pop_back();
        PyMesh& m = target();
        release_views(m);
        if (entry.change) {
            entry.change->undo(m.mesh);
        } else {
            std::swap(m.mesh, *entry.other);
        }
        ++m.version;
        version_ = m.version;
        redo_.push_back(std::move(entry));
    }

    void redo() {
        check_in_step(true);
        if (redo_.empty()) {
            throw py::index_error("nothing to redo");
        }
        Entry entry = std::move(redo_.back());
        redo_.pop_back();
        PyMesh& m = target();
        release_views(m);
        if (entry.change) {
            entry.change->redo(m.mesh);
        } else {
            std::swap(m.mesh, *entry.other);
        }
        ++m.version;
        version_ = m.version;
        undo_.push_back(std::move(entry));
    }

    std::vector<std::string> session() const {
        std::vector<std::string> out;
        for (const Entry& e : undo_) {
            out.push_back(e.text);
        }
        return out;
    }

    bool can_undo() const { return !undo_.empty(); }
    bool can_redo() const { return !redo_.empty(); }

private:
    struct Entry {
        std::string text;
        std::optional<MeshChange> change;  // a local step's recording
        std::optional<Mesh> other;         // a whole-mesh step: the mesh on the other side
    };

    PyMesh& target() const { return mesh_object_.cast<PyMesh&>(); }

    // Runs a list of local steps one by one under the document's recorder (apply_text() would
    // copy the mesh for a list; the recorder's roll_back() undoes a failed list instead).
    static std::vector<std::string> run(PyMesh& m, const std::vector<ops::Step>& steps,
                                        ElementRef* last) {
        std::vector<std::string> notices;
        ops::ApplyOptions options;
        options.notice = [&notices](const std::string& line) { notices.push_back(line); };
        try {
            const ElementRef selected = ops::apply_steps(m.mesh, steps, options);
            if (last != nullptr) {
                *last = selected;
            }
        } catch (const ops::OpError& e) {
            if (e.refused()) {
                throw Refused(e.what());
            }
            throw BadStep(e.what());
        }
        return notices;
    }

    // The history describes the mesh only as the document left it: an edit made to the mesh
    // behind the document's back drops it (and undo/redo say so).
    void check_in_step(bool for_history) {
        if (target().version == version_) {
            return;
        }
        undo_.clear();
        redo_.clear();
        version_ = target().version;
        if (for_history) {
            throw std::runtime_error(
                "the mesh was edited outside the document: its undo history was dropped");
        }
    }

    py::object mesh_object_;
    std::uint64_t version_ = 0;
    std::vector<Entry> undo_;
    std::vector<Entry> redo_;
};

}  // namespace

void bind_document(py::module_& m) {
    py::class_<Document>(m, "Document")
        .def(py::init<py::object>(), py::arg("mesh"))
        .def_property_readonly("mesh", &Document::mesh)
        .def("apply", &Document::apply, py::arg("steps"))
        .def("_step", &Document::step, py::arg("step"))
        .def("undo", &Document::undo)
        .def("redo", &Document::redo)
        .def_property_readonly("session", &Document::session)
        .def_property_readonly("can_undo", &Document::can_undo)
        .def_property_readonly("can_redo", &Document::can_redo);
}

}  // namespace meshedit::python
