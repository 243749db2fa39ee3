#pragma once
// What the breeding tests share: a tiny config (a birth in milliseconds) and
// byte comparisons of session directories.
#include "run/config/experiment_config.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace morphogen::testing {

// Branching growth, 20 steps, at most 150 vertices, the plant fitness.
inline const char* kTinyBreedConfig = R"({
  "network": {"outputs": 7, "hidden": [6]},
  "growth": {"steps": 20, "max_vertices": 150, "mode": "branching", "collisions": "touch"},
  "fitness": {"type": "plant", "spacing": 0.25},
  "evolution": {"population": 12, "mutation_rate": 0.1, "mutation_sigma": 0.3},
  "descriptors": [{"measure": "spread", "min": 0, "max": 4, "bins": 8},
                  {"measure": "slenderness", "min": 0, "max": 4, "bins": 8}],
  "run": {"seed": 7, "name": "tiny_breed"}
})";

ExperimentConfig tiny_breed_config(std::uint64_t seed = 7);

// The files of a session directory (relative paths, sorted), without the
// temporary files of atomic writes.
std::vector<std::string> session_files(const std::filesystem::path& dir);
// "" when both directories hold the same files with the same bytes; else
// the first difference.
std::string session_difference(const std::filesystem::path& a, const std::filesystem::path& b);

// The ids of a session state's grid, in order.
inline std::vector<std::string> grid_ids(const nlohmann::json& state) {
    std::vector<std::string> ids;
    for (const nlohmann::json& p : state.at("grid")) ids.push_back(p.at("id"));
    return ids;
}

}  // namespace morphogen::testing
