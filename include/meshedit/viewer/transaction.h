#pragma once
/// \file
/// The one way the document changes: a Transaction. It begins in one of three ways —
///
///   Recorded   a local edit: the mesh's setters tell a MeshRecorder what they overwrite
///              (core/mesh_change.h); the undo step costs what the edit touched
///   Snapshot   a whole-mesh edit, a curve edit: the document is copied at the start
///   Positions  a drag: recorded as Recorded is, the vertices it moves touched once at the
///              start; every move only writes their positions
///
/// — and ends with commit(), which appends the edit's steps to the session, gives the
/// document a new revision, disarms the "unsaved changes" warnings and pushes one undo
/// step, or with roll_back() (or destruction), which puts the document back bit for bit.
/// commit() returns the Outcome the window reads, with the region of the mesh the edit
/// changed when it was recorded (the GPU buffers and the picking tree follow it).
///
/// A Ledger holds what only transactions write: the undo history, the revision counter,
/// the saved revision and the arming of the warnings. Undo and redo go through it too
/// (step()); opening a document starts it over (start()); a selection change, which leaves
/// the mesh alone, is its own step (select()). Nothing else in src/ pushes
/// history, bumps a revision or appends to the session (tests/check_transactions.cmake).

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "meshedit/core/mesh_change.h"
#include "meshedit/viewer/document.h"
#include "meshedit/viewer/history.h"
#include "meshedit/viewer/outcome.h"

namespace meshedit::viewer {

class Transaction;

/// The document's undo history, revisions and warnings (see the file comment).
class Ledger {
public:
    explicit Ledger(HistoryLimits limits = {}) : history_(limits) {}

    const History& history() const { return history_; }
    /// Unsaved changes: `doc` differs from what was last opened or saved (undoing back to
    /// the saved state makes it clean again).
    bool dirty(const Document& doc) const { return doc.revision != saved_revision_; }
    /// The document as it is now is what the file holds (after a save).
    void mark_saved(const Document& doc) { saved_revision_ = doc.revision; }

    /// Replaces `doc` with `replacement` as a new, clean document with no history.
    void start(Document& doc, Document replacement);
    /// Undo (`forward` false) or redo one step; nullopt when there is none. The region is a
    /// recorded change's (none after a snapshot: everything is redrawn).
    std::optional<std::optional<MeshChange::Region>> step(Document& doc, bool forward);

    /// A selection change as one undo step (a box, a lasso, a loop, a grown region): the
    /// selection was `before` and `also_before` and is now `doc`'s; `step` (a `select` step,
    /// ops::select_step_text()) goes to the session. Not a new revision: selecting is not an
    /// unsaved change. With a non-zero `stroke` equal to the newest step's (a brush drag
    /// painting on), that step takes the new selection and its session step is replaced.
    void select(Document& doc, ElementRef before, std::vector<ElementRef> also_before,
                std::string step, std::uint64_t stroke = 0);

    /// The warnings that let the next quit or open discard unsaved changes; every commit
    /// disarms both.
    bool quit_armed = false;
    bool replace_armed = false;

private:
    friend class Transaction;
    History history_;
    std::uint64_t next_revision_ = 1;
    std::uint64_t saved_revision_ = 0;
};

class Transaction {
public:
    enum class Kind { Recorded, Snapshot, Positions };

    /// Begins: a Recorded or Positions transaction records the mesh from here on (a
    /// Positions one then calls touch() on what it moves); a Snapshot copies the document.
    Transaction(Ledger& ledger, Document& doc, Kind kind);
    /// A Snapshot whose edit replaces the whole mesh by `replacement` (an operation run in the
    /// background): the old mesh moves into the undo record instead of being copied.
    Transaction(Ledger& ledger, Document& doc, Mesh replacement);
    /// Not committed: rolled back.
    ~Transaction();
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;

    Kind kind() const { return kind_; }
    /// Positions: takes the vertex's values now as the undo step's "before"; its position
    /// may then be written any number of times.
    void touch(Vertex v);
    /// Recorded: ends what is recorded so far as a preview (an interactive edit shown at
    /// one amount) and returns where it changed the mesh.
    MeshChange::Region preview();
    /// Recorded, after preview(): the elements the preview touched or made were written
    /// again in place (an interactive edit moving the corners it made, its topology built
    /// once); the change takes their values now. Costs what the preview touched. Returns
    /// where the mesh changed.
    MeshChange::Region amend();
    /// Back to the document as the transaction began (selection included), still open: an
    /// interactive edit trying another amount, in the time of what the preview touched.
    /// Returns where the mesh changed back.
    MeshChange::Region rewind();

    /// Ends the transaction (see the file comment). `changes` and `message` become the
    /// Outcome; `steps` are the edit-language steps that did the edit, for the session.
    /// `look`, if given, sees a recorded transaction's change with the mesh as the edit left it
    /// (the rewiring diagram is read from it) and may undo and redo it there.
    Outcome commit(unsigned changes, std::string message, std::vector<std::string> steps,
                   const std::function<void(const MeshChange&)>& look = {});
    /// Puts the document back as the transaction began and ends it; the region redrawn.
    std::optional<MeshChange::Region> roll_back();

private:
    bool open() const { return ledger_ != nullptr; }
    void restore_selection();
    /// Recorded, Positions: undoes what is recorded so far and restores the selection; where
    /// the mesh changed back, if anything was recorded.
    std::optional<MeshChange::Region> undo_recorded();

    Ledger* ledger_;
    Document* doc_;
    Kind kind_;
    std::optional<Document> before_;  ///< Snapshot
    std::optional<MeshRecorder> recorder_;
    std::optional<MeshChange> change_;  ///< what is recorded so far, when not recording
    ElementRef selection_before_;
    std::vector<ElementRef> also_before_;
};

}  // namespace meshedit::viewer
