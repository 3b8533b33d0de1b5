// `--student LIB`: the keys whose verb names a course function (the verb table's
// course_task) run the student's function in a forked child (meshedit_student's
// attempt_mesh_task()); a result that is not the reference's becomes a side by side the
// student steps back from. Q checks vertex_normal, E (curves) evaluate_step, + and -
// (surfaces) evaluate_patch.

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "grade_checks.h"
#include "grade_sandbox.h"
#include "meshedit/bezier/bezier_curve.h"
#include "meshedit/core/assert.h"
#include "meshedit/core/build.h"
#include "meshedit/core/normals.h"
#include "meshedit/ops/ops.h"
#include "meshedit/viewer/editor.h"
#include "student_library.h"
#include "student_run.h"

namespace meshedit::viewer {

namespace grade = cli::grade;

struct Editor::StudentMode {
    std::filesystem::path library;
    const grade::st::StudentTasks* tasks = nullptr;
    std::optional<StudentComparison> shown;
    // How long a call may take: on one edge (instant when right) and on the whole mesh (Loop
    // on a big mesh is not; the viewer waits, so not much longer).
    double local_seconds = 2.0, whole_mesh_seconds = 10.0;
};

namespace {

// The x range of `soup`'s positions.
std::pair<double, double> x_range(const std::vector<Vec3>& positions) {
    double lo = INFINITY, hi = -INFINITY;
    for (const Vec3& p : positions) {
        lo = std::min(lo, p.x);
        hi = std::max(hi, p.x);
    }
    return {lo, hi};
}

}  // namespace

Outcome Editor::load_student(const std::filesystem::path& library,
                             std::pair<double, double> seconds) {
    // Its initialisers are student code too: loaded in a child first.
    const grade::Outcome probe = grade::run_isolated(
        [&] { return grade::load_student_library(library), std::string(); }, seconds.second);
    if (!probe.pass) {
        return refused("student code " + library.string() + " not loaded: loading it " +
                       probe.message + "; F, S and L run MeshEdit's own operations");
    }
    auto mode = std::make_shared<StudentMode>();
    mode->library = library;
    mode->tasks = &grade::load_student_library(library);
    mode->local_seconds = seconds.first;
    mode->whole_mesh_seconds = seconds.second;
    student_ = std::move(mode);
    return {kDisplay, "student code " + library.filename().string() +
                          ": F, S, L, Q and E (curves) call your functions and compare with "
                          "the reference"};
}

bool Editor::student_mode() const {
    return student_ != nullptr;
}

const StudentComparison* Editor::student_comparison() const {
    if (!student_ || !student_->shown || student_->shown->at_revision != doc_.revision) {
        return nullptr;
    }
    return &*student_->shown;
}

Outcome Editor::run_student(const ops::Verb& verb) {
    const std::optional<grade::MeshTask> task = grade::mesh_task(verb.course_task);
    MESHEDIT_ASSERT(task.has_value());
    const std::string name(verb.course_task);
    if (student_comparison() != nullptr) {
        return refused("this is the side by side of your " + name +
                       " and the reference's: Esc or Ctrl+Z steps back to your input first");
    }
    if (doc_.mesh.has_garbage()) {
        return refused("the mesh has deleted elements: save and open it again first");
    }
    ElementRef on;
    Edge edge;
    if (*task != grade::MeshTask::Upsample) {
        const ElementRef& s = doc_.selection;
        if (s.kind == ElementRef::Kind::Halfedge && is_live(doc_.mesh, s)) {
            edge = Mesh::edge(Halfedge(s.index));  // a halfedge stands for its edge
        } else if (s.kind == ElementRef::Kind::Edge && is_live(doc_.mesh, s)) {
            edge = Edge(s.index);
        } else {
            return refused("select an edge first: your " + name + " runs on it");
        }
        on = ElementRef::edge(edge);
    }
    const ops::Step step = ops::make_step(verb.name, doc_.mesh, on, {});
    const OpStatus status = verb.check(doc_.mesh, step);
    if (!status && *task == grade::MeshTask::Upsample) {
        return refused(status.text());  // nothing the student's upsample() is asked to do
    }
    Mesh reference = doc_.mesh;  // where the reference refuses, the input is its answer
    try {
        if (status) {
            verb.run(reference, step, {});
        }
    } catch (const std::exception& e) {  // out of memory, over the budget
        return refused(e.what());
    }
    const std::string what = name + " on " + (on.is_none() ? "the mesh" : describe(mesh(), on));
    const grade::MeshAttempt a = grade::attempt_mesh_task(
        *student_->tasks, *task, doc_.mesh, edge, reference,
        on.is_none() ? student_->whole_mesh_seconds : student_->local_seconds);
    switch (a.verdict) {
        case grade::MeshAttempt::Verdict::Failed:
            return refused(what + ": your code " + a.message + " — nothing changed");
        case grade::MeshAttempt::Verdict::Same:
            if (!status) {
                return refused(status.text() + " — your " + name +
                               " leaves the mesh as it was too");
            }
            break;
        case grade::MeshAttempt::Verdict::Different:
            return show_comparison(a, reference, name, what);
    }
    // The student's result is the reference's: the reference's goes in, numbered as the
    // session and the rewiring diagram expect.
    Outcome out = on.is_none()
                      ? run_verb(verb)
                      : edit_steps({step}, verb.name, (verb.traits & ops::kChangesTopology) != 0);
    if (!out.refused) {
        out.message = "your " + name + " matches the reference: " + out.message;
    }
    return out;
}

namespace {

// The student's result and the reference's in one soup, the reference's to the right, a
// quarter of their width apart; its vertices start at `offset`.
PolygonSoup side_by_side(PolygonSoup soup, const Mesh& reference, std::uint32_t& offset) {
    const PolygonSoup theirs = to_polygon_soup(reference);
    offset = static_cast<std::uint32_t>(soup.positions.size());
    const auto [lo, hi] = x_range(soup.positions);
    const auto [rlo, rhi] = x_range(theirs.positions);
    const double width = std::max(hi - lo, rhi - rlo);
    const double shift = (soup.positions.empty() ? rhi : hi) - rlo + 0.25 * width +
                         0.05 * std::max(reference.bounds().diagonal(), 1e-9);
    for (const Vec3& p : theirs.positions) {
        soup.positions.push_back(p + Vec3(shift, 0.0, 0.0));
    }
    for (std::size_t f = 0; f < theirs.n_faces(); ++f) {
        std::vector<std::uint32_t> corners;
        for (std::uint32_t k = theirs.face_offsets[f]; k < theirs.face_offsets[f + 1]; ++k) {
            corners.push_back(theirs.indices[k] + offset);
        }
        soup.add_face_range(corners);
    }
    return soup;
}

}  // namespace

Outcome Editor::show_comparison(const grade::MeshAttempt& a, const Mesh& reference,
                                const std::string& task, const std::string& what) {
    std::uint32_t offset = 0;
    const PolygonSoup soup = side_by_side(a.yours, reference, offset);
    Mesh shown;
    try {
        shown = build_mesh(soup);
    } catch (const std::exception& e) {
        return refused(what + ": " + a.message + " (your result cannot be drawn: " + e.what() +
                       ") — nothing changed");
    }
    StudentComparison c;
    c.task = task;
    c.input = what.substr(task.size() + 4);
    c.difference = a.message;
    c.invariant = a.invariant;
    c.reference_from = offset;
    c.yours = grade::element_at(shown, a.kind, a.yours_at);
    // A broken rule has no counterpart in the reference: the same corners there (old
    // vertices keep their numbers in both) show where it went wrong.
    const bool same_corners =
        a.reference_at.empty() &&
        std::all_of(a.yours_at.begin(), a.yours_at.end(),
                    [&](std::uint32_t v) { return v < reference.vertices_size(); });
    c.reference =
        grade::element_at(shown, a.kind, same_corners ? a.yours_at : a.reference_at, offset);
    std::string message = what + ": yours (left) is not the reference's (right): " + a.message;
    message += c.yours.is_none() ? "" : "; framed: the first difference";
    return put_comparison(std::move(shown), std::move(c), message, kNothing);
}

Outcome Editor::put_comparison(Mesh shown, StudentComparison c, const std::string& message,
                               unsigned changes) {
    Outcome out = edit([] { return OpStatus::ok(); },
                       [&](Document& doc) {
                           doc.mesh = std::move(shown);
                           doc.selection = c.yours;
                           doc.also_selected.clear();
                           if (!c.reference.is_none() && c.reference != c.yours) {
                               doc.also_selected.push_back(c.reference);
                           }
                           Edited edited;
                           edited.changes =
                               changes | kTopology | kSelection | kResetCamera | kSceneBounds;
                           edited.message = message + " — Esc steps back to your input";
                           return edited;
                       });
    if (!out.refused) {
        c.at_revision = doc_.revision;
        student_->shown = std::move(c);
    }
    return out;
}

Outcome Editor::check_student_normals() {
    const grade::NormalsAttempt a =
        grade::attempt_normals(*student_->tasks, doc_.mesh, student_->whole_mesh_seconds);
    switch (a.verdict) {
        case grade::MeshAttempt::Verdict::Same:
            return {kDisplay,
                    "smooth shading; your vertex_normal matches the reference at every vertex"};
        case grade::MeshAttempt::Verdict::Failed:
            return {kDisplay,
                    "smooth shading; vertex_normal on every vertex: your code " + a.message, true};
        case grade::MeshAttempt::Verdict::Different:
            break;
    }
    // The mesh twice, each vertex with its normal: the student's left, the reference's right.
    const std::vector<Vec3> want = vertex_normals(doc_.mesh);
    std::uint32_t offset = 0;
    Mesh shown = build_mesh(side_by_side(to_polygon_soup(doc_.mesh), doc_.mesh, offset));
    StudentComparison c;
    c.task = "vertex_normal";
    c.input = "every vertex";
    c.difference = a.message;
    c.reference_from = offset;
    for (const Vertex v : doc_.mesh.vertices()) {
        if (!doc_.mesh.is_isolated(v) && v.idx() < a.normals.size() &&
            !(distance(a.normals[v.idx()], want[v.idx()]) <= 1e-7)) {
            c.yours = ElementRef::vertex(v);
            c.reference = ElementRef::vertex(Vertex(v.idx() + offset));
            break;
        }
    }
    c.yours_normals = a.normals;
    c.reference_normals = want;
    return put_comparison(std::move(shown), std::move(c),
                          "smooth shading; vertex_normal: yours (left) is not the reference's "
                          "(right): " +
                              a.message,
                          kDisplay);
}

std::string Editor::check_student_patches() {
    const int n = std::max(doc_.density, 1);
    const grade::Outcome o = grade::run_isolated(
        [&] {
            for (std::size_t p = 0; p < doc_.patches.size(); ++p) {
                for (int i = 0; i <= n; ++i) {
                    for (int j = 0; j <= n; ++j) {
                        const std::string why = grade::check_patch(
                            *student_->tasks, doc_.patches[p], double(i) / n, double(j) / n);
                        if (!why.empty()) {
                            return "patch " + std::to_string(p) + ": " + why;
                        }
                    }
                }
            }
            return std::string();
        },
        student_->whole_mesh_seconds);
    return o.pass ? "; your evaluate_patch matches the reference at every point of the grid"
                  : "; your evaluate_patch: " + o.message;
}

std::optional<Outcome> Editor::check_student_step(int level) {
    const std::vector<std::vector<Vec3>> levels =
        de_casteljau_levels(doc_.curve.control_points, view_.t, level);
    if (level < 0 || std::size_t(level) >= levels.size()) {
        return std::nullopt;
    }
    const std::vector<Vec3>& points = levels[std::size_t(level)];
    const grade::Outcome o =
        grade::run_isolated([&] { return grade::check_step(*student_->tasks, points, view_.t); },
                            student_->local_seconds);
    if (o.pass) {
        return std::nullopt;
    }
    return refused("evaluate_step from level " + std::to_string(level) +
                   " at t = " + std::to_string(view_.t).substr(0, 4) + ": " + o.message +
                   " — the next level is not shown");
}

}  // namespace meshedit::viewer
