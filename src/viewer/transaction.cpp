// The one way the document changes (transaction.h): the only code that pushes history,
// bumps the revision or appends to the session.

#include "meshedit/viewer/transaction.h"

#include <stdexcept>
#include <utility>

#include "meshedit/core/assert.h"

namespace meshedit::viewer {

// -------------------------------------------------------------------------------- Ledger

void Ledger::start(Document& doc, Document replacement) {
    doc = std::move(replacement);
    doc.revision = next_revision_++;
    saved_revision_ = doc.revision;
    history_.clear();
    quit_armed = false;
    replace_armed = false;
}

std::optional<std::optional<MeshChange::Region>> Ledger::step(Document& doc, bool forward) {
    History::Moved moved = forward ? history_.redo(doc) : history_.undo(doc);
    if (!moved.moved) {
        return std::nullopt;
    }
    return std::move(moved.region);
}

void Ledger::select(Document& doc, ElementRef before, std::vector<ElementRef> also_before,
                    std::string step, std::uint64_t stroke) {
    DocumentChange change;
    change.selection_only = true;
    change.stroke = stroke;
    change.selection_before = before;
    change.also_before = std::move(also_before);
    change.selection_after = doc.selection;
    change.also_after = doc.also_selected;
    change.session_added = {std::move(step)};
    change.revision_before = change.revision_after = doc.revision;
    if (history_.amend_selection(change)) {
        doc.session.back() = change.session_added.front();
        return;
    }
    doc.session.push_back(change.session_added.front());
    history_.push(std::move(change));
}

// --------------------------------------------------------------------------- Transaction

Transaction::Transaction(Ledger& ledger, Document& doc, Kind kind)
    : ledger_(&ledger),
      doc_(&doc),
      kind_(kind),
      selection_before_(doc.selection),
      also_before_(doc.also_selected) {
    if (kind == Kind::Snapshot) {
        before_.emplace(doc);
    } else {
        recorder_.emplace(doc.mesh);
    }
}

Transaction::Transaction(Ledger& ledger, Document& doc, Mesh replacement)
    : ledger_(&ledger),
      doc_(&doc),
      kind_(Kind::Snapshot),
      selection_before_(doc.selection),
      also_before_(doc.also_selected) {
    Mesh old = std::exchange(doc.mesh, std::move(replacement));
    Mesh result = std::exchange(doc.mesh, Mesh());
    before_.emplace(doc);  // without a mesh: nothing big is copied
    before_->mesh = std::move(old);
    doc.mesh = std::move(result);
}

Transaction::~Transaction() {
    if (open()) {
        roll_back();
    }
}

void Transaction::touch(Vertex v) {
    if (recorder_) {
        doc_->mesh.touch(v);
    }
}

MeshChange::Region Transaction::preview() {
    if (recorder_) {
        change_ = recorder_->finish();
        recorder_.reset();
    }
    return change_ ? change_->region() : MeshChange::Region{};
}

MeshChange::Region Transaction::amend() {
    MESHEDIT_ASSERT(change_ && !recorder_);
    change_->refresh_after(doc_->mesh);
    return change_->region();
}

void Transaction::restore_selection() {
    doc_->selection = selection_before_;
    doc_->also_selected = also_before_;
}

std::optional<MeshChange::Region> Transaction::undo_recorded() {
    std::optional<MeshChange::Region> undone;
    if (recorder_) {
        recorder_->roll_back();
        recorder_.reset();
    }
    if (change_) {
        change_->undo(doc_->mesh);
        undone = change_->region();
        change_.reset();
    }
    restore_selection();
    return undone;
}

MeshChange::Region Transaction::rewind() {
    if (kind_ == Kind::Snapshot) {
        *doc_ = *before_;
        return {};
    }
    std::optional<MeshChange::Region> undone = undo_recorded();
    recorder_.emplace(doc_->mesh);
    return undone.value_or(MeshChange::Region{});
}

std::optional<MeshChange::Region> Transaction::roll_back() {
    std::optional<MeshChange::Region> region;
    if (kind_ == Kind::Snapshot) {
        *doc_ = std::move(*before_);
    } else {
        region = undo_recorded();
    }
    ledger_ = nullptr;
    return region;
}

Outcome Transaction::commit(unsigned changes, std::string message, std::vector<std::string> steps,
                            const std::function<void(const MeshChange&)>& look) {
    Ledger& ledger = *std::exchange(ledger_, nullptr);
    Document& doc = *doc_;
    const std::uint64_t revision_before = doc.revision;
    doc.session.insert(doc.session.end(), steps.begin(), steps.end());
    doc.revision = ledger.next_revision_++;
    ledger.quit_armed = false;
    ledger.replace_armed = false;
    Outcome out{changes, std::move(message), false, std::nullopt};
    if (kind_ == Kind::Snapshot) {
        ledger.history_.push(std::move(*before_));
        return out;
    }
    try {
        if (recorder_) {
            change_ = recorder_->finish();
            recorder_.reset();
        }
    } catch (const std::logic_error& e) {
        // An edit wrote what its recording cannot see (a bug the recorded-edit tests and the
        // recorder's self-check are there to catch): the edit stands, but nothing before it
        // can be undone.
        ledger.history_.clear();
        out.message += std::string(" — cannot be undone: ") + e.what();
        return out;
    }
    if (!change_) {
        return out;
    }
    if (look) {
        look(*change_);
    }
    DocumentChange change;
    change.mesh = std::move(*change_);
    change.selection_before = std::move(selection_before_);
    change.also_before = std::move(also_before_);
    change.selection_after = doc.selection;
    change.also_after = doc.also_selected;
    change.session_added = std::move(steps);
    change.revision_before = revision_before;
    change.revision_after = doc.revision;
    out.region = change.mesh.region();
    ledger.history_.push(std::move(change));
    return out;
}

}  // namespace meshedit::viewer
