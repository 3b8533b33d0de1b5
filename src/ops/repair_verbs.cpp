// The repair verbs (repair_verbs.h): the steps of meshedit/repair/repair.h on a built mesh.
// All but fill_holes work on soups, so the mesh goes to the soup a file would hold of it
// (soup_from_mesh(), io.h), is repaired there and built back as a loaded file is; when no
// step changed anything the mesh is left as it was, bit for bit, so each verb is idempotent.

#include "repair_verbs.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "meshedit/core/loop_steps.h"
#include "meshedit/io/io.h"
#include "meshedit/repair/repair.h"

namespace meshedit::ops {
namespace {

// What every repair verb refuses: a mesh without faces, a phased Loop under way (its
// half-done state lives in properties a soup cannot carry), a non-finite position.
OpStatus check_mesh(const Mesh& mesh, const char* verb) {
    const std::string cannot = "cannot " + std::string(verb) + ": ";
    if (mesh.n_faces() == 0) {
        return OpStatus::composed(cannot + "the mesh has no faces");
    }
    if (const int next = next_loop_phase(mesh); next != 1) {
        return OpStatus::composed(cannot + "a phased Loop is under way (phase " +
                                  std::to_string(next) + " of 4 is next: `loop_step:" +
                                  std::to_string(5 - next) + "` finishes it, undo goes back)");
    }
    for (const Vertex v : mesh.vertices()) {
        if (!is_finite(mesh.position(v))) {
            return OpStatus::composed(cannot + "vertex " + std::to_string(v.idx()) +
                                      " has a non-finite position");
        }
    }
    return OpStatus::ok();
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += (text.empty() ? "" : "; ") + line;
    }
    return text;
}

// A count amount: a whole number from `least` up.
OpStatus check_count(double n, double least, const std::string& what) {
    if (!(n >= least && n <= 1e9) || n != std::floor(n)) {
        return OpStatus::composed(what + " must be a whole number from " + number_text(least) +
                                  " to 1000000000, not " + number_text(n));
    }
    return OpStatus::ok();
}

using SoupSteps = std::function<RepairReport(MeshSoup&)>;

// Runs `steps` on the soup of `mesh` and builds the result back into `mesh`, or leaves it as
// it was when they changed nothing. \throws OpError (a refusal, the mesh as it was) when no
// face would be left.
StepResult on_soup(Mesh& mesh, const Step& step, const SoupSteps& steps) {
    std::vector<std::string> unkept;
    MeshSoup soup = soup_from_mesh(mesh, &unkept);
    const std::size_t faces_before = mesh.n_faces();
    RepairReport report = steps(soup);
    StepResult result;
    if (!report.changed()) {
        result.topology = false;
        result.message = "nothing to repair" +
                         (report.lines.empty() ? std::string() : ": " + joined(report.lines));
        return result;
    }
    LoadedMesh built = build_loaded_mesh(std::move(soup), "the mesh");
    // What the builder still had to repair (a merge that pinched a vertex or doubled a face).
    std::istringstream summary(built.repairs.summary());
    for (std::string line; std::getline(summary, line);) {
        if (!line.empty()) {
            report.lines.push_back("the builder " + line);
        }
    }
    if (built.mesh.n_faces() == 0) {
        throw OpError(step.text + " refused: no face of " + std::to_string(faces_before) +
                          " would be left (" + joined(report.lines) + ")",
                      true);
    }
    mesh = std::move(built.mesh);
    result.renumbers = true;
    result.message = joined(report.lines);
    for (const std::string& notice : built.notices) {
        result.notices.push_back(notice);
    }
    if (!unkept.empty()) {
        result.notices.push_back("dropped what a soup cannot carry: " + joined(unkept));
        result.message += "; " + result.notices.back();
    }
    return result;
}

RepairReport one_step(RepairResult step) {
    RepairReport report;
    if (!step.sentence.empty()) {
        report.lines.push_back(step.sentence);
    }
    report.steps.push_back(std::move(step));
    return report;
}

// merge_by_distance:T,A: T a fraction of the bounding-box diagonal, or with A = 1 a distance.
MergeTolerance tolerance_of(const Step& step) {
    return {step.amounts[0], step.amounts[1] == 0.0};
}

}  // namespace

OpStatus check_repair(const Mesh& mesh, const Step&) {
    return check_mesh(mesh, "repair");
}
StepResult run_repair(Mesh& mesh, const Step& step, const RunOptions&) {
    return on_soup(mesh, step, [](MeshSoup& soup) { return repair(soup); });
}

OpStatus check_merge_by_distance(const Mesh& mesh, const Step& step) {
    const double t = step.amounts[0];
    if (!(std::isfinite(t) && t >= 0.0)) {
        return OpStatus::composed(
            "cannot merge: the tolerance must be a finite number of at least 0, not " +
            number_text(t));
    }
    if (step.amounts[1] != 0.0 && step.amounts[1] != 1.0) {
        return OpStatus::composed(
            "cannot merge: the second amount is 0 (a share of the bounding-box diagonal) or 1 "
            "(a distance), not " +
            number_text(step.amounts[1]));
    }
    return check_mesh(mesh, "merge");
}
StepResult run_merge_by_distance(Mesh& mesh, const Step& step, const RunOptions&) {
    const MergeTolerance tolerance = tolerance_of(step);
    return on_soup(mesh, step,
                   [&](MeshSoup& soup) { return one_step(merge_vertices(soup, tolerance)); });
}

