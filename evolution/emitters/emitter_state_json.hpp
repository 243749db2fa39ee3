#pragma once
// A run's emitters' states <-> JSON, inside a MAP-Elites checkpoint
// (map_elites_state_json.hpp); each kind writes and reads its own entry
// (Emitter::state_to_json). The CMA emitters' (cma_emitter.hpp), bit-exact: vectors of genome length
// (mean, variances, paths, the iteration's children) go to the genome blob
// ("genome": k) or, without one, inline ("params": [...]); scalars are JSON
// numbers (shortest round-trip form). The list has one entry per emitter of
// the config: null for a stateless emitter or a CMA emitter not yet started,
//   {"restarts": n, "origin": id | null, "sigma": s, "updates": n,
//    "mean": v, "variances": v, "path_c": v, "path_sigma": v,
//    "children": [{"status": 0|1|2, "value": x | null, <vector>}, ...]}
// otherwise; an emitter with the full covariance model has, instead of
// "variances", "covariance": [<vector>, ...], C's n rows.
#include "evolution/emitters/cma/cma_emitter_state.hpp"
#include "evolution/emitters/emitters.hpp"
#include "evolution/genome_blob.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

// Whether a checkpoint lists these emitters: when any keeps a state.
bool keeps_emitter_states(std::span<const EmitterSlot> emitters);

// The list: one entry per emitter, Emitter::state_to_json.
nlohmann::json emitter_states_to_json(std::span<const EmitterSlot> emitters, GenomeBlobWriter* genomes);

// What a run's emitters must look like at `births` births.
struct EmitterListShape {
    std::span<const EmitterSpec> specs;
    std::uint64_t population = 0;
    std::uint64_t births = 0;
    std::size_t dimension = 0;
};

// Reads and checks the list at `path`: one entry per spec, each read by a
// fresh emitter of its spec (Emitter::state_from_json). Throws
// std::invalid_argument naming the first defect.
std::vector<EmitterSlot> emitter_states_from_json(const nlohmann::json& list, const EmitterListShape& shape,
                                                  const std::string& path, GenomeBlobReader* genomes);

// A CMA emitter's entry; null when not started.
nlohmann::json cma_emitter_state_to_json(const CmaEmitterState& state, GenomeBlobWriter* genomes);
// Reads and checks a CMA emitter's entry (null: not started): numbers
// finite, sigma and variances > 0, a full C symmetric positive definite,
// origin below the birth counter, exactly as many children as the emitter's
// births so far in the current iteration, an invalid child (value null) with
// status 0. `full`: the emitter's covariance model is the full one.
CmaEmitterState cma_emitter_state_from_json(const nlohmann::json& entry, bool full, const EmitterStateShape& shape,
                                            const std::string& path, GenomeBlobReader* genomes);

// Calls `each(holder, path)` for every object of the list that holds a
// vector ("genome" or "params"), for tools that rewrite the genomes.
void for_each_emitter_vector(nlohmann::json& list, const std::string& path,
                             const std::function<void(nlohmann::json&, const std::string&)>& each);

}  // namespace morphogen
