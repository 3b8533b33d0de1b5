#include "support/mesh_compare.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "meshedit/core/validate.h"

namespace meshedit::test {
namespace {

template <class H, class T>
bool same_array(const Mesh& a, const Mesh& b, const char* name, std::ostringstream& why) {
    const auto pa = a.get_property<H, T>(name);
    const auto pb = b.get_property<H, T>(name);
    if (!pa && !pb) {
        return true;
    }
    if (!pa || !pb || pa.vector() != pb.vector()) {
        why << "property '" << name << "' differs";
        return false;
    }
    return true;
}

}  // namespace

::testing::AssertionResult identical(const Mesh& actual, const Mesh& expected) {
    std::ostringstream why;
    if (actual.vertices_size() != expected.vertices_size() ||
        actual.edges_size() != expected.edges_size() ||
        actual.faces_size() != expected.faces_size()) {
        return ::testing::AssertionFailure()
               << "sizes differ: V/E/F " << actual.vertices_size() << "/" << actual.edges_size()
               << "/" << actual.faces_size() << " vs " << expected.vertices_size() << "/"
               << expected.edges_size() << "/" << expected.faces_size();
    }
    const bool same = same_array<Vertex, Vec3>(actual, expected, "v:position", why) &&
                      same_array<Vertex, Halfedge>(actual, expected, "v:halfedge", why) &&
                      same_array<Vertex, std::uint8_t>(actual, expected, "v:deleted", why) &&
                      same_array<Halfedge, Halfedge>(actual, expected, "h:next", why) &&
                      same_array<Halfedge, Halfedge>(actual, expected, "h:prev", why) &&
                      same_array<Halfedge, Vertex>(actual, expected, "h:vertex", why) &&
                      same_array<Halfedge, Face>(actual, expected, "h:face", why) &&
                      same_array<Edge, std::uint8_t>(actual, expected, "e:deleted", why) &&
                      same_array<Edge, std::uint8_t>(actual, expected, "e:crease", why) &&
                      same_array<Face, Halfedge>(actual, expected, "f:halfedge", why) &&
                      same_array<Face, std::uint8_t>(actual, expected, "f:deleted", why);
    if (!same) {
        return ::testing::AssertionFailure() << why.str();
    }
    return ::testing::AssertionSuccess();
}

namespace {

using Cycle = std::vector<Vec3>;

std::vector<Cycle> face_cycles(const Mesh& mesh) {
    std::vector<Cycle> out;
    for (Face f : mesh.faces()) {
        Cycle c;
        for (Vertex v : mesh.vertices(f)) {
            c.push_back(mesh.position(v));
        }
        out.push_back(std::move(c));
    }
    return out;
}

// Equal up to rotation (same orientation), each corner within `tol`. Rotations are tried
// rather than normalised, because choosing a "first" corner by exact comparison would
// depend on rounding.
bool close(const Cycle& a, const Cycle& b, double tol) {
    if (a.size() != b.size()) {
        return false;
    }
    const std::size_t k = a.size();
    for (std::size_t shift = 0; shift < k; ++shift) {
        bool all = true;
        for (std::size_t i = 0; i < k && all; ++i) {
            all = norm(a[i] - b[(i + shift) % k]) <= tol;
        }
        if (all) {
            return true;
        }
    }
    return false;
}

std::string describe(const Cycle& c) {
    std::ostringstream s;
    s << "(";
    for (std::size_t i = 0; i < c.size(); ++i) {
        s << (i ? " " : "") << "[" << c[i].x << "," << c[i].y << "," << c[i].z << "]";
    }
    s << ")";
    return s.str();
}

}  // namespace

::testing::AssertionResult same_faces_by_position(const Mesh& actual, const Mesh& expected,
                                                  double tol) {
    if (actual.n_vertices() != expected.n_vertices() || actual.n_faces() != expected.n_faces()) {
        return ::testing::AssertionFailure()
               << "counts differ: V/F " << actual.n_vertices() << "/" << actual.n_faces()
               << " vs expected " << expected.n_vertices() << "/" << expected.n_faces();
    }
    std::vector<Cycle> a = face_cycles(actual);
    std::vector<Cycle> b = face_cycles(expected);
    // Greedy matching with tolerance: small meshes only, O(F²) is fine in tests.
    std::vector<bool> used(b.size(), false);
    for (const Cycle& ca : a) {
        bool found = false;
        for (std::size_t j = 0; j < b.size() && !found; ++j) {
            if (!used[j] && close(ca, b[j], tol)) {
                used[j] = true;
                found = true;
            }
        }
        if (!found) {
            return ::testing::AssertionFailure()
                   << "face " << describe(ca) << " of the result is not in the expected mesh";
        }
    }
    return ::testing::AssertionSuccess();
}

std::vector<std::vector<std::uint32_t>> canonical_faces(const Mesh& mesh) {
    std::vector<std::vector<std::uint32_t>> out;
    for (Face f : mesh.faces()) {
        std::vector<std::uint32_t> c;
        for (Vertex v : mesh.vertices(f)) {
            c.push_back(v.idx());
        }
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.push_back(std::move(c));
    }
    std::sort(out.begin(), out.end());
    return out;
}

::testing::AssertionResult is_valid(const Mesh& mesh) {
    if (auto error = validate(mesh)) {
        return ::testing::AssertionFailure()
               << "validate(): [" << error->invariant << "] " << error->message;
    }
    return ::testing::AssertionSuccess();
}

}  // namespace meshedit::test
