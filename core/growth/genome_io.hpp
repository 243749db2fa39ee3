#pragma once
// Genome files (docs/algorithm.md §6.4):
//   {"format": "morphogen-genome", "version": 1, "layers": [45, 30, 15], "params": [...]}
// Numbers are written with 17 significant digits, so a round trip is exact.
#include "core/growth/network/network.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace morphogen {

nlohmann::json genome_to_json(const Genome& genome);
// Throws IoError naming `source` and the defect (wrong format/version, sizes
// that do not match the layers, non-finite parameters).
Genome genome_from_json(const nlohmann::json& document, const std::string& source);

// Written atomically (atomic_file.hpp); IoError names the file and the reason.
void save_genome(const Genome& genome, const std::string& path);
Genome load_genome(const std::string& path);

}  // namespace morphogen
