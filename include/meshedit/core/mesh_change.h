#pragma once
/// \file
/// What a local edit changed in a mesh, recorded while it runs: undo and redo in the time and
/// memory of what it touched, not of the mesh (a flip at 1M faces: a few hundred bytes
/// instead of a 70 MB copy).
///
///     MeshRecorder recorder(mesh);     // from here on the mesh reports what it overwrites
///     flip(mesh, e);                   // any local operation
///     MeshChange change = recorder.finish();
///     change.undo(mesh);               // bit for bit the mesh before the flip
///     change.redo(mesh);               // bit for bit the mesh after it
///
/// How: every write to an element goes through a Mesh setter, position() or mark_deleted(),
/// and each calls Mesh::touch() first. The first touch of an element that existed when the
/// recording began copies its values in *every* property of its kind (connectivity,
/// position, crease marks, user data); finish() copies the same elements' values again, and
/// the elements appended meanwhile whole. Properties added meanwhile are kept whole (the
/// first crease mark adds `e:crease`). Code that writes a property through its handle must
/// call Mesh::touch() on the element first (the crease verb does).
///
/// What a recording cannot hold — a write to a whole array (MeshArrays, positions()), garbage
/// collection, resize(), the mesh replaced or moved, a property that existed before removed —
/// makes finish() throw std::logic_error: such operations are global and are undone from a
/// whole copy instead. Tests check that every local verb records completely
/// (tests/core/mesh_change_test.cpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "meshedit/core/mesh.h"

namespace meshedit {

/// A finished recording: the values that changed, before and after, of one edit.
class MeshChange {
public:
    /// Puts `mesh` back as it was before the edit. \pre `mesh` is as the edit left it.
    void undo(Mesh& mesh) const;
    /// Puts `mesh` back as the edit left it. \pre `mesh` is as it was before the edit.
    void redo(Mesh& mesh) const;

    /// Takes the touched and appended elements' values after the edit (and the properties it
    /// added) again from `mesh`, where only they changed since: an edit still under way,
    /// recorded at its first move and brought up to date at every move (a vertex drag; an
    /// extrude that made its topology once and moves its corners). \pre no element was
    /// appended or deleted since the change was recorded.
    void refresh_after(const Mesh& mesh);

    /// Bytes held (for the undo history's budget).
    std::size_t bytes() const;
    /// Where the picture may differ, on either side of the change (so for undo as for
    /// redo): the faces it touched, created or took halfedges from or gave them to, and the
    /// vertices it moved, created, or that are the head of a relinked halfedge, before or
    /// after. Indices may be deleted or, on the side where appended elements do not exist,
    /// out of range. Sorted, unique. For partial GPU and picking updates.
    struct Region {
        std::vector<Face> faces;
        std::vector<Vertex> vertices;
        /// Adds `other`'s elements (two changes redrawn as one; order and repeats allowed).
        void add(const Region& other) {
            faces.insert(faces.end(), other.faces.begin(), other.faces.end());
            vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
        }
    };
    Region region() const;
    /// Number of elements recorded (touched before plus appended), per kind V, H, E, F.
    std::array<std::size_t, 4> counts() const;

private:
    friend class MeshRecorder;
    /// One element kind's part: its sizes, and where its values lie in data_ (packed, so a
    /// flip's change is a few hundred bytes with its bookkeeping).
    struct Kind {
        std::uint32_t size_before = 0;
        std::uint32_t size_after = 0;
        std::uint32_t n_arrays = 0;   ///< arrays that existed when the recording began
        std::uint32_t stride = 0;     ///< bytes of one element over those arrays
        std::uint32_t n_touched = 0;  ///< elements < size_before written by the edit
        std::size_t offset = 0;       ///< in data_: indices, values before, after, appended
        std::size_t before_at() const { return offset + n_touched * sizeof(std::uint32_t); }
        std::size_t after_at() const { return before_at() + std::size_t{n_touched} * stride; }
        std::size_t appended_at() const { return after_at() + std::size_t{n_touched} * stride; }
        std::size_t end() const {
            return appended_at() + std::size_t{size_after - size_before} * stride;
        }
    };
    using AddedArrays = std::array<std::vector<std::unique_ptr<BasePropertyArray>>, 4>;
    void restore(PropertyContainer& c, int kind, bool forward) const;
    /// redo() when `forward`, else undo().
    void apply(Mesh& mesh, bool forward) const;
    std::uint32_t touched(int kind, std::size_t i) const;

