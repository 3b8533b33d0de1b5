// add_problem_marks() (overlay.h): the Problems panel's places drawn in the view, so that the
// repairs a load made and what is still wrong are seen where they are. GL-free.

#include <cstdint>
#include <vector>

#include "meshedit/core/normals.h"
#include "meshedit/overlay/overlay.h"

namespace meshedit {
namespace {

// Every face of the part (faces joined across edges) that `seed` is in.
std::vector<Face> part_of(const Mesh& mesh, Face seed) {
    std::vector<std::uint8_t> seen(mesh.faces_size(), 0);
    std::vector<Face> faces{seed};
    seen[seed.idx()] = 1;
    for (std::size_t i = 0; i < faces.size(); ++i) {
        for (const Halfedge h : mesh.halfedges(faces[i])) {
            const Face g = mesh.face(Mesh::twin(h));
            if (g.is_valid() && seen[g.idx()] == 0) {
                seen[g.idx()] = 1;
                faces.push_back(g);
            }
        }
    }
    return faces;
}

}  // namespace

void add_problem_marks(const Mesh& mesh, const ProblemReport& report, const OverlayStyle& style,
                       OverlayBatch& out) {
    for (const Problem& p : report.problems) {
        if (!is_live(mesh, p.where)) {
            continue;  // a dropped face has no place; a stale report names deleted elements
        }
        const Color& color = style.problems[static_cast<std::size_t>(p.kind)];
        switch (p.kind) {
            case ProblemKind::LoadCut:
                if (p.where.kind == ElementRef::Kind::Vertex) {
                    out.points.push_back(
                        {mesh.position(Vertex(p.where.index)), color, style.vertex_size_px, true});
                }
                break;
            case ProblemKind::Hole: {
                const Edge e(p.where.index);
                const Halfedge h = mesh.is_boundary(mesh.halfedge(e, 0)) ? mesh.halfedge(e, 0)
                                                                         : mesh.halfedge(e, 1);
                for (const Halfedge x : mesh.loop(h)) {
                    out.lines.push_back({mesh.position(mesh.from_vertex(x)),
                                         mesh.position(mesh.to_vertex(x)), color,
                                         style.problem_width_px, true});
                }
                break;
            }
            case ProblemKind::DegenerateFace:
                // No area to tint (and no normal to lift a tint by): a dot and its sides.
                out.points.push_back(
                    {face_centroid(mesh, Face(p.where.index)), color, style.vertex_size_px, true});
                for (const Halfedge x : mesh.halfedges(Face(p.where.index))) {
                    out.lines.push_back({mesh.position(mesh.from_vertex(x)),
                                         mesh.position(mesh.to_vertex(x)), color,
                                         style.edge_width_px, true});
                }
                break;
            case ProblemKind::InsideOut:
                // Its faces' normals point inward, so a tint (lifted along them) would sink
                // under the surface: its edges instead, through the surface.
                for (const Face f : part_of(mesh, Face(p.where.index))) {
                    for (const Halfedge x : mesh.halfedges(f)) {
                        if (x < Mesh::twin(x) || mesh.is_boundary(Mesh::twin(x))) {
                            out.lines.push_back({mesh.position(mesh.from_vertex(x)),
                                                 mesh.position(mesh.to_vertex(x)), color,
                                                 style.edge_width_px, true});
                        }
                    }
                }
                break;
            case ProblemKind::SmallPart: {
                std::vector<ElementRef> faces;
                for (const Face f : part_of(mesh, Face(p.where.index))) {
                    faces.push_back(ElementRef::face(f));
                }
                add_element_highlights(mesh, faces, color, style, out);
                break;
            }
            case ProblemKind::SelfIntersection:
                add_element_highlight(mesh, p.where, color, style, out);
                break;
        }
    }
}

}  // namespace meshedit
