// Foliage cards (see leaf_cards.hpp).
#include "engine/leaf_cards.hpp"

#include "core/mesh/vertex_normals.hpp"
#include "engine/body_inside.hpp"
#include "engine/plant_colour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

namespace morphogen {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// A uniform number in [0, 1) for draw `k` of vertex `v`: a function of
// (seed, v, k) only, so no order of evaluation can change it.
double unit_hash(std::uint64_t seed, int v, int k) {
    const std::uint64_t h = splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(v) * 4 + static_cast<std::uint64_t>(k)));
    return static_cast<double>(h >> 11) * 0x1.0p-53;
}

std::string number_text(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// Points bucketed by cells of edge `cell`: the points within `cell` of a
// place are in its cell or the 26 around it.
class PointGrid {
public:
    explicit PointGrid(double cell) : cell_(cell) {}
    void add(const Vec3& p, int index) { cells_[key(p, 0, 0, 0)].push_back({p, index}); }
    // Calls visit(point, index) for every point within `cell` of p, and more.
    template <class Visit>
    void visit_near(const Vec3& p, Visit&& visit) const {
        for (long long di = -1; di <= 1; ++di)
            for (long long dj = -1; dj <= 1; ++dj)
                for (long long dk = -1; dk <= 1; ++dk) {
                    const auto found = cells_.find(key(p, di, dj, dk));
                    if (found == cells_.end()) continue;
                    for (const auto& [q, index] : found->second) visit(q, index);
                }
    }

private:
    std::uint64_t key(const Vec3& p, long long di, long long dj, long long dk) const {
        const auto at = [&](double x, long long d) {
            return static_cast<std::uint64_t>(static_cast<long long>(std::floor(x / cell_)) + d);
        };
        return splitmix64(at(p.x(), di)) ^ splitmix64(at(p.y(), dj) * 3 + 1) ^ splitmix64(at(p.z(), dk) * 5 + 2);
    }
    double cell_;
    std::unordered_map<std::uint64_t, std::vector<std::pair<Vec3, int>>> cells_;
};

// A unit tangent at normal n pointing as nearly up (+z) as the surface allows.
Vec3 up_tangent(const Vec3& n) {
    Vec3 t = Vec3::UnitZ() - n * n.z();
    if (t.norm() < 1e-6) t = Vec3::UnitX() - n * n.x();
    return t.normalized();
}

}  // namespace

std::string leaf_params_problem(const LeafParams& params, std::string_view size_name, std::string_view density_name) {
    if (!(params.size > 0.0 && params.size <= kMaxLeafSize))
        return std::string(size_name) + " " + number_text(params.size) +
               ": must be a fraction of the plant's height above 0 and at most " + number_text(kMaxLeafSize);
    if (!(params.density > 0.0 && params.density <= 1.0))
        return std::string(density_name) + " " + number_text(params.density) +
               ": must be a fraction of the eligible vertices above 0 and at most 1";
    return {};
}

std::uint64_t leaf_seed(std::string_view genome_hash) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const char c : genome_hash) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    return h;
}

