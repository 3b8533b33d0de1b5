#pragma once
/// \file
/// "What did that operation rewire?": the local neighbourhood of a local operation before
/// and after it, as a flat 2-D picture of halfedges, twins and faces labelled with the names
/// the operation's code and docs/halfedge.md use (h0, t0, a, b, c, d, m, v0 …; other elements
/// by index), the elements it created, deleted or relinked coloured. The viewer draws it in a
/// panel (Alt+R); `meshedit render --ops … --op-diagram` renders it for docs. GL-free.
///
/// The picture is an OverlayBatch in the z = 0 plane: "before" on the left, "after" on the
/// right, each laid out as a Tutte embedding of its faces (the region's outline on a circle,
/// the inner vertices at the average of their neighbours), so a bent neighbourhood (a cube's
/// corner) lies flat and nothing overlaps, whatever the mesh's own geometry.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/overlay/overlay.h"

namespace meshedit {

/// The diagram's colours (one place, as OverlayStyle for the 3-D view).
struct OpDiagramStyle {
    Color unchanged{0.25f, 0.25f, 0.3f, 1.0f};  ///< dark grey
    Color created{0.1f, 0.6f, 0.2f, 1.0f};      ///< green
    Color deleted{0.85f, 0.15f, 0.15f, 1.0f};   ///< red
    Color relinked{0.95f, 0.5f, 0.0f, 1.0f};    ///< orange
    Color edge{0.55f, 0.55f, 0.6f, 1.0f};       ///< the edges, under the halfedge arrows
    float face_alpha = 0.18f;                   ///< face tints
};

struct OpDiagram {
    std::string title;     ///< "flip of edge 17 (7–4)"
    OverlayBatch picture;  ///< z = 0; before at x ∈ [−1, 1], after at x ∈ [kAfterX ± 1]
    Vec3 min, max;         ///< the picture's extent, labels' anchors included
    std::vector<std::string> changes;  ///< "h0: next h1 → t2, to c → a", one line per element
    static constexpr double kAfterX = 2.9;
};

/// The diagram of `verb` (an edit-language verb's name, for the title) run on `input` of
/// `before`, which made `after`. `names` (the verb table's ops::Verb::names) says whose code
/// names the elements: flip, split and collapse between triangles are named as their code
/// does; the other operations, and polygons, are labelled by index. The region shown: for an
/// edge, its faces (CodeNames::Collapse: every face at either end); for
/// a vertex, its faces; for a face, it and the faces across its sides; after the edit, the
/// faces on the same vertices (and any new ones) that are new or were shown before.
/// \pre `after` is `before` after the operation, without garbage collection between (indices
///      name the same elements); `input` is live in `before`.
OpDiagram op_diagram(const Mesh& before, const Mesh& after, std::string_view verb, CodeNames names,
                     ElementRef input, const OpDiagramStyle& style = {});

/// The diagram of a recorded local edit (core/mesh_change.h): `mesh` as the edit left it and
/// `change`, its recording; `input_of` names the element operated on in the mesh before it.
/// The same picture as the overload above, read without a copy of the mesh: the change is
/// undone and redone around copying the neighbourhood drawn (two rings around what it
/// touched) on each side, so it costs what the edit and that neighbourhood touch, at any
/// mesh size. `mesh` is left bit for bit as it was.
OpDiagram op_diagram(Mesh& mesh, const MeshChange& change, std::string_view verb, CodeNames names,
                     const std::function<ElementRef(const Mesh& before)>& input_of,
                     const OpDiagramStyle& style = {});

namespace op_diagram_detail {

/// For local meshes cut out of a bigger one: each local element's index there (halfedge h of
/// local edge e is 2 * edges[e] + h % 2).
struct Originals {
    std::vector<std::uint32_t> vertices, edges, faces;
};

/// The diagram of `before` → `after` titled `title`, labelling elements with `originals`'
/// indices when given.
OpDiagram draw(const Mesh& before, const Mesh& after, std::string title, CodeNames names,
               ElementRef input, const Originals* originals, const OpDiagramStyle& style);

/// Names of elements by index, as an operation's code calls them.
struct Names {
    std::vector<std::pair<std::uint32_t, std::string>> halfedges, vertices, faces;
    const std::string* halfedge(Halfedge h) const;
    const std::string* vertex(Vertex v) const;
    const std::string* face(Face f) const;
};

/// The code's names for `input` (empty for ByIndex and for what the code does not name).
Names code_names(const Mesh& before, CodeNames names, ElementRef input);

}  // namespace op_diagram_detail

}  // namespace meshedit
