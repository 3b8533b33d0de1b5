// The verbs that reduce or rebuild a whole mesh (reduce_verbs.h): crease_by_angle, simplify
// and remesh, translating between a step and meshedit/core/simplify.h and remesh.h.

#include "reduce_verbs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "meshedit/core/normals.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/simplify.h"
#include "phase_verbs.h"

namespace meshedit::ops {

// crease_by_angle:D marks every interior edge sharper than D degrees as a crease; the
// creases there stay (Blender's Mark Sharp from Select Sharp Edges).
OpStatus check_crease_by_angle_step(const Mesh&, const Step& step) {
    return check_crease_by_angle(step.amounts[0]);
}
StepResult run_crease_by_angle(Mesh& mesh, const Step& step, const RunOptions&) {
    const std::size_t marked = crease_by_angle(mesh, step.amounts[0]);
    StepResult result;
    result.topology = false;
    result.message = "marked " + std::to_string(marked) + (marked == 1 ? " edge" : " edges") +
                     " sharper than " + number_text(step.amounts[0]) + "° as creases";
    return result;
}

namespace {

// What the feature angle of simplify and remesh (their third amount) marked first.
std::string creases_marked(std::size_t marked, double degrees) {
    if (degrees == kNoFeatureAngle) {
        return {};
    }
    return "marked " + std::to_string(marked) + " edges sharper than " + number_text(degrees) +
           "° as creases; ";
}

// simplify:R,E keeps about R of the faces (0 < R < 1) or R faces (a whole number), stopping
// before a collapse whose error exceeds E (left out: no bound). The one place the CLI's
// --ratio and --faces, the viewer's D and `--ops` turn a share into a face count.
bool is_face_count(double r) {
    return r >= 1.0 || r == 0.0;
}
SimplifyOptions simplify_options(const Mesh& mesh, const Step& step) {
    SimplifyOptions options;
    const double r = step.amounts[0];
    const double kept = is_face_count(r) ? r : std::round(static_cast<double>(mesh.n_faces()) * r);
    options.target_faces = is_face_count(r) ? static_cast<std::size_t>(std::min(kept, 1e18))
                                            : static_cast<std::size_t>(std::max(1.0, kept));
    options.max_error = step.amounts[1];
    options.feature_angle_deg = step.amounts[2];
    options.attributes = step.attributes.value_or(options.attributes);
    return options;
}
}  // namespace

OpStatus check_simplify_step(const Mesh& mesh, const Step& step) {
    if (const OpStatus why = phased_loop_refusal(mesh, "simplify"); !why) {
        return why;
    }
    const double r = step.amounts[0];
    if (!(r > 0.0 && r < 1.0) && !(is_face_count(r) && r == std::floor(r) && r <= 1e18)) {
        return OpStatus::composed(
            "cannot simplify: keep a share of the faces above 0 and below 1, or a whole "
            "number of faces, not " +
            number_text(r));
    }
    return check_simplify(mesh, simplify_options(mesh, step));
}
StepResult run_simplify(Mesh& mesh, const Step& step, const RunOptions& options) {
    SimplifyOptions simplify_with = simplify_options(mesh, step);
    simplify_with.progress = options.progress;
    const std::size_t before = mesh.n_faces();
    const SimplifyReport report = simplify(mesh, simplify_with);
    StepResult result;
    result.renumbers = true;
    result.message = creases_marked(report.creases_marked, simplify_with.feature_angle_deg) +
                     "simplified " + std::to_string(before) + " faces to " +
                     std::to_string(mesh.n_faces()) + " (" + std::to_string(report.collapses) +
                     " collapses)";
    if (report.stopped_early) {
        result.notices.push_back(
            "stopped at " + std::to_string(mesh.n_faces()) + " faces: " +
            (std::isfinite(simplify_with.max_error)
                 ? "the next collapse exceeds the error bound " +
                       number_text(simplify_with.max_error)
                 : std::string("no further collapse keeps the mesh valid and unfolded")));
        result.message += "; " + result.notices.back();
    }
    return result;
}

namespace {

// remesh, remesh:L, remesh:L,N: target length L (0: the mean), N iterations.
RemeshOptions remesh_options(const Step& step) {
    RemeshOptions options;
    options.target_length = step.amounts[0];
    options.iterations = static_cast<int>(step.amounts[1]);
    options.feature_angle_deg = step.amounts[2];
    return options;
}

// remesh_region:R:L,N: the faces R, and for L = 0 the mean length of their edges.
RemeshOptions region_options(const Mesh& mesh, const Step& step) {
    RemeshOptions options;
    options.faces = named_faces(mesh, step);
    options.iterations = static_cast<int>(step.amounts[1]);
    options.target_length = step.amounts[0];
    if (options.target_length == 0.0) {
        double sum = 0.0;
        std::size_t n = 0;
        for (const Face f : options.faces) {
            for (const Halfedge h : mesh.halfedges(f)) {
                sum +=
                    distance(mesh.position(mesh.from_vertex(h)), mesh.position(mesh.to_vertex(h)));
                ++n;
            }
        }
        options.target_length = n > 0 ? sum / static_cast<double>(n) : 0.0;
    }
    return options;
}

OpStatus check_with(const Mesh& mesh, const Step& step, const RemeshOptions& options) {
    if (const OpStatus why = phased_loop_refusal(mesh, "remesh"); !why) {
        return why;
    }
    const double n = step.amounts[1];
    if (!(n >= 1 && n <= 100) || n != std::floor(n)) {
        return OpStatus::composed(
            "cannot remesh: iterations must be a whole number from 1 to 100, not " +
            number_text(n));
    }
    return check_remesh(mesh, options);
}

// "to edge length 0.05: 1200 faces (10 splits, 4 collapses, 7 flips" (the caller closes it).
std::string remeshed(const RemeshReport& report, std::size_t faces) {
    char length[32];
    std::snprintf(length, sizeof length, "%.4g", report.target_length);
    return "to edge length " + std::string(length) + ": " + std::to_string(faces) + " faces (" +
           std::to_string(report.splits) + " splits, " + std::to_string(report.collapses) +
           " collapses, " + std::to_string(report.flips) + " flips";
}

}  // namespace

OpStatus check_remesh_step(const Mesh& mesh, const Step& step) {
    return check_with(mesh, step, remesh_options(step));
}
StepResult run_remesh(Mesh& mesh, const Step& step, const RunOptions& options) {
    RemeshOptions remesh_with = remesh_options(step);
    remesh_with.progress = options.progress;
    const RemeshReport report = remesh(mesh, remesh_with);
    StepResult result;
    result.renumbers = true;
    result.message = creases_marked(report.creases_marked, remesh_with.feature_angle_deg) +
                     "remeshed " + remeshed(report, mesh.n_faces()) + ")";
    return result;
}

OpStatus check_remesh_region(const Mesh& mesh, const Step& step) {
    return check_with(mesh, step, region_options(mesh, step));
}
StepResult run_remesh_region(Mesh& mesh, const Step& step, const RunOptions& options) {
    RemeshOptions remesh_with = region_options(mesh, step);
    remesh_with.progress = options.progress;
    const std::size_t faces = remesh_with.faces.size();
    const std::size_t before = mesh.n_faces();
    const RemeshReport report = remesh(mesh, remesh_with);
    StepResult result;
    result.renumbers = true;
    const std::size_t now = faces + mesh.n_faces() - before;  // the region cannot lose more
    result.message = "remeshed the region of " + std::to_string(faces) + " faces " +
                     remeshed(report, now) + "; its border and the rest unmoved)";
    return result;
}

}  // namespace meshedit::ops
