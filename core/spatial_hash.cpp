#include "core/spatial_hash.hpp"

#include <bit>

namespace morphogen {

void SpatialHash::reset(double cell_size, std::size_t expected_entries) {
    inverse_cell_ = 1.0 / cell_size;
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(2 * expected_entries, 64));
    if (buckets > head_.size()) head_.resize(buckets);
    mask_ = head_.size() - 1;
    std::fill(head_.begin(), head_.end(), -1);
    entries_.clear();
}

void SpatialHash::insert(int id, const Box3& box) {
    const Cell lo = cell_of(box.lo), hi = cell_of(box.hi);
    for (std::int64_t x = lo.x; x <= hi.x; ++x)
        for (std::int64_t y = lo.y; y <= hi.y; ++y)
            for (std::int64_t z = lo.z; z <= hi.z; ++z) {
                const std::size_t b = bucket({x, y, z});
                entries_.push_back({id, head_[b]});
                head_[b] = static_cast<int>(entries_.size()) - 1;
            }
}

}  // namespace morphogen
