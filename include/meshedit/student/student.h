#pragma once
/// \file
/// The student API (docs/student.md): CS184's MeshEdit vocabulary — HalfedgeIter, VertexIter,
/// `h->twin()`, `v->position`, `mesh.newHalfedge()` — for the six tasks of the course, and the
/// table of functions a student library exports to `meshedit grade`.
///
/// The student's mesh is a plain copy of a MeshEdit mesh in the course's terms (a halfedge
/// stores its twin, its source vertex, its edge and its face; every boundary loop has a face
/// marked isBoundary()). The grader copies a mesh in, calls the student's function, writes
/// the result back through MeshEdit's setters and checks it, so this header needs nothing of
/// MeshEdit's and a student library links nothing. Everything here is inline.
///
/// Stable: kStudentAbiVersion changes whenever a layout or a signature here changes, and the
/// grader refuses a library built against another version.

#include <cmath>
#include <cstddef>
#include <deque>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace meshedit::student {

/// The version of this header's layouts and signatures a library was built with.
inline constexpr int kStudentAbiVersion = 1;

struct Vector2D {
    double x = 0.0, y = 0.0;
    Vector2D() = default;
    Vector2D(double x_, double y_) : x(x_), y(y_) {}
    Vector2D operator+(const Vector2D& o) const { return {x + o.x, y + o.y}; }
    Vector2D operator-(const Vector2D& o) const { return {x - o.x, y - o.y}; }
    Vector2D operator*(double s) const { return {x * s, y * s}; }
    Vector2D operator/(double s) const { return {x / s, y / s}; }
    Vector2D& operator+=(const Vector2D& o) { return *this = *this + o; }
    double norm() const { return std::sqrt(x * x + y * y); }
};
inline Vector2D operator*(double s, const Vector2D& v) {
    return v * s;
}

