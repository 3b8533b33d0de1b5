// ShownPoints' queries (region_pick.h): the tiles a region covers, each taken whole, left, or
// read point by point where the region's border crosses it. The points are built in
// region_pick.cpp, with the depth buffer they come from.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "meshedit/overlay/region_pick.h"
#include "region_shapes.h"

namespace meshedit {

template <class Classify, class Inside>
std::vector<ElementRef> ShownPoints::select(const Mesh& mesh, glm::vec2 lo, glm::vec2 hi,
                                            const Classify& classify, const Inside& inside) const {
    std::vector<std::uint64_t> bits((elements_ + 63) / 64, 0);
    const auto take = [&](std::uint32_t i) { bits[i >> 6] |= std::uint64_t{1} << (i & 63); };
    // The tiles [lo, hi] touches, one more on each side (a point on a tile's right side
    // belongs to the next tile; the classifiers decide exactly).
    if (std::isfinite(lo.x) && std::isfinite(lo.y) && std::isfinite(hi.x) && std::isfinite(hi.y)) {
        const glm::vec2 most(static_cast<float>(width_ + kTile),
                             static_cast<float>(height_ + kTile));
        const glm::vec2 first = glm::clamp(lo, glm::vec2(0.0f), most) / static_cast<float>(kTile);
        const glm::vec2 last = glm::clamp(hi, glm::vec2(0.0f), most) / static_cast<float>(kTile);
        const int tx0 = std::max(0, static_cast<int>(first.x) - 1);
        const int ty0 = std::max(0, static_cast<int>(first.y) - 1);
        const int tx1 = std::min(tiles_x_ - 1, static_cast<int>(last.x) + 1);
        const int ty1 = std::min(tiles_y_ - 1, static_cast<int>(last.y) + 1);
        for (int ty = ty0; ty <= ty1; ++ty) {
            for (int tx = tx0; tx <= tx1; ++tx) {
                const std::size_t t = static_cast<std::size_t>(ty) * tiles_x_ + tx;
                if (starts_[t] == starts_[t + 1]) {
                    continue;
                }
                const glm::vec2 a(static_cast<float>(tx * kTile), static_cast<float>(ty * kTile));
                const Cover cover = classify(a, a + static_cast<float>(kTile));
                for (std::uint32_t i = starts_[t]; i < starts_[t + 1] && cover != Cover::Outside;
                     ++i) {
                    if (cover == Cover::Inside || inside(points_[i].at)) {
                        take(points_[i].index);
                    }
                }
            }
        }
    }
    const auto has = [&](std::uint32_t i) { return (bits[i >> 6] >> (i & 63) & 1) != 0; };
    if (kind_ == ElementRef::Kind::Edge) {
        return region::edges_between(mesh, has);
    }
    std::vector<ElementRef> out;
    for (std::size_t w = 0; w < bits.size(); ++w) {
        for (std::uint64_t word = bits[w]; word != 0; word &= word - 1) {
            const auto i = static_cast<std::uint32_t>(w * 64 + std::countr_zero(word));
            out.push_back(kind_ == ElementRef::Kind::Face ? ElementRef::face(Face(i))
                                                          : ElementRef::vertex(Vertex(i)));
        }
    }
    return out;
}

std::vector<ElementRef> ShownPoints::in_box(const Mesh& mesh, glm::vec2 a, glm::vec2 b) const {
    const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b);
    return select(
        mesh, lo, hi,
        [&](glm::vec2 ta, glm::vec2 tb) {
            if (tb.x < lo.x || ta.x > hi.x || tb.y < lo.y || ta.y > hi.y) {
                return Cover::Outside;
            }
            return ta.x >= lo.x && tb.x <= hi.x && ta.y >= lo.y && tb.y <= hi.y ? Cover::Inside
                                                                                : Cover::Mixed;
        },
        [&](glm::vec2 q) { return q.x >= lo.x && q.x <= hi.x && q.y >= lo.y && q.y <= hi.y; });
}