    std::array<Kind, 4> kinds_;  ///< vertex, halfedge, edge, face
    std::array<std::uint32_t, 3> deleted_before_{};
    std::array<std::uint32_t, 3> deleted_after_{};
    std::vector<std::byte> data_;
    std::unique_ptr<AddedArrays> added_;  ///< properties the edit added, whole; null if none
};

/// Records the edits made to one mesh from construction to finish() (see the file comment).
/// One recorder per mesh at a time; copies of the mesh are not recorded.
class MeshRecorder {
public:
    /// Whether recorders check themselves (Debug and sanitizer builds): each keeps a copy of
    /// the mesh from its start, and finish() fails when undoing the change does not give it
    /// back bit for bit — an element changed that the recording was not told about. Every
    /// test that records then checks the contract for free.
#ifdef NDEBUG
    static constexpr bool kSelfCheck = false;
#else
    static constexpr bool kSelfCheck = true;
#endif

    /// \throws std::logic_error if `mesh` is already being recorded.
    explicit MeshRecorder(Mesh& mesh);
    /// Stops recording; an unfinished recording is dropped (the mesh keeps its changes).
    ~MeshRecorder();
    MeshRecorder(const MeshRecorder&) = delete;
    MeshRecorder& operator=(const MeshRecorder&) = delete;

    /// Stops recording and returns the change.
    /// \throws std::logic_error naming what the edit did that a change cannot hold, or (with
    /// kSelfCheck) what it changed without telling the recorder.
    MeshChange finish();
    /// Stops recording and puts the mesh back as it was when the recording began (an edit
    /// that failed half-way). \throws std::logic_error as finish() does.
    void roll_back();

    /// Called by Mesh::touch() (`kind` 0–3) and on untracked writes (`kind` −1).
    void record(int kind, std::uint32_t index) noexcept;
    /// Called by Mesh::carry() (kSelfCheck: finish() checks every new element was derived).
    void carried(int kind, std::uint32_t index) noexcept;
    /// Called by Mesh::remove_property(): only arrays added since the recording began may go.
    void removing(const BasePropertyArray* array) noexcept;

private:
    struct Seen {  // open addressing over uint32 indices; ~0u is empty
        std::vector<std::uint32_t> slots = std::vector<std::uint32_t>(64, ~0u);
        std::size_t n = 0;
        bool insert(std::uint32_t i);
    };
    struct Log {  // one kind's recording so far
        std::size_t size_before = 0;
        std::size_t n_arrays = 0;
        std::size_t stride = 0;
        std::vector<std::uint32_t> touched;
        std::vector<std::byte> before;
        Seen seen;
        std::vector<std::uint8_t> carried;  ///< kSelfCheck: new element i - size_before derived
    };
    PropertyContainer& container(int kind) const;
    void stop();
    /// kSelfCheck: the first live element made without Mesh::carry(), or "".
    std::string underived() const;

    Mesh* mesh_;
    std::array<Log, 4> logs_;
    std::array<std::size_t, 3> deleted_before_{};
    std::string problem_;          ///< the first untracked write, or a failed allocation
    std::unique_ptr<Mesh> start_;  ///< kSelfCheck: the mesh as the recording began
};

/// The faces whose picture a change may have altered in `mesh` (either side of it): the
/// region's faces and every live face around its live vertices (a moved vertex reshapes
/// them). Sorted, unique; may include deleted or out-of-range indices from the region.
std::vector<Face> faces_to_redraw(const Mesh& mesh, const MeshChange::Region& region);

/// True when both meshes hold the same properties (names, kinds, order) with the same bytes
/// in every element, deleted ones included, and the same deletion counts; otherwise false
/// with the first difference in `why`. For tests of recorded edits and undo.
bool bitwise_equal(const Mesh& a, const Mesh& b, std::string* why = nullptr);

}  // namespace meshedit
