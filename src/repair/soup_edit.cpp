// Removing faces, renumbering vertices and turning faces over, with every attribute of the
// soup kept in step (soup_edit.h).

#include "soup_edit.h"

#include <algorithm>
#include <limits>
#include <type_traits>
#include <utility>

#include "meshedit/core/number_text.h"

namespace meshedit::repair_detail {
namespace {

// Keeps values[i] where keep[i], in order. Arrays whose size does not match the elements
// are ones the builder ignores (soup_attributes.cpp): they are left as they are.
template <class T>
void keep_if(std::vector<T>& values, const std::vector<bool>& keep) {
    if (values.size() != keep.size()) {
        return;
    }
    std::size_t out = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (keep[i]) {
            values[out++] = std::move(values[i]);
        }
    }
    values.resize(out);
}

// values[new_index[v]] = values[v] for the lowest v of each new index.
template <class T>
void renumber(std::vector<T>& values, const std::vector<std::uint32_t>& new_index,
              std::size_t n_new) {
    if (values.size() != new_index.size()) {
        return;
    }
    std::vector<T> out(n_new);
    std::vector<bool> set(n_new, false);
    for (std::size_t v = 0; v < values.size(); ++v) {
        const std::uint32_t to = new_index[v];
        if (to != kGone && !set[to]) {
            out[to] = std::move(values[v]);
            set[to] = true;
        }
    }
    values = std::move(out);
}

}  // namespace

// `fraction` of the box's diagonal without overflow: scaled by the largest extent first, and
// clamped to the largest double when the product is past it (a distance larger than the
// mesh, which merges everything within reach).
double fraction_of_diagonal(const BoundingBox& box, double fraction) {
    if (box.is_empty() || fraction == 0.0) {
        return 0.0;
    }
    const Vec3 extent = box.max * 0.5 - box.min * 0.5;  // half, so it cannot overflow
    const double largest = std::max({extent.x, extent.y, extent.z});
    if (largest == 0.0) {
        return 0.0;
    }
    const double distance = fraction * largest * (2.0 * norm(extent / largest));
    return std::min(distance, std::numeric_limits<double>::max());
}

double merge_distance(const PolygonSoup& soup, const MergeTolerance& tolerance) {
    if (!tolerance.relative) {
        return tolerance.value;
    }
    const std::vector<bool> used = used_vertices(soup);
    BoundingBox box;
    for (std::size_t v = 0; v < soup.positions.size(); ++v) {
        if (used[v]) {
            box.add(soup.positions[v]);
        }
    }
    return fraction_of_diagonal(box, tolerance.value);
}

std::vector<bool> used_vertices(const PolygonSoup& soup) {
    std::vector<bool> used(soup.positions.size(), false);
    for (const std::uint32_t v : soup.indices) {
        if (v < used.size()) {
            used[v] = true;
        }
    }
    return used;
}

void keep_faces(MeshSoup& soup, const std::vector<bool>& keep) {
    PolygonSoup& s = soup.soup;
    const std::size_t n_faces = s.n_faces();
    std::vector<bool> keep_corner(s.indices.size(), false);
    for (std::size_t f = 0; f < n_faces; ++f) {
        if (keep[f]) {
            std::fill(keep_corner.begin() + s.face_offsets[f],
                      keep_corner.begin() + s.face_offsets[f + 1], true);
        }
    }
    keep_if(soup.corner_texcoords, keep_corner);
    keep_if(soup.corner_texcoords1, keep_corner);
    keep_if(soup.corner_normals, keep_corner);
    keep_if(soup.face_materials, keep);
    keep_if(soup.face_colors, keep);
    for (UserProperty& property : soup.face_properties) {
        keep_if(property.values, keep);
    }
    std::vector<std::uint32_t> offsets{0};
    offsets.reserve(n_faces + 1);
    std::size_t out = 0;
    for (std::size_t f = 0; f < n_faces; ++f) {
        if (!keep[f]) {
            continue;
        }
        for (std::uint32_t c = s.face_offsets[f]; c < s.face_offsets[f + 1]; ++c) {
            s.indices[out++] = s.indices[c];
        }
        offsets.push_back(static_cast<std::uint32_t>(out));
    }
    s.indices.resize(out);
    s.face_offsets = std::move(offsets);
}

void rebuild_faces(MeshSoup& soup, const std::vector<NewCorner>& corners,
                   const std::vector<std::uint32_t>& offsets,
                   const std::vector<std::uint32_t>& source) {
    PolygonSoup& s = soup.soup;
    const auto blend = [](const auto& values, const NewCorner& k) {
        return values[k.c] * (1.0 - k.t) + values[k.d] * k.t;
    };
    const auto corner_values = [&](auto& values, auto finish) {
        if (values.size() != s.indices.size()) {
            return;  // absent (or ignored by the builder, as keep_if leaves them)
        }
        std::remove_reference_t<decltype(values)> out;
        out.reserve(corners.size());
        for (const NewCorner& k : corners) {
            out.push_back(finish(blend(values, k)));
        }
        values = std::move(out);
    };
    const auto same = [](const auto& x) { return x; };
    corner_values(soup.corner_texcoords, same);
    corner_values(soup.corner_texcoords1, same);
    corner_values(soup.corner_normals, [](const Vec3& n) {
        const double length = norm(n);
        return length > 0.0 ? n / length : n;
    });
    const auto face_values = [&](auto& values) {
        if (values.size() != s.n_faces()) {
            return;
        }
        std::remove_reference_t<decltype(values)> out;
        out.reserve(source.size());
        for (const std::uint32_t f : source) {
            out.push_back(values[f]);
        }
        values = std::move(out);
    };
    face_values(soup.face_materials);
    face_values(soup.face_colors);
    for (UserProperty& property : soup.face_properties) {
        face_values(property.values);
    }
    s.indices.resize(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) {
        s.indices[i] = corners[i].vertex;
    }
    s.face_offsets = offsets;
}

