// The editor's interactive edits (editor.h, Modal), each one recorded transaction: extrude,
// inset and bevel run their verb once and then only move the corners it made (a position
// amendment of the recorded change per mouse move; a bevel also derives what its corners
// carry again, from the values it kept). Bevels that touch one another rewind the recorded
// preview and run again instead, so that the session's steps replay to the same bits. Move,
// rotate and scale set the selected vertices from their positions as they were. Confirming
// commits one undo step; cancelling rolls back.

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string_view>
#include <unordered_set>

#include "meshedit/core/local_ops.h"
#include "meshedit/ops/ops.h"
#include "meshedit/viewer/editor.h"
#include "selection_steps.h"

namespace meshedit::viewer {

namespace {

// A drag of this many pixels sets a unitless amount (shrink, t) to 1.
constexpr double kPixelsPerUnit = 300.0;
// Unitless amounts stop short of 1, where the new face would be a point.
constexpr double kMaxFraction = 0.95;
constexpr double kPi = 3.14159265358979323846;

// What a bevel step will make, taken before it runs; none when the step would refuse (the
// refusal is run_steps()'s to report). \throws ops::OpError if the step names no element.
std::optional<BevelBase> bevel_base(const Mesh& mesh, const ops::Step& step) {
    const double t = step.amounts[0];
    if (step.target == ops::Target::Vertex) {
        const Vertex v = ops::named_vertex(mesh, step);
        if (is_bevel_vertex_ok(mesh, v, t)) {
            return bevel_vertex_base(mesh, v);
        }
    } else if (step.target == ops::Target::Edge) {
        const Edge e = ops::named_edge(mesh, step);
        if (is_bevel_edge_ok(mesh, e, t)) {
            return bevel_edge_base(mesh, e);
        }
    }
    return std::nullopt;
}

// Whether the bevels can be placed one by one at a new amount without running again: none
// reads a vertex, halfedge or face another one writes (its corners, its new halfedges and
// face, the faces' corners it blends in place).
bool independent(const Mesh& mesh, const std::vector<BevelBase>& bevels) {
    if (bevels.size() < 2) {
        return true;
    }
    const auto vertex = [](Vertex v) { return (std::uint64_t{1} << 62) | v.idx(); };
    const auto face = [](Face f) { return (std::uint64_t{2} << 62) | f.idx(); };
    const auto halfedge = [](Halfedge h) { return std::uint64_t{h.idx()}; };
    const auto writes = [&](const BevelBase& b) {
        std::unordered_set<std::uint64_t> out{face(b.face)};
        const std::size_t n = b.o.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Halfedge made =
                Mesh::halfedge(Edge(b.first_edge + static_cast<std::uint32_t>(i)), 0);
            out.insert({vertex(b.w[i]), halfedge(Mesh::twin(b.o[(i + 1) % n])), halfedge(made),
                        halfedge(Mesh::twin(made))});
        }
        return out;
    };
    std::vector<std::unordered_set<std::uint64_t>> written;
    for (const BevelBase& b : bevels) {
        written.push_back(writes(b));
    }
    for (std::size_t j = 0; j < bevels.size(); ++j) {
        const BevelBase& b = bevels[j];
        for (std::size_t i = 0; i < b.o.size(); ++i) {
            const std::uint64_t reads[] = {vertex(b.from[i]),       vertex(mesh.to_vertex(b.o[i])),
                                           halfedge(b.at_start[i]), halfedge(b.at_next[i]),
                                           halfedge(b.o[i]),        halfedge(Mesh::twin(b.o[i])),
                                           face(mesh.face(b.o[i]))};
            for (std::size_t k = 0; k < bevels.size(); ++k) {
                for (const std::uint64_t x : reads) {
                    if (k != j && written[k].count(x) != 0) {
                        return false;
                    }
                }
            }
        }
    }
    return true;
}

const char* verb_of(Modal kind) {
    switch (kind) {
        case Modal::Extrude:
            return "extrude";
        case Modal::Inset:
            return "inset";
        case Modal::Bevel:
            return "bevel";
        case Modal::ExtrudeRegion:
            return "extrude_region";
        case Modal::InsetRegion:
            return "inset_region";
        default:
            return nullptr;
    }
}

const char* name_of(Modal kind) {
    switch (kind) {
        case Modal::Move:
            return "move";
        case Modal::Rotate:
            return "rotate";
        case Modal::Scale:
            return "scale";
        case Modal::ExtrudeRegion:
            return "extrude region";
        case Modal::InsetRegion:
            return "inset region";
        default:
            return verb_of(kind);
    }
}

Vec3 unit_axis(int axis) {
    Vec3 a;
    a[axis] = 1.0;
    return a;
}

// "0.25,0.1" as typed, into up to two numbers; an unfinished number ("-", "") counts as 0.
std::array<double, 2> typed_numbers(const std::string& typed, std::size_t& count) {
    std::array<double, 2> out{};
    count = 0;
    std::size_t start = 0;
    while (start <= typed.size() && count < out.size()) {
        const std::size_t comma = std::min(typed.find(',', start), typed.size());
        const char* first = typed.data() + start;
        double value = 0.0;
        std::from_chars(first, typed.data() + comma, value);
        out[count++] = value;
        start = comma + 1;
    }
    return out;
}

// Rodrigues: `p` turned `radians` about the unit `axis` through `center`.
Vec3 rotated(const Vec3& p, const Vec3& center, const Vec3& axis, double radians) {
    const Vec3 v = p - center;
    const double c = std::cos(radians);
    const double s = std::sin(radians);
    return center + v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0 - c));
}

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
}

}  // namespace

