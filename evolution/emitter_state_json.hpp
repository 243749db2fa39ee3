#pragma once
// The CMA emitters' states (cma_emitter.hpp) <-> JSON, inside a MAP-Elites
// checkpoint (map_elites_state_json.hpp), bit-exact: vectors of genome length
// (mean, variances, paths, the iteration's children) go to the genome blob
// ("genome": k) or, without one, inline ("params": [...]); scalars are JSON
// numbers (shortest round-trip form). The list has one entry per emitter of
// the config: null for a stateless emitter or a CMA emitter not yet started,
//   {"restarts": n, "origin": id | null, "sigma": s, "updates": n,
//    "mean": v, "variances": v, "path_c": v, "path_sigma": v,
//    "children": [{"status": 0|1|2, "value": x | null, <vector>}, ...]}
// otherwise; an emitter with the full covariance model has, instead of
// "variances", "covariance": [<vector>, ...], C's n rows.
#include "evolution/cma_emitter.hpp"
#include "evolution/emitters.hpp"
#include "evolution/genome_blob.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

nlohmann::json emitter_states_to_json(std::span<const CmaEmitterState> states, GenomeBlobWriter* genomes);

// What a run's emitters must look like at `births` births.
struct EmitterStateShape {
    std::span<const EmitterSpec> specs;
    std::span<const std::uint64_t> per_generation;  // births_per_generation(specs, population)
    std::uint64_t population = 0;
    std::uint64_t births = 0;
    std::size_t dimension = 0;
};

// Reads and checks the list at `path`: one entry per spec, null for the
// stateless ones; numbers finite, sigma and variances > 0, a full C
// symmetric positive definite, origin below the
// birth counter, exactly as many children as the emitter's births so far in
// the current iteration, an invalid child (value null) with status 0.
// Throws std::invalid_argument naming the first defect.
std::vector<CmaEmitterState> emitter_states_from_json(const nlohmann::json& list, const EmitterStateShape& shape,
                                                      const std::string& path, GenomeBlobReader* genomes);

// Calls `each(holder, path)` for every object of the list that holds a
// vector ("genome" or "params"), for tools that rewrite the genomes.
void for_each_emitter_vector(nlohmann::json& list, const std::string& path,
                             const std::function<void(nlohmann::json&, const std::string&)>& each);

}  // namespace morphogen