std::vector<ElementRef> ShownPoints::in_lasso(const Mesh& mesh,
                                              const std::vector<glm::vec2>& outline) const {
    if (outline.size() < 3) {
        return {};
    }
    const glm::vec2 lo = region::lower(outline), hi = region::upper(outline);
    // Tiles an edge of the outline comes within a pixel of are decided point by point; every
    // other tile lies wholly on one side, which its centre tells.
    std::vector<std::uint8_t> crossed(static_cast<std::size_t>(tiles_x_) * tiles_y_, 0);
    const float size = static_cast<float>(kTile);
    const auto column = [&](float x) {
        return std::clamp(static_cast<int>(std::floor(x / size)), 0, tiles_x_ - 1);
    };
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const glm::vec2 p = outline[j], q = outline[i];
        // Row by row of tiles: the part of the edge within a pixel of the row's band, and
        // the tiles within a pixel of that part.
        const float top = std::min(p.y, q.y) - 1.0f, bottom = std::max(p.y, q.y) + 1.0f;
        const int row0 = std::clamp(static_cast<int>(std::floor(top / size)), 0, tiles_y_ - 1);
        const int row1 = std::clamp(static_cast<int>(std::floor(bottom / size)), 0, tiles_y_ - 1);
        for (int ty = row0; ty <= row1; ++ty) {
            float left = std::min(p.x, q.x), right = std::max(p.x, q.x);
            if (std::abs(q.y - p.y) > 1e-3f) {
                const auto x_at = [&](float y) {
                    const float t = std::clamp((y - p.y) / (q.y - p.y), 0.0f, 1.0f);
                    return p.x + t * (q.x - p.x);
                };
                const float a = x_at(static_cast<float>(ty) * size - 1.0f);
                const float b = x_at(static_cast<float>(ty + 1) * size + 1.0f);
                left = std::min(a, b);
                right = std::max(a, b);
            }
            for (int tx = column(left - 1.0f); tx <= column(right + 1.0f); ++tx) {
                crossed[static_cast<std::size_t>(ty) * tiles_x_ + tx] = 1;
            }
        }
    }
    // The edges that can cross a point's rightward ray: those spanning its row of tiles in y
    // (the parity is the same as over every edge, each edge tested the same way).
    std::vector<std::vector<std::uint32_t>> spanning(static_cast<std::size_t>(tiles_y_));
    for (std::size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
        const float top = std::min(outline[i].y, outline[j].y) / size;
        const float bottom = std::max(outline[i].y, outline[j].y) / size;
        for (int ty = std::clamp(static_cast<int>(std::floor(top)), 0, tiles_y_ - 1);
             ty <= std::clamp(static_cast<int>(std::floor(bottom)), 0, tiles_y_ - 1); ++ty) {
            spanning[static_cast<std::size_t>(ty)].push_back(static_cast<std::uint32_t>(i));
        }
    }
    const auto inside = [&](glm::vec2 q) {
        if (q.x < lo.x || q.x > hi.x || q.y < lo.y || q.y > hi.y) {
            return false;
        }
        const int row = std::clamp(static_cast<int>(q.y) / kTile, 0, tiles_y_ - 1);
        bool odd = false;
        for (const std::uint32_t i : spanning[static_cast<std::size_t>(row)]) {
            const glm::vec2 &a = outline[i], &b = outline[i == 0 ? outline.size() - 1 : i - 1];
            if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) {
                odd = !odd;
            }
        }
        return odd;
    };
    return select(
        mesh, lo, hi,
        [&](glm::vec2 ta, glm::vec2 tb) {
            const int tx = static_cast<int>(ta.x) / kTile, ty = static_cast<int>(ta.y) / kTile;
            if (crossed[static_cast<std::size_t>(ty) * tiles_x_ + tx] != 0) {
                return Cover::Mixed;
            }
            return region::in_outline(outline, (ta + tb) * 0.5f) ? Cover::Inside : Cover::Outside;
        },
        inside);
}

std::vector<ElementRef> ShownPoints::in_circle(const Mesh& mesh, glm::vec2 centre,
                                               float radius) const {
    const glm::vec2 r(radius, radius);
    return select(
        mesh, centre - r, centre + r,
        [&](glm::vec2 ta, glm::vec2 tb) {
            // A hundredth of a pixel clear of the circle: rounding cannot move a point across.
            const glm::vec2 nearest = glm::clamp(centre, ta, tb) - centre;
            if (glm::length(nearest) > radius + 0.01f) {
                return Cover::Outside;
            }
            const glm::vec2 farthest = glm::max(glm::abs(ta - centre), glm::abs(tb - centre));
            return glm::length(farthest) < radius - 0.01f ? Cover::Inside : Cover::Mixed;
        },
        [&](glm::vec2 q) { return region::in_circle(centre, radius, q); });
}

}  // namespace meshedit
