#pragma once
/// \file
/// The editor's random command sweep with a model of undo and redo (see undo_sweep_test.cpp):
/// shared by the viewer tests (1,000 commands) and the long soak (10,000).

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/viewer/editor.h"
#include "support/mesh_compare.h"

namespace meshedit::viewer {

using Kind = ElementRef::Kind;

inline bool same_ref(const ElementRef& a, const ElementRef& b) {
    return a.kind == b.kind && (a.kind == Kind::None || a.index == b.index);
}

inline ::testing::AssertionResult same_document(const Document& actual, const Document& expected) {
    if (auto r = test::identical(actual.mesh, expected.mesh); !r) {
        return r;
    }
    if (!same_ref(actual.selection, expected.selection)) {
        return ::testing::AssertionFailure() << "selection differs";
    }
    if (actual.revision != expected.revision) {
        return ::testing::AssertionFailure()
               << "revision " << actual.revision << ", expected " << expected.revision;
    }
    return ::testing::AssertionSuccess();
}

/// The direct core operation on a copy, as the editor must have done it on the selected
/// element `s` (a halfedge standing for its edge) with `amounts`.
inline Mesh apply_directly(const Mesh& before, std::string_view verb, const ElementRef& s,
                           std::array<double, 2> amounts = {}) {
    Mesh m = before;
    const bool edge = s.kind == Kind::Edge || s.kind == Kind::Halfedge;
    const Edge e = !edge                  ? Edge()
                   : s.kind == Kind::Edge ? Edge(s.index)
                                          : Mesh::edge(Halfedge(s.index));
    const Vertex v = s.kind == Kind::Vertex ? Vertex(s.index) : Vertex();
    const Face f = s.kind == Kind::Face ? Face(s.index) : Face();
    if (verb == "flip") {
        EXPECT_TRUE(flip(m, e));
    } else if (verb == "split") {
        EXPECT_TRUE(split(m, e));
    } else if (verb == "bisect") {
        EXPECT_TRUE(bisect(m, e));
    } else if (verb == "collapse") {
        EXPECT_TRUE(f.is_valid() ? collapse_face(m, f).ok() : collapse(m, e).ok());
    } else if (verb == "dissolve") {
        EXPECT_TRUE(v.is_valid() ? dissolve_vertex(m, v).ok() : dissolve_edge(m, e).ok());
    } else if (verb == "make_boundary") {
        EXPECT_TRUE(make_boundary(m, f));
    } else if (verb == "poke") {
        EXPECT_TRUE(poke(m, f));
    } else if (verb == "extrude") {
        EXPECT_TRUE(extrude_face(m, f, amounts[0], amounts[1]));
    } else if (verb == "inset") {
        EXPECT_TRUE(inset_face(m, f, amounts[0]));
    } else if (verb == "bevel") {
        EXPECT_TRUE(v.is_valid() ? bevel_vertex(m, v, amounts[0]).ok()
                                 : bevel_edge(m, e, amounts[0]).ok());
    } else if (verb == "triangulate") {
        triangulate(m);
    } else if (verb == "flip_orientation") {
        flip_orientation(m);
    } else if (verb == "crease") {
        auto crease = m.property<Edge, std::uint8_t>(kCreaseProperty, 0);
        crease[e] = crease[e] != 0 ? 0 : 1;
    } else if (verb == "loop") {
        loop_subdivide(m);
    } else if (verb == "loop_step") {
        loop_step(m);
    } else {
        ADD_FAILURE() << "not an edit: " << verb;
    }
    // Only whole-mesh edits collect garbage; local ones leave tombstones (indices stay).
    const bool whole = verb == "triangulate" || verb == "flip_orientation" || verb == "loop" ||
                       verb == "loop_step";
    if (whole && m.has_garbage()) {
        m.garbage_collection();
    }
    return m;
}

class Sweep {
public:
    explicit Sweep(std::uint32_t seed) : ed_(limits()), rng_(seed) {
        Document start;
        start.mesh = shapes::torus(6, 4);  // 24 vertices, 48 triangles, genus 1
        ed_.set_document(std::move(start));
    }

    // Nothing may be trimmed here: the model keeps every state, so must the editor.
    static HistoryLimits limits() {
        return {std::numeric_limits<std::size_t>::max(), std::numeric_limits<std::size_t>::max()};
    }

    void run(int commands) {
        for (step_ = 0; step_ < commands; ++step_) {
            one_command();
            if (::testing::Test::HasFatalFailure()) {
                return;
            }
            ASSERT_VALID(ed_.mesh()) << "after command " << step_;
            ASSERT_EQ(ed_.history().undo_steps(), undo_.size()) << "after command " << step_;
            ASSERT_EQ(ed_.history().redo_steps(), redo_.size()) << "after command " << step_;
        }
    }

