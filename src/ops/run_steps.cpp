// Running steps of the edit language: one step (run_step()), or a list with its plans, its
// progress, its notices and the selection it carries (run_steps()).

#include <algorithm>
#include <string>
#include <vector>

#include "meshedit/core/loop_steps.h"
#include "meshedit/ops/ops.h"

namespace meshedit::ops {
namespace {

// What a step made, selected after it as the viewer selects it; indices the step renumbered
// would name other elements, so nothing older stays selected.
Selection made_by(const StepResult& result) {
    Selection out;
    if (result.selected.is_none()) {
        return out;
    }
    const bool halfedge = result.selected.kind == ElementRef::Kind::Halfedge;
    out.kind = halfedge ? ElementRef::Kind::Edge : result.selected.kind;
    out.indices.push_back(halfedge ? Mesh::edge(Halfedge(result.selected.index)).idx()
                                   : result.selected.index);
    for (const ElementRef& e : result.selected_too) {
        if (e.kind == out.kind) {
            out.indices.push_back(e.index);
        }
    }
    return out;
}

}  // namespace

bool draws_diagram(const Step& step) {
    return step.target != Target::None && (step.verb->traits & kDrawsDiagram) != 0;
}

StepResult run_step(Mesh& mesh, const Step& step, const RunOptions& options) {
    if (const OpStatus status = step.verb->check(mesh, step); !status) {
        throw OpError(step.text + " refused: " + status.text(), true);
    }
    return step.verb->run(mesh, step, options);
}

StepsRun run_steps(Mesh& mesh, const std::vector<Step>& steps, OnRefusal on_refusal,
                   const ApplyOptions& options) {
    // Every subdivision level of the list must fit before any work is done (the local steps
    // barely change the size; each level of any scheme about quadruples the faces, so the
    // levels so far are planned with the step's own scheme); each step is checked again
    // when it runs. A phased verb counts phases: four make one level, whose second (the split)
    // is the one that grows the mesh; a phased Loop may be under way (next_loop_phase()).
    struct Planned {
        std::size_t step;
        int levels;
    };
    std::vector<Planned> planned;
    int levels = 0;
    int phase = next_loop_phase(mesh) - 1;  // 0 to 3: the next phase's place in its level
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        if (step.verb->plan == nullptr) {
            continue;
        }
        if (step.verb->phases) {
            for (int k = 0; k < step.levels; ++k) {
                levels += phase == 1 ? 1 : 0;
                phase = (phase + 1) % 4;
            }
        } else {
            levels += step.levels;
        }
        planned.push_back({i, levels});
    }
    // One plan per scheme, for its deepest step, is a pass over the mesh each; only when one
    // is refused are the steps walked to name the first that does not fit.
    std::vector<Planned> deepest;
    for (const Planned& p : planned) {
        const auto same = std::find_if(deepest.begin(), deepest.end(), [&](const Planned& d) {
            return steps[d.step].verb->plan == steps[p.step].verb->plan;
        });
        if (same == deepest.end()) {
            deepest.push_back(p);
        } else {
            *same = p;
        }
    }
    const auto refusal = [&](const Planned& p) {
        return steps[p.step].verb->plan(mesh, std::max(p.levels, 1));
    };
    if (std::any_of(deepest.begin(), deepest.end(),
                    [&](const Planned& p) { return p.levels > 0 && !refusal(p).ok(); })) {
        int checked = 0;
        for (const Planned& p : planned) {
            if (p.levels > checked) {
                checked = p.levels;
                if (const SubdivisionPlan plan = refusal(p); !plan.ok()) {
                    throw OpError(steps[p.step].text + " refused: " + plan.status.text(), true);
                }
            }
        }
        for (const Planned& p : deepest) {
            if (const SubdivisionPlan plan = refusal(p); p.levels > 0 && !plan.ok()) {
                throw OpError(steps[p.step].text + " refused: " + plan.status.text(), true);
            }
        }
    }
    // Progress is weighted by face count: each subdivision level costs about as much as the
    // faces it starts from, and the local steps cost nothing in comparison.
    std::vector<double> cost(steps.size(), 0.0);
    double total = 0.0;
    double faces = static_cast<double>(mesh.n_faces());
    for (std::size_t i = 0; i < steps.size(); ++i) {
        for (int level = 0; steps[i].verb->plan != nullptr && level < steps[i].levels; ++level) {
            cost[i] += faces;
            faces *= 4.0;
        }
        total += cost[i];
    }
    double done = 0.0;
    StepsRun out;
    Selection& selection = out.selection;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        // A region written `sel` is the selection's faces now.
        Step with_selection;
        if (steps[i].from_selection) {
            with_selection = steps[i];
            with_selection.from_selection = false;
            if (selection.kind == ElementRef::Kind::Face) {
                for (const std::uint32_t f : selection.indices) {
                    with_selection.region.push_back({f, f});
                }
            }
            if (with_selection.region.empty()) {
                const std::string why =
                    "the selection holds no faces (select:R, or a select_ "
                    "verb, picks them first)";
                if (on_refusal == OnRefusal::Stop) {
                    throw OpError(steps[i].text + " refused: " + why, true);
                }
                if (out.refused++ == 0) {
                    out.first_refusal = steps.size() == 1 ? why : steps[i].text + ": " + why;
                }
                continue;
            }
        }
        const Step& step = steps[i].from_selection ? with_selection : steps[i];
        std::string reason;
        try {
            reason = step.verb->check(mesh, step).text();
        } catch (const OpError& e) {
            if (on_refusal == OnRefusal::Stop) {
                throw;
            }
            reason = e.what();  // an earlier step removed what this one names
        }
        if (!reason.empty()) {
            if (on_refusal == OnRefusal::Stop) {
                throw OpError(step.text + " refused: " + reason, true);
            }
            if (out.refused++ == 0) {
                out.first_refusal = steps.size() == 1 ? reason : step.text + ": " + reason;
            }
            continue;
        }
        RunOptions run;
        run.weights = options.weights;
        if (options.progress && total > 0.0) {
            run.progress = [&, i](double f) {
                options.progress(std::min(1.0, (done + f * cost[i]) / total));
            };
        }
        StepResult result = step.verb->run(mesh, step, run);
        ++out.ran;
        out.done.push_back(&steps[i]);
        if (step.verb->select != nullptr) {
            selection = step.verb->select(mesh, step, selection);
        } else if (result.topology) {
            selection = made_by(result);
        }
        if (!result.selected.is_none()) {
            out.made.push_back(result.selected);
        }
        out.made.insert(out.made.end(), result.selected_too.begin(), result.selected_too.end());
        out.last = result.selected;
        out.last_message = std::move(result.message);
        done += cost[i];
        if (options.progress && total > 0.0) {
            options.progress(std::min(1.0, done / total));
        }
        for (const std::string& notice : result.notices) {
            if (options.notice) {
                options.notice(step.text + ": " + notice);
            }
        }
    }
    return out;
}

ElementRef apply_steps(Mesh& mesh, const std::vector<Step>& steps, const ApplyOptions& options) {
    return run_steps(mesh, steps, OnRefusal::Stop, options).last;
}

}  // namespace meshedit::ops