std::vector<LeafCard> leaf_cards(const LeafInputs& in, const LeafParams& params) {
    if (const std::string problem = leaf_params_problem(params, "leaf size", "leaf density"); !problem.empty())
        throw std::invalid_argument(problem);
    const std::size_t n = in.placed.positions.size();
    if (in.birth_steps.size() != n)
        throw std::invalid_argument("leaf cards: " + std::to_string(in.birth_steps.size()) + " birth steps for " +
                                    std::to_string(n) + " vertices");
    if (!in.light.empty() && in.light.size() != n)
        throw std::invalid_argument("leaf cards: " + std::to_string(in.light.size()) + " light values for " +
                                    std::to_string(n) + " vertices");
    if (n == 0 || in.steps <= 0) return {};
    double lo = in.placed.positions[0].z(), hi = lo;
    for (const Vec3& p : in.placed.positions) lo = std::min(lo, p.z()), hi = std::max(hi, p.z());
    if (!(hi > lo)) return {};
    const double length = params.size * (hi - lo);
    const std::vector<Vec3> normals = vertex_normals(in.placed);

    std::vector<LeafCard> candidates;
    for (std::size_t v = 0; v < n; ++v) {
        const int vi = static_cast<int>(v);
        const double young = static_cast<double>(in.birth_steps[v]) / in.steps;
        const double light = in.light.empty() ? (in.placed.positions[v].z() - lo) / (hi - lo) : in.light[v];
        if (young < kLeafYoung || !(light >= kLeafLight) || normals[v] == Vec3::Zero()) continue;
        const double key = unit_hash(in.seed, vi, 0);
        if (key >= params.density) continue;
        const Vec3& nv = normals[v];
        const double turn = (unit_hash(in.seed, vi, 1) * 2.0 - 1.0) * std::numbers::pi / 3.0;  // ±60°
        const double lift = (25.0 + 25.0 * unit_hash(in.seed, vi, 2)) * std::numbers::pi / 180.0;
        const Vec3 t0 = up_tangent(nv);
        const Vec3 t = t0 * std::cos(turn) + nv.cross(t0) * std::sin(turn);
        LeafCard card;
        card.vertex = vi;
        card.key = key;
        card.base = in.placed.positions[v] + nv * (kLeafLiftOffset * length);
        card.axis = (t * std::cos(lift) + nv * std::sin(lift)).normalized();
        card.across = nv.cross(t).normalized();
        card.normal = card.axis.cross(card.across).normalized();
        card.length = length;
        candidates.push_back(card);
    }
    std::ranges::sort(candidates, [](const LeafCard& a, const LeafCard& b) {
        return a.key != b.key ? a.key < b.key : a.vertex < b.vertex;
    });
    // Candidates in order of key: one that stands within half a card of a
    // card placed already, or that reaches into the body (its base's corners,
    // middle or tip inside: a fold of the surface over it, or a hollow), is skipped.
    const BodyInside body(in.placed, length);
    PointGrid anchors(length / 2.0);
    std::vector<LeafCard> cards;
    for (const LeafCard& card : candidates) {
        const Vec3& anchor = in.placed.positions[static_cast<std::size_t>(card.vertex)];
        bool near = false;
        anchors.visit_near(anchor, [&](const Vec3& q, int) { near = near || (q - anchor).norm() < length / 2.0; });
        if (near) continue;
        const Vec3 tip = card.base + card.axis * length, half = card.across * (kLeafAspect * length / 2.0);
        const Vec3 blade[] = {card.base, card.base + half, card.base - half, card.base + card.axis * (length / 2.0),
                              tip, tip + half, tip - half};
        if (std::ranges::any_of(blade, [&](const Vec3& p) { return body.inside(p); })) continue;
        anchors.add(anchor, card.vertex);
        cards.push_back(card);
    }
    return cards;
}

std::vector<double> leaf_light(const GrowthState& state, const GrowthParams& params) {
    if (params.mode != GrowthMode::branching) return {};
    return final_exposure(state.mesh, ExposureParams{.cell = params.exposure_cell,
                                                     .depth = params.exposure_depth,
                                                     .full_shade = params.exposure_full_shade});
}

LeafMesh leaf_mesh(std::span<const LeafCard> cards, std::size_t count, double scale, std::span<const float> anchor_wind) {
    count = std::min(count, cards.size());
    LeafMesh out;
    out.mesh.positions.reserve(4 * count);
    out.mesh.faces.reserve(2 * count);
    out.uv.reserve(8 * count);
    if (!anchor_wind.empty()) out.wind.reserve(16 * count);
    for (std::size_t c = 0; c < count; ++c) {
        const LeafCard& card = cards[c];
        const double length = card.length * scale;
        const Vec3 half = card.across * (kLeafAspect * length / 2.0);
        const Vec3 tip = card.base + card.axis * length;
        const int first = static_cast<int>(out.mesh.positions.size());
        out.mesh.positions.insert(out.mesh.positions.end(), {card.base - half, card.base + half, tip + half, tip - half});
        // Wound so that each triangle's normal is the card's (axis x across).
        out.mesh.faces.push_back({first, first + 2, first + 1});
        out.mesh.faces.push_back({first, first + 3, first + 2});
        out.uv.insert(out.uv.end(), {0.0f, 1.0f, 1.0f, 1.0f, 1.0f, 0.0f, 0.0f, 0.0f});
        if (anchor_wind.empty()) continue;
        const std::size_t at = 4 * static_cast<std::size_t>(card.vertex);
        if (at + 4 > anchor_wind.size()) throw std::invalid_argument("leaf cards: wind data for fewer vertices");
        for (int corner = 0; corner < 4; ++corner) {
            out.wind.insert(out.wind.end(), anchor_wind.begin() + static_cast<std::ptrdiff_t>(at),
                            anchor_wind.begin() + static_cast<std::ptrdiff_t>(at + 4));
            if (corner >= 2) out.wind[out.wind.size() - 3] = 1.0f;  // the tip flutters fully
        }
    }
    return out;
}

LodLeaves lod_leaves(std::size_t cards, double fraction) {
    if (cards == 0) return {};
    fraction = std::clamp(fraction, 1e-9, 1.0);
    const auto count = static_cast<std::size_t>(std::llround(fraction * static_cast<double>(cards)));
    return {.count = std::clamp<std::size_t>(count, 1, cards),
            .scale = std::min(std::sqrt(1.0 / fraction), kMaxLodLeafScale)};
}

}  // namespace morphogen
