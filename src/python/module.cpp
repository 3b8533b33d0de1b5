// The `meshedit` Python module's C++ half (`meshedit._meshedit`): reading and writing, meshes
// from and to numpy, the edit language, info(), validate() and fields. python/meshedit's
// __init__.py turns each verb of the language into a method (docs/python.md).
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "meshedit/core/attributes.h"
#include "meshedit/core/build.h"
#include "meshedit/core/fields.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/threads.h"
#include "meshedit/core/topology.h"
#include "meshedit/core/validate.h"
#include "meshedit/files/files.h"
#include "meshedit/files/io_error.h"
#include "meshedit/io/document.h"
#include "meshedit/io/io.h"
#include "meshedit/ops/ops.h"
#include "meshedit/repair/problems.h"
#include "py_arrays.h"
#include "py_mesh.h"

namespace py = pybind11;

namespace meshedit::python {
namespace {

// A corner attribute in the order faces() lists corners (corner i of a face is the head of
// the halfedge before its i-th), as a (corners, n) float64 array; None without it.
template <class T>
py::object corner_values(const Mesh& mesh, const char* name) {
    const auto prop = mesh.get_property<Halfedge, T>(name);
    if (!prop) {
        return py::none();
    }
    constexpr py::ssize_t n = sizeof(T) / sizeof(double);
    std::size_t corners = 0;
    for (const Face f : mesh.faces()) {
        corners += mesh.valence(f);
    }
    py::array_t<double> out({static_cast<py::ssize_t>(corners), n});
    double* p = out.mutable_data();
    for (const Face f : mesh.faces()) {
        for (const Halfedge h : mesh.halfedges(f)) {
            const T& v = prop[mesh.prev(h)];
            std::memcpy(p, &v, sizeof(T));
            p += n;
        }
    }
    return out;
}

}  // namespace

void bind_document(py::module_& m);

py::object element_of(const Mesh& mesh, const ElementRef& e) {
    switch (e.kind) {
        case ElementRef::Kind::Vertex:
        case ElementRef::Kind::Face:
            return py::int_(e.index);
        case ElementRef::Kind::Edge:
            if (is_live(mesh, e)) {
                return py::make_tuple(mesh.vertex(Edge(e.index), 0).idx(),
                                      mesh.vertex(Edge(e.index), 1).idx());
            }
            return py::none();
        default:
            return py::none();
    }
}

namespace {

// "line one\nline two" → one entry per non-empty line.
std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        end = end == std::string::npos ? text.size() : end;
        if (end > start) {
            out.push_back(text.substr(start, end - start));
        }
        start = end + 1;
    }
    return out;
}

// A mesh file, or a .bez file's welded tessellation (as `meshedit info` reads it).
PyMesh read_path(const std::filesystem::path& path, int density) {
    if (density < 1 || density > 256) {
        throw py::value_error("density: expected 1 to 256, got " + std::to_string(density));
    }
    ReadOptions options;
    options.density = density;
    LoadedDocument loaded = read_document(path, options);
    if (loaded.kind == DocumentKind::Curve) {
        throw IoError(path.string(), "", "a Bezier curve, not a mesh");
    }
    PyMesh out(std::move(loaded.mesh), std::move(loaded.notices));
    if (loaded.kind == DocumentKind::Surface) {
        out.notices.push_back("tessellated " + std::to_string(loaded.patches.size()) +
                              " Bezier patches at density " + std::to_string(density));
    }
    for (std::string& line : lines_of(loaded.repairs.summary())) {
        out.notices.push_back(std::move(line));
    }
    return out;
}

PyMesh from_arrays(const py::object& v, const py::object& f, const py::object& indices) {
    const PolygonSoup soup = soup_from_arrays(v, f, indices);
    BuildReport report;
    PyMesh out;
    try {
        out.mesh = build_mesh(soup, &report);
    } catch (const TopologyError& e) {
        throw py::value_error(e.what());
    }
    out.notices = lines_of(report.summary());
    return out;
}

std::size_t count_creases(const Mesh& mesh) {
    std::size_t n = 0;
    if (const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
        for (const Edge e : mesh.edges()) {
            n += crease[e] != 0 ? 1 : 0;
        }
    }
    return n;
}

py::object bbox_of(const Mesh& mesh) {
    const BoundingBox box = mesh.bounds();
    if (box.is_empty()) {
        return py::none();
    }
    py::dict d;
    d["min"] = py::make_tuple(box.min.x, box.min.y, box.min.z);
    d["max"] = py::make_tuple(box.max.x, box.max.y, box.max.z);
    return d;
}

