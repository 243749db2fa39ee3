#pragma once
// GaState <-> JSON for checkpoints. Doubles are stored as JSON numbers, which
// nlohmann writes in shortest round-trip form, so a reload is bit-exact. An
// invalid individual's fitness (-infinity) is stored as null, never as a
// non-finite number.
//
// Genomes: without a blob (checkpoint format 1) an individual's parameters
// are a JSON array "params"; with one (format 2, genome_blob.hpp) they go to
// the blob and the individual holds "genome": <index> instead.
#include "evolution/ga/ga_params.hpp"
#include "evolution/genome_blob.hpp"
#include "evolution/ga/steady_state.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphogen {

// A parameter vector of genome length (an individual's, or a CMA emitter's
// mean or path) into `object`: "genome": index with a blob, else "params".
void genome_to_json(nlohmann::json& object, const std::vector<double>& params, GenomeBlobWriter* genomes);
// Reads what genome_to_json wrote: `dimension` finite values. Throws
// std::invalid_argument naming `path`.
std::vector<double> genome_from_json(const nlohmann::json& object, std::size_t dimension, const std::string& path,
                                     GenomeBlobReader* genomes);

nlohmann::json individual_to_json(const Individual& individual, GenomeBlobWriter* genomes = nullptr);
// Reads one individual stored by individual_to_json (descriptors are not part
// of it), checking types, `dimension` parameters, finite values and parents
// older than the child. Throws std::invalid_argument naming `path`. With
// `genomes`, the parameters are taken from it ("genome": index).
Individual individual_from_json(const nlohmann::json& object, std::size_t dimension, const std::string& path,
                                GenomeBlobReader* genomes = nullptr);
nlohmann::json ga_state_to_json(const GaState& state, GenomeBlobWriter* genomes = nullptr);

// Reads and checks a state against the run's parameters: field types,
// parameter counts, finite values, ids unique and below the birth counter,
// population size consistent with the birth counter. Throws
// std::invalid_argument naming the first defect (with its JSON path). With
// `genomes`, every genome of the blob must belong to exactly one individual.
GaState ga_state_from_json(const nlohmann::json& document, const GaParams& params, std::size_t dimension,
                           GenomeBlobReader* genomes = nullptr);

}  // namespace morphogen
