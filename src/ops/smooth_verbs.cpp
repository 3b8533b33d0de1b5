// The smoothing verbs and fair (smooth_verbs.h): each translates between a step and
// meshedit/core/smoothing.h; each verb's pair of functions names its method and weights.

#include "smooth_verbs.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "meshedit/core/smoothing.h"
#include "region_verbs.h"

namespace meshedit::ops {
namespace {

// Cotangent weights where they are defined (triangles), uniform on a mesh with polygons.
SmoothWeights natural_weights(const Mesh& mesh) {
    return mesh.is_triangle_mesh() ? SmoothWeights::Cotangent : SmoothWeights::Uniform;
}

// A step's options, or why its amounts cannot be (a count that is not a whole number from 1
// to 1000, a keep-the-volume flag other than 0 or 1).
struct Parsed {
    SmoothOptions options;
    std::string why;
};

void take_count(Parsed& p, double n) {
    if (!(n >= 1 && n <= 1000) || n != std::floor(n)) {
        p.why = "cannot smooth: iterations must be a whole number from 1 to 1000, not " +
                number_text(n);
        return;
    }
    p.options.iterations = static_cast<int>(n);
}

void take_keep(Parsed& p, double keep) {
    if (keep != 0.0 && keep != 1.0) {
        p.why = "cannot smooth: keep the volume is 1 (yes) or 0 (no), not " + number_text(keep);
    }
    p.options.keep_volume = keep == 1.0;
}

// smooth:N,L,K and smooth_cotan:N,L,K.
Parsed explicit_options(const Step& step, SmoothWeights weights) {
    Parsed p;
    p.options.weights = weights;
    p.options.lambda = step.amounts[1];
    take_keep(p, step.amounts[2]);
    take_count(p, step.amounts[0]);
    return p;
}
Parsed uniform_options(const Mesh&, const Step& step) {
    return explicit_options(step, SmoothWeights::Uniform);
}
Parsed cotan_options(const Mesh&, const Step& step) {
    return explicit_options(step, SmoothWeights::Cotangent);
}
// taubin:N,L,M.
Parsed taubin_options(const Mesh&, const Step& step) {
    Parsed p;
    p.options.method = SmoothMethod::Taubin;
    p.options.lambda = step.amounts[1];
    p.options.mu = step.amounts[2];
    take_count(p, step.amounts[0]);
    return p;
}
// smooth_implicit:T,N,K.
Parsed implicit_options(const Mesh& mesh, const Step& step) {
    Parsed p;
    p.options.method = SmoothMethod::Implicit;
    p.options.weights = natural_weights(mesh);
    p.options.time = step.amounts[0];
    take_keep(p, step.amounts[2]);
    take_count(p, step.amounts[1]);
    return p;
}

using MakeOptions = Parsed (*)(const Mesh&, const Step&);

OpStatus check_with(const Mesh& mesh, const Step& step, MakeOptions make) {
    const Parsed p = make(mesh, step);
    if (!p.why.empty()) {
        return OpStatus::composed(p.why);
    }
    return check_smooth(mesh, p.options);
}

// "volume −0.81 %" (a true minus), or "volume unchanged".
std::string volume_change(double before, double after) {
    const double percent = (after - before) / std::abs(before) * 100.0;
    if (!(std::abs(percent) >= 5e-7)) {
        return "volume unchanged";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.3g %%", std::abs(percent));
    return std::string("volume ") + (percent < 0 ? "−" : "+") + text;
}

std::string length_text(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

StepResult run_with(Mesh& mesh, const Step& step, const RunOptions& options, MakeOptions make) {
    SmoothOptions smooth_with = make(mesh, step).options;
    smooth_with.progress = options.progress;
    const SmoothReport report = smooth(mesh, smooth_with);
    const int n = report.iterations;
    StepResult result;
    result.message = std::string(smooth_with.method == SmoothMethod::Taubin ? "Taubin-" : "") +
                     "smoothed " + std::to_string(n) + (n == 1 ? " iteration" : " iterations");
    if (smooth_with.method == SmoothMethod::Implicit) {
        result.message = "smoothed implicitly (t = " + number_text(smooth_with.time) + ", " +
                         std::to_string(n) + (n == 1 ? " step" : " steps") + ", solved in " +
                         length_text(report.solve_seconds) + " s)";
    }
    result.message += report.closed
                          ? ": " + volume_change(report.volume_before, report.volume_after)
                          : ": largest move " + length_text(report.max_displacement);
    return result;
}

}  // namespace

OpStatus check_smooth_uniform(const Mesh& mesh, const Step& step) {
    return check_with(mesh, step, uniform_options);
}
StepResult run_smooth_uniform(Mesh& mesh, const Step& step, const RunOptions& options) {
    return run_with(mesh, step, options, uniform_options);
}
OpStatus check_smooth_cotan(const Mesh& mesh, const Step& step) {
    return check_with(mesh, step, cotan_options);
}
StepResult run_smooth_cotan(Mesh& mesh, const Step& step, const RunOptions& options) {
    return run_with(mesh, step, options, cotan_options);
}
OpStatus check_taubin(const Mesh& mesh, const Step& step) {
    return check_with(mesh, step, taubin_options);
}
StepResult run_taubin(Mesh& mesh, const Step& step, const RunOptions& options) {
    return run_with(mesh, step, options, taubin_options);
}
OpStatus check_smooth_implicit(const Mesh& mesh, const Step& step) {
    return check_with(mesh, step, implicit_options);
}
StepResult run_smooth_implicit(Mesh& mesh, const Step& step, const RunOptions& options) {
    return run_with(mesh, step, options, implicit_options);
}

// smooth_region:R:N,L: smooth's uniform steps on the inner vertices of the faces R only.
Parsed region_options(const Mesh& mesh, const Step& step) {
    Parsed p = explicit_options(step, SmoothWeights::Uniform);
    const std::vector<Face> faces = named_faces(mesh, step);  // throws for a missing face
    p.options.vertices = region_inner_vertices(mesh, faces);
    if (p.why.empty() && p.options.vertices.empty()) {
        p.why = "cannot smooth: every vertex of the " + std::to_string(faces.size()) +
                (faces.size() == 1 ? " face" : " faces") +
                " is on their border (select the faces around a vertex too)";
    }
    return p;
}

OpStatus check_smooth_region(const Mesh& mesh, const Step& step) {
    return check_with(mesh, step, region_options);
}

StepResult run_smooth_region(Mesh& mesh, const Step& step, const RunOptions& options) {
    const std::vector<Face> faces = named_faces(mesh, step);
    const std::size_t inner = region_options(mesh, step).options.vertices.size();
    StepResult whole = run_with(mesh, step, options, region_options);
    StepResult result = local(ElementRef::face(faces.front()), "");
    for (std::size_t i = 1; i < faces.size(); ++i) {
        result.selected_too.push_back(ElementRef::face(faces[i]));
    }
    // "smoothed 10 iterations: volume −0.2 %" → "... of 9 inner vertices of 16 faces (border
    // fixed): volume −0.2 %".
    const std::size_t colon = whole.message.find(':');
    result.message = whole.message.substr(0, colon) + " of " + std::to_string(inner) +
                     (inner == 1 ? " inner vertex of " : " inner vertices of ") +
                     std::to_string(faces.size()) + (faces.size() == 1 ? " face" : " faces") +
                     " (border fixed)" + whole.message.substr(colon);
    return result;
}

OpStatus check_fair_step(const Mesh& mesh, const Step& step) {
    const std::vector<Face> faces = named_faces(mesh, step);  // throws for a missing face
    FairOptions options;
    options.weights = natural_weights(mesh);
    return check_fair(mesh, faces, options);
}

StepResult run_fair(Mesh& mesh, const Step& step, const RunOptions&) {
    const std::vector<Face> faces = named_faces(mesh, step);
    FairOptions options;
    options.weights = natural_weights(mesh);
    const FairReport report = fair(mesh, faces, options);
    StepResult result =
        local(ElementRef::face(faces.front()),
              "faired " + std::to_string(report.moved) + " inner vertices of " +
                  std::to_string(faces.size()) + (faces.size() == 1 ? " face" : " faces") +
                  " (border fixed): largest move " + length_text(report.max_displacement));
    for (std::size_t i = 1; i < faces.size(); ++i) {
        result.selected_too.push_back(ElementRef::face(faces[i]));
    }
    return result;
}

}  // namespace meshedit::ops
