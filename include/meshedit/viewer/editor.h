#pragma once
/// \file
/// The viewer's logic without a window or GL: the open document, selection, undo history,
/// display toggles and every key command. The window (src/viewer/app.cpp) turns input into
/// calls here and reads back what to redraw; unit tests drive the same calls directly.

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "meshedit/core/fields.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/stencil.h"
#include "meshedit/io/document.h"
#include "meshedit/ops/ops.h"
#include "meshedit/overlay/camera.h"
#include "meshedit/overlay/colormap.h"
#include "meshedit/overlay/op_diagram.h"
#include "meshedit/overlay/shading.h"
#include "meshedit/repair/problems.h"
#include "meshedit/selection/region_ops.h"
#include "meshedit/selection/selection.h"
#include "meshedit/viewer/bindings.h"
#include "meshedit/viewer/history.h"
#include "meshedit/viewer/outcome.h"
#include "meshedit/viewer/student_view.h"
#include "meshedit/viewer/transaction.h"

namespace meshedit::ops {
struct Step;
}
namespace meshedit::cli::grade {
struct MeshAttempt;
}

namespace meshedit::viewer {

/// What the window measured since the interactive edit began.
struct ModalInput {
    double dx = 0.0;     ///< cursor motion in pixels, right positive
    double dy = 0.0;     ///< cursor motion in pixels, up positive
    double pixel = 0.0;  ///< world size of a pixel at the selection's depth
    Vec3 offset;         ///< the cursor's world motion in the screen plane through the centre
    double angle = 0.0;  ///< radians the cursor turned about the centre on screen, anticlockwise
    double scale = 1.0;  ///< the cursor's distance from the centre on screen, now / at the start
    Vec3 toward_viewer;  ///< unit vector from the selection's centre toward the eye
};

/// The viewer's render defaults: the renderer's, with the wireframe on.
inline RenderOptions with_wireframe() {
    RenderOptions options;
    options.wireframe = true;
    return options;
}

/// A document opens with smooth shading from this many faces, flat below (Q toggles).
inline constexpr std::size_t kSmoothFromFaces = 500;

/// Display state: not part of the document, not undone.
struct ViewState {
    RenderOptions render = with_wireframe();  ///< edges visible: they are what one picks
    bool show_info = true;
    bool show_help = false;
    bool show_nets = false;  ///< Surface mode
    bool show_curve = true;  ///< Curve mode
    double t = 0.5;          ///< Curve mode: de Casteljau parameter
    int level = -1;          ///< Curve mode: levels shown (−1 = all, with B(t))
    UpAxis up = UpAxis::Y;   ///< which world axis is up on the screen (Y cycles)
    bool trackball = false;  ///< free rotation instead of the turntable (O toggles)
    /// The stencil view (Alt+W cycles): the hovered (else selected) element's subdivision
    /// stencil is drawn and spelled out in the info panel; off when empty.
    std::optional<StencilScheme> stencil;
    /// The rewiring panel (Alt+R): the last local operation's before/after diagram.
    bool show_diagram = true;
    /// A phased Loop's marks only near the selection (Alt+N; SceneContent).
    bool marks_near_selection = false;
    /// Which edges split smooth shading (the Shading panel): creases, and with Auto Smooth
    /// every edge sharper than its angle.
    NormalSplit normals;
    /// The scalar field shown (Alt+F cycles; core/fields.h), or none; its colour map
    /// (empty: the field's default) and the share of values clipped at each end.
    const FieldInfo* field = nullptr;
    std::optional<ColorMap> colormap;
    float field_clip = 0.05f;
    /// Surface mode (Shift+U): patch `patch` evaluated at (patch_u, patch_v) by de Casteljau
    /// up to step `patch_step` (SceneContent::steps); off when negative.
    int patch_step = -1;
    std::size_t patch = 0;
    double patch_u = 0.5, patch_v = 0.5;
};

/// The parameters of the whole-mesh operations the keys run (the info panel's "Global
/// operations" section sets them): not part of the document, not undone.
/// Which verbs take them is the verb table's fact (ops::kToolAmounts), not the viewer's.
class ToolSettings {
public:
    using Amounts = std::array<double, ops::kMaxAmounts>;
    /// The amounts the verb called `verb` runs with from a key: at first its defaults (D keeps
    /// half the faces; Shift+R: the mean edge length, 3 rounds). \pre the verb exists.
    Amounts& amounts(std::string_view verb);
    /// What Shift+G selects (the info panel's Selection section sets it). FacingAway takes
    /// its direction from the view when it runs (Editor::set_view_direction()).
    TraitQuery trait;

private:
    std::vector<std::pair<const ops::Verb*, Amounts>> amounts_;
};

/// The viewer's logic: one class, its members spread over files by responsibility.
///
///   editor.cpp            run() and press(): dispatch through the key table; display
///                         toggles; undo, redo, quitting; and edit(), the funnel every change
///                         of the document goes through
///   editor_files.cpp      open, save, save as, the window title
///   editor_session.cpp    the session: the steps of the edit language that made the
///                         mesh, exported for `meshedit convert --ops @FILE`
///   editor_mesh.cpp       mesh edits: the verbs of the edit language (meshedit/ops/ops.h)
///                         on the selection or the whole mesh, Delete; garbage collection
///                         (the steps a selection makes: selection_steps.cpp)
///   editor_modal.cpp      interactive edits: extrude, inset, bevel, move, rotate, scale
///   editor_curve.cpp      curve and surface commands
///   editor_student.cpp    --student: the student's functions behind F, S, L, Q and E
///   editor_selection.cpp  selection (several elements, all, a hole, framing), moving it
///                         through the connectivity, vertex drags
///   element_info.cpp      the info panel's rows
class Editor {
public:
    explicit Editor(HistoryLimits limits = {});
    /// A running operation is cancelled and waited for.
    ~Editor();
    /// Not while busy(): the operation reads the document it was started on.
    Editor(Editor&&) noexcept;
    Editor& operator=(Editor&&) noexcept;

