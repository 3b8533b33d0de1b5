#pragma once
/// \file
/// `meshedit-view --student`: what the window shows after a student's F, S or L whose result
/// is not the reference's — the two results side by side in one mesh (the student's left,
/// the reference's right), the first differing element selected in each and framed — and the
/// marks that frame them (docs/student.md).

#include <cstdint>
#include <string>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"
#include "meshedit/overlay/overlay.h"

namespace meshedit::viewer {

/// The side by side the document holds after a student's result differed.
struct StudentComparison {
    std::string task;        ///< the student's function: "flip_edge"
    std::string input;       ///< what it ran on: "edge 5 (2–7)", "the mesh"
    std::string difference;  ///< what differs, in the student's own numbering
    std::string invariant;   ///< the broken rule ("twin"), empty when the result is valid
    /// The first differing element in the document's mesh (the side by side): the student's,
    /// and the reference's (none when the reference has no counterpart).
    ElementRef yours, reference;
    /// vertex_normal's side by side: each half's normals by vertex (the student's of vertex
    /// v, the reference's of vertex reference_from + v); empty for the mesh tasks.
    std::vector<Vec3> yours_normals, reference_normals;
    /// Vertices from this index on are the reference's (the right half).
    std::uint32_t reference_from = 0;
    std::uint64_t at_revision = 0;  ///< the document's revision that shows it
};

/// The normals drawn at each vertex of vertex_normal's side by side.
inline constexpr Color kComparisonNormal{0.0f, 0.75f, 0.45f, 1.0f};  ///< green
/// Frames drawn around the two differing elements.
inline constexpr Color kComparisonFrame{1.0f, 0.0f, 1.0f, 1.0f};  ///< magenta

/// A box around each differing element, labelled, a caption over each half ("yours",
/// "reference"), and each vertex's normal when the comparison has them.
void add_comparison_marks(const Mesh& mesh, const StudentComparison& comparison, OverlayBatch& out);

}  // namespace meshedit::viewer
