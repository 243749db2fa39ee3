#pragma once
// Colour from growth history (docs/algorithm.md §13): every vertex's linear
// RGB from its age (birth step), its growth state and its exposure, tinted by
// a hue the genome's own network gives. An export-time pass: it reads what
// growth left and changes nothing growth computes.
#include "core/growth/growth.hpp"

#include <array>
#include <span>
#include <vector>

namespace morphogen {

using Rgb = std::array<float, 3>;  // linear, each in [0, 1]

struct ColourInputs {
    std::span<const Vec3> positions;
    std::span<const int> birth_steps;      // one per vertex (engine/birth_steps.hpp)
    int steps = 0;                         // steps grown: the age scale
    std::span<const std::uint8_t> active;  // branching mode: 1 growing, 0 dormant; empty in the paper's mode
    std::span<const double> exposure;      // one per vertex in [0, 1]; empty: height stands in (§13)
    double tint = 0.5;                     // genome_tint(), in [0, 1]
};

// The three ends of the palette before the tint (§13).
inline constexpr Rgb kBark{0.14f, 0.075f, 0.035f};
inline constexpr Rgb kShoot{0.42f, 0.58f, 0.16f};
inline constexpr Rgb kFoliage{0.07f, 0.30f, 0.05f};

// The species' tint (§13): the mean of the network's last output channel
// over the vertices after the last step, in [0, 1]; 0.5 for an empty state.
double genome_tint(const GrowthState& state);

// One colour per vertex. Throws std::invalid_argument when birth_steps,
// active or exposure (when given) do not have one entry per vertex.
std::vector<Rgb> plant_colours(const ColourInputs& inputs);

// RGBA floats (A = 1), 4 per vertex: what GrownPlant::colours and COLOR_0 take.
std::vector<float> colour_rgba(std::span<const Rgb> colours);

// The colours of a grown plant as GrownPlant::colours takes them (RGBA):
// §13 with the branching mode's growth state and final exposure, or the
// paper mode's height, and the genome's tint.
// `exposure`: final_exposure of this state where already computed (one per
// vertex; leaf_light gives the same), else computed here.
std::vector<float> growth_colours(const GrowthState& state, std::span<const int> birth_steps,
                                  const GrowthParams& params, std::span<const double> exposure = {});

// For the branching mode: exposure of the final mesh with the growth's
// exposure parameters (§5.9), computed here whether or not growth used it.
std::vector<double> final_exposure(const TriMesh& mesh, const ExposureParams& params);

}  // namespace morphogen