    // ------------------------------------------------------------- files (editor_files.cpp)

    /// Opens `path` (.dae .gltf .glb .obj .off .ply .stl → Mesh, .bez → Surface, .bzc → Curve).
    /// With unsaved changes it is refused once, as quitting is (every way a document is replaced —
    /// Ctrl+O, a dropped file — comes here); the next open goes through. On failure throws IoError
    /// and leaves the current document untouched. Clears history and selection; the document
    /// is clean (not dirty). `discard_confirmed`: the user has already been told that the
    /// changes are lost (the Open chooser says so above its buttons), so no second ask.
    Outcome open(const std::filesystem::path& path, bool discard_confirmed = false);
    /// Replaces the document with an in-memory one (tests, new documents); clean.
    void set_document(Document document, std::filesystem::path path = {});

    /// Saves to path() atomically (Ctrl+S). Refused (with reason) when there is no path or
    /// the format cannot hold the document (a .bez path in Surface mode: the edited mesh is
    /// no patch set — use save as a mesh file). A format that would lose something (creases
    /// in OBJ, polygons in glTF) is refused once with what it would lose; saving again goes
    /// through and says what was not kept. IoErrors become refused outcomes.
    Outcome save();
    /// Saves to `path` and makes it the document's path (Ctrl+Shift+S after the window has
    /// asked for a path). Mesh/Surface write a mesh format; Curve writes .bzc.
    Outcome save_as(const std::filesystem::path& path);
    /// Writes the session (Document::session) to `path` as a session file that `meshedit
    /// convert IN OUT --ops @FILE` replays to the same mesh (Ctrl+Shift+E): a '#' header
    /// naming the opened file and its content_hash(), then one step per line. Mesh mode only.
    Outcome export_session(const std::filesystem::path& path);
    /// "name.dae — V 8 E 18 F 12 *" for the window title.
    std::string title() const;

    // ------------------------------------------------------------------ commands (editor.cpp)

    /// Runs one key action (the window looks it up in bindings()).
    Outcome run(Action action);
    /// Looks `key`+`mods` up in the binding table for the current mode and runs it; an
    /// unbound key returns an empty Outcome.
    Outcome press(Key key, unsigned mods);

    // ------------------------------------------------------ student code (editor_student.cpp)

