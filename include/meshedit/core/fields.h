#pragma once
/// \file
/// Scalar fields on a mesh's vertices, edges or faces: discrete curvature and mesh quality,
/// what engineers read off a mesh as colours (docs/fields.md). Each field is one value per
/// element index; elements without a value (deleted ones, a boundary vertex's curvature, a
/// polygon's triangle quality) hold NaN.
///
/// Curvature is measured on the display triangulation (polygons fanned as the renderer draws
/// them; core/display_fan.h): Gaussian curvature as the angle defect over the mixed Voronoi
/// area, mean curvature from the cotangent Laplacian over the same area (Meyer, Desbrun,
/// Schröder and Barr 2003).

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "meshedit/core/element_ref.h"
#include "meshedit/core/mesh.h"

namespace meshedit {

/// Where a field's values live.
enum class FieldSite { Vertex, Edge, Face };

struct FieldInfo {
    std::string_view name;   ///< "gauss": the CLI word
    std::string_view title;  ///< "Gaussian curvature"
    std::string_view unit;   ///< "1/length²", "°", "" (a count or a ratio)
    FieldSite site;
    bool is_signed;                ///< values of both signs around 0 (a diverging colour map)
    std::string_view description;  ///< one line: how it is computed
    /// A stored field's property ("v:ply:deviation"); empty for the computed ones.
    std::string_view property = {};
};

/// Every field, in the order `--field` and the viewer list them.
std::span<const FieldInfo> field_infos();
/// The field called `name`, or nullptr.
const FieldInfo* find_field(std::string_view name);

/// The scalar vertex and face properties `mesh` carries — a PLY file's columns such as
/// `meshedit compare --field`'s deviation, a library user's numbers — as fields: each is named
/// by its property without the "v:"/"f:" and "ply:" prefixes ("v:ply:deviation" → "deviation"),
/// or with "ply:" kept where that would take a computed field's name. The MeshEdit's own
/// attributes (materials, the Loop overlay) are not fields. The pointers stay valid for the
/// program's life: one FieldInfo per property name and site, made on first sight.
std::vector<const FieldInfo*> stored_fields(const Mesh& mesh);
/// Every field of `mesh`: the computed ones (field_infos()), then its stored ones.
std::vector<const FieldInfo*> mesh_fields(const Mesh& mesh);
/// The field of `mesh` called `name`, computed or stored, or nullptr.
const FieldInfo* find_field(const Mesh& mesh, std::string_view name);
/// "gauss mean … deviation": the names of mesh_fields(mesh), for messages.
std::string field_names(const Mesh& mesh, std::string_view separator = " ");

struct FieldOptions {
    /// `distance`: the vertex distances are measured from (the selection in the viewer).
    Vertex source{0};
};

/// The values of field `info` by element index of its site. O(size of the mesh); distance
/// is Dijkstra over the edges, O(E log V). A stored field reads its property (NaN for every
/// element when the mesh no longer has it).
std::vector<double> compute_field(const Mesh& mesh, const FieldInfo& info,
                                  const FieldOptions& options = {});

/// Summary of a field's finite values.
struct FieldStats {
    std::size_t count = 0;  ///< finite values
    double min = 0.0, mean = 0.0, max = 0.0;
};
FieldStats field_stats(std::span<const double> values);

/// The value below which `fraction` (0…1) of the finite values lie (nearest rank); 0 for
/// none. For clamping a colour map's range to percentiles.
double field_percentile(std::span<const double> values, double fraction);

/// A field's values at `element` of any kind (the viewer's hover): its own value when it is of
/// the field's site; otherwise those of the site's elements it touches — a face's corners or
/// sides, an edge's ends or faces, a halfedge's edge, head or face, a vertex's edges or faces
/// — in the mesh's order around it. Empty for none or a deleted element.
std::vector<std::pair<ElementRef, double>> field_values_at(const Mesh& mesh, FieldSite site,
                                                           std::span<const double> values,
                                                           ElementRef element);

/// The sum of the angle defects (2π − the angles at each interior vertex; π − them at a
/// boundary vertex) over every vertex: 2π times the Euler characteristic, exactly up to
/// rounding, on any mesh (discrete Gauss–Bonnet).
double total_angle_defect(const Mesh& mesh);

/// The surface area (the display triangulation's).
double surface_area(const Mesh& mesh);

}  // namespace meshedit
