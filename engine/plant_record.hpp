#pragma once
// What an engine-ready GLB says about its plant in glTF `extras`
// (docs/engine-glb.md, "Engine-ready GLB"): where it came from and how
// well it did. Godot keeps extras as node metadata; other engines read them
// from the file.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace morphogen {

struct PlantRecord {
    std::string id;                   // names the plant: node "plant_<id>"
    std::string genome_hash;          // genome_hash() of its parameters
    std::optional<double> fitness;    // absent when the mesh could not be scored
    std::vector<std::pair<std::string, double>> measures;  // descriptor name, value
    std::string run;                  // run.name; "" when not from a run
    std::optional<std::uint64_t> birth;  // its birth index in the run
    std::vector<std::uint64_t> parents;  // birth indices of its parents (0, 1 or 2)
    std::optional<std::uint64_t> cell;   // its MAP-Elites cell, where there is one
};

// FNV-1a 64 of the parameters as little-endian IEEE doubles, 16 hex digits:
// the same genome gives the same hash on every machine.
std::string genome_hash(std::span<const double> params);

// The record as a JSON object, absent fields (and no parents) left out.
nlohmann::json record_json(const PlantRecord& record);

}  // namespace morphogen