    /// `--student LIB`: loads a student library (meshedit/student/student.h), in a child
    /// first, as its initialisers are student code. From then on F, S and L run the student's
    /// flip_edge, split_edge and upsample on a copy of the mesh in a forked child with a time
    /// limit, compared with the reference on the same input: the same result goes in as the
    /// usual undo step; another becomes a side by side (student_comparison()) that Esc or
    /// Ctrl+Z steps back from; a crash, an endless loop or an exception is refused, naming
    /// the function and the edge, the document untouched. Q turning smooth shading on checks
    /// vertex_normal, E in Curve mode evaluate_step. Refused (nothing loaded) when the library
    /// cannot be loaded or crashes loading. `seconds`: how long a call on one edge, and one on
    /// the whole mesh (upsample, normals), may take before it counts as an endless loop.
    Outcome load_student(const std::filesystem::path& library,
                         std::pair<double, double> seconds = {2.0, 10.0});
    bool student_mode() const;
    /// The side by side the last F, S or L made, while the document is it; null otherwise.
    const StudentComparison* student_comparison() const;

    // ---------------------------------------------------------- mesh edits (editor_mesh.cpp)

    /// Runs the edit-language verb `verb` ("flip"): a whole-mesh verb on the mesh; an element
    /// verb on every selected element it accepts (a selected halfedge stands for its edge, as
    /// in CS184), one after another in one undo step, skipping those an earlier one removed;
    /// `weld` on the two selected edges. Refused, with the first reason, when none can run.
    Outcome edit_mesh(std::string_view verb);
    /// Delete (Scotty3D's): dissolves the selected vertices and edges and makes the selected
    /// faces holes, in one undo step.
    Outcome delete_selection();

    // ------------------------------------------------- interactive edits (editor_modal.cpp)

    /// Starts an interactive edit on the selection: extrude or inset the selected faces, bevel
    /// the selected vertices or edges, move, rotate or scale the selected elements' vertices.
    /// Refused (nothing starts) when the selection has nothing it applies to.
    Outcome begin_modal(Modal kind);
    Modal modal() const { return modal_.kind; }
    /// How the interactive edit under way has previewed so far: runs of its verb (topology)
    /// and previews that only moved what the verb made (extrude, inset).
    struct ModalCounts {
        std::size_t topology_changes = 0;
        std::size_t position_amendments = 0;
    };
    ModalCounts modal_counts() const {
        return {modal_.topology_changes, modal_.position_amendments};
    }
    /// During an interactive edit, the keys it takes: Enter confirms, Esc cancels, digits
    /// . - , Backspace type the amount, X Y Z lock an axis (move, rotate, scale). nullopt
    /// for any other key (press() then confirms the edit and runs the key, as Blender does).
    std::optional<Outcome> modal_key(Key key, unsigned mods);
    /// Sets the amount from the mouse (ignored after a number was typed).
    Outcome modal_input(const ModalInput& input);
    /// A typed character: digits, '.', '-', ',' (extrude: height,shrink) or '\b' (erase); the
    /// typed number replaces the mouse's amount.
    Outcome modal_type(char c);
    /// Move, rotate, scale: lock to world axis 0, 1, 2 (X, Y, Z); the same axis again unlocks.
    Outcome modal_axis(int axis);
    /// Keeps the edit as one undo step (Enter, left click).
    Outcome confirm_modal();
    /// Puts the document back as it was before begin_modal() (Esc, right click).
    Outcome cancel_modal();
    /// "extrude height 0.25, shrink 0.1 — Enter/click to apply, Esc/right-click to cancel".
    std::string modal_status() const;

    // ------------------------------------ whole-mesh operations in the background
    // (editor_jobs.cpp)

    /// On (the window): whole-mesh verbs (subdivide, simplify, remesh, …) run on a worker
    /// thread, on a copy of the mesh, and so do reading a file to open and writing a mesh to
    /// save. The command then returns at once with kJobStarted; the document stays as it was
    /// (the window keeps drawing it, hover keeps working) and takes no edit, selection, undo
    /// or file command until the operation ends; finish_job() then puts the result in (a
    /// verb's as one undo step, exactly as the same verb run in place would). Off (the
    /// default: tests, scripts): they run where called.
    void set_background(bool on) { background_ = on; }
    /// An operation is running (or has ended and waits for finish_job()).
    bool busy() const { return job_ != nullptr; }
    /// The running operation: what it is ("simplify", "open bunny.ply"), the fraction done
    /// (0…1; −1 when it cannot tell) and the seconds since it began.
    struct JobProgress {
        std::string verb;
        double fraction = 0.0;
        double seconds = 0.0;
    };
    std::optional<JobProgress> job_progress() const;
    /// When the running operation has ended: its result put in (or its refusal, or "cancelled:
    /// nothing changed"); nullopt while it runs or when none is. The window calls it every frame.
    std::optional<Outcome> finish_job();
    /// Esc while busy: asks the operation to stop at its next progress report; the document
    /// is never touched. finish_job() reports it once the worker has stopped.
    Outcome cancel_job();
    /// Blocks until the running operation ends, then finish_job() (tests, quitting).
    std::optional<Outcome> wait_job();

