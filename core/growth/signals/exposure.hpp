#pragma once
// growth.exposure (docs/algorithm.md §5.9): each vertex's light, from the
// shadow the other vertices cast on a voxel grid (Palubicki et al. 2009,
// "Self-organizing tree models for image synthesis"). A vertex in voxel
// (I, J, K) casts shadow 2^-d on every voxel (I + dx, J + dy, K − d) with
// |dx|, |dy| ≤ d, for d = 0 .. depth (its own voxel included, d = 0); a
// vertex's exposure is clamp((full_shade − s + 1) / full_shade, 0, 1), s the
// shadow on its voxel. Every shadow is a sum of integer counts times powers
// of two, so it is exact: the result depends on no summation order.
#include "core/mesh/mesh.hpp"

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace morphogen {

struct ExposureParams {
    double cell = 1.0;         // growth.exposure_cell: voxel edge length
    int depth = 4;             // growth.exposure_depth: d = 0 .. depth
    double full_shade = 32.0;  // growth.exposure_full_shade: shadow beyond a vertex's own that makes it dark
};

// Voxel indices are floor(coordinate / cell), clamped to ±2^40 (beyond that
// a coordinate is absurd, and the clamp keeps index arithmetic in range).
inline constexpr double kMaxVoxelIndex = 1099511627776.0;  // 2^40

struct Voxel {
    std::int64_t i = 0, j = 0, k = 0;  // k is up (z)
    bool operator==(const Voxel&) const = default;
};
struct VoxelHash {
    std::size_t operator()(const Voxel& v) const noexcept;
};

// The voxel of a position.
Voxel voxel_of(const Vec3& position, double cell);

// Buffers reused from step to step (no allocation once they have grown).
struct ExposureWorkspace {
    std::vector<Voxel> voxels;                          // each vertex's voxel
    std::vector<std::int32_t> prefix_counts;            // one summed-area table per level
    std::unordered_map<Voxel, int, VoxelHash> sparse;   // the fallback: vertices per voxel
};

// exposure[i] for every position, as above. Where the vertices' bounding box
// of voxels is small (the usual case) the shadow comes from summed-area
// tables of vertex counts, one per level, in O(V · depth); a sprawling box
// falls back to a hash map of counts, O(V · depth³). Both give the same bits.
void compute_exposure(std::span<const Vec3> positions, const ExposureParams& params, ExposureWorkspace& workspace,
                      std::vector<double>& exposure);

// The same with the summed-area tables allowed only up to `max_table_cells`
// cells (0: always the hash map); for tests of both paths.
void compute_exposure(std::span<const Vec3> positions, const ExposureParams& params, ExposureWorkspace& workspace,
                      std::vector<double>& exposure, std::uint64_t max_table_cells);

}  // namespace morphogen
