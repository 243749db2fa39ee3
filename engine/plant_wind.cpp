#include "engine/plant_wind.hpp"

#include "engine/plant_frame.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>
#include <utility>

namespace morphogen {

namespace {

// Each vertex's neighbours, in ascending order (so the result never depends
// on the order of the faces around a vertex).
std::vector<std::vector<int>> neighbours_of(MeshView mesh) {
    std::vector<std::vector<int>> out(mesh.positions.size());
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            out[f[k]].push_back(f[(k + 1) % 3]);
            out[f[k]].push_back(f[(k + 2) % 3]);
        }
    for (std::vector<int>& list : out) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return out;
}

// Shortest paths along the edges from the foot (every vertex within
// kFootBand of the height above the lowest point): distances and the
// predecessor of each vertex (-1 at the foot and where no path reaches).
struct FootPaths {
    std::vector<double> distance;
    std::vector<int> parent;
};

FootPaths paths_from_foot(MeshView mesh, const std::vector<std::vector<int>>& neighbours) {
    const std::size_t n = mesh.positions.size();
    double top = 0;
    for (const Vec3& p : mesh.positions) top = std::max(top, p.z());
    FootPaths paths{std::vector<double>(n, std::numeric_limits<double>::infinity()), std::vector<int>(n, -1)};
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t v = 0; v < n; ++v)
        if (mesh.positions[v].z() <= kFootBand * top) paths.distance[v] = 0, queue.emplace(0.0, static_cast<int>(v));
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > paths.distance[v]) continue;
        for (int u : neighbours[v]) {
            const double through = d + (mesh.positions[u] - mesh.positions[v]).norm();
            if (through < paths.distance[u]) {
                paths.distance[u] = through;
                paths.parent[u] = v;
                queue.emplace(through, u);
            }
        }
    }
    return paths;
}

// log(1 + carried) / log(1 + n), carried = the vertices whose path to the
// foot runs through v (v included), then averaged with the neighbours twice.
std::vector<double> stiffness_of(const FootPaths& paths, const std::vector<std::vector<int>>& neighbours) {
    const std::size_t n = paths.distance.size();
    std::vector<int> order(n);
    for (std::size_t v = 0; v < n; ++v) order[v] = static_cast<int>(v);
    // Farthest first, so every vertex is counted before its predecessor.
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return paths.distance[a] > paths.distance[b]; });
    std::vector<double> carried(n, 1.0);
    for (int v : order)
        if (paths.parent[v] >= 0) carried[paths.parent[v]] += carried[v];
    std::vector<double> stiffness(n);
    for (std::size_t v = 0; v < n; ++v) stiffness[v] = std::log1p(carried[v]) / std::log1p(static_cast<double>(n));
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<double> smoothed(n);
        for (std::size_t v = 0; v < n; ++v) {
            double sum = stiffness[v];
            for (int u : neighbours[v]) sum += stiffness[u];
            smoothed[v] = sum / static_cast<double>(neighbours[v].size() + 1);
        }
        stiffness = std::move(smoothed);
    }
    return stiffness;
}

float unit(double value) { return static_cast<float>(std::clamp(value, 0.0, 1.0)); }

}  // namespace

std::vector<float> plant_wind(MeshView placed, std::span<const int> birth_steps, int steps) {
    const std::size_t n = placed.positions.size();
    if (birth_steps.size() != n) throw std::invalid_argument("plant_wind: one birth step per vertex is needed");
    const std::vector<std::vector<int>> neighbours = neighbours_of(placed);
    FootPaths paths = paths_from_foot(placed, neighbours);
    double farthest = 0;
    for (double d : paths.distance)
        if (std::isfinite(d)) farthest = std::max(farthest, d);
    for (double& d : paths.distance)
        if (!std::isfinite(d)) d = farthest;  // a part no path reaches sways as the farthest tip
    const std::vector<double> stiffness = stiffness_of(paths, neighbours);

    std::vector<float> wind;
    wind.reserve(4 * n);
    for (std::size_t v = 0; v < n; ++v) {
        const double reach = farthest > 0 ? paths.distance[v] / farthest : 0.0;
        const Vec3& p = placed.positions[v];
        double phase = std::atan2(p.y(), p.x()) / (2 * std::numbers::pi);
        if (phase < 0) phase += 1;
        wind.push_back(unit(reach * reach));
        wind.push_back(unit(steps > 0 ? static_cast<double>(birth_steps[v]) / steps : 0.0));
        wind.push_back(unit(phase));
        wind.push_back(unit(stiffness[v]));
    }
    return wind;
}

std::optional<WindPreset> wind_preset_named(std::string_view name) {
    for (std::size_t i = 0; i < std::size(kWindPresetNames); ++i)
        if (kWindPresetNames[i] == name) return static_cast<WindPreset>(i);
    return std::nullopt;
}

std::string_view wind_preset_name(WindPreset preset) { return kWindPresetNames[static_cast<std::size_t>(preset)]; }

namespace {
// The channels `channels` (indices into bend, flutter, phase, stiffness) of
// every vertex, as one attribute.
VertexAttribute wind_channels(std::span<const float> wind, std::string name, std::initializer_list<int> channels) {
    VertexAttribute attribute{.name = std::move(name), .components = static_cast<int>(channels.size()), .values = {}};
    attribute.values.reserve(wind.size() / 4 * channels.size());
    for (std::size_t v = 0; v < wind.size() / 4; ++v)
        for (const int channel : channels) attribute.values.push_back(wind[4 * v + static_cast<std::size_t>(channel)]);
    return attribute;
}
}  // namespace

std::vector<VertexAttribute> wind_preset_attributes(std::span<const float> wind, std::span<const WindPreset> presets) {
    if (wind.size() % 4 != 0) throw std::invalid_argument("wind presets: wind data needs 4 values per vertex");
    enum { bend, flutter, phase, stiffness };
    std::vector<VertexAttribute> out;
    const auto asked = [&](WindPreset preset) { return std::find(presets.begin(), presets.end(), preset) != presets.end(); };
    if (asked(WindPreset::color)) out.push_back(wind_channels(wind, "COLOR_0", {flutter, phase, bend, stiffness}));
    if (asked(WindPreset::uv)) {
        out.push_back(wind_channels(wind, "TEXCOORD_0", {bend, flutter}));
        out.push_back(wind_channels(wind, "TEXCOORD_1", {phase, stiffness}));
    }
    if (asked(WindPreset::godot)) out.push_back(wind_channels(wind, "_CUSTOM0", {bend, flutter, phase, stiffness}));
    return out;
}

}  // namespace morphogen