    // ------------------------------------------------ selection, drags (editor_selection.cpp)

    /// Selection and hover from picking (ElementRef of the mesh, or in Curve mode a Vertex
    /// ref whose index is a control point). Invalid or deleted elements select nothing.
    /// Replaces the whole selection. A click (and a Shift+click) is how one looks at an
    /// element, so it is not an undo step; every other way of selecting below is one, with
    /// its `select` step in the session (Ledger::select()).
    Outcome select(ElementRef element);
    /// Shift+click: adds `element` to the selection as the active element, or removes it if
    /// it is selected already.
    Outcome toggle_select(ElementRef element);
    /// Ctrl+A: every live element of the active element's kind (faces if nothing is
    /// selected). Alt+A: nothing.
    Outcome select_all();
    /// Loops, rings, linked, more, less, invert, path, by trait (editor_regions.cpp,
    /// selection/selection.h).
    Outcome select_region(Command command);
    /// The direction from the view's target toward the eye (the window sets it before each
    /// key): "faces turned away" is measured from it.
    void set_view_direction(const Vec3& toward_eye) { toward_eye_ = toward_eye; }
    /// The up axis the next open() takes whatever the file (the command line's --up for the
    /// file it names); later opens take each file's own: the one remembered for it (Y
    /// remembers a choice per file content), else +Y as the file declares.
    void set_up_for_next_open(UpAxis up) { up_for_next_open_ = up; }
    /// Takes `elements` out of the selection (a brush's Shift+drag); the active element moves
    /// to the last one left.
    Outcome deselect_elements(const std::vector<ElementRef>& elements, const std::string& what);
    /// Selects `elements` (a box's; active the last), or adds them to the selection;
    /// `what` names the region in the message.
    Outcome select_elements(const std::vector<ElementRef>& elements, bool add,
                            const std::string& what);
    /// The kind a region selects: the selection's (a halfedge's is Edge), faces if none.
    ElementRef::Kind region_kind() const;
    /// A brush drag begins (ends): what it paints until it ends is one undo step.
    void begin_selection_stroke() { stroke_ = next_stroke_++; }
    void end_selection_stroke() { stroke_ = 0; }
    Outcome select_none();
    /// Selects every edge of the hole the selected boundary edge (or halfedge) borders.
    Outcome select_boundary_loop();
    /// The active element first, then the others; none deleted.
    std::vector<ElementRef> selected() const;
    /// The box around the selected elements' vertices (for framing), or none.
    std::optional<std::pair<Vec3, Vec3>> selection_bounds() const;
    void set_hover(ElementRef element) { hover_ = element; }

    /// Dragging the selected vertex (or control point): begin records one undo step,
    /// move sets its position (world space; z ignored in Curve mode), end finishes. A drag
    /// with no movement leaves no undo step and does not dirty the document. In Curve mode
    /// a `pixel` size (world units) rounds x and y to the decimal step just below it, so a
    /// dragged point saves as 0.3075, not 0.30750003457069397.
    bool begin_drag();
    Outcome drag_to(const Vec3& position, double pixel = 0.0);
    /// Ends a drag; after a move its outcome says what moved and by how much.
    Outcome end_drag();
    bool dragging() const { return dragging_; }

    // ------------------------------------------------------------- curve (editor_curve.cpp)

    /// Curve mode: t in [0, 1], clamped (the scroll wheel and [ ]).
    Outcome set_t(double t);

    // ----------------------------------------------------------------------- state

