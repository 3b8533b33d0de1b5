#pragma once
// Private: the steps of the edit language a verb makes of the selection, and running them one
// after another (editor_mesh.cpp for keys, editor_modal.cpp for drags).

#include <span>
#include <string>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/ops/ops.h"
#include "meshedit/viewer/document.h"

namespace meshedit::viewer {

/// The steps of `verb` on the selected elements it accepts, in selection order (a halfedge
/// stands for its edge); for weld the one step on the two selected edges. Empty when the
/// selection has nothing the verb takes; then `hint` says what to select.
std::vector<ops::Step> steps_for_selection(const Mesh& mesh, const ops::Verb& verb,
                                           const std::vector<ElementRef>& selected,
                                           std::span<const double> amounts, std::string& hint);

/// The vertices of the selected elements (a face's corners, an edge's ends), each once, in
/// increasing order.
std::vector<std::uint32_t> selected_vertices(const Mesh& mesh,
                                             const std::vector<ElementRef>& selected);

/// What running a list of steps did.
struct StepsRun {
    std::size_t ran = 0;
    std::size_t refused = 0;             ///< refused, or naming an element an earlier step removed
    std::string first_refusal;           ///< "dissolve:v3 refused: cannot dissolve: …"
    std::vector<ElementRef> made;        ///< each step's result, where it has one
    std::vector<std::string> steps;      ///< the text of each step that ran, for the session
    std::vector<const ops::Step*> done;  ///< the steps that ran (into the list run)
    std::string message;                 ///< for the status line
};

/// ops::run_steps() with OnRefusal::Skip (each step whose check passes runs; a step that names
/// an element an earlier one removed counts as refused), and a status line: with several
/// steps "`what`: 3 of 4 done (…)".
StepsRun run_steps(Mesh& mesh, const std::vector<ops::Step>& steps, std::string_view what);

/// The session's record of vertex `v` where it is now: "move:v12:0.5,-1,0.25".
std::string move_step(const Mesh& mesh, std::uint32_t v);

/// Selects what the steps made: the last one active, the others with it.
void select_made(Document& doc, const std::vector<ElementRef>& made);

}  // namespace meshedit::viewer