    /// Undoes to the start, checking every state, then redoes to the end of the redo stack.
    void unwind_and_replay() {
        // Every state in order: the undo stack, the present, then what redo would bring.
        std::vector<Document> chain = undo_;
        chain.push_back(ed_.document());
        chain.insert(chain.end(), redo_.rbegin(), redo_.rend());
        for (std::size_t k = undo_.size(); k-- > 0;) {
            ASSERT_FALSE(ed_.run({Command::Undo}).refused);
            ASSERT_TRUE(same_document(ed_.document(), chain[k])) << "undo to state " << k;
            ASSERT_VALID(ed_.mesh());
        }
        EXPECT_TRUE(ed_.run({Command::Undo}).refused);
        EXPECT_FALSE(ed_.dirty()) << "back at the opened document";
        for (std::size_t k = 1; k < chain.size(); ++k) {
            ASSERT_FALSE(ed_.run({Command::Redo}).refused);
            ASSERT_TRUE(same_document(ed_.document(), chain[k])) << "redo to state " << k;
        }
        EXPECT_TRUE(ed_.run({Command::Redo}).refused);
    }

    const Editor& editor() const { return ed_; }
    std::size_t edits() const { return edits_; }
    std::size_t refusals() const { return refusals_; }
    std::size_t undos() const { return undos_; }
    std::size_t loops() const { return loops_; }
    std::size_t drags() const { return drags_; }
    std::size_t modals() const { return modals_; }

private:
    int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

    /// A random live element (or, now and then, an out-of-range one the editor must reject).
    void random_select() {
        const Mesh& m = ed_.mesh();
        const int kind = uniform(0, 3);
        std::size_t size = kind == 0   ? m.vertices_size()
                           : kind == 1 ? m.edges_size()
                           : kind == 2 ? m.halfedges_size()
                                       : m.faces_size();
        const bool out_of_range = uniform(0, 49) == 0;
        const auto index = static_cast<std::uint32_t>(
            out_of_range ? size + 3
                         : static_cast<std::size_t>(uniform(0, static_cast<int>(size) - 1)));
        const Kind kinds[] = {Kind::Vertex, Kind::Edge, Kind::Halfedge, Kind::Face};
        const ElementRef ref{kinds[kind], index};
        const bool deleted = !out_of_range && !is_live(m, ref);  // a tombstone
        ed_.select(ref);
        if (out_of_range || deleted) {
            ASSERT_TRUE(ed_.selection().is_none());
        } else {
            ASSERT_TRUE(same_ref(ed_.selection(), ref));
        }
    }

    void record_edit(Document before) {
        undo_.push_back(std::move(before));
        redo_.clear();
        ++edits_;
    }

    void mesh_op(std::string_view verb) {
        const Document before = ed_.document();
        const ElementRef s = before.selection;
        const Outcome out = ed_.run(edit(verb));
        if (out.refused) {
            ++refusals_;
            ASSERT_FALSE(out.message.empty());
            ASSERT_TRUE(same_document(ed_.document(), before)) << "refused: " << out.message;
            return;
        }
        ASSERT_NE(ed_.document().revision, before.revision);
        ASSERT_TRUE(test::identical(ed_.mesh(), apply_directly(before.mesh, verb, s)))
            << verb << " at step " << step_;
        record_edit(before);
        loops_ += verb == "loop";
    }

    /// An interactive edit on the selection: mouse motion, then a typed amount; confirmed
    /// (one undo step equal to the core operation with the typed amount) or cancelled (the
    /// document bit for bit as before).
    void modal_op() {
        random_select();
        const Document before = ed_.document();
        const ElementRef s = before.selection;
        const int which = uniform(0, 2);
        const Modal kinds[] = {Modal::Extrude, Modal::Inset, Modal::Bevel};
        const char* verbs[] = {"extrude", "inset", "bevel"};
        const Outcome began = ed_.begin_modal(kinds[which]);
        if (began.refused) {
            ++refusals_;
            ASSERT_TRUE(same_document(ed_.document(), before)) << began.message;
            return;
        }
        ModalInput in;
        in.dx = uniform(-200, 200);
        in.dy = uniform(-200, 200);
        in.pixel = 0.01;
        ed_.modal_input(in);
        const std::string typed[] = {"0.25", "0.1", "0.5"};
        const std::string amount = typed[uniform(0, 2)];
        for (char c : amount) {
            ed_.modal_type(c);
        }
        std::array<double, 2> amounts{std::stod(amount), 0.0};
        if (which == 0 && uniform(0, 1) == 0) {
            for (char c : std::string(",0.5")) {
                ed_.modal_type(c);
            }
            amounts[1] = 0.5;
        }
        if (uniform(0, 3) == 0) {
            ed_.cancel_modal();
            ASSERT_TRUE(same_document(ed_.document(), before)) << "cancelled at step " << step_;
            return;
        }
        const Outcome out = ed_.confirm_modal();
        if (out.refused) {
            ++refusals_;
            ASSERT_TRUE(same_document(ed_.document(), before)) << out.message;
            return;
        }
        ASSERT_TRUE(
            test::identical(ed_.mesh(), apply_directly(before.mesh, verbs[which], s, amounts)))
            << verbs[which] << " at step " << step_;
        record_edit(before);
        ++modals_;
    }

