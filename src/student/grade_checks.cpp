// The checks of `meshedit grade`: the student's answer against MeshEdit's on the same input.
// Messages name the kind of failure first ("invariant twin: …", "differs from the
// reference: …", "vertex 3 is at …") so a reader, and the seeded-bug tests, can tell
// mistakes apart.

#include "grade_checks.h"

#include <algorithm>
#include <cmath>

#include <cstdio>

#include "meshedit/core/compare.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/number_text.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"

namespace meshedit::cli::grade {
namespace {

std::string text(const Vec3& p) {
    return "(" + readable_number(p.x) + ", " + readable_number(p.y) + ", " + readable_number(p.z) +
           ")";
}
std::string text2(const Vec3& p) {
    return "(" + readable_number(p.x) + ", " + readable_number(p.y) + ")";
}
Vec3 from_student(const st::Vector3D& p) {
    return {p.x, p.y, p.z};
}
std::string edge_text(const Mesh& mesh, Edge e) {
    return std::to_string(mesh.vertex(e, 1).idx()) + "-" + std::to_string(mesh.vertex(e, 0).idx());
}

// Writes the student's mesh back and validates it: "" or the broken invariant.
std::string write_back(st::HalfedgeMesh& student, Mesh& mesh) {
    if (const BridgeError e = copy_out(student, mesh); !e.invariant.empty()) {
        return "invariant " + e.invariant + ": " + e.message;
    }
    if (const auto e = validate(mesh)) {
        return "invariant " + e->invariant + ": " + e->message;
    }
    return "";
}

double tolerance_for(const Mesh& mesh) {
    return 1e-7 * std::max(1.0, mesh.bounds().diagonal());
}

}  // namespace

Difference compare_results(const Mesh& got, const Mesh& expected) {
    const TopologyMatch match = match_topology(got, expected);
    if (!match.isomorphic) {
        std::string out =
            "differs from the reference (A yours, B the reference): " + match.difference;
        if (!match.first_a.is_none()) {
            out += " (first at your " + to_string(match.first_a) + ")";
        }
        return {out, match.first_a, match.first_b};
    }
    const double tol = tolerance_for(expected);
    for (const Vertex v : got.vertices()) {
        const Vertex w(match.vertex[v.idx()]);
        if (!w.is_valid()) {
            continue;
        }
        const Vec3 &p = got.position(v), &q = expected.position(w);
        if (!(distance(p, q) <= tol)) {
            return {"vertex " + std::to_string(v.idx()) + " is at " + text(p) +
                        ", the reference puts it at " + text(q),
                    ElementRef::vertex(v), ElementRef::vertex(w)};
        }
    }
    return {};
}

std::string difference(const Mesh& got, const Mesh& expected) {
    return compare_results(got, expected).text;
}

std::string check_step(const st::StudentTasks& tasks, const std::vector<Vec3>& points, double t) {
    if (tasks.evaluate_step == nullptr) {
        return "not handed in";
    }
    std::vector<st::Vector2D> in;
    for (const Vec3& p : points) {
        in.emplace_back(p.x, p.y);
    }
    const std::vector<st::Vector2D> out = tasks.evaluate_step(in, t);
    if (out.size() + 1 != in.size()) {
        return "returned " + std::to_string(out.size()) + " points for " +
               std::to_string(in.size()) + ", expected " + std::to_string(in.size() - 1);
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
        const Vec3 want = points[i] * (1.0 - t) + points[i + 1] * t;
        const Vec3 got(out[i].x, out[i].y, 0.0);
        const double scale = std::max({1.0, norm(points[i]), norm(points[i + 1])});
        if (!(distance(Vec3(want.x, want.y, 0.0), got) <= 1e-9 * scale)) {
            return "point " + std::to_string(i) + " is " + text2(got) + ", expected " +
                   text2(want) + " = (1-t)·P" + std::to_string(i) + " + t·P" +
                   std::to_string(i + 1);
        }
    }
    return "";
}

std::string check_patch(const st::StudentTasks& tasks, const BezierPatch& patch, double u,
                        double v) {
    if (tasks.evaluate_patch == nullptr) {
        return "not handed in";
    }
    std::vector<std::vector<st::Vector3D>> cp(std::size_t(patch.rows));
    for (int r = 0; r < patch.rows; ++r) {
        for (int c = 0; c < patch.cols; ++c) {
            const Vec3& p = patch.cp(r, c);
            cp[std::size_t(r)].emplace_back(p.x, p.y, p.z);
        }
    }
    const Vec3 got = from_student(tasks.evaluate_patch(cp, u, v));
    const Vec3 want = patch.evaluate(u, v);
    double scale = 1.0;
    for (const Vec3& p : patch.control_points) {
        scale = std::max(scale, norm(p));
    }
    if (!(distance(got, want) <= 1e-9 * scale)) {
        return "S(" + readable_number(u) + ", " + readable_number(v) + ") is " + text(got) +
               ", expected " + text(want);
    }
    return "";
}

std::string check_normals(const st::StudentTasks& tasks, const Mesh& mesh) {
    if (tasks.vertex_normal == nullptr) {
        return "not handed in";
    }
    st::HalfedgeMesh student;
    copy_in(mesh, student);
    const std::vector<Vec3> want = vertex_normals(mesh);
    for (const Vertex v : mesh.vertices()) {
        if (mesh.is_isolated(v)) {
            continue;
        }
        const Vec3 n = from_student(tasks.vertex_normal(st::VertexIter(&student, int(v.idx()))));
        const Vec3& w = want[v.idx()];
        if (distance(n, w) <= 1e-7) {
            continue;
        }
        const std::string at = "vertex " + std::to_string(v.idx()) + ": normal " + text(n);
        if (distance(n, w * -1.0) <= 1e-7) {
            return at + " is reversed: expected " + text(w) + " (faces are counter-clockwise)";
        }
        if (norm(n) > 0.0 && distance(normalize(n), w) <= 1e-7) {
            return at + " is not unit length (" + readable_number(norm(n)) + "): expected " +
                   text(w);
        }
        return at + ", expected " + text(w) + " (area-weighted, unit length)";
    }
    return "";
}

std::string check_flip(const st::StudentTasks& tasks, const Mesh& mesh, Edge e) {
    if (tasks.flip_edge == nullptr) {
        return "not handed in";
    }
    Mesh expected = mesh;
    const OpResult<Edge> flipped = flip(expected, e);
    st::HalfedgeMesh student;
    copy_in(mesh, student);
    Mesh got = mesh;
    const st::EdgeIter out = tasks.flip_edge(student, st::EdgeIter(&student, int(e.idx())));
    if (std::string why = write_back(student, got); !why.empty()) {
        return why;
    }
    if (!flipped) {
        const std::string d = difference(got, expected);
        return d.empty() ? ""
                         : "should refuse (" + std::string(flipped.reason()) +
                               ") and leave the mesh as it was, but: " + d;
    }
    if (std::string d = difference(got, expected); !d.empty()) {
        return d;
    }
    // Flip renumbers nothing, so the returned edge must join the same two vertices.
    const Edge want = flipped.value();
    if (!out.isSet() || !got.is_valid(Edge(std::uint32_t(out.index()))) ||
        got.is_deleted(Edge(std::uint32_t(out.index())))) {
        return "returned no live edge; expected the flipped edge " + edge_text(expected, want);
    }
    const Edge back(std::uint32_t(out.index()));
    const auto ends = [](const Mesh& m, Edge x) {
        return std::minmax(m.vertex(x, 0).idx(), m.vertex(x, 1).idx());
    };
    if (ends(got, back) != ends(expected, want)) {
        return "returned edge " + std::to_string(back.idx()) + " (" + edge_text(got, back) +
               "); expected the flipped edge " + edge_text(expected, want);
    }
    return "";
}

std::string check_split(const st::StudentTasks& tasks, const Mesh& mesh, Edge e) {
    if (tasks.split_edge == nullptr) {
        return "not handed in";
    }
    Mesh expected = mesh;
    const OpResult<Vertex> made = split(expected, e);
    st::HalfedgeMesh student;
    copy_in(mesh, student);
    Mesh got = mesh;
    const st::VertexIter out = tasks.split_edge(student, st::EdgeIter(&student, int(e.idx())));
    if (std::string why = write_back(student, got); !why.empty()) {
        return why;
    }
    if (!made) {
        const std::string d = difference(got, expected);
        return d.empty() ? "" : "should refuse (" + std::string(made.reason()) + "), but: " + d;
    }
    const TopologyMatch match = match_topology(got, expected);
    if (std::string d = difference(got, expected); !d.empty()) {
        return d;
    }
    const Vertex back(std::uint32_t(out.isSet() ? out.index() : -1));
    if (!out.isSet() || !got.is_valid(back) || got.is_deleted(back)) {
        return "returned no live vertex; expected the new vertex";
    }
    if (match.vertex[back.idx()] != made.value().idx()) {
        return "returned vertex " + std::to_string(back.idx()) + " at " + text(got.position(back)) +
               ", not the new vertex";
    }
    return "";
}

std::string check_loop(const st::StudentTasks& tasks, const Mesh& mesh) {
    if (tasks.upsample == nullptr) {
        return "not handed in";
    }
    Mesh expected = mesh;
    loop_subdivide(expected);
    st::HalfedgeMesh student;
    Mesh got = mesh;
    copy_in(got, student);
    st::HalfedgeMesh::Operations ops;
    bind_operations(student, got, ops);
    tasks.upsample(student);
    if (std::string why = write_back(student, got); !why.empty()) {
        return why;
    }
    return difference(got, expected);
}

std::string check_session(const st::StudentTasks& tasks, const Mesh& mesh,
                          const std::vector<SessionStep>& steps) {
    Mesh current = mesh;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const SessionStep& s = steps[i];
        const Edge e = current.find_edge(Vertex(s.a), Vertex(s.b));
        const std::string name = std::string(s.split ? "split:" : "flip:") + std::to_string(s.a) +
                                 "-" + std::to_string(s.b);
        if (!e.is_valid()) {
            return "step " + std::to_string(i + 1) + " " + name + ": no such edge";
        }
        const std::string why =
            s.split ? check_split(tasks, current, e) : check_flip(tasks, current, e);
        if (!why.empty()) {
            return "step " + std::to_string(i + 1) + " " + name + ": " + why;
        }
        // Go on from the reference's mesh, so one mistake is reported once.
        if (s.split) {
            (void)split(current, e);
        } else {
            (void)flip(current, e);
        }
    }
    return "";
}

}  // namespace meshedit::cli::grade