    const Document& document() const { return doc_; }
    const Mesh& mesh() const { return doc_.mesh; }
    Mode mode() const { return doc_.mode; }
    const ElementRef& selection() const { return doc_.selection; }
    const std::vector<ElementRef>& also_selected() const { return doc_.also_selected; }
    const ElementRef& hover() const { return hover_; }
    /// What the last edit rewired, when it was one local operation (F, S, C, …): its
    /// before/after diagram (render/op_diagram.h); empty after any other edit, undo or redo.
    const std::optional<OpDiagram>& last_diagram() const { return diagram_; }
    /// What the stencil view shows: the hovered element, else the selected one (none when
    /// the view is off or outside mesh modes).
    ElementRef stencil_element() const;
    ViewState& view() { return view_; }
    const ViewState& view() const { return view_; }
    ToolSettings& tools() { return tools_; }
    const ToolSettings& tools() const { return tools_; }
    /// Called during a whole-mesh operation with its verb and the fraction done (0…1, coarse
    /// intervals), so the window can show progress; it must not touch the document, which is
    /// half built at that moment.
    using ProgressHook = std::function<void(std::string_view verb, double fraction)>;
    void set_progress_hook(ProgressHook hook) { progress_hook_ = std::move(hook); }
    const History& history() const { return ledger_.history(); }
    /// The Problems panel's list (Alt+V, editor_problems.cpp): null until found for this
    /// revision of the document.
    const ProblemReport* problems() const;
    /// Whether the loader repaired the document as it is now (its cuts are listed first).
    bool load_repaired() const;
    const std::filesystem::path& path() const { return path_; }
    /// Unsaved changes: the content differs from what was last opened or saved (undoing
    /// back to the saved state makes it clean again).
    bool dirty() const { return ledger_.dirty(doc_); }
    /// Quitting with unsaved changes is refused once with a warning; this says whether the
    /// next Quit/Escape-quit will go through.
    bool quit_armed() const { return ledger_.quit_armed; }

private:
    /// What an edit did, as the function edit() runs reports it.
    struct Edited {
        unsigned changes = kNothing;  ///< Change bits
        std::string message;          ///< the status line
        /// The new selection; empty keeps the current one (remapped through garbage
        /// collection).
        std::optional<ElementRef> select;
        /// The steps of the edit language that did it, for the session.
        std::vector<std::string> steps;
        /// A local edit of one step: the step (into the list that ran), whose rewiring
        /// diagram may be drawn; null otherwise.
        const ops::Step* step = nullptr;
    };

    /// The edit funnel (editor.cpp), as Scotty3D's Model::update_mesh: `check` says why the
    /// edit cannot run (ok: it can) without touching anything; then a Transaction begins
    /// (transaction.h), `apply` changes the document, and on an exception (no memory, a file
    /// that cannot be read) the transaction rolls back and the edit is refused with the
    /// reason; otherwise deleted elements are collected (the selection remapped), the result
    /// is selected and described, and the transaction commits as one undo step.
    ///
    /// A `local` edit (one that changes what it touches: the element verbs) is a Recorded
    /// transaction (core/mesh_change.h): no snapshot, no garbage collection, so it costs what
    /// it touches at any mesh size. Any other is a Snapshot.
    Outcome edit(const std::function<OpStatus()>& check,
                 const std::function<Edited(Document&)>& apply, bool local = false);
    /// The Edited of a whole-mesh verb that ran (`step` its text): the new mesh's selection
    /// (none when it renumbered, but vertices), message and changes.
    Edited after_whole_mesh(const ops::StepResult& result, const std::string& step);
    /// What edit() does to the document's own state after a successful edit: selection,
    /// hover.
    void settle(Edited& edited);
    /// Garbage-collects the mesh, remapping the selection, when it has deleted elements;
    /// true if it did (the session then records a `compact`).
    bool compact();

