#pragma once
/// \file
/// The edit language: named steps such as `flip:3-4`, `split:0-1`, `loop:2`, written as a
/// comma list after `--ops` (`meshedit convert`, `meshedit render`, `meshedit-make-samples`)
/// and run by the viewer for its keys, so that every program edits through the same code.
///
/// One table, verbs(), holds each verb's name, argument shape, help texts and functions; the
/// parser, `--help`, the table in docs/cli.md (checked by a test) and the viewer's key help
/// all come from it. Adding an operation to the language is adding a row (see
/// docs/contributing.md).

#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/subdivision.h"

namespace meshedit::ops {

/// How a verb's argument is written.
enum class Shape {
    None,    ///< `triangulate`
    Edge,    ///< `flip:A-B`: an edge, by the vertex indices of its two ends
    Levels,  ///< `loop` or `loop:K` (K from 1 to 12)
};

struct Verb;

/// One parsed step: a verb and its argument.
struct Step {
    const Verb* verb = nullptr;
    std::uint32_t a = 0;  ///< Shape::Edge: first end
    std::uint32_t b = 0;  ///< Shape::Edge: second end
    int levels = 1;       ///< Shape::Levels
    std::string text;     ///< the step as written ("flip:3-4"), for messages
};

/// What a step did.
struct StepResult {
    /// The element the step documents (flip: the edge; split: the new vertex; collapse: the
    /// survivor; crease: the edge); none for whole-mesh steps.
    ElementRef selected;
    /// Whole-mesh steps that renumber edges, halfedges and faces (vertices keep their
    /// indices): a selected vertex survives them, nothing else does.
    bool renumbers = false;
    /// False when only attributes changed (a crease mark), not elements or positions.
    bool topology = true;
    /// A sentence for a status line ("flipped edge 5 (2–7)").
    std::string message;
    /// What the user should also hear ("triangulated 6 non-triangle faces first").
    std::vector<std::string> notices;
};

/// How a step runs.
struct RunOptions {
    LoopWeights weights = LoopWeights::Warren;
    /// Fraction of this step done (0…1); may be empty.
    std::function<void(double)> progress;
};

/// A row of the table.
struct Verb {
    std::string_view name;    ///< "flip"
    Shape shape;              ///< how its argument is written
    std::string_view syntax;  ///< "flip:A-B"
    std::string_view help;    ///< for `--help` and docs/cli.md
    /// For the viewer's key table, as the step applies to the selection or the whole mesh
    /// ("flip the selected edge").
    std::string_view key_help;
    /// Why the step cannot run on `mesh` ("cannot flip: boundary edge"), or empty. Pure.
    /// \throws OpError (not a refusal) if the step names an element the mesh does not have.
    std::string (*check)(const Mesh& mesh, const Step& step);
    /// Runs the step. \pre check() returned empty.
    StepResult (*run)(Mesh& mesh, const Step& step, const RunOptions& options);
};

/// Every verb, in the order `--help` and the docs list them.
std::span<const Verb> verbs();
/// The verb called `name`, or nullptr.
const Verb* find_verb(std::string_view name);

/// The list is malformed: an unknown verb, a bad index or count, an empty item. Bad usage.
class SyntaxError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A step could not run. `refused()` is true when the mesh operation itself said no (a
/// failure, exit status 1); false when the step names an element the mesh does not have
/// (bad input, exit status 2). The message names the step and the reason.
class OpError : public std::runtime_error {
public:
    OpError(const std::string& message, bool refused)
        : std::runtime_error(message), refused_(refused) {}
    bool refused() const { return refused_; }

private:
    bool refused_;
};

/// Parses one step ("flip:3-4"). \throws SyntaxError naming it.
Step parse_step(std::string_view text);
/// Parses a comma list. \throws SyntaxError naming the offending item.
std::vector<Step> parse(std::string_view list);

/// The step `verb` on edge `e` of `mesh` (named by its ends, as the language names it), or
/// on the whole mesh for verbs of other shapes. \pre `verb` exists.
Step make_step(std::string_view verb, const Mesh& mesh, Edge e = Edge());

/// The edge a Shape::Edge step names. \throws OpError (not a refusal) if there is none.
Edge named_edge(const Mesh& mesh, const Step& step);

/// Runs one step: check(), then run(). \throws OpError with "<step> refused: <reason>".
StepResult run_step(Mesh& mesh, const Step& step, const RunOptions& options = {});

/// How a list runs.
struct ApplyOptions {
    LoopWeights weights = LoopWeights::Warren;
    /// Overall fraction done (0…1) across the whole list; may be empty.
    std::function<void(double)> progress;
    /// Receives each notice, prefixed with its step ("loop: triangulated 6 faces first").
    std::function<void(const std::string&)> notice;
};

/// Runs `steps` in order. Vertex indices name the mesh as it is before each step: a split's
/// new vertex is appended (index = vertices_size() before the split), a collapse deletes the
/// larger end without renumbering, and loop renumbers as loop_subdivide() documents (old
/// vertices keep their indices). Loop levels are checked against plan_loop() before any step
/// runs. \throws OpError; steps before the failing one stay applied (callers write nothing
/// on error).
void apply_steps(Mesh& mesh, const std::vector<Step>& steps, const ApplyOptions& options = {});

/// "flip:A-B split:A-B …" for a one-line usage.
std::string syntax_list();
/// The verbs as `--help` lines: two-space indent, syntax, help.
std::string help_lines();
/// The verbs as the Markdown table of docs/cli.md.
std::string markdown_table();

}  // namespace meshedit::ops
