// The phased subdivisions' shared check and the cc_step verb (phase_verbs.h).

#include "phase_verbs.h"

#include <string>

#include "meshedit/core/cc_steps.h"
#include "meshedit/core/loop_steps.h"

namespace meshedit::ops {

OpStatus check_phases_left(const char* scheme, int asked, int next) {
    if (asked > 5 - next) {
        return OpStatus::composed("cannot step " + std::string(scheme) + ": " +
                                  std::to_string(asked) + " phases asked, but phase " +
                                  std::to_string(next) + " of 4 is next (" +
                                  std::to_string(5 - next) + " remain)");
    }
    return OpStatus::ok();
}

// cc_step, cc_step:N: the next N phases of a phased Catmull-Clark (core/cc_steps.h).
OpStatus check_cc_step_verb(const Mesh& mesh, const Step& step) {
    if (const OpStatus why = check_phases_left("Catmull-Clark", step.levels, next_cc_phase(mesh));
        !why) {
        return why;
    }
    return check_cc_step(mesh);
}
StepResult run_cc_step(Mesh& mesh, const Step& step, const RunOptions&) {
    StepResult result;
    for (int phase = 0; phase < step.levels; ++phase) {
        const CcStepReport report = cc_step(mesh);
        result.message = report.message;
        result.renumbers = result.renumbers || report.phase == 4;  // compacted
    }
    return result;
}

// Loop is defined on triangles; rather than cut polygons the user did not ask to cut, it
// says so and names the step that does (the core's loop_subdivide() still triangulates).
// A whole-mesh subdivision, simplification or remesh in the middle of a phased Loop would
// carry its half-done state into a new mesh (the next phase threw "split did not append the
// vertex" or "flip refused"); `verb` names the refused one.
OpStatus phased_loop_refusal(const Mesh& mesh, const char* verb) {
    const int next = next_loop_phase(mesh);
    if (next == 1) {
        return OpStatus::ok();
    }
    return OpStatus::composed("cannot " + std::string(verb) +
                              ": a phased Loop is under way (phase " + std::to_string(next) +
                              " of 4 is next: `loop_step:" + std::to_string(5 - next) +
                              "` finishes it, undo goes back)");
}

}  // namespace meshedit::ops
