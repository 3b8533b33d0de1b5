#pragma once
/// \file
/// Helpers of the editor's tests (tests/viewer/editor_*_test.cpp): documents and editors
/// made from a mesh, edges by their ends, crease flags.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "meshedit/core/attributes.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/validate.h"
#include "meshedit/viewer/editor.h"
#include "support/scratch_dir.h"

namespace meshedit::viewer {

namespace fs = std::filesystem;
using Kind = ElementRef::Kind;

using TempDir = test::ScratchDir;

inline Document mesh_document(Mesh mesh, Mode mode = Mode::Mesh) {
    Document d;
    d.mode = mode;
    d.mesh = std::move(mesh);
    return d;
}

inline Editor editor_with(Mesh mesh) {
    Editor ed;
    ed.set_document(mesh_document(std::move(mesh)));
    return ed;
}

inline Edge edge_of(const Mesh& mesh, std::uint32_t a, std::uint32_t b) {
    const Edge e = mesh.find_edge(Vertex(a), Vertex(b));
    EXPECT_TRUE(e.is_valid()) << a << "-" << b;
    return e;
}

inline int crease_of(const Mesh& mesh, Edge e) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    return crease ? crease[e] : -1;
}

inline Halfedge boundary_halfedge(const Mesh& mesh) {
    for (Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            return h;
        }
    }
    ADD_FAILURE() << "no boundary";
    return {};
}

// An interactive edit's result is bit for bit `expected` (what the session's steps make from
// `before`), valid, and undo and redo give `before` and it back.
inline void expect_as_replayed(Editor& ed, const Mesh& before, const Mesh& expected) {
    std::string why;
    EXPECT_TRUE(bitwise_equal(ed.mesh(), expected, &why)) << why;
    EXPECT_TRUE(!validate(ed.mesh()).has_value());
    ed.run({Command::Undo});
    EXPECT_TRUE(bitwise_equal(ed.mesh(), before, &why)) << why;
    ed.run({Command::Redo});
    EXPECT_TRUE(bitwise_equal(ed.mesh(), expected, &why)) << why;
}

}  // namespace meshedit::viewer
