#pragma once
/// \file
/// Undo/redo (written only through viewer/transaction.h): each step is either a recorded change (a
/// local edit: what it touched, before and after, core/mesh_change.h) or a whole-document snapshot
/// (a global operation, a drag, a curve edit: whatever replaces too much to record), bounded in
/// bytes and in steps.
///
/// Either way undo is exact bit for bit. A change applies only to the document its edit
/// left, which the stacks guarantee: undo takes the newest undo step, redo the newest redo
/// step, and any new edit clears the redo stack. Memory: the stacks together hold at most
/// `max_bytes` (default 512 MiB) and `max_steps` (default 200) steps; the oldest undo steps
/// go first. A flip at 1M faces is a few hundred bytes, so 200 local edits cost well under a
/// megabyte; a snapshot costs the whole document (about 70 MB at 1M triangles). At least one
/// undo step is always kept, so a document larger than the budget still undoes its last
/// edit.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "meshedit/core/mesh_change.h"
#include "meshedit/viewer/document.h"

namespace meshedit::viewer {

/// A local edit of the mesh as recorded: the mesh's change and the document's small state
/// around it (selection, session, revision), before and after.
struct DocumentChange {
    MeshChange mesh;
    ElementRef selection_before, selection_after;
    std::vector<ElementRef> also_before, also_after;
    std::vector<std::string> session_added;  ///< the steps the edit appended to the session
    std::uint64_t revision_before = 0, revision_after = 0;
    /// A selection change (a box, a loop, a grown region): `mesh` is empty and untouched by
    /// undo and redo; the selection, its session step and nothing else change.
    bool selection_only = false;
    /// A selection change's stroke (a brush drag): the next change of the same non-zero
    /// stroke amends this step instead of adding one (History::amend_selection()).
    std::uint64_t stroke = 0;

    /// Each keeps the selection of the side it leaves, for the way back.
    void undo(Document& doc);
    void redo(Document& doc);
    std::size_t bytes() const;
};

struct HistoryLimits {
    std::size_t max_bytes = std::size_t{512} << 20;
    std::size_t max_steps = 200;
};

class History {
public:
    explicit History(HistoryLimits limits = {}) : limits_(limits) {}

    /// Records `before` (the document as it was before an edit) and clears the redo stack.
    void push(Document before);
    /// Records a local edit's change (applied already to the current document) and clears
    /// the redo stack.
    void push(DocumentChange change);
    /// A selection change of the same stroke as the newest undo step (a selection change,
    /// nothing redone since): that step takes `change`'s selection after and session step
    /// and true is returned; otherwise false and nothing changes.
    bool amend_selection(const DocumentChange& change);
    /// What undo() or redo() did: whether there was a step, and where a recorded change
    /// changed the mesh (MeshChange::region(); none after a snapshot).
    struct Moved {
        bool moved = false;
        std::optional<MeshChange::Region> region;
        explicit operator bool() const { return moved; }
    };
    /// Takes `current` back one step (undoing a change, or swapping in a snapshot, current
    /// going to redo).
    Moved undo(Document& current);
    /// Takes `current` forward one step.
    Moved redo(Document& current);
    void clear();

    std::size_t undo_steps() const { return undo_.size(); }
    std::size_t redo_steps() const { return redo_.size(); }
    std::size_t bytes() const { return bytes_; }
    const HistoryLimits& limits() const { return limits_; }

    /// Whether the last undo step is a recorded change (not a snapshot); for tests.
    bool last_is_change() const {
        return !undo_.empty() && std::holds_alternative<DocumentChange>(undo_.back());
    }

private:
    using Step = std::variant<Document, DocumentChange>;
    static std::size_t bytes_of(const Step& step);
    /// A new edit's step: clears the redo stack.
    void push_step(Step step);
    /// Moves the newest step of `from` onto `to`, applying it to `current` in `forward`
    /// direction (redo) or backward (undo).
    template <class From, class To>
    Moved move_step(From& from, To& to, Document& current, bool forward);
    void trim();

    HistoryLimits limits_;
    std::deque<Step> undo_;
    std::vector<Step> redo_;
    std::size_t bytes_ = 0;  ///< of undo_ and redo_ together
};

}  // namespace meshedit::viewer