Outcome Editor::begin_modal(Modal kind) {
    if (modal_.kind != Modal::None) {
        cancel_modal();
    }
    if (doc_.mode == Mode::Curve || kind == Modal::None) {
        return refused("interactive edits are for meshes");
    }
    const std::vector<ElementRef> sel = selected();
    ModalState m;
    m.kind = kind;
    if (const char* verb = verb_of(kind)) {
        std::string hint;
        const ops::Verb& v = *ops::find_verb(verb);
        if (steps_for_selection(doc_.mesh, v, sel, {}, hint).empty()) {
            return refused(hint);
        }
        m.targets = sel;
    } else {
        m.vertices = selected_vertices(doc_.mesh, sel);
        if (m.vertices.empty()) {
            return refused(std::string("select something to ") + name_of(kind) + " first");
        }
        for (const std::uint32_t v : m.vertices) {
            m.center += doc_.mesh.position(Vertex(v));
            m.base_positions.push_back(doc_.mesh.position(Vertex(v)));
        }
        m.center /= static_cast<double>(m.vertices.size());
        m.amounts = {kind == Modal::Scale ? 1.0 : 0.0, 0.0};
    }
    end_drag();
    m.base_selection = doc_.selection;
    m.base_also = doc_.also_selected;
    m.transaction = std::make_unique<Transaction>(ledger_, doc_, Transaction::Kind::Recorded);
    modal_ = std::move(m);
    return apply_modal();
}

std::optional<Outcome> Editor::modal_key(Key key, unsigned mods) {
    if (modal_.kind == Modal::None) {
        return std::nullopt;
    }
    const int k = static_cast<int>(key);
    const int digit0 = static_cast<int>(Key::Num0);
    const int keypad0 = 320;  // GLFW_KEY_KP_0
    if ((mods & (kCtrl | kAlt)) != 0) {
        return std::nullopt;
    }
    switch (key) {
        case Key::Enter:
        case Key::KeypadEnter:
            return confirm_modal();
        case Key::Escape:
            return cancel_modal();
        case Key::Backspace:
            return modal_type('\b');
        case Key::Period:
        case Key::KeypadDecimal:
            return modal_type('.');
        case Key::Minus:
        case Key::KeypadSubtract:
            return modal_type('-');
        case Key::Comma:
            return modal_type(',');
        default:
            break;
    }
    if (k >= digit0 && k <= digit0 + 9 && mods == kNoMods) {
        return modal_type(static_cast<char>('0' + k - digit0));
    }
    if (k >= keypad0 && k <= keypad0 + 9) {
        return modal_type(static_cast<char>('0' + k - keypad0));
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (key == key_of(static_cast<char>('X' + axis)) && mods == kNoMods &&
            modal_.kind >= Modal::Move) {
            return modal_axis(axis);
        }
    }
    return std::nullopt;
}

Outcome Editor::modal_input(const ModalInput& in) {
    if (modal_.kind == Modal::None) {
        return {};
    }
    modal_.last = in;
    if (!modal_.typed.empty()) {
        return {};
    }
    const double along = std::hypot(in.dx, in.dy) / kPixelsPerUnit;
    switch (modal_.kind) {
        case Modal::Extrude:
            modal_.amounts = {in.dy * in.pixel,
                              std::clamp(in.dx / kPixelsPerUnit, -kMaxFraction, kMaxFraction)};
            break;
        case Modal::Inset:
        case Modal::Bevel:
            modal_.amounts[0] = std::min(along, kMaxFraction);
            break;
        case Modal::ExtrudeRegion:
            modal_.amounts[0] = in.dy * in.pixel;
            break;
        case Modal::InsetRegion:  // a distance on the mesh, as far as the mouse went
            modal_.amounts[0] = std::hypot(in.dx, in.dy) * in.pixel;
            break;
        case Modal::Move:
            modal_.offset = in.offset;
            if (modal_.axis >= 0) {
                const Vec3 a = unit_axis(modal_.axis);
                modal_.offset = a * dot(in.offset, a);
            }
            break;
        case Modal::Rotate:
            modal_.amounts[0] = in.angle * 180.0 / kPi;
            break;
        case Modal::Scale:
            modal_.amounts[0] = in.scale;
            break;
        case Modal::None:
            break;
    }
    return apply_modal();
}

