#pragma once
/// \file
/// What the window and meshedit-render draw besides the mesh, derived from the document: the
/// fixed part of the overlay (feature edges, a phased Loop's marks), the scalar field on
/// screen and the picking tree. One owner for both programs: told what changed (follow()),
/// it brings along what a recorded change touched and recomputes the rest when next asked.

#include <cstdint>
#include <optional>
#include <vector>

#include <optional>
#include <thread>

#include "meshedit/core/face_bvh.h"
#include "meshedit/core/fields.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/overlay/colormap.h"
#include "meshedit/overlay/overlay.h"

namespace meshedit {

/// The scalar field on screen (Alt+F, --field): what was computed for the current mesh.
struct FieldDisplay {
    const FieldInfo* info = nullptr;  ///< none shown
    std::vector<double> values;       ///< by element index of its site
    FieldColoring coloring;
    FieldStats stats;
    Vertex source;  ///< distance: where it is measured from
    /// The settings it was computed with.
    float clip = 0.0f;
    std::optional<ColorMap> colormap;
};

/// Which field, and how coloured (ViewState's field settings, meshedit-render's options).
struct FieldRequest {
    const FieldInfo* info = nullptr;
    Vertex source;  ///< distance: where it is measured from
    float clip = 0.05f;
    std::optional<ColorMap> colormap;
};

class DisplayData {
public:
    /// What changed in the document since the last call.
    struct Change {
        bool mesh = false;      ///< positions or connectivity (or a new document)
        bool features = false;  ///< what the fixed overlay shows: crease marks, display state
        /// Where a recorded change (or its undo or redo) changed the mesh; the picking tree
        /// follows it in the time of what it touched if it showed revision `before`.
        const MeshChange::Region* region = nullptr;
        std::uint64_t before = 0;  ///< the document's revision before the change
        std::uint64_t after = 0;   ///< and after it
    };
    void follow(const Mesh& mesh, const Change& change);

    /// Boundary and crease edges (`edges`, with UV `seams` and material `borders`) and a
    /// phased Loop's marks (`marks`) of `mesh`, recomputed when the mesh or the features
    /// changed.
    const OverlayBatch& features(const Mesh& mesh, bool edges, bool marks, bool seams = false,
                                 bool borders = false);
    /// The overlay of a frame: the features of the scene's mesh and the scene's marks.
    OverlayBatch overlay(const SceneContent& scene, bool edges, bool marks);

    /// The field `request` asks for on `mesh`; recomputed when the mesh changed or the
    /// request differs, and then `*recomputed` is set. Cleared when request.info is null.
    const FieldDisplay& field(const Mesh& mesh, const FieldRequest& request,
                              bool* recomputed = nullptr);
    const FieldDisplay& field() const { return field_; }

    /// The picking tree of `mesh` at document revision `revision`, built when first asked
    /// after a change it did not follow.
    const FaceBvh& picking_tree(const Mesh& mesh, std::uint64_t revision);
    /// Starts building the picking tree of `mesh` (at `revision`) on a worker thread, so the
    /// first hover after an open or a whole-mesh operation does not wait for it (a fifth of a
    /// second per million triangles). `mesh` must not change until settle(), which
    /// picking_tree() and follow() call first.
    void prebuild(const Mesh& mesh, std::uint64_t revision);
    /// Waits for the tree being built, if any, and takes it.
    void settle();

private:
    OverlayBatch features_;
    bool features_stale_ = true;
    bool features_edges_ = true, features_marks_ = true;
    bool features_seams_ = false, features_borders_ = false;
    FieldDisplay field_;
    bool field_stale_ = true;
    FaceBvh tree_;
    bool tree_stale_ = true;
    std::uint64_t tree_revision_ = 0;
    std::optional<FaceBvh> building_;  ///< written by builder_ until settle() joins it
    std::uint64_t building_revision_ = 0;
    std::jthread builder_;  ///< last: joins before what it writes goes
};

}  // namespace meshedit
