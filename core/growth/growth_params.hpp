#pragma once
// The `network` and `growth` config sections (docs/algorithm.md §5.6; every constant a
// key, defaults as documented in docs/config.md and configs/schema.json).
#include "core/base/config_reader.hpp"

#include <string>
#include <vector>

namespace morphogen {

struct NetworkParams {
    int outputs = 15;             // network.outputs (N >= 3)
    std::vector<int> hidden{30};  // network.hidden
    std::vector<int> layers() const;  // [3N, hidden..., N]
};

// The radii a built-in seed may have (growth.seed_radius).
inline constexpr double kMinSeedRadius = 1e-6;
inline constexpr double kMaxSeedRadius = 1e6;

// growth.collisions (docs/algorithm.md §5.7): whether a step may make the
// surface pass through itself; "touch" (§5.7.1) stops a vertex at a contact.
enum class Collisions { allow, prevent, touch };

// growth.mode (docs/algorithm.md §5.8): the paper's model, or the branching
// mode, in which outputs 3-6 also stop and start a vertex's growth and steer
// its direction.
enum class GrowthMode { paper, branching };

// The network outputs the branching mode needs (channels 0-6).
inline constexpr int kBranchingOutputs = 7;
// growth.signal_diffusion (§5.9) spreads channel 7, the first one the
// branching mode leaves to the network, so it needs N >= 8.
inline constexpr int kSignalChannel = kBranchingOutputs;
inline constexpr int kSignalOutputs = kSignalChannel + 1;

struct GrowthParams {
    int steps = 200;
    double speed = 0.2;
    double budget = 20.0;
    bool ground = true;
    double split_area = 0.75;
    int max_vertices = 4000;
    int flip_every = 1;
    double flip_max_angle_deg = 30.0;
    int min_valence = 4;
    double height_scale = 10.0;
    std::string seed_mesh = "icosahedron";  // built-in name or a mesh file path
    double seed_radius = 1.0;  // in [kMinSeedRadius, kMaxSeedRadius]
    Collisions collisions = Collisions::allow;
    GrowthMode mode = GrowthMode::paper;
    double turn_rate = 0.1;  // growth.turn_rate, branching mode only (§5.8)
    // The signals of §5.9, branching mode only, each off by default (the
    // step is then bit for bit the one without them).
    bool exposure = false;             // growth.exposure: input 3N-6 is the vertex's light
    double exposure_cell = 1.0;        // growth.exposure_cell: voxel edge length
    int exposure_depth = 4;            // growth.exposure_depth: levels a shadow reaches down
    double exposure_full_shade = 32.0; // growth.exposure_full_shade: shadow that makes a vertex dark
    int signal_diffusion = 0;          // growth.signal_diffusion: iterations on channel 7 (0: off)
    double signal_rate = 0.5;          // growth.signal_rate: D of each iteration
    double contact_distance = 0.2;  // growth.contact_distance, collisions "touch" only (§5.7.1)
};

// Read a section; problems are added to reader.issues(), defaults fill gaps.
// Both call reader.finish().
NetworkParams read_network_params(ObjectReader& reader);
GrowthParams read_growth_params(ObjectReader& reader);

}  // namespace morphogen