Outcome Editor::modal_type(char c) {
    if (modal_.kind == Modal::None) {
        return {};
    }
    if (c == '\b') {
        if (!modal_.typed.empty()) {
            modal_.typed.pop_back();
        }
    } else if ((c >= '0' && c <= '9') || c == '.' || c == '-' ||
               (c == ',' && modal_.kind == Modal::Extrude)) {
        modal_.typed += c;
    } else if (c != '\0') {  // '\0': re-apply what is typed (an axis changed)
        return {};
    }
    if (modal_.typed.empty()) {
        return modal_input(modal_.last);  // back to the mouse's amount
    }
    std::size_t count = 0;
    const std::array<double, 2> typed = typed_numbers(modal_.typed, count);
    switch (modal_.kind) {
        case Modal::Extrude:
            modal_.amounts = {typed[0], count > 1 ? typed[1] : 0.0};
            break;
        case Modal::Move:
            // A typed distance goes along the locked axis (X when none is), as in Blender.
            modal_.offset = unit_axis(std::max(modal_.axis, 0)) * typed[0];
            break;
        default:
            modal_.amounts[0] = typed[0];
            break;
    }
    return apply_modal();
}

Outcome Editor::modal_axis(int axis) {
    if (modal_.kind != Modal::Move && modal_.kind != Modal::Rotate && modal_.kind != Modal::Scale) {
        return {};
    }
    modal_.axis = modal_.axis == axis ? -1 : axis;
    return modal_.typed.empty() ? modal_input(modal_.last) : modal_type('\0');
}

