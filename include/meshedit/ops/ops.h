#pragma once
/// \file
/// The edit language: named steps such as `flip:3-4`, `dissolve:v12`, `extrude:f7:0.2,0.9`,
/// `weld:0-1+5-6`, `loop:2`, written as a comma list after `--ops` (`meshedit convert`, `meshedit
/// render`, `meshedit-make-samples`) and run by the viewer for its keys, so that every program
/// edits through the same code.
///
/// One table, verbs(), holds each verb's name, argument shape, help texts and functions; the
/// parser, `--help`, the table in docs/cli.md (checked by a test) and the viewer's key help
/// all come from it. Adding an operation to the language is adding a row (see
/// docs/contributing.md).

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/local_ops.h"  // CodeNames
#include "meshedit/core/mesh.h"
#include "meshedit/core/number_text.h"  // amounts are written as number_text() writes them
#include "meshedit/core/simplify.h"     // SimplifyAttributes
#include "meshedit/core/subdivision.h"

namespace meshedit::ops {

/// What a step's argument names; a verb accepts one or more (Verb::takes, a mask of these).
enum Arg : unsigned {
    kWholeMesh = 1u << 0,  ///< no argument: `triangulate`
    kLevels = 1u << 1,     ///< `loop:K` (K from 1 to 12)
    kVertexArg = 1u << 2,  ///< `dissolve:v12`: a vertex by its index
    kEdgeArg = 1u << 3,    ///< `flip:A-B`: an edge by the indices of its two ends
    kFaceArg = 1u << 4,    ///< `extrude:f7`: a face by its index
    kEdgePair = 1u << 5,   ///< `weld:A-B+C-D`: two edges
    /// `extrude_region:f1..3+f7`: a region of faces, as indices and ranges joined by '+'
    kRegion = 1u << 6,
    /// `loop:uv=corners`, `loop:2:uv=none`: how texture coordinates are refined (the names of
    /// uv_interpolation_name(), subdivision.h), after the levels
    kUvArg = 1u << 7,
    /// `simplify:0.1:attributes=blind`: whether QEM weighs texture coordinates and colours
    /// (aware or blind, simplify.h), after the amounts
    kAttributesArg = 1u << 8,
    /// With kRegion: the list may name vertices (`select:v4..9`) or edges (`select:3-4+4-5`,
    /// each by its two ends) instead of faces, one kind per step
    kElementList = 1u << 9,
};

/// The element kind a step names.
enum class Target { None, Vertex, Edge, Face, EdgePair, Region };

struct Verb;

/// What the programs need to know of a verb beyond running it (Verb::traits), so that no
/// program compares verb names.
enum Trait : unsigned {
    kChangesTopology = 1u << 0,  ///< makes, deletes or relinks elements (crease and move do not)
    kDrawsDiagram = 1u << 1,     ///< naming an element, its rewiring diagram is drawn
    /// A whole-mesh verb whose amounts the viewer takes from its tool settings (the info
    /// panel's sliders) rather than the defaults; element verbs with amounts are drags.
    kToolAmounts = 1u << 2,
    /// Rebuilds the whole mesh (a region remesh compacts it): an editor undoes it from a copy,
    /// as a whole-mesh verb, since it cannot be recorded element by element.
    kRebuildsMesh = 1u << 3,
    kDefaultTraits = kChangesTopology | kDrawsDiagram,
};

/// The selection a list of steps carries from one step to the next (run_steps()): what the
/// `select` verbs set and a region verb's `sel` names. Elements of one kind, in order.
struct Selection {
    ElementRef::Kind kind = ElementRef::Kind::Face;
    std::vector<std::uint32_t> indices;
};

/// At most this many numbers follow a step's element (`extrude:f7:0.2,0.9`).
inline constexpr std::size_t kMaxAmounts = 3;

/// One parsed step: a verb, the element it names and its amounts.
struct Step {
    const Verb* verb = nullptr;
    Target target = Target::None;
    std::uint32_t a = 0;  ///< Edge, EdgePair: first end; Vertex, Face: the index
    std::uint32_t b = 0;  ///< Edge, EdgePair: second end
    std::uint32_t c = 0;  ///< EdgePair: the second edge's ends
    std::uint32_t d = 0;
    int levels = 1;  ///< kLevels
    /// Region: the faces as ranges of indices, first and last included (`f4` is {4, 4}).
    std::vector<std::array<std::uint32_t, 2>> region;
    /// Region: what `region` names — faces; with kElementList also vertices (ranges, as
    /// faces) or edges (each item one edge {a, b} by its two ends).
    ElementRef::Kind region_kind = ElementRef::Kind::Face;
    /// Region written `sel`: the faces of the selection run_steps() carries, filled in
    /// before the step is checked.
    bool from_selection = false;
    /// The amounts (height, shrink, t): as written, the verb's defaults after them.
    std::array<double, kMaxAmounts> amounts{};
    /// kUvArg: the texture coordinates' interpolation as written, else the core's default.
    std::optional<UvInterpolation> uv;
    /// kAttributesArg: `attributes=aware|blind` as written, else the core's default.
    std::optional<SimplifyAttributes> attributes;
    std::string text;  ///< the step as written ("flip:3-4"), for messages
};

/// What a step did.
struct StepResult {
    /// The element the step documents (flip: the edge; split: the new vertex; collapse: the
    /// survivor; crease: the edge); none for whole-mesh steps.
    ElementRef selected;
    /// A region step's other results (the rest of the extruded region), selected with it.
    std::vector<ElementRef> selected_too;
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
    std::string_view name;  ///< "flip"
    unsigned takes;         ///< what its argument may name: a mask of Arg
    /// How many amounts may follow the element (0 to kMaxAmounts), how many must, and the
    /// values of those left out.
    std::uint8_t max_amounts = 0;
    std::uint8_t min_amounts = 0;
    std::array<double, kMaxAmounts> defaults{};
    std::string_view syntax;  ///< "flip:A-B"
    std::string_view help;    ///< for `--help` and docs/cli.md
    /// For the viewer's key table, as the step applies to the selection or the whole mesh
    /// ("flip the selected edge").
    std::string_view key_help;
    /// Why the step cannot run on `mesh` ("cannot flip: boundary edge"), or ok. Pure.
    /// \throws OpError (not a refusal) if the step names an element the mesh does not have.
    OpStatus (*check)(const Mesh& mesh, const Step& step);
    /// Runs the step. \pre check() returned ok.
    StepResult (*run)(Mesh& mesh, const Step& step, const RunOptions& options);
    /// For subdivision verbs (kLevels): what K levels would make and whether they fit, asked
    /// for a whole list before any step runs; null for the others.
    SubdivisionPlan (*plan)(const Mesh& mesh, int levels) = nullptr;
    /// Whether the verb's count is of phases of a level (`loop_step:N`: four phases make one
    /// level) rather than of levels, for planning a list.
    bool phases = false;
    /// A mask of Trait.
    unsigned traits = kDefaultTraits;
    /// Whose names its rewiring diagram gives the elements, and what region it draws.
    CodeNames names = CodeNames::ByIndex;
    /// For the selection verbs (`select_loop:3-4`): the selection after the step, from the
    /// one before; they leave the mesh as it is. Null for the others.
    Selection (*select)(const Mesh& mesh, const Step& step, const Selection& now) = nullptr;
    /// The course's function that does what the verb does on one element or the whole mesh
    /// (meshedit/student/student.h: "flip_edge", "split_edge", "upsample"), which the viewer
    /// calls instead under `--student`; empty for the others.
    std::string_view course_task = {};

