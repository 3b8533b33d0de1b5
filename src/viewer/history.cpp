// Undo/redo by whole-document snapshots (see history.h).

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

void History::push(Document before) {
    for (const Document& d : redo_) {
        bytes_ -= d.bytes();
    }
    redo_.clear();
    bytes_ += before.bytes();
    undo_.push_back(std::move(before));
    trim();
}

bool History::undo(Document& current) {
    if (undo_.empty()) {
        return false;
    }
    Document previous = std::move(undo_.back());
    undo_.pop_back();
    bytes_ -= previous.bytes();
    bytes_ += current.bytes();
    redo_.push_back(std::move(current));
    current = std::move(previous);
    trim();
    return true;
}

bool History::redo(Document& current) {
    if (redo_.empty()) {
        return false;
    }
    Document next = std::move(redo_.back());
    redo_.pop_back();
    bytes_ -= next.bytes();
    bytes_ += current.bytes();
    undo_.push_back(std::move(current));
    current = std::move(next);
    trim();
    return true;
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
        bytes_ -= undo_.front().bytes();
        undo_.pop_front();
    }
    // Only possible after undo/redo moved a larger document onto the redo stack: drop the
    // redo steps furthest from the present, keeping the next one.
    while (redo_.size() > 1 && over()) {
        bytes_ -= redo_.front().bytes();
        redo_.erase(redo_.begin());
    }
}

}  // namespace meshedit::viewer