Outcome Editor::apply_modal() {
    ModalState& m = modal_;
    m.refusal.clear();
    const bool faces = m.kind == Modal::Extrude || m.kind == Modal::Inset;
    if (faces && !m.built.empty()) {
        return move_extruded();
    }
    if (m.kind == Modal::Bevel && !m.bevelled.empty()) {
        return move_bevelled();
    }
    if ((m.kind == Modal::ExtrudeRegion && m.region_built) ||
        (m.kind == Modal::InsetRegion && m.inset_built)) {
        return move_region_top();
    }
    // Back to the document before the edit (in the time of what the last preview touched),
    // then the new preview, recorded: no copy of the mesh per mouse move.
    MeshChange::Region region = m.transaction->rewind();
    Outcome out;
    if (const char* verb = verb_of(m.kind)) {
        std::string hint;
        const ops::Verb& v = *ops::find_verb(verb);
        const std::size_t n = v.max_amounts;
        const std::vector<ops::Step> steps = steps_for_selection(
            doc_.mesh, v, m.targets, std::span<const double>(m.amounts.data(), n), hint);
        // One step at a time, so that each extrude's base is taken just before it runs.
        m.steps.clear();
        m.built.clear();
        m.bevelled.clear();
        m.region_built.reset();
        m.inset_built.reset();
        std::vector<ElementRef> made;
        for (const ops::Step& step : steps) {
            std::optional<ExtrudeBase> base;
            std::optional<BevelBase> bevel;
            try {
                if (m.kind == Modal::ExtrudeRegion || m.kind == Modal::InsetRegion) {
                    m.region = ops::named_faces(doc_.mesh, step);
                    FaceSet set(doc_.mesh.faces_size());
                    for (const Face f : m.region) {
                        set.insert(f);
                    }
                    if (m.kind == Modal::ExtrudeRegion) {
                        m.region_built = extrude_region_base(doc_.mesh, set);
                    } else {
                        m.inset_built = inset_region_base(doc_.mesh, set);
                    }
                } else if (faces) {
                    base = extrude_base(doc_.mesh, ops::named_face(doc_.mesh, step));
                } else if (m.kind == Modal::Bevel) {
                    bevel = bevel_base(doc_.mesh, step);
                }
            } catch (const ops::OpError&) {
                // an earlier step removed the element: run_steps() says so below
            }
            const StepsRun one = run_steps(doc_.mesh, {step}, verb);
            if (one.ran == 0 && m.refusal.empty()) {
                m.refusal =
                    steps.size() == 1 ? one.first_refusal : step.text + ": " + one.first_refusal;
            }
            if (one.ran == 1) {
                made.insert(made.end(), one.made.begin(), one.made.end());
                m.steps.push_back(step.text);
                if (base) {
                    m.built.push_back(std::move(*base));
                }
                if (bevel) {
                    m.bevelled.push_back(std::move(*bevel));
                }
            }
        }
        if (m.steps.empty() || !independent(doc_.mesh, m.bevelled)) {
            m.bevelled.clear();
        }
        if (m.steps.empty()) {
            m.built.clear();
            m.region_built.reset();
            m.inset_built.reset();
        } else {
            m.refusal.clear();  // some ran: a partial result, as a key on a selection gives
            select_made(doc_, made);
            ++m.topology_changes;
        }
        hover_ = {};
        out = {kTopology | kSelection, modal_status()};
    } else {
        if (m.kind == Modal::Rotate) {
            m.rotation_axis = m.axis >= 0 ? unit_axis(m.axis) : m.last.toward_viewer;
            if (!(sqrnorm(m.rotation_axis) > 0.0)) {
                m.rotation_axis = unit_axis(2);  // no view yet (tests): about Z
            }
        }
        for (std::size_t k = 0; k < m.vertices.size(); ++k) {
            const Vec3& p = m.base_positions[k];
            Vec3 q = p;
            switch (m.kind) {
                case Modal::Move:
                    q = p + m.offset;
                    break;
                case Modal::Rotate:
                    q = rotated(p, m.center, m.rotation_axis, m.amounts[0] * kPi / 180.0);
                    break;
                case Modal::Scale:
                    if (m.axis >= 0) {
                        q[m.axis] =
                            m.center[m.axis] + (p[m.axis] - m.center[m.axis]) * m.amounts[0];
                    } else {
                        q = m.center + (p - m.center) * m.amounts[0];
                    }
                    break;
                default:
                    break;
            }
            if (!std::isfinite(sqrnorm(q))) {  // as extrude: squares (normals, areas) must fit
                m.refusal = "the amount puts corners beyond the range of numbers";
                q = p;
            }
            doc_.mesh.position(Vertex(m.vertices[k])) = q;
        }
        out = {kGeometry | kSelection, modal_status()};
    }
    // What the window redraws: what the last preview changed and what this one changes.
    region.add(m.transaction->preview());
    out.region = std::move(region);
    return out;
}

// Extrude and inset after their first preview: the topology stands and only the corners it
// made move (extrude_positions(), the same code the operation places them with, so the
// session's step replays to the same bits); the recorded change takes their new values.
Outcome Editor::move_extruded() {
    ModalState& m = modal_;
    const bool extrude = m.kind == Modal::Extrude;
    const double height = extrude ? m.amounts[0] : 0.0;
    const double shrink = extrude ? m.amounts[1] : m.amounts[0];
    for (const ExtrudeBase& base : m.built) {
        if (const OpStatus ok = is_extrude_positions_ok(base, height, shrink); !ok) {
            m.refusal = std::string(ok.reason());
            if (!extrude) {  // an inset names itself
                m.refusal.replace(0, std::string_view("cannot extrude").size(), "cannot inset");
            }
            return {kSelection, modal_status()};  // the last amounts that fit stay shown
        }
    }
    for (const ExtrudeBase& base : m.built) {
        extrude_positions(doc_.mesh, base, height, shrink);
    }
    Outcome out{kGeometry | kSelection, modal_status()};
    out.region = m.transaction->amend();
    ++m.position_amendments;
    const ops::Verb& v = *ops::find_verb(verb_of(m.kind));
    m.steps.clear();
    for (const ExtrudeBase& base : m.built) {
        m.steps.push_back(ops::make_step(v.name, doc_.mesh, ElementRef::face(base.f),
                                         std::span<const double>(m.amounts.data(), v.max_amounts))
                              .text);
    }
    return out;
}

// Extrude or inset region after its first preview: the walls (the ring) stand and only the
// top (the inner border) moves (extrude_region_positions(), inset_region_positions(): the
// code the operation places it with).
Outcome Editor::move_region_top() {
    ModalState& m = modal_;
    const double height = m.amounts[0];
    const bool inset = m.kind == Modal::InsetRegion;
    if (const OpStatus ok = inset ? inset_region_positions(doc_.mesh, *m.inset_built, height)
                                  : extrude_region_positions(doc_.mesh, *m.region_built, height);
        !ok) {
        m.refusal = ok.text();
        return {kSelection, modal_status()};  // the last height that fits stays shown
    }
    Outcome out{kGeometry | kSelection, modal_status()};
    out.region = m.transaction->amend();
    ++m.position_amendments;
    m.steps = {
        ops::make_region_step(verb_of(m.kind), m.region, std::span<const double>(&height, 1)).text};
    return out;
}

