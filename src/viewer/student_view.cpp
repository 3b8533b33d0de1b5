// The side by side's marks: a box around each differing element, drawn through the surface
// (the element may lie behind it), padded so that a single edge or vertex gets a visible
// frame, and captions over the two halves.

#include <algorithm>
#include <array>

#include "meshedit/viewer/student_view.h"

namespace meshedit::viewer {

namespace {

constexpr Color kCaption{1.0f, 1.0f, 1.0f, 1.0f};

// The positions of `element`'s corners.
BoundingBox element_box(const Mesh& mesh, const ElementRef& element) {
    BoundingBox box;
    if (!is_live(mesh, element)) {
        return box;
    }
    switch (element.kind) {
        case ElementRef::Kind::Vertex:
            box.add(mesh.position(Vertex(element.index)));
            break;
        case ElementRef::Kind::Edge:
        case ElementRef::Kind::Halfedge: {
            const Halfedge h(element.kind == ElementRef::Kind::Edge ? 2 * element.index
                                                                    : element.index);
            box.add(mesh.position(mesh.from_vertex(h)));
            box.add(mesh.position(mesh.to_vertex(h)));
            break;
        }
        case ElementRef::Kind::Face:
            for (const Vertex v : mesh.vertices(Face(element.index))) {
                box.add(mesh.position(v));
            }
            break;
        case ElementRef::Kind::None:
            break;
    }
    return box;
}

void add_box(BoundingBox box, double pad, OverlayBatch& out) {
    for (int i = 0; i < 3; ++i) {
        box.min[i] -= pad;
        box.max[i] += pad;
    }
    const auto corner = [&](int bits) {
        return Vec3((bits & 1) ? box.max.x : box.min.x, (bits & 2) ? box.max.y : box.min.y,
                    (bits & 4) ? box.max.z : box.min.z);
    };
    // The 12 edges: between corners that differ in one bit.
    for (int a = 0; a < 8; ++a) {
        for (const int bit : {1, 2, 4}) {
            if ((a & bit) == 0) {
                out.lines.push_back({corner(a), corner(a | bit), kComparisonFrame, 3.0f, true});
            }
        }
    }
}

}  // namespace

void add_comparison_marks(const Mesh& mesh, const StudentComparison& comparison,
                          OverlayBatch& out) {
    BoundingBox halves[2];
    for (const Vertex v : mesh.vertices()) {
        halves[v.idx() >= comparison.reference_from ? 1 : 0].add(mesh.position(v));
    }
    const double diagonal = mesh.bounds().diagonal();
    const std::vector<Vec3>* normals[2] = {&comparison.yours_normals,
                                           &comparison.reference_normals};
    for (const Vertex v : mesh.vertices()) {
        const bool right = v.idx() >= comparison.reference_from;
        const std::size_t i = right ? v.idx() - comparison.reference_from : v.idx();
        if (i < normals[right]->size()) {
            const Vec3& p = mesh.position(v);
            // Through the surface: a reversed normal points inside.
            out.lines.push_back(
                {p, p + 0.08 * diagonal * (*normals[right])[i], kComparisonNormal, 2.0f, true});
        }
    }
    const ElementRef framed[2] = {comparison.yours, comparison.reference};
    const char* captions[2] = {"yours", "reference"};
    for (int side = 0; side < 2; ++side) {
        if (!halves[side].is_empty()) {
            const Vec3 top(halves[side].center().x, halves[side].max.y + 0.04 * diagonal,
                           halves[side].center().z);
            out.labels.push_back(
                {top, captions[side], kCaption, OverlayBatch::Label::Side::Centre, true});
        }
        const BoundingBox box = element_box(mesh, framed[side]);
        if (box.is_empty()) {
            continue;
        }
        const double pad = 0.05 * box.diagonal() + 0.015 * diagonal;
        add_box(box, pad, out);
        const std::string text =
            comparison.invariant.empty() ? "first difference" : "broken: " + comparison.invariant;
        out.labels.push_back({Vec3(box.max.x + pad, box.max.y + pad, box.center().z), text,
                              kComparisonFrame, OverlayBatch::Label::Side::Right, false});
    }
}

}  // namespace meshedit::viewer
