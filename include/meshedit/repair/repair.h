#pragma once
/// \file
/// Repairing a mesh as a file holds it (a MeshSoup, io.h), before build_mesh() makes it a
/// halfedge mesh: merging vertices by distance (which also stitches the coincident boundary
/// edges of an unwelded soup), removing degenerate and duplicate faces, stitching
/// T-junctions, orienting faces coherently, removing small components; and, on the built
/// mesh, filling small holes.
///
/// Each step returns what it changed (RepairResult: a count, the first few indices as they
/// were before the step, and one sentence for the user) and keeps every attribute of the soup
/// consistent with its faces and vertices:
/// - a removed face takes its corners' texture coordinates and normals, its material and its
///   face property values with it;
/// - a face turned over reverses its corners and their attributes together, so every corner
///   keeps the texture coordinate and normal it had (normals are not negated: they describe
///   the shading the file asked for, which a winding error does not change);
/// - merged vertices keep the values of the vertex they merge into, the lowest-numbered one
///   of those merged (its position, per-vertex normal and user property values); the others'
///   values are dropped;
/// - vertices that a step leaves unused (merged away, or used only by removed faces) are
///   removed and the rest renumbered in order; crease pairs are renumbered with them, and a
///   crease whose ends became one vertex or were removed is dropped (and counted).
/// Vertices no face used before a step stay: an isolated point may be meant.
///
/// repair() runs the safe sequence; running it again on its result changes nothing.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "meshedit/core/mesh.h"
#include "meshedit/io/io.h"

namespace meshedit {

/// How many indices a RepairResult lists (the rest are counted).
inline constexpr std::size_t kRepairShown = 5;

/// What one repair step did.
struct RepairResult {
    /// How many elements it changed: vertices merged away, faces removed or turned over,
    /// components removed, holes filled.
    std::size_t count = 0;
    /// The first few of them (at most kRepairShown), numbered as before the step: vertex
    /// indices for a merge, face indices for face steps, the first face of each removed
    /// component, a vertex on each filled hole.
    std::vector<std::uint32_t> first;
    /// Problems found and left as they are: vertices within the tolerance kept apart (their
    /// faces would touch only there), edges that cannot agree (a non-orientable part), holes
    /// too large or degenerate to fill.
    std::size_t left = 0;
    /// Corners dropped from faces that stay (remove_degenerate_faces(): repeated corners).
    std::size_t corners = 0;
    /// Unused vertices the step removed with what it removed (see the file comment).
    std::size_t removed_vertices = 0;
    /// One sentence for the user ("merged 2 vertices into others within 1e-06: 3, 4"),
    /// empty when the step neither changed nor left anything.
    std::string sentence;

