#pragma once
// MapElitesState <-> JSON for checkpoints (bit-exact, as ga_state_json.hpp):
//   {"births": n, "invalid_in_generation": n, "new_cells_in_generation": n,
//    "best": individual | null,
//    "archive": {"type": "grid" | "cvt", "centroids": [...] (cvt only, row-major),
//                "elites": [{"cell": c, "descriptors": [...], <individual>,
//                            "threshold": t (cma_mae runs, cells whose threshold rose)}, ...] (cell order)},
//    "emitters": [...] (runs with an emitter that keeps a state, such as a
//                       CMA emitter: emitter_state_json.hpp)}
// The CVT centroids are stored so a resume never recomputes them. Genomes:
// inline or in a blob, as in ga_state_json.hpp.
#include "evolution/genome_blob.hpp"
#include "evolution/schedulers/map_elites.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace morphogen {

nlohmann::json map_elites_state_to_json(const MapElitesState& state, GenomeBlobWriter* genomes = nullptr);

// Reads and checks a state against the run's archive definition (`kind`,
// `ranges`, `cells` for a CVT) and genome size: types, parameter counts,
// centroids in [0,1] and as many as the config's cells, elites valid, in
// increasing cell order, their descriptors mapping to their cell, ids unique
// and below the birth counter, the best valid and at least as fit as every
// elite; with `genomes`, every genome of the blob belongs to exactly one
// individual; with CMA emitters, their states (emitter_state_json.hpp) and
// every threshold above the cma_mae emitters' threshold_min and at most its
// elite's fitness. `emitters`: the config's (empty: default_emitters()).
// Throws std::invalid_argument naming the first defect ("map_elites.…").
MapElitesState map_elites_state_from_json(const nlohmann::json& document, ArchiveKind kind,
                                          const std::vector<DescriptorRange>& ranges, std::uint64_t cells,
                                          std::uint64_t population, std::size_t dimension,
                                          std::span<const EmitterSpec> emitters, GenomeBlobReader* genomes = nullptr);

}  // namespace morphogen
