#pragma once
/// \file
/// What a command of the viewer's logic changed, as the window reads it: change bits, the
/// status line, and where a recorded edit changed the mesh.

#include <optional>
#include <string>
#include <utility>

#include "meshedit/core/mesh_change.h"

namespace meshedit::viewer {

/// What a command changed, so the window knows what to re-upload or do.
enum Change : unsigned {
    kNothing = 0,
    kTopology = 1u << 0,   ///< the mesh's elements changed: full upload
    kGeometry = 1u << 1,   ///< positions only (same triangles): update_geometry()
    kSelection = 1u << 2,  ///< selection or hover overlay
    kDisplay = 1u << 3,    ///< render options, panels, curve level/t, nets
    kCurve = 1u << 4,      ///< curve control points
    kResetCamera = 1u << 5,
    kScreenshot = 1u << 6,   ///< the window should write a screenshot
    kAskSavePath = 1u << 7,  ///< the window should ask for a path, then call save_as()
    kAskOpenPath = 1u << 8,  ///< the window should ask for a path, then call open()
    kQuit = 1u << 9,
    kDocument = 1u << 10,        ///< a different document (open, undo/redo): reframe nothing,
                                 ///< re-upload everything
    kFrameSelection = 1u << 11,  ///< the camera should centre on selection_bounds()
    /// The mesh's extent may have changed (a whole-mesh operation): the depth range follows
    /// it, the view stays where the user put it, as in Blender (Space frames the mesh).
    kSceneBounds = 1u << 12,
    kAskSessionPath = 1u << 13,  ///< the window should ask for a path, then export_session()
    kReloadShaders = 1u << 14,   ///< the window should recompile every shader from disk
    kBoxSelect = 1u << 15,       ///< the window's next left drag draws a box that selects
    kBrushSelect = 1u << 16,     ///< the window's left drags paint a selection with a circle
    /// An operation began in the background (Editor::set_background): the window shows its
    /// progress and calls Editor::finish_job() every frame until it ends.
    kJobStarted = 1u << 17,
};

/// The result of a command: what changed, and a status line for the user (empty when there
/// is nothing to say). `refused` marks a command that did nothing and says why.
struct Outcome {
    Outcome() = default;
    Outcome(unsigned changes_, std::string message_ = {}, bool refused_ = false,
            std::optional<MeshChange::Region> region_ = std::nullopt)
        : changes(changes_),
          message(std::move(message_)),
          refused(refused_),
          region(std::move(region_)) {}

    unsigned changes = kNothing;
    std::string message;
    bool refused = false;
    /// Where the mesh changed when the command was a recorded local edit, its undo or redo, a
    /// drag's move or an interactive edit's preview (MeshChange::region(), for
    /// MeshRenderer::update() and FaceBvh::update()); none when everything is to be redrawn.
    std::optional<MeshChange::Region> region;
};

/// A refused command: nothing changed, and `message` says why.
inline Outcome refused(std::string message) {
    return {kNothing, std::move(message), true, std::nullopt};
}

}  // namespace meshedit::viewer