    bool changed() const { return count > 0 || corners > 0 || removed_vertices > 0; }
};

/// A merge distance: absolute, or a fraction of the bounding-box diagonal of the vertices
/// that faces use.
struct MergeTolerance {
    double value = 1e-6;
    bool relative = true;
};

/// Merges vertices closer than the tolerance. Vertices are taken in index order and grouped
/// with the lowest-numbered earlier group leader within the tolerance (or lead a group of
/// their own), so leaders end up farther apart than the tolerance; a uniform grid of cells at
/// least the tolerance wide finds them, in time linear in the number of vertices. A group
/// becomes one vertex, the lowest-numbered of it, unless its faces would then touch only at
/// that point (two cones tip to tip): the corners of a group fall into fans, joined through
/// the edges they share once merged, and each fan becomes one vertex; such vertices are
/// counted in `left`. So a second merge does nothing, and the merge never makes a vertex the
/// builder would split again. Faces are re-indexed. Vertices no face uses are not merged.
/// A tolerance of 0 merges equal positions only.
/// \throws std::invalid_argument for a negative or non-finite tolerance; TopologyError (as
/// build_mesh()) for an index out of range or a non-finite position.
RepairResult merge_vertices(MeshSoup& soup, const MergeTolerance& tolerance = {});

/// Removes faces that cannot be a polygon: first repeated consecutive corners are dropped
/// (a, a, b, c becomes a, b, c, with that corner's attributes), then faces with fewer than 3
/// corners, with a corner repeated elsewhere (which build_mesh() would drop), or with zero
/// area (below 1e-12 of the square of its longest side: rounding cannot tell it from 0).
RepairResult remove_degenerate_faces(MeshSoup& soup);

/// Removes every face whose set of vertices equals an earlier face's (in either winding);
/// the first is kept.
RepairResult remove_duplicate_faces(MeshSoup& soup);

/// How stitch_borders() finds T-junctions.
struct StitchOptions {
    /// A boundary vertex goes into a boundary edge when it is at most `ratio` times the edge's
    /// length off it (0 < ratio < 0.5; relative to the edge, as the bulge of a curve between
    /// two tessellations grows with the edge), at most a quarter of its distance from the
    /// nearer end (a 14° turn) and farther than the merge distance from either end.
    double ratio = 0.05;
    /// Rounds of splitting and merging at most (each joins the pieces the last one made).
    std::size_t max_rounds = 8;
};

/// Stitches T-junctions, the cracks between patches tessellated apart (a CAD export: the
/// vertices of one side lie on the other side's edges, so the merge finds no partner): each
/// boundary vertex lying on a boundary edge that runs against its own border (the other side
/// of the crack) becomes a corner of that edge's face. A triangle split on one side becomes a
/// fan from its third corner, another face a polygon with the new corners; the new corners
/// take texture coordinates and normals interpolated along the edge, the new faces their
/// face's material and values, and a crease along the edge runs through the new vertices.
/// Then merge_vertices() joins the vertices that now share edges (the merge kept them apart
/// while their faces touched only at a point) and remove_degenerate_faces() and
/// remove_duplicate_faces() remove what the joins flattened; repeated while a round finds a
/// T-junction, at most options.max_rounds times. `count` is the vertices put into edges,
/// `left` what the last merge kept apart. No vertex moves or is added.
/// \throws std::invalid_argument for a ratio outside (0, 0.5).
RepairResult stitch_borders(MeshSoup& soup, const StitchOptions& options = {},
                            const MergeTolerance& tolerance = {});

/// Turns faces over so that every edge shared by exactly two faces is used once in each
/// direction: faces joined across such edges form a part, walked breadth-first; each part
/// keeps the winding most of its faces have. A closed part (every edge shared by exactly two
/// of its faces) that encloses a negative signed volume is turned over as a whole, so its
/// normals point outward. Edges of three or more faces are not walked (build_mesh() cuts
/// them); a part that cannot agree (a Möbius strip) keeps its conflicting edges, counted in
/// `left`.
RepairResult orient_faces(MeshSoup& soup);

/// Which components remove_small_components() removes: those with fewer than `min_faces`
/// faces or less than `min_area` area (0: no bound).
struct ComponentBounds {
    std::size_t min_faces = 0;
    double min_area = 0.0;
};

/// Removes the components (faces joined through shared vertices) below `bounds`, with the
/// vertices only they use. Never removes everything: when every component is below the
/// bounds, the one with the most faces (then the largest area) stays and the sentence says so.
RepairResult remove_small_components(MeshSoup& soup, const ComponentBounds& bounds);

/// Fills every hole (boundary loop) of at most `max_edges` edges with fill_hole()
/// (local_ops.h), and, when every face of the mesh was a triangle before, triangulates the new
/// face. Holes whose outline has zero area (a fill would be a degenerate face) or more edges
/// are left and counted in `left`. `first` lists a vertex of each filled hole.
RepairResult fill_holes(Mesh& mesh, std::size_t max_edges);

/// How fill_holes_fair() fills.
struct FairFillOptions {
    /// Holes of at most this many edges (0: every hole).
    std::size_t max_edges = 0;
    /// Add vertices until the patch's edges are as long as those around the hole.
    bool refine = true;
    /// Then move the new vertices so that the patch continues the surface (bi-Laplacian).
    bool fair = true;
    /// Liepa's density α: a triangle is split when its centroid is farther than 1/α times
    /// the wanted edge length from each corner; larger gives more, smaller triangles.
    double density = 1.4142135623730951;
    /// The most new vertices one fairing solves for (its factorisation's time and memory
    /// grow faster than they do): refinement pauses there, the patches are faired, and
    /// refinement goes on after on the faired surface, unfaired.
    std::size_t max_faired = 20'000;
};

/// Fills holes as Liepa (2003) does and CGAL's triangulate_refine_and_fair_hole: the
/// triangulation whose largest dihedral angle is smallest (O(n³), up to 100 edges; a larger
/// hole whose outline is simple in its mean plane is covered by ears clipped there, smallest
/// inside angle first, and flipped to Delaunay: its constrained Delaunay triangulation in that
/// plane; one that folds there by the O(n³) search up to 300 edges, then by ears), refined
/// until its edges match the lengths around the hole with Delaunay flips at each split and
/// between rounds, new vertices left with three edges dissolved, then faired (fair(),
/// smoothing.h) with every old vertex fixed and flipped to Delaunay on the faired shape. Made
/// with the local operations (fill_hole, triangulate, flip, poke, dissolve), so attributes
/// are carried. A hole it cannot cover (every triangulation repeats an edge the mesh has, or
/// is flat) is left, named in the sentence with its reason; nothing loops without a bound.
/// `first` lists a vertex of each filled hole. \post validate(mesh) passes.
RepairResult fill_holes_fair(Mesh& mesh, const FairFillOptions& options);

/// Fills the one hole whose border the boundary halfedge `h` lies on, as fill_holes_fair()
/// fills each, without looking for the other holes (as CGAL's triangulate_refine_and_fair_hole
/// and pmp's fill_hole, which take a border halfedge too). Besides the hole and the faces
/// around it, it reads only the positions, once, for the bounding box that scales the distance
/// under which two corners are one point (as repair's merge). Unlike fill_holes_fair() it leaves
/// the rest of the mesh as it is, so a part the patch closes keeps the orientation of the surface
/// around the hole. `h` not on a border: nothing changes, count is 0 and the sentence says why.
/// \post validate(mesh) passes.
RepairResult fill_hole_fair(Mesh& mesh, Halfedge h, const FairFillOptions& options);

/// Which steps repair() runs; the defaults are the safe sequence.
struct RepairOptions {
    bool merge = true;
    MergeTolerance tolerance;
    bool remove_degenerate = true;
    bool remove_duplicates = true;
    /// stitch_borders() after the merge and the removals (when merging).
    bool stitch = true;
    StitchOptions stitch_options;
    bool orient = true;
    /// remove_small_components(), when either bound is set.
    ComponentBounds components;
    /// fill_holes() up to this many edges (0: no filling); only repair_and_build() fills.
    std::size_t fill_holes = 0;
    /// Fill them with fill_holes_fair() (refined and faired) instead.
    bool fair_holes = false;
};

/// What repair() did: the result of every step it ran, in order, and one line per step
/// that changed or left something.
struct RepairReport {
    std::vector<RepairResult> steps;
    std::vector<std::string> lines;

    bool changed() const;
};

/// Merge (relative 1e-6), degenerate and duplicate removal, T-junction stitching, orientation, then
/// small components when bounded, as `options` says. Running it again on its result changes
/// nothing. \throws std::invalid_argument for a bad merge tolerance.
RepairReport repair(MeshSoup& soup, const RepairOptions& options = {});

/// A repaired soup built into a mesh, with what was done to it.
struct RepairedMesh {
    LoadedMesh loaded;
    RepairReport report;
};

/// repair(), then build_loaded_mesh() (io.h), then fill_holes() when options.fill_holes is
/// set. The report also lists what the builder still had to repair (non-manifold edges and
/// vertices), one line each. `name` names the input in errors. \throws IoError when the soup
/// cannot be built (a non-finite position), std::invalid_argument for a bad merge tolerance.
RepairedMesh repair_and_build(MeshSoup soup, const RepairOptions& options, const std::string& name);

}  // namespace meshedit
