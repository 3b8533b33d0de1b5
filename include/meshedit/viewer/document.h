#pragma once
/// \file
/// The editor's document: what undo restores and save writes.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "meshedit/bezier/bezier_curve.h"
#include "meshedit/bezier/bezier_patch.h"
#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/io/document.h"

namespace meshedit::viewer {

/// What the document shows, the kind of file it came from: a mesh file, Bezier patches (.bez,
/// edited as their welded tessellation) or a Bezier curve (.bzc). Its short name is
/// kind_name(mode).
using Mode = DocumentKind;

/// "mesh", "Bezier surface (welded tessellation)", "Bezier curve" (the info panel's heading).
const char* mode_description(Mode mode);

/// The editable state.
struct Document {
    Mode mode = Mode::Mesh;
    Mesh mesh;                         ///< Mesh and Surface modes
    std::vector<BezierPatch> patches;  ///< Surface mode
    int density = 8;                   ///< Surface mode: quads per patch side
    BezierCurve curve;                 ///< Curve mode
    ElementRef selection;              ///< the active element; Curve mode: Vertex = control point
    /// Mesh and Surface modes: elements selected besides the active one (Shift+click, Ctrl+A,
    /// a boundary loop), in the order they were added; never holds `selection`.
    std::vector<ElementRef> also_selected;
    std::uint64_t revision = 0;  ///< identifies the content; new on every edit
    /// Mesh mode: the steps of the edit language that made this mesh from the opened file,
    /// in order (a drag is a `move`, the renumbering after a deleting edit a `compact`), so
    /// undo and redo keep it in step with the mesh; Ctrl+Shift+E exports it.
    std::vector<std::string> session;

    /// Bytes this document holds (for the history budget).
    std::size_t bytes() const;
};

}  // namespace meshedit::viewer