void keep_corners(MeshSoup& soup, const std::vector<bool>& keep) {
    PolygonSoup& s = soup.soup;
    keep_if(soup.corner_texcoords, keep);
    keep_if(soup.corner_texcoords1, keep);
    keep_if(soup.corner_normals, keep);
    std::size_t out = 0;
    std::uint32_t begin = 0;
    for (std::size_t f = 0; f < s.n_faces(); ++f) {
        const std::uint32_t end = s.face_offsets[f + 1];
        for (std::uint32_t c = begin; c < end; ++c) {
            if (keep[c]) {
                s.indices[out++] = s.indices[c];
            }
        }
        begin = end;
        s.face_offsets[f + 1] = static_cast<std::uint32_t>(out);
    }
    s.indices.resize(out);
}

std::size_t renumber_vertices(MeshSoup& soup, const std::vector<std::uint32_t>& new_index,
                              std::size_t n_new) {
    renumber(soup.soup.positions, new_index, n_new);
    renumber(soup.normals, new_index, n_new);
    renumber(soup.colors, new_index, n_new);
    for (UserProperty& property : soup.vertex_properties) {
        renumber(property.values, new_index, n_new);
    }
    for (std::uint32_t& v : soup.soup.indices) {
        if (v < new_index.size()) {
            v = new_index[v];  // a used vertex is never kGone
        }
    }
    std::size_t dropped = 0;
    std::size_t out = 0;
    for (std::size_t i = 0; i < soup.creases.size(); ++i) {
        auto [a, b] = soup.creases[i];
        a = a < new_index.size() ? new_index[a] : kGone;
        b = b < new_index.size() ? new_index[b] : kGone;
        if (a == kGone || b == kGone || a == b) {
            ++dropped;
            continue;
        }
        soup.creases[out++] = {a, b};
    }
    soup.creases.resize(out);
    return dropped;
}

std::size_t remove_unused_vertices(MeshSoup& soup, const std::vector<bool>& used_before,
                                   std::size_t& dropped_creases) {
    const std::vector<bool> used = used_vertices(soup.soup);
    std::vector<std::uint32_t> new_index(used.size(), kGone);
    std::uint32_t next = 0;
    std::size_t removed = 0;
    for (std::size_t v = 0; v < used.size(); ++v) {
        if (used[v] || !used_before[v]) {
            new_index[v] = next++;
        } else {
            ++removed;
        }
    }
    if (removed > 0) {
        dropped_creases += renumber_vertices(soup, new_index, next);
    }
    return removed;
}

void reverse_face(MeshSoup& soup, std::size_t f) {
    const std::size_t first = soup.soup.face_offsets[f] + 1;
    const std::size_t end = soup.soup.face_offsets[f + 1];
    if (end <= first) {
        return;
    }
    const auto reverse = [&](auto& values) {
        if (values.size() == soup.soup.indices.size()) {
            std::reverse(values.begin() + first, values.begin() + end);
        }
    };
    reverse(soup.soup.indices);
    reverse(soup.corner_texcoords);
    reverse(soup.corner_texcoords1);
    reverse(soup.corner_normals);
}

void drop_repeated_corners(std::vector<std::uint32_t>& corners) {
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    while (corners.size() > 1 && corners.front() == corners.back()) {
        corners.pop_back();
    }
}

Degenerate degenerate(const std::vector<Vec3>& positions,
                      const std::vector<std::uint32_t>& corners) {
    const std::size_t n = corners.size();
    if (n < 3) {
        return Degenerate::Few;
    }
    std::vector<std::uint32_t> sorted = corners;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
        return Degenerate::Pinched;
    }
    // Twice the area vector (Newell, about the first corner so that a face far from the
    // origin keeps its digits) against the longest side.
    const Vec3 origin = positions[corners[0]];
    Vec3 area;
    double longest = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 a = positions[corners[i]] - origin;
        const Vec3 b = positions[corners[(i + 1) % n]] - origin;
        area += cross(a, b);
        longest = std::max(longest, sqrnorm(b - a));
    }
    return 0.5 * norm(area) <= 1e-12 * longest ? Degenerate::Flat : Degenerate::None;
}

void note_first(RepairResult& result, std::uint32_t index) {
    if (result.first.size() < kRepairShown) {
        result.first.push_back(index);
    }
}

std::string count_of(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string listed(const RepairResult& result) {
    std::string text;
    for (std::size_t i = 0; i < result.first.size(); ++i) {
        text += (i == 0 ? ": " : ", ") + std::to_string(result.first[i]);
    }
    if (result.count > result.first.size() && !result.first.empty()) {
        text += ", …";
    }
    return text;
}

std::string also_removed(std::size_t vertices, std::size_t creases) {
    std::string text;
    if (vertices > 0) {
        text += "; removed " + count_of(vertices, "vertex", "vertices") + " only they used";
    }
    if (creases > 0) {
        text += "; dropped " + count_of(creases, "crease mark", "crease marks") +
                " whose ends went with them";
    }
    return text;
}

std::string number(double x) {
    return readable_number(x);  // a report is read by a person; the verbs keep exact amounts
}

}  // namespace meshedit::repair_detail
