#pragma once
// The `network` and `growth` config sections (docs/algorithm.md §5.6; every constant a
// key, defaults as documented in docs/config.md and configs/schema.json).
#include "base/config_reader.hpp"

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
    double contact_distance = 0.2;  // growth.contact_distance, collisions "touch" only (§5.7.1)
};

// Read a section; problems are added to reader.issues(), defaults fill gaps.
// Both call reader.finish().
NetworkParams read_network_params(ObjectReader& reader);
GrowthParams read_growth_params(ObjectReader& reader);

}  // namespace morphogen
