// ElementRef helpers: liveness, names, remapping through garbage collection.

#include "meshedit/core/element_ref.h"

#include <vector>

namespace meshedit {
namespace {

using Kind = ElementRef::Kind;

template <class H>
ElementRef remap_one(const std::vector<H>& map, std::uint32_t index, Kind kind) {
    if (index >= map.size() || !map[index].is_valid()) {
        return {};
    }
    return {kind, map[index].idx()};
}

}  // namespace

std::size_t elements_size(const Mesh& mesh, Kind kind) {
    switch (kind) {
        case Kind::Vertex:
            return mesh.vertices_size();
        case Kind::Edge:
            return mesh.edges_size();
        case Kind::Halfedge:
            return mesh.halfedges_size();
        case Kind::Face:
            return mesh.faces_size();
        case Kind::None:
            break;
    }
    return 0;
}

const char* kind_name(Kind kind) {
    switch (kind) {
        case Kind::Vertex:
            return "vertex";
        case Kind::Edge:
            return "edge";
        case Kind::Halfedge:
            return "halfedge";
        case Kind::Face:
            return "face";
        case Kind::None:
            break;
    }
    return "nothing";
}

bool is_live(const Mesh& mesh, const ElementRef& element) {
    if (element.kind == Kind::None || element.index >= elements_size(mesh, element.kind)) {
        return false;
    }
    switch (element.kind) {
        case Kind::Vertex:
            return !mesh.is_deleted(Vertex(element.index));
        case Kind::Edge:
            return !mesh.is_deleted(Edge(element.index));
        case Kind::Halfedge:
            return !mesh.is_deleted(Halfedge(element.index));
        case Kind::Face:
            return !mesh.is_deleted(Face(element.index));
        case Kind::None:
            break;
    }
    return false;
}

std::string to_string(const ElementRef& element) {
    if (element.kind == Kind::None) {
        return "none";
    }
    return std::string(kind_name(element.kind)) + " " + std::to_string(element.index);
}

std::string describe(const Mesh& mesh, const ElementRef& element) {
    if (element.kind == Kind::None) {
        return "nothing selected";
    }
    std::string out = to_string(element);
    if (element.index >= elements_size(mesh, element.kind)) {
        return out + " (not in the mesh)";
    }
    if (!is_live(mesh, element)) {
        return out + " (deleted)";
    }
    if (element.kind == Kind::Edge || element.kind == Kind::Halfedge) {
        const Halfedge h = element.kind == Kind::Edge ? Mesh::halfedge(Edge(element.index), 0)
                                                      : Halfedge(element.index);
        const char* joint = element.kind == Kind::Edge ? "–" : "→";
        out += " (" + std::to_string(mesh.from_vertex(h).idx()) + joint +
               std::to_string(mesh.to_vertex(h).idx()) + ")";
    }
    return out;
}

ElementRef remap(const ElementRef& element, const GarbageCollectionMap& map) {
    switch (element.kind) {
        case Kind::Vertex:
            return remap_one(map.vertices, element.index, Kind::Vertex);
        case Kind::Edge:
            return remap_one(map.edges, element.index, Kind::Edge);
        case Kind::Halfedge:
            return remap_one(map.halfedges, element.index, Kind::Halfedge);
        case Kind::Face:
            return remap_one(map.faces, element.index, Kind::Face);
        case Kind::None:
            break;
    }
    return {};
}

}  // namespace meshedit