    /// The interactive edit under way (kind None: none).
    struct ModalState {
        Modal kind = Modal::None;
        /// The edit's transaction: the preview shown is what it recorded so far (rewound to
        /// try other amounts, rolled back at a cancel, committed at a confirm).
        std::unique_ptr<Transaction> transaction;
        ElementRef base_selection;            ///< the selection before the edit
        std::vector<ElementRef> base_also;    ///< and the rest of it
        std::vector<Vec3> base_positions;     ///< Move, Rotate, Scale: where `vertices` were
        std::vector<ElementRef> targets;      ///< Extrude, Inset, Bevel: the elements
        std::vector<std::uint32_t> vertices;  ///< Move, Rotate, Scale: the vertices moved
        Vec3 center;                          ///< Rotate, Scale: the pivot
        /// The amounts now: extrude height and shrink; inset shrink; bevel t; rotate degrees;
        /// scale factor.
        std::array<double, 2> amounts{};
        Vec3 offset;                     ///< Move: the offset now
        Vec3 rotation_axis;              ///< Rotate: the unit axis now
        std::string typed;               ///< digits typed so far
        int axis = -1;                   ///< the locked axis, or −1
        ModalInput last;                 ///< the last mouse input
        std::string refusal;             ///< why the amounts now cannot apply, or empty
        std::vector<std::string> steps;  ///< Extrude, Inset, Bevel: the steps now, for the session
        /// Extrude, Inset: what each extrude that ran needs to move its corners again.
        std::vector<ExtrudeBase> built;
        /// Bevel: what each bevel that ran needs to place its corners again; empty when two
        /// bevels touch what the other wrote (each preview then runs them all again).
        std::vector<BevelBase> bevelled;
        /// ExtrudeRegion, InsetRegion: the region's faces and, once it ran, what moves its
        /// top (its inner border) again.
        std::vector<Face> region;
        std::optional<RegionExtrude> region_built;
        std::optional<RegionInset> inset_built;
        std::size_t topology_changes = 0;     ///< previews that ran the verb
        std::size_t position_amendments = 0;  ///< previews that only moved what it made
    };
    /// Extrude, Inset with their topology built: moves the corners to the amounts now.
    Outcome move_extruded();
    /// Bevel with its topology built: places the corners at the amount now.
    Outcome move_bevelled();
    /// Extrude region with its walls built: moves the top to the height now.
    Outcome move_region_top();
    /// Runs the modal edit with its amounts: rewinds the preview, records the new one.
    Outcome apply_modal();
    /// Undo (`forward` false) or redo, after ending a drag and cancelling an interactive edit.
    Outcome step_history(bool forward);

    /// edit_mesh() without the student's code: the verb on the selection or the whole mesh.
    Outcome run_verb(const ops::Verb& verb);
    /// The student's function for `verb` (its course_task), checked (editor_student.cpp).
    Outcome run_student(const ops::Verb& verb);
    /// Puts the side by side of a student's result that differs in as one undo step.
    Outcome show_comparison(const cli::grade::MeshAttempt& attempt, const Mesh& reference,
                            const std::string& task, const std::string& what);
    /// The side by side `shown` as one undo step, `comparison`'s elements selected.
    Outcome put_comparison(Mesh shown, StudentComparison comparison, const std::string& message,
                           unsigned changes);
    /// Q under --student turning smooth shading on: vertex_normal checked at every vertex; a
    /// difference shows the mesh twice with each one's normals.
    Outcome check_student_normals();
    /// + and - (Surface mode) under --student: "; your evaluate_patch …" at every point of
    /// the tessellation's grid on every patch.
    std::string check_student_patches();
    /// E under --student: why the next curve level is not shown, or nullopt.
    std::optional<Outcome> check_student_step(int level);
    struct StudentMode;
    std::shared_ptr<StudentMode> student_;  ///< null without --student