// What `meshedit info --json` says about a mesh (src/cli/info.cpp), from the same functions;
// `stats`: also what --stats adds.
py::dict info(const PyMesh& self, bool stats) {
    const Mesh& mesh = self.mesh;
    const MeshStats s = compute_stats(mesh);
    py::dict d;
    d["vertices"] = s.vertices;
    d["edges"] = s.edges;
    d["faces"] = s.faces;
    d["triangle_mesh"] = mesh.is_triangle_mesh();
    py::dict degrees;
    for (const Face f : mesh.faces()) {
        const py::int_ k(mesh.valence(f));
        degrees[k] =
            degrees.contains(k) ? py::int_(degrees[k].cast<std::size_t>() + 1) : py::int_(1);
    }
    d["face_degrees"] = degrees;
    d["boundary_loops"] = s.boundary_loops;
    d["components"] = s.components;
    d["euler_characteristic"] = s.euler_characteristic;
    d["genus"] = s.genus;
    d["creases"] = count_creases(mesh);
    d["bbox"] = bbox_of(mesh);
    d["notices"] = self.notices;
    if (stats) {
        py::dict st;
        st["area"] = surface_area(mesh);
        if (s.boundary_loops == 0) {
            st["volume"] = signed_volume(mesh);
        }
        st["total_angle_defect"] = total_angle_defect(mesh);
        py::dict fields;
        for (const FieldInfo* field_ptr : mesh_fields(mesh)) {
            const FieldInfo& field = *field_ptr;
            const FieldStats fs = field_stats(compute_field(mesh, field));
            py::dict one;
            one["count"] = fs.count;
            one["min"] = fs.min;
            one["mean"] = fs.mean;
            one["max"] = fs.max;
            fields[py::str(std::string(field.name))] = one;
        }
        st["fields"] = fields;
        d["stats"] = st;
    }
    return d;
}

py::array field(const PyMesh& self, const std::string& name, std::uint32_t source) {
    const FieldInfo* info = find_field(self.mesh, name);
    if (info == nullptr) {
        throw py::value_error("unknown field '" + name +
                              "' (fields: " + field_names(self.mesh, ", ") + ")");
    }
    if (info->name == "distance" &&
        (source >= self.mesh.vertices_size() || self.mesh.is_deleted(Vertex(source)))) {
        throw py::index_error("source: vertex " + std::to_string(source) + " is not in the mesh");
    }
    FieldOptions options;
    options.source = Vertex(source);
    const std::vector<double> values = compute_field(self.mesh, *info, options);
    py::array_t<double> out(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), out.mutable_data());
    return out;
}

// Vec3s as an (n, 3) float64 array (a copy).
py::array vec3_array(const std::vector<Vec3>& values) {
    py::array_t<double> out({static_cast<py::ssize_t>(values.size()), py::ssize_t{3}});
    double* p = out.mutable_data();
    for (const Vec3& v : values) {
        *p++ = v.x;
        *p++ = v.y;
        *p++ = v.z;
    }
    return out;
}

// The crease edges (the e:crease mark Loop keeps sharp) as an (n, 2) array of vertex indices.
py::array creases_of(const Mesh& mesh) {
    std::vector<std::int64_t> ends;
    if (const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty)) {
        for (const Edge e : mesh.edges()) {
            if (crease[e] != 0) {
                ends.push_back(mesh.vertex(e, 0).idx());
                ends.push_back(mesh.vertex(e, 1).idx());
            }
        }
    }
    py::array_t<std::int64_t> out({static_cast<py::ssize_t>(ends.size() / 2), py::ssize_t{2}});
    std::copy(ends.begin(), ends.end(), out.mutable_data());
    return out;
}

py::list verb_table() {
    py::list out;
    for (const ops::Verb& verb : ops::verbs()) {
        py::dict d;
        d["name"] = std::string(verb.name);
        d["whole_mesh"] = (verb.takes & ops::kWholeMesh) != 0;
        d["levels"] = (verb.takes & ops::kLevels) != 0;
        d["uv"] = (verb.takes & ops::kUvArg) != 0;
        d["attributes"] = (verb.takes & ops::kAttributesArg) != 0;
        d["vertex"] = (verb.takes & ops::kVertexArg) != 0;
        d["edge"] = (verb.takes & ops::kEdgeArg) != 0;
        d["face"] = (verb.takes & ops::kFaceArg) != 0;
        d["edge_pair"] = (verb.takes & ops::kEdgePair) != 0;
        d["region"] = (verb.takes & ops::kRegion) != 0;
        d["max_amounts"] = verb.max_amounts;
        d["min_amounts"] = verb.min_amounts;
        d["defaults"] = std::vector<double>(verb.defaults.begin(), verb.defaults.end());
        d["syntax"] = std::string(verb.syntax);
        d["help"] = std::string(verb.help);
        out.append(d);
    }
    return out;
}

}  // namespace
}  // namespace meshedit::python