    bool accepts(Target target) const;
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
/// Parses a comma list. \throws SyntaxError naming the offending item; BudgetError
/// (core/budget.h) when the steps it may hold would not fit the memory budget.
std::vector<Step> parse(std::string_view list);
/// The bytes parsing `text` (a comma list or a session) may take at most, about 150 per step:
/// what parse() and parse_session() check against the memory budget before parsing.
double parse_cost(std::string_view text);

/// The steps of a session file (`--ops @FILE`; what the viewer's Ctrl+Shift+E exports): lines
/// that start with '#' are comments (the header), every other line holds one step or a comma
/// list; blank lines are skipped. \throws SyntaxError naming the line; BudgetError as parse().
std::vector<Step> parse_session(std::string_view text);
/// A session file: each `header` line after "# ", then one step per line.
std::string session_text(const std::vector<std::string>& header,
                         const std::vector<std::string>& steps);
/// The value of a header line "# KEY: VALUE" of a session file, if it has one.
std::optional<std::string> session_header_value(std::string_view text, std::string_view key);

/// The step `verb` on `target` (a vertex, edge or face of `mesh`; none for whole-mesh verbs;
/// `second` the other edge of a weld) with `amounts` (fewer than the verb takes: its
/// defaults), written as the language writes it, so that its text parses back to the same
/// step. \pre `verb` exists and accepts the target.
Step make_step(std::string_view verb, const Mesh& mesh, const ElementRef& target = {},
               std::span<const double> amounts = {}, const ElementRef& second = {});

/// The region step `verb` on `faces` (live faces of `mesh`, any order) with `amounts`, its
/// faces written as sorted ranges ("extrude_region:f4..6+f9:0.5"). \pre `verb` takes kRegion.
Step make_region_step(std::string_view verb, const std::vector<Face>& faces,
                      std::span<const double> amounts = {});

/// The `select` step that makes `selected` the selection (a session records a region
/// selection with it): its elements of the last one's kind (a halfedge stands for its edge)
/// as sorted ranges, `select:f4..6+f9`, `select:v2..3`, `select:3-4+4-5`; `select_none` when
/// it holds none.
std::string select_step_text(const Mesh& mesh, const std::vector<ElementRef>& selected);

/// An element named in text, the one grammar of `--ops` steps, `--select` and the viewer's
/// session: `v12` (a vertex), `3-4` (the edge between two vertices), `h3-4` (the halfedge
/// 3 -> 4), `f7` (a face); the older `--select` spellings `v:12`, `e:3-4`, `h:3-4`, `f:7` are
/// accepted too. Indices only: whether the mesh has them is the caller's question.
struct ElementName {
    ElementRef::Kind kind = ElementRef::Kind::None;
    std::uint32_t a = 0;  ///< the vertex or face; an edge's or halfedge's first end
    std::uint32_t b = 0;  ///< the second end
};
/// Parses one element name; nullopt when `text` is none.
std::optional<ElementName> parse_element_name(std::string_view text);

/// The elements a step names. \throws OpError (not a refusal) if the mesh has no such
/// element (a vertex or face index out of range or deleted, no edge between two vertices).
Vertex named_vertex(const Mesh& mesh, const Step& step);
Edge named_edge(const Mesh& mesh, const Step& step);
Face named_face(const Mesh& mesh, const Step& step);
/// The faces a Region step names, as a set over `mesh`'s face indices.
/// \throws OpError (not a refusal) if one is out of range or deleted.
std::vector<Face> named_faces(const Mesh& mesh, const Step& step);
/// A weld's second edge (C-D).
Edge named_second_edge(const Mesh& mesh, const Step& step);
/// The element a step names (a weld: its first edge); none for whole-mesh steps.
ElementRef named_element(const Mesh& mesh, const Step& step);

/// Whether `step` gets a rewiring diagram (the viewer's Rewiring panel, `meshedit render
/// --op-diagram`): a verb with kDrawsDiagram on an element.
bool draws_diagram(const Step& step);

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

/// What a list of steps does when one is refused: stop there (the CLI, the headless
/// renderer, Python: the list is a program) or go on with the next (the viewer on a
/// selection: each selected element is tried).
enum class OnRefusal { Stop, Skip };

/// What running a list did.
struct StepsRun {
    Selection selection;  ///< the selection after the last step
    std::size_t ran = 0;
    std::size_t refused = 0;  ///< Skip: refused, or naming an element an earlier step removed
    /// Skip: "dissolve:v3: cannot dissolve: …" (a list of one: just the reason).
    std::string first_refusal;
    std::vector<const Step*> done;  ///< the steps that ran, in order (into the list run)
    std::vector<ElementRef> made;   ///< each one's StepResult::selected, where it has one
    ElementRef last;                ///< what the last step that ran selected
    std::string last_message;       ///< its StepResult::message
};

/// Runs `steps` in order, each step's predicate once: the one runner of the viewer, the CLI,
/// the headless renderer and Python. Vertex indices name the mesh as it is before each step:
/// a split's new vertex is appended (index = vertices_size() before the split), a collapse
/// deletes the larger end without renumbering, and the subdivision verbs renumber as
/// loop_subdivide() and quad_subdivide() document (old vertices keep their indices). Their
/// levels are checked against the verbs' plans (plan_loop(), plan_quad_subdivision()) before
/// any step runs (\throws OpError). With OnRefusal::Stop a refused step throws OpError
/// ("<step> refused: <reason>"; not a refusal when it names an element the mesh does not
/// have); steps before it stay applied (callers write nothing on error).
StepsRun run_steps(Mesh& mesh, const std::vector<Step>& steps, OnRefusal on_refusal,
                   const ApplyOptions& options = {});
/// run_steps() with OnRefusal::Stop. \return what the last step selected (its
/// StepResult::selected): the result to show.
ElementRef apply_steps(Mesh& mesh, const std::vector<Step>& steps,
                       const ApplyOptions& options = {});

/// "flip:A-B split:A-B …" for a one-line usage.
std::string syntax_list();
/// The verbs as `--help` lines: two-space indent, syntax, help.
std::string help_lines();
/// The verbs as the Markdown table of docs/cli.md.
std::string markdown_table();

}  // namespace meshedit::ops
