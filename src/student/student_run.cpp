// A mesh task of student code in a forked child, its verdict and result sent back through
// run_isolated()'s pipe as text: a marker line, the message and the invariant, the first
// differing element's corners, then the result's polygons.

#include "student_run.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "grade_bridge.h"
#include "grade_checks.h"
#include "grade_sandbox.h"
#include "meshedit/core/validate.h"

namespace meshedit::cli::grade {
namespace {

constexpr std::string_view kMarker = "MESHEDIT-ATTEMPT 1\n";
// No loop of a face in a result the viewer can draw is longer; a walk past it has left its
// loop (a student's next that never comes back).
constexpr std::size_t kMaxCorners = 4096;

ElementRef::Kind kind_of(ElementKind k) {
    switch (k) {
        case ElementKind::Vertex:
            return ElementRef::Kind::Vertex;
        case ElementKind::Halfedge:
            return ElementRef::Kind::Halfedge;
        case ElementKind::Edge:
            return ElementRef::Kind::Edge;
        case ElementKind::Face:
            return ElementRef::Kind::Face;
    }
    return ElementRef::Kind::None;
}

// The student's own mesh, read as its handles say (when the write-back refused it).
template <class T>
bool usable(st::HalfedgeMesh& m, const st::ElementIter<T>& it) {
    return it.isSet() && std::size_t(it.index()) < m.list<T>().size();
}

std::uint32_t idx(int i) {
    return static_cast<std::uint32_t>(i);
}

// The "from" vertices of the loop that starts at halfedge `start`, or nothing when the loop
// does not close within kMaxCorners or reaches a handle that is not set.
std::vector<std::uint32_t> student_loop(st::HalfedgeMesh& m, st::HalfedgeIter start) {
    std::vector<std::uint32_t> out;
    st::HalfedgeIter h = start;
    while (usable(m, h) && usable(m, h->vertex()) && out.size() < kMaxCorners) {
        out.push_back(idx(h->vertex().index()));
        h = h->next();
        if (h == start) {
            return out;
        }
    }
    return {};
}

std::vector<std::uint32_t> student_corners(st::HalfedgeMesh& m, const ElementRef& e) {
    st::HalfedgeIter h;
    switch (e.kind) {
        case ElementRef::Kind::Vertex:
            return {e.index};
        case ElementRef::Kind::Face:
            if (e.index < m.faces.size()) {
                return student_loop(m, m.faces[e.index].halfedge());
            }
            return {};
        case ElementRef::Kind::Edge:
            if (e.index < m.edges.size()) {
                h = m.edges[e.index].halfedge();
            }
            break;
        case ElementRef::Kind::Halfedge:
            h = st::HalfedgeIter(&m, int(e.index));
            break;
        case ElementRef::Kind::None:
            return {};
    }
    std::vector<std::uint32_t> out;
    if (usable(m, h) && usable(m, h->vertex())) {
        out.push_back(idx(h->vertex().index()));
        // The other end: the twin's start, else the next's.
        for (const st::HalfedgeIter g : {h->twin(), h->next()}) {
            if (usable(m, g) && usable(m, g->vertex())) {
                out.push_back(idx(g->vertex().index()));
                break;
            }
        }
    }
    return out;
}

void add_positions(std::vector<Vec3>& out, st::HalfedgeMesh& m) {
    for (const st::Vertex& v : m.vertices) {
        out.emplace_back(v.position.x, v.position.y, v.position.z);
    }
}

PolygonSoup student_soup(st::HalfedgeMesh& m) {
    PolygonSoup soup;
    add_positions(soup.positions, m);
    for (st::Face& f : m.faces) {
        if (!f.deleted && !f.isBoundary()) {
            if (const auto loop = student_loop(m, f.halfedge()); !loop.empty()) {
                soup.add_face_range(loop);
            }
        }
    }
    return soup;
}

// A loop of a written-back mesh, bounded: validate() may have found it broken.
std::vector<std::uint32_t> mesh_loop(const Mesh& mesh, Halfedge start) {
    std::vector<std::uint32_t> out;
    Halfedge h = start;
    while (mesh.is_valid(h) && out.size() < kMaxCorners) {
        const Vertex v = mesh.from_vertex(h);
        if (!mesh.is_valid(v)) {
            return {};
        }
        out.push_back(v.idx());
        h = mesh.next(h);
        if (h == start) {
            return out;
        }
    }
    return {};
}

PolygonSoup mesh_soup(const Mesh& mesh) {
    PolygonSoup soup;
    for (std::size_t i = 0; i < mesh.vertices_size(); ++i) {
        soup.positions.push_back(mesh.position(Vertex(std::uint32_t(i))));
    }
    for (std::size_t i = 0; i < mesh.faces_size(); ++i) {
        const Face f{std::uint32_t(i)};
        if (!mesh.is_deleted(f)) {
            if (const auto loop = mesh_loop(mesh, mesh.halfedge(f)); !loop.empty()) {
                soup.add_face_range(loop);
            }
        }
    }
    return soup;
}

void write_list(std::ostringstream& out, const std::vector<std::uint32_t>& list) {
    out << list.size();
    for (const std::uint32_t i : list) {
        out << ' ' << i;
    }
    out << '\n';
}

std::string encode(const MeshAttempt& a) {
    std::ostringstream out;
    out << kMarker << a.message.size() << ' ' << a.invariant.size() << ' ' << int(a.kind) << '\n'
        << a.message << a.invariant << '\n';
    write_list(out, a.yours_at);
    write_list(out, a.reference_at);
    out << a.yours.positions.size() << '\n';
    char number[96];
    for (const Vec3& p : a.yours.positions) {
        std::snprintf(number, sizeof number, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
        out << number;
    }
    out << a.yours.n_faces() << '\n';
    for (std::size_t f = 0; f < a.yours.n_faces(); ++f) {
        const std::vector<std::uint32_t> corners(
            a.yours.indices.begin() + a.yours.face_offsets[f],
            a.yours.indices.begin() + a.yours.face_offsets[f + 1]);
        write_list(out, corners);
    }
    return out.str();
}

std::vector<std::uint32_t> read_list(std::istringstream& in) {
    std::size_t n = 0;
    in >> n;
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < n && in; ++i) {
        std::uint32_t v = 0;
        in >> v;
        out.push_back(v);
    }
    return out;
}

// A coordinate as the child printed it; "nan" and "inf" too (a student's result may hold
// them: validate() names them, the picture shows them at 0).
double read_number(std::istringstream& in) {
    std::string word;
    in >> word;
    const double x = std::strtod(word.c_str(), nullptr);
    return std::isfinite(x) ? x : 0.0;
}

MeshAttempt decode(const std::string& text) {
    std::istringstream in(text.substr(kMarker.size()));
    MeshAttempt a;
    a.verdict = MeshAttempt::Verdict::Different;
    std::size_t message = 0, invariant = 0;
    int kind = 0;
    in >> message >> invariant >> kind;
    in.get();
    a.message.resize(message);
    a.invariant.resize(invariant);
    in.read(a.message.data(), std::streamsize(message));
    in.read(a.invariant.data(), std::streamsize(invariant));
    a.kind = static_cast<ElementRef::Kind>(kind);
    a.yours_at = read_list(in);
    a.reference_at = read_list(in);
    std::size_t n = 0;
    in >> n;
    for (std::size_t i = 0; i < n && in; ++i) {
        const double x = read_number(in), y = read_number(in), z = read_number(in);
        a.yours.positions.emplace_back(x, y, z);
    }
    in >> n;
    for (std::size_t f = 0; f < n && in; ++f) {
        a.yours.add_face_range(read_list(in));
    }
    if (!in) {
        throw std::runtime_error("the child's answer was cut short");
    }
    check_polygon_soup(a.yours);
    return a;
}

// In the child: the student's function, the write-back, validate(), the comparison. "" when
// the result is the reference's.
std::string run_task(const st::StudentTasks& tasks, MeshTask task, const Mesh& input, Edge edge,
                     const Mesh& reference) {
    st::HalfedgeMesh student;
    Mesh got = input;
    copy_in(got, student);
    st::HalfedgeMesh::Operations ops;
    switch (task) {
        case MeshTask::FlipEdge:
            tasks.flip_edge(student, st::EdgeIter(&student, int(edge.idx())));
            break;
        case MeshTask::SplitEdge:
            tasks.split_edge(student, st::EdgeIter(&student, int(edge.idx())));
            break;
        case MeshTask::Upsample:
            bind_operations(student, got, ops);
            tasks.upsample(student);
            break;
    }
    MeshAttempt a;
    if (const BridgeError e = copy_out(student, got); !e.invariant.empty()) {
        a.message = "invariant " + e.invariant + ": " + e.message;
        a.invariant = e.invariant;
        a.yours = student_soup(student);
        a.kind = e.element.kind;
        a.yours_at = student_corners(student, e.element);
    } else if (const auto v = validate(got)) {
        a.message = "invariant " + v->invariant + ": " + v->message;
        a.invariant = v->invariant;
        a.yours = mesh_soup(got);
        a.kind = kind_of(v->kind);
        a.yours_at = corners_of(got, ElementRef{a.kind, v->index});
    } else {
        const Difference d = compare_results(got, reference);
        if (d.text.empty()) {
            return "";
        }
        a.message = d.text;
        a.yours = mesh_soup(got);
        a.kind = d.got.kind;
        a.yours_at = corners_of(got, d.got);
        a.reference_at = corners_of(reference, d.expected);
    }
    return encode(a);
}

constexpr std::string_view kNormalsMarker = "MESHEDIT-NORMALS 1\n";

// In the child: the grader's check, then every normal for the picture.
std::string normals_in_child(const st::StudentTasks& tasks, const Mesh& mesh) {
    const std::string why = check_normals(tasks, mesh);
    if (why.empty() || tasks.vertex_normal == nullptr) {
        return why;  // the same, or not handed in: nothing to draw
    }
    st::HalfedgeMesh student;
    copy_in(mesh, student);
    std::ostringstream out;
    out << kNormalsMarker << why.size() << '\n' << why << '\n' << mesh.vertices_size() << '\n';
    char number[96];
    for (const Vertex v : mesh.vertices()) {
        st::Vector3D n;
        if (!mesh.is_isolated(v)) {
            n = tasks.vertex_normal(st::VertexIter(&student, int(v.idx())));
        }
        std::snprintf(number, sizeof number, "%.17g %.17g %.17g\n", n.x, n.y, n.z);
        out << number;
    }
    return out.str();
}

NormalsAttempt decode_normals(const std::string& text) {
    std::istringstream in(text.substr(kNormalsMarker.size()));
    NormalsAttempt a;
    a.verdict = MeshAttempt::Verdict::Different;
    std::size_t message = 0, n = 0;
    in >> message;
    in.get();
    a.message.resize(message);
    in.read(a.message.data(), std::streamsize(message));
    in >> n;
    for (std::size_t i = 0; i < n && in; ++i) {
        const double x = read_number(in), y = read_number(in), z = read_number(in);
        a.normals.emplace_back(x, y, z);
    }
    if (!in) {
        throw std::runtime_error("the child's answer was cut short");
    }
    return a;
}

bool handed_in(const st::StudentTasks& tasks, MeshTask task) {
    switch (task) {
        case MeshTask::FlipEdge:
            return tasks.flip_edge != nullptr;
        case MeshTask::SplitEdge:
            return tasks.split_edge != nullptr;
        case MeshTask::Upsample:
            return tasks.upsample != nullptr;
    }
    return false;
}

}  // namespace

std::optional<MeshTask> mesh_task(std::string_view name) {
    if (name == "flip_edge") {
        return MeshTask::FlipEdge;
    }
    if (name == "split_edge") {
        return MeshTask::SplitEdge;
    }
    if (name == "upsample") {
        return MeshTask::Upsample;
    }
    return std::nullopt;
}

MeshAttempt attempt_mesh_task(const st::StudentTasks& tasks, MeshTask task, const Mesh& input,
                              Edge edge, const Mesh& reference, double seconds) {
    MeshAttempt a;
    if (!handed_in(tasks, task)) {
        a.message = "is not handed in (the library has no such function)";
        return a;
    }
    const Outcome o =
        run_isolated([&] { return run_task(tasks, task, input, edge, reference); }, seconds);
    if (o.pass) {
        a.verdict = MeshAttempt::Verdict::Same;
        return a;
    }
    if (o.message.rfind(kMarker, 0) != 0) {
        a.message = o.message;  // crashed, timed out, threw
        return a;
    }
    try {
        return decode(o.message);
    } catch (const std::exception& e) {
        a.message = std::string("its result could not be read back: ") + e.what();
        return a;
    }
}

NormalsAttempt attempt_normals(const st::StudentTasks& tasks, const Mesh& mesh, double seconds) {
    NormalsAttempt a;
    const Outcome o = run_isolated([&] { return normals_in_child(tasks, mesh); }, seconds);
    if (o.pass) {
        a.verdict = MeshAttempt::Verdict::Same;
        return a;
    }
    if (o.message.rfind(kNormalsMarker, 0) != 0) {
        a.message = o.message;  // crashed, timed out, threw, not handed in
        return a;
    }
    try {
        return decode_normals(o.message);
    } catch (const std::exception& e) {
        a.message = std::string("its result could not be read back: ") + e.what();
        return a;
    }
}

std::vector<std::uint32_t> corners_of(const Mesh& mesh, const ElementRef& element) {
    const std::uint32_t i = element.index;
    switch (element.kind) {
        case ElementRef::Kind::Vertex:
            return {i};
        case ElementRef::Kind::Face:
            return Face(i).idx() < mesh.faces_size() ? mesh_loop(mesh, mesh.halfedge(Face(i)))
                                                     : std::vector<std::uint32_t>{};
        case ElementRef::Kind::Edge:
        case ElementRef::Kind::Halfedge: {
            const Halfedge h(element.kind == ElementRef::Kind::Edge ? 2 * i : i);
            if (!mesh.is_valid(h) || !mesh.is_valid(mesh.from_vertex(h)) ||
                !mesh.is_valid(mesh.to_vertex(h))) {
                return {};
            }
            return {mesh.from_vertex(h).idx(), mesh.to_vertex(h).idx()};
        }
        case ElementRef::Kind::None:
            break;
    }
    return {};
}

ElementRef element_at(const Mesh& mesh, ElementRef::Kind kind,
                      const std::vector<std::uint32_t>& corners, std::uint32_t offset) {
    if (corners.empty()) {
        return {};
    }
    const Vertex a(corners[0] + offset);
    if (!mesh.is_valid(a) || mesh.is_deleted(a)) {
        return {};
    }
    if (kind == ElementRef::Kind::Vertex || corners.size() < 2) {
        return ElementRef::vertex(a);
    }
    const Vertex b(corners[1] + offset);
    if (!mesh.is_valid(b) || mesh.is_deleted(b)) {
        return ElementRef::vertex(a);
    }
    const Halfedge h = mesh.find_halfedge(a, b);
    if (!h.is_valid()) {
        return ElementRef::vertex(a);
    }
    switch (kind) {
        case ElementRef::Kind::Edge:
            return ElementRef::edge(Mesh::edge(h));
        case ElementRef::Kind::Face:
            return mesh.is_boundary(h) ? ElementRef::edge(Mesh::edge(h))
                                       : ElementRef::face(mesh.face(h));
        default:
            return ElementRef::halfedge(h);
    }
}

}  // namespace meshedit::cli::grade
