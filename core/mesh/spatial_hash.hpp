#pragma once
// A uniform grid of axis-aligned boxes, hashed (docs/algorithm.md §5.7): the
// broad phase of the collision check. Each box is listed in every cell it
// overlaps, with a copy of the box; a query visits the cells a box overlaps
// and reports what is listed there. build() lists many boxes at once, each
// bucket's entries side by side (a query reads them in order, not by
// pointer); insert() adds one later (a face that changed is listed again).
// Nothing is removed until the next build(), so a caller must expect stale
// and repeated entries. Deterministic: a fixed history gives a fixed order.
#include "core/mesh/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace morphogen {

struct Box3 {
    Vec3 lo, hi;
    static Box3 of(const Vec3& a, const Vec3& b, const Vec3& c) {
        return {a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)};
    }
    Box3 merged(const Box3& o) const { return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)}; }
    // Grown by `margin` (>= 0) on every side; rounding may grow it a little
    // more, never less (lo - m rounds to at most lo, hi + m to at least hi).
    Box3 inflated(double margin) const { return {lo.array() - margin, hi.array() + margin}; }
    // Whether `o` lies inside this box (closed).
    bool contains(const Box3& o) const { return (lo.array() <= o.lo.array()).all() && (o.hi.array() <= hi.array()).all(); }
    // Closed boxes: touching counts as overlapping (as for CGAL's boxes).
    // Without short-circuits: the answer is a coin toss for a grid's
    // candidates, and one branch instead of six mispredicts less.
    bool overlaps(const Box3& o) const {
        return (lo.x() <= o.hi.x()) & (o.lo.x() <= hi.x()) & (lo.y() <= o.hi.y()) & (o.lo.y() <= hi.y()) &
               (lo.z() <= o.hi.z()) & (o.lo.z() <= hi.z());
    }
};

class SpatialHash {
public:
    // A cell edge about as large as the mean box, so no box spans more than
    // 17 cells a side (1 where every box is a point).
    static double cell_size_for(const std::vector<Box3>& boxes);
    // Lists boxes[i] as id i, and nothing else; cells of edge `cell_size`
    // (> 0, finite).
    void build(double cell_size, const std::vector<Box3>& boxes);
    // Lists `box` as `id` too.
    void insert(int id, const Box3& box);
    // Entries listed by build(), and by insert() since.
    std::size_t built_entries() const { return entries_.size(); }
    std::size_t late_entries() const { return late_.size(); }

    // Calls fn(id, listed_box) for every entry in the buckets of the cells
    // `box` overlaps. A bucket may also hold entries of other cells (hash
    // collisions); an id may come more than once, with an older box.
    template <class Fn>
    void for_each_candidate(const Box3& box, Fn&& fn) const {
        for_each_cell(box, [&](std::size_t b) {
            for (std::size_t e = start_[b]; e < start_[b + 1]; ++e) fn(entries_[e].id, entries_[e].box);
            for (int e = late_head_[b]; e >= 0; e = late_[e].next) fn(late_[e].id, late_[e].box);
        });
    }

private:
    struct Entry {
        Box3 box;
        int id;
    };
    struct LateEntry {
        Box3 box;
        int id, next;
    };
    // Clamped: a huge coordinate over a tiny cell would overflow the cast
    // (undefined); cells beyond the clamp merely share indices.
    std::int64_t coordinate(double v) const {
        return static_cast<std::int64_t>(std::clamp(std::floor(v * inverse_cell_), -0x1p62, 0x1p62));
    }
    // Calls fn(bucket) for each cell `box` overlaps.
    template <class Fn>
    void for_each_cell(const Box3& box, Fn&& fn) const {
        const std::int64_t x0 = coordinate(box.lo.x()), x1 = coordinate(box.hi.x());
        const std::int64_t y0 = coordinate(box.lo.y()), y1 = coordinate(box.hi.y());
        const std::int64_t z0 = coordinate(box.lo.z()), z1 = coordinate(box.hi.z());
        for (std::int64_t x = x0; x <= x1; ++x)
            for (std::int64_t y = y0; y <= y1; ++y)
                for (std::int64_t z = z0; z <= z1; ++z) fn(bucket(x, y, z));
    }
    std::size_t bucket(std::int64_t x, std::int64_t y, std::int64_t z) const {
        const auto h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                       static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^
                       static_cast<std::uint64_t>(z) * 0x165667B19E3779F9ull;
        return static_cast<std::size_t>(h >> 32) & mask_;
    }

    double inverse_cell_ = 1.0;
    std::size_t mask_ = 0;
    std::vector<std::size_t> start_;  // per bucket + 1: where its entries begin
    std::vector<Entry> entries_;      // from build(), bucket by bucket
    std::vector<int> late_head_;      // per bucket: the last insert()ed entry, -1 = none
    std::vector<LateEntry> late_;
    std::vector<std::size_t> fill_cursor_;  // build()'s scratch: each bucket's next free slot
};

}  // namespace morphogen
