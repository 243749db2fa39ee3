#include "engine/plant_colour.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace morphogen {

double genome_tint(const GrowthState& state) {
    const int n = state.mesh.num_vertices();
    if (n == 0 || state.outputs_per_vertex == 0) return 0.5;
    const int channel = state.outputs_per_vertex - 1;
    double sum = 0.0;  // vertex order: the same bits for any thread count
    for (int v = 0; v < n; ++v) sum += state.output(v, channel);
    return std::clamp(sum / n, 0.0, 1.0);
}

namespace {

// Rotation of a colour about the grey axis by `angle` (a hue shift that
// keeps the colour's grey level), clamped to [0, 1].
Rgb rotate_hue(const Rgb& c, double angle) {
    const double cs = std::cos(angle), sn = std::sin(angle), k = (1.0 - cs) / 3.0, s = sn / std::sqrt(3.0);
    const double r = c[0], g = c[1], b = c[2];
    const double m[3][3] = {{cs + k, k - s, k + s}, {k + s, cs + k, k - s}, {k - s, k + s, cs + k}};
    Rgb out{};
    for (int i = 0; i < 3; ++i)
        out[i] = static_cast<float>(std::clamp(m[i][0] * r + m[i][1] * g + m[i][2] * b, 0.0, 1.0));
    return out;
}

void check_size(std::size_t got, std::size_t want, const char* what) {
    if (got != want)
        throw std::invalid_argument(std::string("plant colours: ") + what + " has " + std::to_string(got) +
                                    " entries for " + std::to_string(want) + " vertices");
}

}  // namespace

std::vector<float> colour_rgba(std::span<const Rgb> colours) {
    std::vector<float> out;
    out.reserve(4 * colours.size());
    for (const Rgb& c : colours) out.insert(out.end(), {c[0], c[1], c[2], 1.0f});
    return out;
}

std::vector<float> growth_colours(const GrowthState& state, std::span<const int> birth_steps,
                                  const GrowthParams& params, std::span<const double> exposure_known) {
    std::vector<double> exposure(exposure_known.begin(), exposure_known.end());
    if (params.mode == GrowthMode::branching && exposure.size() != state.mesh.positions().size())
        exposure = final_exposure(state.mesh, ExposureParams{.cell = params.exposure_cell,
                                                             .depth = params.exposure_depth,
                                                             .full_shade = params.exposure_full_shade});
    return colour_rgba(plant_colours({.positions = state.mesh.positions(),
                                      .birth_steps = birth_steps,
                                      .steps = state.steps_done,
                                      .active = state.active,
                                      .exposure = exposure,
                                      .tint = genome_tint(state)}));
}

std::vector<double> final_exposure(const TriMesh& mesh, const ExposureParams& params) {
    ExposureWorkspace workspace;
    std::vector<double> exposure;
    compute_exposure(mesh.positions(), params, workspace, exposure);
    return exposure;
}

std::vector<Rgb> plant_colours(const ColourInputs& in) {
    const std::size_t n = in.positions.size();
    check_size(in.birth_steps.size(), n, "birth_steps");
    if (!in.active.empty()) check_size(in.active.size(), n, "active");
    if (!in.exposure.empty()) check_size(in.exposure.size(), n, "exposure");
    // Height as a fraction of the plant's: the paper's mode's stand-in for light.
    double lo = 0.0, hi = 0.0;
    if (n > 0) {
        lo = hi = in.positions[0].z();
        for (const Vec3& p : in.positions) lo = std::min(lo, p.z()), hi = std::max(hi, p.z());
    }
    const double span = hi > lo ? hi - lo : 1.0;
    const double angle = (std::clamp(in.tint, 0.0, 1.0) - 0.5) * std::numbers::pi / 3.0;  // ±30°
    const Rgb bark = rotate_hue(kBark, angle / 3.0), shoot = rotate_hue(kShoot, angle),
              foliage = rotate_hue(kFoliage, angle);
    const double steps = std::max(in.steps, 1);
    constexpr double kFloor = 1e-3;  // bark where no weight speaks
    std::vector<Rgb> out(n);
    for (std::size_t v = 0; v < n; ++v) {
        const double age = std::clamp((steps - in.birth_steps[v]) / steps, 0.0, 1.0);  // 1: the seed's
        const double young = 1.0 - age;
        const double height = (in.positions[v].z() - lo) / span;
        const double light = in.exposure.empty() ? height : std::clamp(in.exposure[v], 0.0, 1.0);
        const double growing = in.active.empty() ? young : (in.active[v] ? 1.0 : 0.0);
        // Wood: old or low (the base lignifies first and longest), unless it
        // still grows in the light.
        const double woody = 0.4 * age + 0.6 * (1.0 - height);
        const double w_bark = woody * (2.0 - growing - light) / 2.0 + kFloor;
        const double w_shoot = young * growing * (1.0 - light) * height;
        const double w_leaf = young * light + light * height * (1.0 - woody);
        const double total = w_bark + w_shoot + w_leaf;
        for (int c = 0; c < 3; ++c)
            out[v][c] = static_cast<float>(
                std::clamp((w_bark * bark[c] + w_shoot * shoot[c] + w_leaf * foliage[c]) / total, 0.0, 1.0));
    }
    return out;
}

}  // namespace morphogen
