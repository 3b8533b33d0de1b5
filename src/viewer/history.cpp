// Undo/redo by recorded changes and whole-document snapshots (see history.h).

#include "meshedit/viewer/history.h"

#include <utility>

namespace meshedit::viewer {

const char* mode_description(Mode mode) {
    switch (mode) {
        case Mode::Mesh:
            return "mesh";
        case Mode::Surface:
            return "Bezier surface (welded tessellation)";
        case Mode::Curve:
            return "Bezier curve";
    }
    return "";
}

std::size_t Document::bytes() const {
    std::size_t n = sizeof(Document) + mesh.bytes();
    n += patches.capacity() * sizeof(BezierPatch);
    for (const BezierPatch& p : patches) {
        n += p.control_points.capacity() * sizeof(Vec3);
    }
    n += curve.control_points.capacity() * sizeof(Vec3);
    n += also_selected.capacity() * sizeof(ElementRef);
    for (const std::string& step : session) {
        n += sizeof(std::string) + step.capacity();
    }
    return n;
}

// The selection is not part of the change: like a snapshot, each side keeps the selection
// it had when the document last left it (a click after the edit survives undo and redo).
void DocumentChange::undo(Document& doc) {
    if (!selection_only) {
        mesh.undo(doc.mesh);
    }
    selection_after = std::exchange(doc.selection, selection_before);
    also_after = std::exchange(doc.also_selected, also_before);
    doc.session.resize(doc.session.size() - session_added.size());
    doc.revision = revision_before;
}

void DocumentChange::redo(Document& doc) {
    if (!selection_only) {
        mesh.redo(doc.mesh);
    }
    selection_before = std::exchange(doc.selection, selection_after);
    also_before = std::exchange(doc.also_selected, also_after);
    doc.session.insert(doc.session.end(), session_added.begin(), session_added.end());
    doc.revision = revision_after;
}

std::size_t DocumentChange::bytes() const {
    std::size_t n = sizeof(*this) - sizeof(MeshChange) + mesh.bytes() +
                    (also_before.capacity() + also_after.capacity()) * sizeof(ElementRef);
    for (const std::string& step : session_added) {
        n += sizeof(std::string) + step.capacity();
    }
    return n;
}

std::size_t History::bytes_of(const Step& step) {
    return std::visit([](const auto& s) { return s.bytes(); }, step);
}

void History::push(Document before) {
    push_step(std::move(before));
}

void History::push(DocumentChange change) {
    push_step(std::move(change));
}

void History::push_step(Step step) {
    for (const Step& s : redo_) {
        bytes_ -= bytes_of(s);
    }
    redo_.clear();
    bytes_ += bytes_of(step);
    undo_.push_back(std::move(step));
    trim();
}

bool History::amend_selection(const DocumentChange& change) {
    auto* last = undo_.empty() ? nullptr : std::get_if<DocumentChange>(&undo_.back());
    if (last == nullptr || !last->selection_only || !redo_.empty() || change.stroke == 0 ||
        last->stroke != change.stroke) {
        return false;
    }
    bytes_ -= last->bytes();
    last->selection_after = change.selection_after;
    last->also_after = change.also_after;
    last->session_added = change.session_added;
    bytes_ += last->bytes();
    trim();
    return true;
}

template <class From, class To>
History::Moved History::move_step(From& from, To& to, Document& current, bool forward) {
    if (from.empty()) {
        return {};
    }
    Moved moved{true, std::nullopt};
    Step step = std::move(from.back());
    from.pop_back();
    bytes_ -= bytes_of(step);
    if (auto* change = std::get_if<DocumentChange>(&step)) {
        moved.region = change->selection_only ? MeshChange::Region{} : change->mesh.region();
        if (forward) {
            change->redo(current);
        } else {
            change->undo(current);
        }
    } else {
        // A snapshot: the current document becomes the step that leads back to it.
        std::swap(std::get<Document>(step), current);
    }
    bytes_ += bytes_of(step);
    to.push_back(std::move(step));
    trim();
    return moved;
}

History::Moved History::undo(Document& current) {
    return move_step(undo_, redo_, current, false);
}

History::Moved History::redo(Document& current) {
    return move_step(redo_, undo_, current, true);
}

void History::clear() {
    undo_.clear();
    redo_.clear();
    bytes_ = 0;
}

void History::trim() {
    const auto over = [&] {
        return bytes_ > limits_.max_bytes || undo_.size() + redo_.size() > limits_.max_steps;
    };
    // The oldest undo steps go first, down to one.
    while (undo_.size() > 1 && over()) {
        bytes_ -= bytes_of(undo_.front());
        undo_.pop_front();
    }
    // Only possible after undo/redo moved a larger document onto the redo stack: drop the
    // redo steps furthest from the present, keeping the next one.
    while (redo_.size() > 1 && over()) {
        bytes_ -= bytes_of(redo_.front());
        redo_.erase(redo_.begin());
    }
}

}  // namespace meshedit::viewer
