#pragma once
/// \file
/// What is wrong with a mesh, each problem with a place to look at: the cuts the loader made
/// (non-manifold or disagreeing edges, split vertices, dropped faces), holes, degenerate faces,
/// closed parts turned inside out, small floating parts and faces that pass through each
/// other. `meshedit check --problems` prints them, the viewer's Problems panel lists them and
/// frames each on a click, and repair.h's steps remove most of them.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "meshedit/core/build.h"
#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

enum class ProblemKind {
    LoadCut,           ///< an edge the loader cut apart, a vertex it split, a face it dropped
    Hole,              ///< a boundary loop
    DegenerateFace,    ///< zero area, or two corners at one point
    InsideOut,         ///< a closed part whose faces enclose a negative volume
    SmallPart,         ///< a part (faces joined across edges) of few faces
    SelfIntersection,  ///< two faces that pass through each other (sharing no vertex)
};
inline constexpr std::size_t kProblemKinds = 6;

/// "load cut", "hole", … : the word `--json` and the panel use.
const char* problem_kind_name(ProblemKind kind);

struct Problem {
    ProblemKind kind;
    ElementRef where;  ///< the element to select and frame
    std::size_t size;  ///< a hole's edges, a part's faces; 1 otherwise
    std::string text;  ///< "hole of 12 edges at vertex 40"
};

struct ProblemOptions {
    /// Parts of fewer faces than this are small (when the mesh has more than one part).
    std::size_t small_part_faces = 10;
    /// Look for faces that pass through each other (a grid of cells: about linear time).
    bool self_intersections = true;
    /// At most this many problems of each kind are listed (all are counted).
    std::size_t listed = 500;
};

struct ProblemReport {
    std::vector<Problem> problems;                    ///< in kind order, then by place
    std::array<std::size_t, kProblemKinds> counts{};  ///< every one found, by kind
    bool empty() const;
    /// "2 holes, 1 small part" or "no problems".
    std::string summary() const;
};

/// The problems of `mesh`; `load` is what its loader repaired (nullptr: none known).
ProblemReport find_problems(const Mesh& mesh, const BuildReport* load,
                            const ProblemOptions& options = {});

/// Pairs of faces that pass through each other: each face's display triangles (a fan) are
/// tested against those of faces sharing no vertex with it and near it (a uniform grid of
/// cells about two mean edge lengths wide). Touching or coplanar overlap is not counted.
std::vector<std::pair<Face, Face>> self_intersections(const Mesh& mesh);

}  // namespace meshedit
