#pragma once
/// \file
/// Undo/redo by whole-document snapshots, bounded in bytes and in steps.
///
/// A snapshot is the document before an edit (mesh, patches, curve, selection), so undo is
/// exact bit for bit and every edit — local op, Loop, crease, drag, retessellation — is
/// undone the same way. Memory: the stacks together hold at most `max_bytes` (default
/// 512 MiB) and `max_steps` (default 200) snapshots; the oldest undo steps go first. At
/// least one undo step is always kept, so a document larger than the budget still undoes
/// its last edit (then the bound is one snapshot).

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "meshedit/viewer/document.h"

namespace meshedit::viewer {

struct HistoryLimits {
    std::size_t max_bytes = std::size_t{512} << 20;
    std::size_t max_steps = 200;
};

class History {
public:
    explicit History(HistoryLimits limits = {}) : limits_(limits) {}

    /// Records `before` (the document as it was before an edit) and clears the redo stack.
    void push(Document before);
    /// Swaps `current` with the last undo step (current goes to redo). False if none.
    bool undo(Document& current);
    /// Swaps `current` with the last redo step. False if none.
    bool redo(Document& current);
    void clear();

    std::size_t undo_steps() const { return undo_.size(); }
    std::size_t redo_steps() const { return redo_.size(); }
    std::size_t bytes() const { return bytes_; }
    const HistoryLimits& limits() const { return limits_; }

private:
    void trim();

    HistoryLimits limits_;
    std::deque<Document> undo_;
    std::vector<Document> redo_;
    std::size_t bytes_ = 0;  ///< of undo_ and redo_ together
};

}  // namespace meshedit::viewer