    /// Runs `steps` one after another through the edit funnel as one undo step and selects
    /// what they made (edit_mesh, delete_selection); refused with the first reason if none
    /// runs.
    /// `recorded` false: undone from a copy (a verb that rebuilds the mesh, ops::kRebuildsMesh).
    Outcome edit_steps(const std::vector<ops::Step>& steps, std::string_view what, bool topology,
                       bool recorded = true);
    /// Shift+V: validate(); on failure the culprit selected and framed, the broken
    /// invariant's sentence as the (refused) outcome.
    Outcome validate_mesh();
    /// " (3 selected)" when more than one element is selected.
    std::string count_text() const;
    Outcome run_navigation(Command command);
    Outcome run_selection(Command command);
    Outcome run_curve(Action action);
    Outcome run_surface(Command command);
    Outcome run_display(Action action);
    Outcome cycle_stencil();
    Outcome cycle_field();
    /// Alt+C: the next surface colour the mesh has data for (overlay/shading.h).
    Outcome cycle_surface_color();
    Outcome step_patch();
    Outcome undo();
    Outcome redo();
    Outcome quit();
    /// Writes the document to `path` (save and save as).
    Outcome write_to(const std::filesystem::path& path);
    /// After a mesh or patches were written to `path`: the document is saved, the message says
    /// what the format could not keep (`unkept`); `changes` adds to the outcome's.
    Outcome saved(const std::filesystem::path& path, const std::vector<std::string>& unkept,
                  unsigned changes);
    /// Open's second half: the read document becomes the editor's (`hash`: the file's
    /// content_hash(), empty if unknown).
    Outcome take_loaded(const std::filesystem::path& path, LoadedDocument loaded, std::string hash);

public:
    /// What a failed open says: the file's own message (an IoError names it) or the path with
    /// the reason, and which document stays open.
    std::string open_failure(const std::filesystem::path& path, const std::exception& e) const;

private:
    Document doc_;
    Ledger ledger_;
    ViewState view_;
    /// Makes `chosen` the selection (its last element active) and says so: `if_empty`, or
    /// `before` + "N faces" + `after`.
    Outcome take_selection(std::vector<ElementRef> chosen, const std::string& if_empty,
                           const std::string& before, const std::string& after);
    /// Runs `change` (a way of selecting) and, when it changed a mesh's selection, makes
    /// that one undo step with its `select` step in the session.
    Outcome recorded_selection(const std::function<Outcome()>& change);
    Outcome choose_region(Command command);  ///< select_region() before it is recorded
    Outcome choose_all();                    ///< select_all() before it is recorded
    Outcome choose_boundary_loop();          ///< select_boundary_loop() before it is recorded
    std::uint64_t stroke_ = 0;               ///< the brush drag under way, or 0
    std::uint64_t next_stroke_ = 1;
    ToolSettings tools_;
    Vec3 toward_eye_{0, 0, 1};
    std::optional<UpAxis> up_for_next_open_;
    ProgressHook progress_hook_;
    /// The operation running in the background (editor_jobs.cpp), or null.
    struct Job;
    std::unique_ptr<Job> job_;
    bool background_ = false;
    /// Starts `verb` (a whole-mesh verb) on a worker thread (set_background()).
    Outcome start_job(const ops::Verb& verb, ops::Step step);
    /// Starts `work` on a worker thread; `finish` puts its result in on the UI thread.
    /// `label` names it in the status line; `stoppable`: Esc stops it; `measured`: it reports
    /// progress.
    Outcome start_job(std::string label, bool stoppable, bool measured,
                      std::function<void(Job&)> work, std::function<Outcome()> finish);
    /// Why a command cannot run now, when an operation is running: nullopt if none is.
    std::optional<Outcome> refuse_if_busy() const;
    /// Alt+V: finds the document's problems (with the loader's repairs while the document
    /// is as loaded) and says how many.
    Outcome find_problems();
    BuildReport load_repairs_;
    std::uint64_t load_revision_ = UINT64_MAX;
    std::optional<ProblemReport> problems_;
    std::uint64_t problems_revision_ = UINT64_MAX;
    /// Remaps the selection through a garbage collection's map (compact(), finish_job()).
    void remap_selection(const GarbageCollectionMap& map);
    ElementRef hover_;
    std::optional<OpDiagram> diagram_;
    std::filesystem::path path_;
    /// The file the session starts from and its content_hash() (set by open()).
    std::filesystem::path session_source_;
    std::string session_source_hash_;
    ModalState modal_;
    bool dragging_ = false;
    /// The drag's transaction, begun at its first move (a click without a move leaves no
    /// undo step), committed when it ends.
    std::unique_ptr<Transaction> drag_;
    Vec3 drag_from_;                     ///< where the dragged point was before the drag
    std::filesystem::path lossy_armed_;  ///< the next save to this path may lose what it said
    std::uint32_t drag_index_ = 0;       ///< the vertex or control point being dragged
    /// Surface mode: revisions whose mesh is exactly tessellate(patches, density), so a
    /// density change can say whether it replaces mesh edits.
    std::unordered_set<std::uint64_t> pristine_revisions_;
};

// --------------------------------------------------------------------- info panel rows

/// The info panel's rows for an element of a mesh: kind and index, position, degree,
/// boundary and crease flags, neighbours' indices, and for a halfedge its next, twin, vertex
/// (to and from), edge and face. Empty for none.
std::vector<std::pair<std::string, std::string>> element_info(const Mesh& mesh,
                                                              const ElementRef& element);
/// The elements the rows of element_info() name, by row ("next" → that halfedge, "faces" →
/// each face; boundary gaps left out), for the inspector's links: clicking one selects it,
/// hovering highlights it. Empty for a dead element.
std::vector<std::pair<std::string, std::vector<ElementRef>>> element_links(
    const Mesh& mesh, const ElementRef& element);
/// The same for control point `index` of a curve.
std::vector<std::pair<std::string, std::string>> control_point_info(const BezierCurve& curve,
                                                                    std::uint32_t index);

}  // namespace meshedit::viewer