// stitch:R, R the farthest a vertex may be off an edge, as a share of its length.
OpStatus check_stitch(const Mesh& mesh, const Step& step) {
    const double r = step.amounts[0];
    if (!(r > 0.0 && r < 0.5)) {
        return OpStatus::composed(
            "cannot stitch: the ratio must be more than 0 and less than 0.5 of an edge's "
            "length, not " +
            number_text(r));
    }
    return check_mesh(mesh, "stitch");
}
StepResult run_stitch(Mesh& mesh, const Step& step, const RunOptions&) {
    StitchOptions options;
    options.ratio = step.amounts[0];
    return on_soup(mesh, step,
                   [&](MeshSoup& soup) { return one_step(stitch_borders(soup, options)); });
}

OpStatus check_remove_degenerate(const Mesh& mesh, const Step&) {
    return check_mesh(mesh, "remove degenerate faces");
}
StepResult run_remove_degenerate(Mesh& mesh, const Step& step, const RunOptions&) {
    return on_soup(mesh, step, [](MeshSoup& soup) {
        RepairReport report = one_step(remove_degenerate_faces(soup));
        RepairReport duplicates = one_step(remove_duplicate_faces(soup));
        report.lines.insert(report.lines.end(), duplicates.lines.begin(), duplicates.lines.end());
        report.steps.push_back(std::move(duplicates.steps.front()));
        return report;
    });
}

// The builder cut the edges where neighbours disagreed into seams of coincident vertices:
// those are merged first (equal positions only), so that orienting can join them again.
OpStatus check_orient(const Mesh& mesh, const Step&) {
    return check_mesh(mesh, "orient");
}
StepResult run_orient(Mesh& mesh, const Step& step, const RunOptions&) {
    return on_soup(mesh, step, [](MeshSoup& soup) {
        RepairOptions options;
        options.tolerance = {0.0, false};
        options.remove_degenerate = false;
        options.remove_duplicates = false;
        options.stitch = false;
        return repair(soup, options);
    });
}

OpStatus check_remove_small(const Mesh& mesh, const Step& step) {
    if (const OpStatus why = check_count(step.amounts[0], 1,
                                         "cannot remove small components: "
                                         "the face count");
        !why) {
        return why;
    }
    return check_mesh(mesh, "remove small components");
}
StepResult run_remove_small(Mesh& mesh, const Step& step, const RunOptions&) {
    ComponentBounds bounds;
    bounds.min_faces = static_cast<std::size_t>(step.amounts[0]);
    return on_soup(mesh, step,
                   [&](MeshSoup& soup) { return one_step(remove_small_components(soup, bounds)); });
}

namespace {

// What a fill tells the user, "nothing to fill: …" when it filled nothing.
StepResult filled_step(const RepairResult& filled) {
    StepResult result;
    result.topology = filled.changed();
    result.message = filled.changed()
                         ? filled.sentence
                         : "nothing to fill" + (filled.sentence.empty() ? std::string(": no hole")
                                                                        : ": " + filled.sentence);
    return result;
}

}  // namespace

// On the mesh itself: filling adds faces through fill_hole(), which carries attributes.
// fill_holes_fair's 0 (its default) fills every hole; other sizes are at least 3 edges.
OpStatus check_fill_holes(const Mesh& mesh, const Step& step) {
    if (const bool every =
            step.verb->name == std::string_view("fill_holes_fair") && step.amounts[0] == 0.0;
        !every) {
        if (const OpStatus why =
                check_count(step.amounts[0], 3, "cannot fill holes: the largest hole's edge count");
            !why) {
            return why;
        }
    }
    return check_mesh(mesh, "fill holes");
}
StepResult run_fill_holes(Mesh& mesh, const Step& step, const RunOptions&) {
    const RepairResult filled = fill_holes(mesh, static_cast<std::size_t>(step.amounts[0]));
    return filled_step(filled);
}

Halfedge hole_side(const Mesh& mesh, Edge e) {
    const Halfedge h = mesh.halfedge(e, 0);
    return mesh.is_boundary(h) ? h : mesh.halfedge(e, 1);
}
OpStatus check_on_a_hole(const Mesh& mesh, Edge e) {
    return mesh.is_boundary(e)
               ? OpStatus::ok()
               : OpStatus::refused("cannot fill: the edge is not on a hole (pick a boundary edge)");
}

// fill_fair:A-B: the one hole that boundary edge A-B borders, as fill_holes_fair fills each;
// the rest of the mesh is not read (fill_hole_fair(), repair.h).
OpStatus check_fill_fair(const Mesh& mesh, const Step& step) {
    if (const OpStatus on_hole = check_on_a_hole(mesh, named_edge(mesh, step)); !on_hole) {
        return on_hole;
    }
    return check_mesh(mesh, "fill the hole");
}
StepResult run_fill_fair(Mesh& mesh, const Step& step, const RunOptions&) {
    const RepairResult filled =
        fill_hole_fair(mesh, hole_side(mesh, named_edge(mesh, step)), FairFillOptions{});
    if (filled.count == 0) {
        // Decided before the first change (repair.h): the mesh is as it was.
        throw OpError(step.text + " refused: " + filled.sentence, true);
    }
    StepResult result;
    result.topology = true;
    result.message = filled.sentence;
    return result;
}

StepResult run_fill_holes_fair(Mesh& mesh, const Step& step, const RunOptions&) {
    FairFillOptions options;
    options.max_edges = static_cast<std::size_t>(step.amounts[0]);
    const RepairResult filled = fill_holes_fair(mesh, options);
    return filled_step(filled);
}

}  // namespace meshedit::ops
