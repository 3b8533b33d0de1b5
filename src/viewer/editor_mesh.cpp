// The editor's mesh edits: every key that changes the mesh runs a verb of the edit language
// (meshedit/ops/ops.h) through the edit funnel, on the selected elements or the whole mesh.

#include <span>
#include <stdexcept>
#include <vector>

#include "meshedit/core/assert.h"
#include "meshedit/ops/ops.h"
#include "meshedit/viewer/editor.h"
#include "selection_steps.h"

namespace meshedit::viewer {

Outcome Editor::edit_mesh(std::string_view name) {
    const ops::Verb* verb = ops::find_verb(name);
    if (verb == nullptr) {
        return refused("no such edit: '" + std::string(name) + "'");
    }
    if (student_ && !verb->course_task.empty()) {
        return run_student(*verb);
    }
    return run_verb(*verb);
}

Outcome Editor::run_verb(const ops::Verb& v) {
    const ops::Verb* verb = &v;
    const std::string_view name = verb->name;
    if (verb->accepts(ops::Target::None)) {
        // Whole-mesh verbs with amounts take them from the tool settings (the info panel).
        std::span<const double> amounts;
        if ((verb->traits & ops::kToolAmounts) != 0) {
            amounts = std::span<const double>(tools_.amounts(verb->name).data(), verb->max_amounts);
        }
        const ops::Step step = ops::make_step(name, doc_.mesh, ElementRef{}, amounts);
        if (background_ && doc_.mode == Mode::Mesh) {
            if (const OpStatus status = verb->check(doc_.mesh, step); !status) {
                return refused(status.text());
            }
            return start_job(*verb, step);
        }
        return edit([&] { return verb->check(doc_.mesh, step); },
                    [&](Document& doc) {
                        ops::RunOptions run;
                        if (progress_hook_) {
                            run.progress = [&](double f) { progress_hook_(name, f); };
                        }
                        return after_whole_mesh(verb->run(doc.mesh, step, run), step.text);
                    });
    }
    // Amount verbs run from a key as drags (begin_modal); here with their defaults.
    std::string hint;
    const std::vector<ops::Step> steps =
        steps_for_selection(doc_.mesh, *verb, selected(), {}, hint);
    if (steps.empty()) {
        return refused(hint);
    }
    return edit_steps(steps, verb->name, (verb->traits & ops::kChangesTopology) != 0,
                      (verb->traits & ops::kRebuildsMesh) == 0);
}

Editor::Edited Editor::after_whole_mesh(const ops::StepResult& result, const std::string& step) {
    Edited edited;
    edited.message = result.message;
    edited.steps = {step};
    // A whole-mesh operation may shrink or grow the shape: the view stays (what the operation
    // did is what the user should see), the depth range follows.
    edited.changes = kTopology | kSelection | kSceneBounds;
    if (result.renumbers && doc_.selection.kind != ElementRef::Kind::Vertex) {
        edited.select = ElementRef{};  // only vertices keep their numbers
    } else if (result.renumbers) {
        doc_.also_selected.clear();
    }
    return edited;
}

Outcome Editor::delete_selection() {
    std::vector<ops::Step> steps;
    std::string hint;
    for (const char* name : {"dissolve", "make_boundary"}) {
        const std::vector<ops::Step> some =
            steps_for_selection(doc_.mesh, *ops::find_verb(name), selected(), {}, hint);
        steps.insert(steps.end(), some.begin(), some.end());
    }
    if (steps.empty()) {
        return refused("select vertices, edges or faces to delete first");
    }
    return edit_steps(steps, "delete", true);
}

Outcome Editor::edit_steps(const std::vector<ops::Step>& steps, std::string_view what,
                           bool topology, bool recorded) {
    // Each step's predicate runs once, in run_steps(); a list none of whose steps could run
    // is refused with the first reason, the recording rolled back.
    return edit([] { return OpStatus::ok(); },
                [&](Document& doc) {
                    const StepsRun run = run_steps(doc.mesh, steps, what);
                    if (run.ran == 0) {
                        throw std::runtime_error(run.first_refusal);
                    }
                    select_made(doc, run.made);
                    Edited edited;
                    edited.message = run.message;
                    edited.steps = run.steps;
                    edited.step = run.done.size() == 1 && steps.size() == 1 ? run.done[0] : nullptr;
                    edited.changes = topology ? kTopology | kSelection : kSelection | kDisplay;
                    return edited;
                },
                recorded);
}

ToolSettings::Amounts& ToolSettings::amounts(std::string_view verb) {
    const ops::Verb* v = ops::find_verb(verb);
    MESHEDIT_ASSERT(v != nullptr);
    for (auto& [known, values] : amounts_) {
        if (known == v) {
            return values;
        }
    }
    return amounts_.emplace_back(v, v->defaults).second;
}

bool Editor::compact() {
    if (doc_.mode == Mode::Curve || !doc_.mesh.has_garbage()) {
        return false;
    }
    GarbageCollectionMap map;
    doc_.mesh.garbage_collection(&map);
    remap_selection(map);
    return true;
}

void Editor::remap_selection(const GarbageCollectionMap& map) {
    doc_.selection = remap(doc_.selection, map);
    std::vector<ElementRef> also;
    for (const ElementRef& e : doc_.also_selected) {
        if (const ElementRef r = remap(e, map); !r.is_none() && r != doc_.selection) {
            also.push_back(r);
        }
    }
    doc_.also_selected = std::move(also);
    hover_ = {};
}

}  // namespace meshedit::viewer
