#include "core/growth/signals/exposure.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen {

std::size_t VoxelHash::operator()(const Voxel& v) const noexcept {
    // Three multiplicative hashes folded together (splitmix64's finaliser).
    std::uint64_t h = static_cast<std::uint64_t>(v.i) * 0x9E3779B97F4A7C15ULL ^
                      static_cast<std::uint64_t>(v.j) * 0xC2B2AE3D27D4EB4FULL ^
                      static_cast<std::uint64_t>(v.k) * 0x165667B19E3779F9ULL;
    h ^= h >> 31;
    h *= 0xBF58476D1CE4E5B9ULL;
    return static_cast<std::size_t>(h ^ (h >> 29));
}

Voxel voxel_of(const Vec3& position, double cell) {
    const auto index = [cell](double coordinate) {
        // NaN cannot occur (positions are finite, cell > 0); ±inf clamps.
        return static_cast<std::int64_t>(std::clamp(std::floor(coordinate / cell), -kMaxVoxelIndex, kMaxVoxelIndex));
    };
    return {index(position.x()), index(position.y()), index(position.z())};
}

namespace {

double exposure_of_shadow(double shadow, double full_shade) {
    return std::clamp((full_shade - shadow + 1.0) / full_shade, 0.0, 1.0);
}

// The summed-area tables of vertex counts over the voxels' bounding box, one
// per level: table(l, r, c) counts the vertices of level k0 + l with
// i < i0 + c and j < j0 + r.
class CountTables {
public:
    CountTables(std::span<const Voxel> voxels, const Voxel& low, const Voxel& high, std::vector<std::int32_t>& storage)
        : low_(low), columns_(high.i - low.i + 1), rows_(high.j - low.j + 1), levels_(high.k - low.k + 1),
          table_(storage) {
        table_.assign(static_cast<std::size_t>((columns_ + 1) * (rows_ + 1) * levels_), 0);
        for (const Voxel& v : voxels) ++at(v.k - low_.k, v.j - low_.j + 1, v.i - low_.i + 1);
        for (std::int64_t l = 0; l < levels_; ++l)
            for (std::int64_t r = 1; r <= rows_; ++r)
                for (std::int64_t c = 1; c <= columns_; ++c)
                    at(l, r, c) += at(l, r - 1, c) + at(l, r, c - 1) - at(l, r - 1, c - 1);
    }

    // Vertices in voxels (i + dx, j + dy, k) with |dx|, |dy| ≤ radius.
    std::int64_t box(const Voxel& centre, std::int64_t radius) const {
        const std::int64_t l = centre.k - low_.k;
        if (l >= levels_) return 0;
        const std::int64_t c = centre.i - low_.i, r = centre.j - low_.j;
        const std::int64_t c0 = std::max<std::int64_t>(c - radius, 0), c1 = std::min(c + radius, columns_ - 1) + 1;
        const std::int64_t r0 = std::max<std::int64_t>(r - radius, 0), r1 = std::min(r + radius, rows_ - 1) + 1;
        return at(l, r1, c1) - at(l, r0, c1) - at(l, r1, c0) + at(l, r0, c0);
    }

private:
    std::int32_t& at(std::int64_t l, std::int64_t r, std::int64_t c) {
        return table_[static_cast<std::size_t>((l * (rows_ + 1) + r) * (columns_ + 1) + c)];
    }
    std::int32_t at(std::int64_t l, std::int64_t r, std::int64_t c) const {
        return table_[static_cast<std::size_t>((l * (rows_ + 1) + r) * (columns_ + 1) + c)];
    }

    Voxel low_;
    std::int64_t columns_, rows_, levels_;
    std::vector<std::int32_t>& table_;
};

// Vertices in voxels (i + dx, j + dy, k) with |dx|, |dy| ≤ radius, looked up one voxel at a time.
std::int64_t sparse_box(const std::unordered_map<Voxel, int, VoxelHash>& counts, const Voxel& centre,
                        std::int64_t radius) {
    std::int64_t total = 0;
    for (std::int64_t dj = -radius; dj <= radius; ++dj)
        for (std::int64_t di = -radius; di <= radius; ++di) {
            const auto found = counts.find({centre.i + di, centre.j + dj, centre.k});
            if (found != counts.end()) total += found->second;
        }
    return total;
}

// Σ_{d = 0..depth} 2^-d · (vertices within the level-(k + d) box of radius d),
// added in the order of d; every term and partial sum is exact.
template <class Box>
double shadow_at(const Voxel& v, int depth, const Box& box) {
    double shadow = 0.0;
    for (int d = 0; d <= depth; ++d)
        shadow += std::ldexp(static_cast<double>(box(Voxel{v.i, v.j, v.k + d}, d)), -d);
    return shadow;
}

}  // namespace

void compute_exposure(std::span<const Vec3> positions, const ExposureParams& params, ExposureWorkspace& workspace,
                      std::vector<double>& exposure, std::uint64_t max_table_cells) {
    std::vector<Voxel>& voxels = workspace.voxels;
    voxels.resize(positions.size());
    std::transform(positions.begin(), positions.end(), voxels.begin(),
                   [&](const Vec3& p) { return voxel_of(p, params.cell); });
    exposure.resize(positions.size());
    if (voxels.empty()) return;
    Voxel low = voxels[0], high = voxels[0];
    for (const Voxel& v : voxels) {
        low = {std::min(low.i, v.i), std::min(low.j, v.j), std::min(low.k, v.k)};
        high = {std::max(high.i, v.i), std::max(high.j, v.j), std::max(high.k, v.k)};
    }
    // In double: the product of three spans of up to 2^41 overflows 64 bits.
    const double table_cells = static_cast<double>(high.i - low.i + 2) * static_cast<double>(high.j - low.j + 2) *
                               static_cast<double>(high.k - low.k + 1);
    if (table_cells <= static_cast<double>(max_table_cells)) {
        const CountTables tables(voxels, low, high, workspace.prefix_counts);
        const auto box = [&](const Voxel& centre, std::int64_t radius) { return tables.box(centre, radius); };
        for (std::size_t i = 0; i < voxels.size(); ++i)
            exposure[i] = exposure_of_shadow(shadow_at(voxels[i], params.depth, box), params.full_shade);
        return;
    }
    auto& counts = workspace.sparse;
    counts.clear();
    for (const Voxel& v : voxels) ++counts[v];
    const auto box = [&](const Voxel& centre, std::int64_t radius) { return sparse_box(counts, centre, radius); };
    for (std::size_t i = 0; i < voxels.size(); ++i)
        exposure[i] = exposure_of_shadow(shadow_at(voxels[i], params.depth, box), params.full_shade);
}

void compute_exposure(std::span<const Vec3> positions, const ExposureParams& params, ExposureWorkspace& workspace,
                      std::vector<double>& exposure) {
    // Tables of up to 64 cells a vertex (and at least 2^18: 1 MiB) cost less than the lookups they save.
    const std::uint64_t max_cells = std::max<std::uint64_t>(std::uint64_t{1} << 18, 64 * positions.size());
    compute_exposure(positions, params, workspace, exposure, max_cells);
}

}  // namespace morphogen
