#include "core/mesh/spatial_hash.hpp"

#include <algorithm>
#include <bit>

namespace morphogen {

double SpatialHash::cell_size_for(const std::vector<Box3>& boxes) {
    double extent_sum = 0.0, extent_max = 0.0;
    for (const Box3& box : boxes) {
        const double extent = (box.hi - box.lo).maxCoeff();
        extent_sum += extent;
        extent_max = std::max(extent_max, extent);
    }
    const double cell = std::max(extent_sum / static_cast<double>(std::max<std::size_t>(boxes.size(), 1)), extent_max / 16.0);
    return cell > 0.0 ? cell : 1.0;
}

void SpatialHash::build(double cell_size, const std::vector<Box3>& boxes) {
    inverse_cell_ = 1.0 / cell_size;
    // Twice as many buckets as entries: few cells share a bucket, so a query
    // reads little beyond its own cells.
    std::size_t listed = 0;
    for (const Box3& box : boxes) {
        const auto span = [&](double lo, double hi) { return static_cast<std::size_t>(coordinate(hi) - coordinate(lo) + 1); };
        listed += span(box.lo.x(), box.hi.x()) * span(box.lo.y(), box.hi.y()) * span(box.lo.z(), box.hi.z());
    }
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(2 * listed, 64));
    mask_ = buckets - 1;
    // Counting sort by bucket: count, prefix sums, fill.
    start_.assign(buckets + 1, 0);
    for (const Box3& box : boxes) for_each_cell(box, [&](std::size_t b) { ++start_[b + 1]; });
    for (std::size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
    entries_.resize(start_[buckets]);
    std::vector<std::size_t>& next = fill_cursor_;
    next.assign(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for_each_cell(boxes[i], [&](std::size_t b) { entries_[next[b]++] = {boxes[i], static_cast<int>(i)}; });
    late_head_.assign(buckets, -1);
    late_.clear();
}

void SpatialHash::insert(int id, const Box3& box) {
    for_each_cell(box, [&](std::size_t b) {
        late_.push_back({box, id, late_head_[b]});
        late_head_[b] = static_cast<int>(late_.size()) - 1;
    });
}

}  // namespace morphogen
