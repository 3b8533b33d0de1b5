// The Problems panel's list (editor.h, Alt+V): found on request for the document as it is,
// with the loader's repairs while it is as loaded; opened by itself after a load that
// repaired something, so those repairs are shown where they are, not only said.

#include "meshedit/viewer/editor.h"

namespace meshedit::viewer {

const ProblemReport* Editor::problems() const {
    return problems_ && problems_revision_ == doc_.revision ? &*problems_ : nullptr;
}

bool Editor::load_repaired() const {
    return doc_.revision == load_revision_ && load_repairs_.repaired();
}

Outcome Editor::find_problems() {
    if (const std::optional<Outcome> busy = refuse_if_busy()) {
        return *busy;
    }
    const bool as_loaded = doc_.revision == load_revision_;
    problems_ = meshedit::find_problems(doc_.mesh, as_loaded ? &load_repairs_ : nullptr);
    problems_revision_ = doc_.revision;
    return {kDisplay, "problems: " + problems_->summary() +
                          (problems_->empty() ? "" : " (listed in the info panel: click one)")};
}

}  // namespace meshedit::viewer