struct Vector3D {
    double x = 0.0, y = 0.0, z = 0.0;
    Vector3D() = default;
    Vector3D(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    Vector3D operator+(const Vector3D& o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vector3D operator-(const Vector3D& o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vector3D operator-() const { return {-x, -y, -z}; }
    Vector3D operator*(double s) const { return {x * s, y * s, z * s}; }
    Vector3D operator/(double s) const { return {x / s, y / s, z / s}; }
    Vector3D& operator+=(const Vector3D& o) { return *this = *this + o; }
    Vector3D& operator-=(const Vector3D& o) { return *this = *this - o; }
    Vector3D& operator*=(double s) { return *this = *this * s; }
    Vector3D& operator/=(double s) { return *this = *this / s; }
    double norm2() const { return x * x + y * y + z * z; }
    double norm() const { return std::sqrt(norm2()); }
    /// This vector scaled to length 1 (unchanged when it is zero).
    Vector3D unit() const {
        const double n = norm();
        return n > 0.0 ? *this / n : *this;
    }
    void normalize() { *this = unit(); }
};
inline Vector3D operator*(double s, const Vector3D& v) {
    return v * s;
}
inline double dot(const Vector3D& a, const Vector3D& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vector3D cross(const Vector3D& a, const Vector3D& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

class HalfedgeMesh;
class Halfedge;
class Vertex;
class Edge;
class Face;

/// A handle to an element of a HalfedgeMesh: the mesh and the element's index. Handles stay
/// valid while elements are added (unlike pointers into a growing array); `++` steps to the
/// next live element. A default handle is unset; dereferencing it throws std::logic_error.
template <class T>
class ElementIter {
public:
    ElementIter() = default;
    ElementIter(HalfedgeMesh* mesh, int index) : mesh_(mesh), index_(index) {}

    T* operator->() const;
    T& operator*() const { return *operator->(); }
    bool operator==(const ElementIter& o) const { return index_ == o.index_ && mesh_ == o.mesh_; }
    ElementIter& operator++();
    ElementIter operator++(int) {
        ElementIter old = *this;
        ++*this;
        return old;
    }
    /// The element's index in its mesh (-1 for an unset handle).
    int index() const { return index_; }
    bool isSet() const { return mesh_ != nullptr && index_ >= 0; }

private:
    HalfedgeMesh* mesh_ = nullptr;
    int index_ = -1;
};

using HalfedgeIter = ElementIter<Halfedge>;
using VertexIter = ElementIter<Vertex>;
using EdgeIter = ElementIter<Edge>;
using FaceIter = ElementIter<Face>;
// The course's const handles; here the same types.
using HalfedgeCIter = HalfedgeIter;
using VertexCIter = VertexIter;
using EdgeCIter = EdgeIter;
using FaceCIter = FaceIter;

/// A directed half of an edge. vertex() is where it starts (the course's convention); the
/// accessors return references, so `h->next() = g;` rewires.
class Halfedge {
public:
    HalfedgeIter& twin() { return twin_; }
    HalfedgeIter& next() { return next_; }
    VertexIter& vertex() { return vertex_; }
    EdgeIter& edge() { return edge_; }
    FaceIter& face() { return face_; }
    /// True when face() is a boundary loop.
    bool isBoundary() const;
    void setNeighbors(HalfedgeIter next, HalfedgeIter twin, VertexIter vertex, EdgeIter edge,
                      FaceIter face) {
        next_ = next;
        twin_ = twin;
        vertex_ = vertex;
        edge_ = edge;
        face_ = face;
    }
    bool deleted = false;  ///< set by HalfedgeMesh::deleteHalfedge()

private:
    HalfedgeIter twin_, next_;
    VertexIter vertex_;
    EdgeIter edge_;
    FaceIter face_;
};

class Vertex {
public:
    Vector3D position;
    Vector3D newPosition;  ///< scratch for Loop subdivision
    bool isNew = false;    ///< scratch for Loop subdivision
    bool deleted = false;
    /// One of the halfedges leaving this vertex.
    HalfedgeIter& halfedge() { return halfedge_; }
    /// True when one of its halfedges lies on a boundary loop.
    bool isBoundary() const;
    /// The number of edges at this vertex.
    int degree() const;

private:
    HalfedgeIter halfedge_;
};

class Edge {
public:
    Vector3D newPosition;  ///< scratch for Loop subdivision
    bool isNew = false;    ///< scratch for Loop subdivision
    bool deleted = false;
    /// Marked sharp in the file (MeshEdit's creases): Loop treats it like a boundary edge.
    bool isCrease = false;
    HalfedgeIter& halfedge() { return halfedge_; }
    /// True when either of its halfedges lies on a boundary loop.
    bool isBoundary() const;

private:
    HalfedgeIter halfedge_;
};

/// A face, or a boundary loop (isBoundary()): every halfedge has a face, as in the course.
class Face {
public:
    bool deleted = false;
    HalfedgeIter& halfedge() { return halfedge_; }
    bool isBoundary() const { return boundary_; }
    /// The unit normal of the face (Newell's sum of its corners' cross products).
    Vector3D normal() const;
    /// The number of its sides.
    int degree() const;

private:
    friend class HalfedgeMesh;
    HalfedgeIter halfedge_;
    bool boundary_ = false;
};

/// The mesh: four element lists, iteration over the live ones, allocation and deletion. A
/// new element starts unset (its handles unset, position zero); deleting only marks it.
class HalfedgeMesh {
public:
    HalfedgeMesh() = default;
    HalfedgeMesh(const HalfedgeMesh&) = delete;  // handles point at their mesh
    HalfedgeMesh& operator=(const HalfedgeMesh&) = delete;

    HalfedgeIter halfedgesBegin() { return first<Halfedge>(); }
    HalfedgeIter halfedgesEnd() { return {this, static_cast<int>(halfedges.size())}; }
    VertexIter verticesBegin() { return first<Vertex>(); }
    VertexIter verticesEnd() { return {this, static_cast<int>(vertices.size())}; }
    EdgeIter edgesBegin() { return first<Edge>(); }
    EdgeIter edgesEnd() { return {this, static_cast<int>(edges.size())}; }
    /// Faces, boundary loops skipped.
    FaceIter facesBegin() { return first<Face>(); }
    FaceIter facesEnd() { return {this, static_cast<int>(faces.size())}; }

    std::size_t nVertices() const { return live(vertices); }
    std::size_t nEdges() const { return live(edges); }
    std::size_t nHalfedges() const { return live(halfedges); }
    std::size_t nFaces() const;

    HalfedgeIter newHalfedge() { return append(halfedges); }
    VertexIter newVertex() { return append(vertices); }
    EdgeIter newEdge() { return append(edges); }
    FaceIter newFace() { return append(faces); }
    void deleteHalfedge(HalfedgeIter h) { h->deleted = true; }
    void deleteVertex(VertexIter v) { v->deleted = true; }
    void deleteEdge(EdgeIter e) { e->deleted = true; }
    void deleteFace(FaceIter f) { f->deleted = true; }

    /// For upsample(): flip and split as MeshEdit does them (the grader's, not yours, so that
    /// Loop is graded on its own). Handles you hold stay valid; new elements are appended.
    EdgeIter flipEdge(EdgeIter e) { return ops_->flip(*this, e); }
    VertexIter splitEdge(EdgeIter e) { return ops_->split(*this, e); }

    // The element lists, by index (handles index into them). A deque never moves its
    // elements, so a reference stays good while new ones are appended.
    std::deque<Halfedge> halfedges;
    std::deque<Vertex> vertices;
    std::deque<Edge> edges;
    std::deque<Face> faces;

    /// What flipEdge() and splitEdge() call; set by the grader.
    struct Operations {
        EdgeIter (*flip)(HalfedgeMesh&, EdgeIter) = nullptr;
        VertexIter (*split)(HalfedgeMesh&, EdgeIter) = nullptr;
        void* context = nullptr;
    };
    Operations* ops_ = nullptr;

    /// Marks `f` a boundary loop (the grader's copy-in).
    static void set_boundary(Face& f, bool boundary) { f.boundary_ = boundary; }
    template <class T>
    std::deque<T>& list();

private:
    template <class T>
    ElementIter<T> first() {
        ElementIter<T> it(this, -1);
        return ++it;
    }
    template <class T>
    static std::size_t live(const std::deque<T>& list) {
        std::size_t n = 0;
        for (const T& x : list) {
            n += x.deleted ? 0 : 1;
        }
        return n;
    }
    template <class T>
    ElementIter<T> append(std::deque<T>& list) {
        list.emplace_back();
        return {this, static_cast<int>(list.size()) - 1};
    }
};

template <>
inline std::deque<Halfedge>& HalfedgeMesh::list<Halfedge>() {
    return halfedges;
}
template <>
inline std::deque<Vertex>& HalfedgeMesh::list<Vertex>() {
    return vertices;
}
template <>
inline std::deque<Edge>& HalfedgeMesh::list<Edge>() {
    return edges;
}
template <>
inline std::deque<Face>& HalfedgeMesh::list<Face>() {
    return faces;
}

template <class T>
T* ElementIter<T>::operator->() const {
    if (mesh_ == nullptr || index_ < 0 ||
        static_cast<std::size_t>(index_) >= mesh_->template list<T>().size()) {
        throw std::logic_error("dereferenced an unset handle");
    }
    return &mesh_->template list<T>()[static_cast<std::size_t>(index_)];
}

template <class T>
ElementIter<T>& ElementIter<T>::operator++() {
    const auto& list = mesh_->template list<T>();
    const int size = static_cast<int>(list.size());
    do {
        ++index_;
        if (index_ >= size) {
            index_ = size;
            break;
        }
        const T& x = list[static_cast<std::size_t>(index_)];
        if constexpr (std::is_same_v<T, Face>) {
            if (!x.deleted && !x.isBoundary()) {
                break;
            }
        } else if (!x.deleted) {
            break;
        }
    } while (true);
    return *this;
}

inline bool Halfedge::isBoundary() const {
    return face_->isBoundary();
}
inline bool Edge::isBoundary() const {
    return halfedge_->isBoundary() || halfedge_->twin()->isBoundary();
}
inline bool Vertex::isBoundary() const {
    HalfedgeIter h = halfedge_;
    int guard = 0;
    do {
        if (h->isBoundary()) {
            return true;
        }
        h = h->twin()->next();
    } while (h != halfedge_ && ++guard < 1 << 20);
    return false;
}
inline int Vertex::degree() const {
    int n = 0;
    HalfedgeIter h = halfedge_;
    do {
        ++n;
        h = h->twin()->next();
    } while (h != halfedge_ && n < 1 << 20);
    return n;
}
inline Vector3D Face::normal() const {
    Vector3D sum;
    HalfedgeIter h = halfedge_;
    int guard = 0;
    do {
        const Vector3D& a = h->vertex()->position;
        const Vector3D& b = h->next()->vertex()->position;
        sum += cross(a, b);
        h = h->next();
    } while (h != halfedge_ && ++guard < 1 << 20);
    return sum.unit();
}
inline int Face::degree() const {
    int n = 0;
    HalfedgeIter h = halfedge_;
    do {
        ++n;
        h = h->next();
    } while (h != halfedge_ && n < 1 << 20);
    return n;
}
inline std::size_t HalfedgeMesh::nFaces() const {
    std::size_t n = 0;
    for (const Face& f : faces) {
        n += f.deleted || f.isBoundary() ? 0 : 1;
    }
    return n;
}

// ------------------------------------------------------------------ the six tasks

/// Task 1: one step of de Casteljau's algorithm: the points one level down at `t`.
std::vector<Vector2D> evaluate_step(const std::vector<Vector2D>& points, double t);
/// Task 2: the Bezier patch with `control_points[row][col]` at (u, v): each row is a curve
/// in u, the column of their points a curve in v.
Vector3D evaluate_patch(const std::vector<std::vector<Vector3D>>& control_points, double u,
                        double v);
/// Task 3: the area-weighted unit normal at `v`.
Vector3D vertex_normal(VertexCIter v);
/// Task 4: flips `e` inside its two triangles; a boundary edge is refused (nothing changes).
/// \return the flipped edge (or `e` when refused).
EdgeIter flip_edge(HalfedgeMesh& mesh, EdgeIter e);
/// Task 5: splits `e` at its midpoint. \return the new vertex.
VertexIter split_edge(HalfedgeMesh& mesh, EdgeIter e);
/// Task 6: one level of Loop subdivision in place.
void upsample(HalfedgeMesh& mesh);

/// What a student library exports through meshedit_student_tasks(); a null entry is a task
/// not handed in.
struct StudentTasks {
    int abi_version = kStudentAbiVersion;
    std::vector<Vector2D> (*evaluate_step)(const std::vector<Vector2D>&, double) = nullptr;
    Vector3D (*evaluate_patch)(const std::vector<std::vector<Vector3D>>&, double, double) = nullptr;
    Vector3D (*vertex_normal)(VertexCIter) = nullptr;
    EdgeIter (*flip_edge)(HalfedgeMesh&, EdgeIter) = nullptr;
    VertexIter (*split_edge)(HalfedgeMesh&, EdgeIter) = nullptr;
    void (*upsample)(HalfedgeMesh&) = nullptr;
};

}  // namespace meshedit::student

/// The name the grader looks up in the library.
#define MESHEDIT_STUDENT_ENTRY "meshedit_student_tasks"

/// Defines meshedit_student_tasks() returning the six functions above; one .cpp of the
/// library says MESHEDIT_STUDENT_REGISTER() once.
#define MESHEDIT_STUDENT_REGISTER()                                                          \
    extern "C" __attribute__((visibility("default"))) const meshedit::student::StudentTasks* \
    meshedit_student_tasks() {                                                               \
        static const meshedit::student::StudentTasks tasks{                                  \
            meshedit::student::kStudentAbiVersion, &meshedit::student::evaluate_step,        \
            &meshedit::student::evaluate_patch,    &meshedit::student::vertex_normal,        \
            &meshedit::student::flip_edge,         &meshedit::student::split_edge,           \
            &meshedit::student::upsample};                                                   \
        return &tasks;                                                                       \
    }
