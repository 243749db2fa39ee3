#include "core/growth/branching.hpp"

#include "core/mesh/vertex_normals.hpp"

#include <cstddef>

namespace morphogen {

namespace {

// v / |v|, or zero where |v| is at most 1e-12 (no direction to speak of).
Vec3 unit_or_zero(const Vec3& v) {
    const double length = v.norm();
    return length > 1e-12 ? Vec3(v / length) : Vec3::Zero();
}

}  // namespace

void update_activity(std::span<std::uint8_t> active, std::span<const double> outputs, int N) {
    for (std::size_t i = 0; i < active.size(); ++i) {
        const double w = outputs[i * static_cast<std::size_t>(N) + kSwitchChannel];
        if (active[i] != 0 && w < kStopBelow) active[i] = 0;
        else if (active[i] == 0 && w > kStartAbove) active[i] = 1;
    }
}

void steer_directions(std::span<Vec3> directions, const TriMesh& mesh, std::span<const double> outputs, int N,
                      std::span<const int> neighbour_offsets, std::span<const int> neighbours, double turn_rate,
                      std::vector<Vec3>& scratch) {
    // scratch[i] holds vertex i's normal, then its new direction (each normal
    // serves its own vertex only); the directions are written at the end, as
    // every vertex turns from the old ones.
    vertex_normals(mesh.view(), scratch);
    const Vec3 up(0.0, 0.0, 1.0);
    for (std::size_t i = 0; i < directions.size(); ++i) {
        const Vec3& h = directions[i];
        Vec3 mean = Vec3::Zero();
        const int first = neighbour_offsets[i], last = neighbour_offsets[i + 1];
        for (int k = first; k < last; ++k) mean += directions[neighbours[k]];
        if (last > first) mean /= static_cast<double>(last - first);
        const Vec3 apart = unit_or_zero(h - mean);
        const double* w = outputs.data() + i * static_cast<std::size_t>(N);
        const Vec3 target = (2.0 * w[kTurnNormalChannel] - 1.0) * scratch[i] + (2.0 * w[kTurnUpChannel] - 1.0) * up +
                            (2.0 * w[kTurnApartChannel] - 1.0) * apart;
        const Vec3 turned = h + turn_rate * target;
        const double length = turned.norm();
        scratch[i] = length > 1e-12 ? Vec3(turned / length) : h;
    }
    std::copy(scratch.begin(), scratch.end(), directions.begin());
}

}  // namespace morphogen
