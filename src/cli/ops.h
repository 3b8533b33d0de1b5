#pragma once
/// \file
/// The `--ops` edit language of `meshedit convert` (docs/cli.md): a comma list of
/// `flip:A-B`, `split:A-B`, `collapse:A-B`, `crease:A-B`, `loop`, `loop:K`, `triangulate`,
/// applied in order. Kept in its own library so that `meshedit-make-samples` produces the
/// reference files through exactly the code path the CLI uses.

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/core/subdivision.h"

namespace meshedit::cli {

/// One parsed operation.
struct Op {
    enum class Kind { Flip, Split, Collapse, Crease, Loop, Triangulate };
    Kind kind = Kind::Loop;
    std::uint32_t a = 0;  ///< first endpoint (edge ops)
    std::uint32_t b = 0;  ///< second endpoint (edge ops)
    int levels = 1;       ///< Loop levels (loop:K)
    std::string text;     ///< the op as the user wrote it, for messages
};

/// The list is malformed: an unknown op name, a bad index or count. Bad usage (exit 2).
class OpSyntaxError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// An op could not run. `refused()` is true when the mesh operation itself said no (a
/// failure, exit 1); false when the op names an element the mesh does not have (bad
/// input, exit 2). The message names the op and the reason.
class OpError : public std::runtime_error {
public:
    OpError(const std::string& message, bool refused)
        : std::runtime_error(message), refused_(refused) {}
    bool refused() const { return refused_; }

private:
    bool refused_;
};

/// Parses a comma list. \throws OpSyntaxError naming the offending item.
std::vector<Op> parse_ops(std::string_view list);

/// How ops run.
struct ApplyOptions {
    LoopWeights weights = LoopWeights::Warren;
    /// Overall fraction done (0…1) across the whole list; may be empty.
    std::function<void(double)> progress;
    /// Receives one sentence per thing the user should hear ("loop: triangulated 6 faces
    /// first"); may be empty.
    std::function<void(const std::string&)> notice;
};

/// Applies `ops` in order. Vertex indices name the mesh as it is before each op: a split's
/// new vertex is appended (index = vertices_size() before the split), a collapse deletes
/// the larger endpoint without renumbering, and loop renumbers as loop_subdivide()
/// documents (old vertices keep their indices). \throws OpError; ops before the failing
/// one stay applied (callers write nothing on error).
void apply_ops(Mesh& mesh, const std::vector<Op>& ops, const ApplyOptions& options = {});

}  // namespace meshedit::cli