    void drag() {
        const Mesh& m = ed_.mesh();
        auto v =
            Vertex(static_cast<std::uint32_t>(uniform(0, static_cast<int>(m.vertices_size()) - 1)));
        while (m.is_deleted(v)) {  // tombstones of local edits
            v = Vertex(
                static_cast<std::uint32_t>(uniform(0, static_cast<int>(m.vertices_size()) - 1)));
        }
        ed_.select(ElementRef::vertex(v));
        const Document before = ed_.document();
        ASSERT_TRUE(ed_.begin_drag());
        const int moves = uniform(0, 3);  // 0: a click without a move
        Vec3 p = m.position(v);
        for (int i = 0; i < moves; ++i) {
            p += Vec3{0.01 * uniform(-5, 5), 0.01 * uniform(-5, 5), 0.01 * uniform(-5, 5)};
            ed_.drag_to(p);
        }
        ed_.end_drag();
        if (ed_.document().revision == before.revision) {
            ASSERT_TRUE(same_document(ed_.document(), before));
            return;
        }
        ASSERT_GE(moves, 1);
        Mesh expected = before.mesh;
        expected.position(v) = p;
        ASSERT_TRUE(test::identical(ed_.mesh(), expected));
        record_edit(before);
        ++drags_;
    }

    void navigate() {
        const Command commands[] = {Command::Next,     Command::Twin,   Command::ToHalfedge,
                                    Command::ToVertex, Command::ToEdge, Command::ToFace};
        const Document before = ed_.document();
        ed_.run({commands[uniform(0, 5)]});
        ASSERT_TRUE(test::identical(ed_.mesh(), before.mesh));
        ASSERT_EQ(ed_.document().revision, before.revision);
        ASSERT_TRUE(ed_.selection().is_none() || is_live(ed_.mesh(), ed_.selection()));
    }

    void undo() {
        const Outcome out = ed_.run({Command::Undo});
        if (undo_.empty()) {
            ASSERT_TRUE(out.refused);
            return;
        }
        ASSERT_FALSE(out.refused);
        redo_.push_back(current_before_undo_redo_);
        ASSERT_TRUE(same_document(ed_.document(), undo_.back())) << "undo at step " << step_;
        undo_.pop_back();
        ++undos_;
    }

    void redo() {
        const Outcome out = ed_.run({Command::Redo});
        if (redo_.empty()) {
            ASSERT_TRUE(out.refused);
            return;
        }
        ASSERT_FALSE(out.refused);
        undo_.push_back(current_before_undo_redo_);
        ASSERT_TRUE(same_document(ed_.document(), redo_.back())) << "redo at step " << step_;
        redo_.pop_back();
    }

    void one_command() {
        const int roll = uniform(0, 99);
        if (roll < 30) {
            random_select();
            const std::string_view ops[] = {"flip", "split", "collapse", "crease"};
            // Collapse a little more often than split, so the mesh does not only grow.
            const int pick = uniform(0, 9);
            mesh_op(ops[pick < 3 ? 0 : pick < 5 ? 1 : pick < 9 ? 2 : 3]);
        } else if (roll < 36) {
            random_select();
            const std::string_view ops[] = {"bisect",      "dissolve",    "make_boundary",   "poke",
                                            "triangulate", "triangulate", "flip_orientation"};
            mesh_op(ops[uniform(0, 6)]);
        } else if (roll < 40) {
            modal_op();
        } else if (roll < 44) {
            if (ed_.mesh().n_faces() < 200) {
                mesh_op(roll < 42 ? "loop" : "loop_step");
            }
        } else if (roll < 52) {
            drag();
        } else if (roll < 62) {
            random_select();
            navigate();
        } else if (roll < 80) {
            current_before_undo_redo_ = ed_.document();
            undo();
        } else if (roll < 92) {
            current_before_undo_redo_ = ed_.document();
            redo();
        } else {
            random_select();
        }
    }

    Editor ed_;
    std::mt19937 rng_;
    std::vector<Document> undo_;  ///< model: documents before each undoable edit
    std::vector<Document> redo_;  ///< model: documents undone, most recent last
    Document current_before_undo_redo_;
    int step_ = 0;
    std::size_t edits_ = 0;
    std::size_t refusals_ = 0;
    std::size_t undos_ = 0;
    std::size_t loops_ = 0;
    std::size_t drags_ = 0;
    std::size_t modals_ = 0;
};

}  // namespace meshedit::viewer