using namespace meshedit;
using namespace meshedit::python;

PYBIND11_MODULE(_meshedit, m) {
    m.doc() = "MeshEdit's halfedge meshes, file formats and edit language (docs/python.md)";
    m.attr("__version__") = MESHEDIT_VERSION;

    // IoError is an OSError; Refused a RuntimeError; BadStep and SyntaxError ValueErrors.
    static py::exception<IoError> io_error(m, "IoError", PyExc_OSError);
    static py::exception<Refused> refused(m, "Refused", PyExc_RuntimeError);
    static py::exception<BadStep> bad_step(m, "BadStep", PyExc_ValueError);
    static py::exception<ops::SyntaxError> syntax_error(m, "SyntaxError", bad_step.ptr());
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) {
                std::rethrow_exception(p);
            }
        } catch (const IoError& e) {
            io_error(e.what());
        } catch (const Refused& e) {
            refused(e.what());
        } catch (const ops::SyntaxError& e) {
            syntax_error(e.what());
        } catch (const BadStep& e) {
            bad_step(e.what());
        }
    });

    py::class_<PositionsPin>(m, "_PositionsPin");
    py::class_<PyMesh>(m, "Mesh")
        .def(py::init<>(), "An empty mesh.")
        .def_static("from_arrays", &from_arrays, py::arg("V"), py::arg("F"),
                    py::arg("indices") = py::none(),
                    "Mesh.from_arrays(V, F) with F of shape (n, 3) or (n, 4), or "
                    "Mesh.from_arrays(V, offsets, indices) for polygons.")
        .def("copy", [](const PyMesh& self) { return PyMesh(self); })
        .def("__copy__", [](const PyMesh& self) { return PyMesh(self); })
        .def("__deepcopy__", [](const PyMesh& self, py::dict) { return PyMesh(self); })
        .def_property_readonly(
            "V", [](py::object self) { return positions_view(self, self.cast<PyMesh&>()); },
            "(vertices_size, 3) float64 view of the positions, no copy (deleted vertices keep "
            "their rows until compact()). Take it again after an edit that adds vertices.")
        .def("faces", [](const PyMesh& self) { return faces_of(self.mesh); })
        .def(
            "texcoords",
            [](const PyMesh& self, int set) {
                if (set < 0 || set >= static_cast<int>(std::size(kTexCoordSets))) {
                    throw py::value_error("texcoords(set): set is 0 or 1, not " +
                                          std::to_string(set));
                }
                return corner_values<Vec2>(self.mesh, kTexCoordSets[set]);
            },
            py::arg("set") = 0,
            "Texture coordinates per face corner, (corners, 2) float64 in the order of faces() "
            "flattened, or None when the mesh has none: set 0 (OBJ vt, glTF TEXCOORD_0) or set 1, "
            "the second set (glTF TEXCOORD_1, COLLADA's second TEXCOORD set).")
        .def(
            "corner_normals",
            [](const PyMesh& self) {
                return corner_values<Vec3>(self.mesh, kCornerNormalProperty);
            },
            "The file's normals per face corner, (corners, 3) in the order of faces() flattened, "
            "or None.")
        .def(
            "face_materials",
            [](const PyMesh& self) -> py::object {
                const auto index = self.mesh.get_property<Face, std::uint32_t>(kMaterialProperty);
                if (!index) {
                    return py::none();
                }
                py::array_t<std::int64_t> out(static_cast<py::ssize_t>(self.mesh.n_faces()));
                std::int64_t* p = out.mutable_data();
                for (const Face f : self.mesh.faces()) {
                    *p++ = index[f];
                }
                return out;
            },
            "Each live face's index into materials(), in the order of faces(), or None.")
        .def(
            "materials",
            [](const PyMesh& self) {
                py::list out;
                for (const Material& material : self.mesh.materials()) {
                    py::dict d;
                    d["name"] = material.name;
                    d["base_colour"] =
                        py::make_tuple(material.base_colour.x, material.base_colour.y,
                                       material.base_colour.z, material.opacity);
                    d["texture"] = material.base_colour_texture;
                    d["texcoord_set"] = material.base_colour_texcoord;
                    out.append(d);
                }
                return out;
            },
            "The materials: name, base colour (r, g, b, opacity), base-colour texture path and the "
            "texture coordinate set it reads (0 or 1).")
        .def("edges", [](const PyMesh& self) { return edges_of(self.mesh); })
        .def("creases", [](const PyMesh& self) { return creases_of(self.mesh); })
        .def(
            "vertex_normals",
            [](const PyMesh& self) {
                std::vector<Vec3> normals;
                compute_vertex_normals(self.mesh, normals);
                return vec3_array(normals);
            },
            "Area-weighted unit vertex normals by vertex index, (vertices_size, 3).")
        .def(
            "face_normals", [](const PyMesh& self) { return vec3_array(face_normals(self.mesh)); },
            "Unit face normals by face index, (faces_size, 3); zero for deleted faces.")
        .def_readonly("notices", &PyMesh::notices)
        .def_property_readonly("n_vertices", [](const PyMesh& s) { return s.mesh.n_vertices(); })
        .def_property_readonly("n_edges", [](const PyMesh& s) { return s.mesh.n_edges(); })
        .def_property_readonly("n_faces", [](const PyMesh& s) { return s.mesh.n_faces(); })
        .def("info", &info, py::arg("stats") = false)
        .def("validate",
             [](const PyMesh& self) -> py::object {
                 if (const auto error = validate(self.mesh)) {
                     return py::str(error->message);
                 }
                 return py::none();
             })
        .def(
            "problems",
            [](const PyMesh& self) {
                // As `meshedit check --problems` and the viewer's Problems panel list them.
                py::list out;
                for (const Problem& p : find_problems(self.mesh, nullptr).problems) {
                    py::dict d;
                    d["kind"] = problem_kind_name(p.kind);
                    d["element"] = p.where.is_none() ? std::string() : to_string(p.where);
                    d["size"] = p.size;
                    d["text"] = p.text;
                    out.append(d);
                }
                return out;
            },
            "What is wrong beyond the invariants (holes, degenerate faces, parts inside out, "
            "small parts, faces that pass through each other), one dict each: kind, element, "
            "size, text.")
        .def("field", &field, py::arg("name"), py::arg("source") = 0)
        .def(
            "write",
            [](const PyMesh& self, const std::filesystem::path& path, bool ascii, bool normals) {
                IoFlags flags;
                flags.ascii = ascii;
                flags.write_normals = normals;
                return write_mesh(self.mesh, path, flags);
            },
            py::arg("path"), py::arg("ascii") = false, py::arg("normals") = true)
        .def(
            "apply",
            [](PyMesh& self, const std::string& steps) { return apply_text(self, steps, false); },
            py::arg("steps"))
        .def(
            "apply_file",
            [](PyMesh& self, const std::filesystem::path& path) {
                const std::string text = read_file(path);
                try {
                    return apply_text(self, text, true);
                } catch (const ops::SyntaxError& e) {
                    throw ops::SyntaxError(path.string() + ": " + e.what());
                }
            },
            py::arg("path"))
        .def(
            "_step",
            [](PyMesh& self, const std::string& step) {
                ElementRef last;
                std::vector<std::string> notices = apply_text(self, step, false, &last);
                return py::make_tuple(element_of(self.mesh, last), notices);
            },
            py::arg("step"))
        .def("__repr__", [](const PyMesh& self) {
            return "<meshedit.Mesh V=" + std::to_string(self.mesh.n_vertices()) +
                   " E=" + std::to_string(self.mesh.n_edges()) +
                   " F=" + std::to_string(self.mesh.n_faces()) + ">";
        });

    m.def("read", &read_path, py::arg("path"), py::arg("density") = 8,
          ("Reads a mesh file (" + meshedit::mesh_extension_list(" ") + ").").c_str());
    m.def("verbs", &verb_table, "The edit language's verb table.");
    m.def("field_names", [] {
        std::vector<std::string> names;
        for (const FieldInfo& f : field_infos()) {
            names.emplace_back(f.name);
        }
        return names;
    });
    m.def("amount_text", &meshedit::number_text);
    // A bad MESHEDIT_THREADS stops the import, as it stops the programs.
    if (const auto problem = thread_environment_problem()) {
        throw py::value_error(*problem);
    }
    m.def(
        "set_threads",
        [](py::object n) {
            if (!py::isinstance<py::int_>(n) || py::isinstance<py::bool_>(n)) {
                throw py::type_error("set_threads: expected an int, got " +
                                     std::string(py::str(py::type::of(n).attr("__name__"))));
            }
            const long long count = n.cast<long long>();
            if (count < 0 || count > kMaxThreads) {
                throw py::value_error("set_threads: " + bad_thread_count(std::to_string(count)));
            }
            set_thread_count(static_cast<unsigned>(count));
        },
        py::arg("n"),
        "Threads for subdivision, normals and loading in this process; 0 means all cores. "
        "Overrides MESHEDIT_THREADS. The results are the same on any number.");
    m.def("threads", &thread_count, "The threads the parallel passes use now (at least 1).");
    bind_document(m);
}