// Bevel after its first preview: the faces stand; each bevel's corners go to the amount now
// and derive what they carry again (bevel_positions(), the code the operation places them
// with, so the session's step replays to the same bits).
Outcome Editor::move_bevelled() {
    ModalState& m = modal_;
    const double t = m.amounts[0];
    for (const BevelBase& base : m.bevelled) {
        if (const OpStatus ok = is_bevel_positions_ok(base, t); !ok) {
            m.refusal = ok.text();
            return {kSelection, modal_status()};  // the last amount that fits stays shown
        }
    }
    for (const BevelBase& base : m.bevelled) {
        bevel_positions(doc_.mesh, base, t);
    }
    Outcome out{kGeometry | kSelection, modal_status()};
    out.region = m.transaction->amend();
    ++m.position_amendments;
    for (std::string& text : m.steps) {
        text = text.substr(0, text.rfind(':') + 1) + number_text(t);  // "bevel:v3:" + t
    }
    return out;
}

Outcome Editor::confirm_modal() {
    if (modal_.kind == Modal::None) {
        return {};
    }
    ModalState m = std::move(modal_);
    modal_ = {};
    if (!m.refusal.empty()) {
        const std::string why = std::string(name_of(m.kind)) + " not applied: " + m.refusal;
        Outcome out{kTopology | kSelection, why, true, m.transaction->roll_back()};
        return out;
    }
    const bool positions = verb_of(m.kind) == nullptr;
    bool unchanged = positions;
    for (std::size_t k = 0; k < m.vertices.size() && unchanged; ++k) {
        unchanged = doc_.mesh.position(Vertex(m.vertices[k])) == m.base_positions[k];
    }
    if (unchanged) {
        // Bit for bit the document before (nothing moved).
        return {kSelection, "nothing moved", false, m.transaction->roll_back()};
    }
    std::vector<std::string> steps;
    if (!positions) {
        steps = m.steps;
    } else {
        for (std::size_t k = 0; k < m.vertices.size(); ++k) {
            if (doc_.mesh.position(Vertex(m.vertices[k])) != m.base_positions[k]) {
                steps.push_back(move_step(doc_.mesh, m.vertices[k]));
            }
        }
    }
    Outcome out = m.transaction->commit(
        positions ? kGeometry | kSelection : kTopology | kSelection,
        std::string(name_of(m.kind)) + " applied (Ctrl+Z undoes it)", std::move(steps));
    out.region.reset();  // the preview drew it already
    return out;
}

Outcome Editor::cancel_modal() {
    if (modal_.kind == Modal::None) {
        return {};
    }
    ModalState m = std::move(modal_);
    modal_ = {};
    hover_ = {};
    return {kTopology | kSelection, std::string(name_of(m.kind)) + " cancelled", false,
            m.transaction->roll_back()};
}

std::string Editor::modal_status() const {
    const ModalState& m = modal_;
    std::string out = name_of(m.kind);
    switch (m.kind) {
        case Modal::Extrude:
            out += " height " + number(m.amounts[0]) + ", shrink " + number(m.amounts[1]);
            break;
        case Modal::Inset:
            out += " shrink " + number(m.amounts[0]);
            break;
        case Modal::ExtrudeRegion:
            out += " height " + number(m.amounts[0]);
            break;
        case Modal::InsetRegion:
            out += " thickness " + number(m.amounts[0]);
            break;
        case Modal::Bevel:
            out += " t " + number(m.amounts[0]);
            break;
        case Modal::Move:
            out += " by (" + number(m.offset.x) + ", " + number(m.offset.y) + ", " +
                   number(m.offset.z) + ")";
            break;
        case Modal::Rotate:
            out += " " + number(m.amounts[0]) + "°";
            break;
        case Modal::Scale:
            out += " ×" + number(m.amounts[0]);
            break;
        case Modal::None:
            return {};
    }
    if (m.axis >= 0) {
        out += std::string(" along ") + "XYZ"[m.axis];
    }
    if (!m.typed.empty()) {
        out += " (typed " + m.typed + ")";
    }
    if (!m.refusal.empty()) {
        out += " — refused: " + m.refusal;
    }
    return out + " — Enter or click applies, Esc or right-click cancels";
}

}  // namespace meshedit::viewer
