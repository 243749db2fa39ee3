#pragma once
// NslcState <-> JSON for checkpoints (docs/algorithm.md §14.8), in the form
// of the GA's (ga_state_json.hpp): population members and the best are
// individuals with their descriptors; archive points are id, fitness and
// descriptors, with no genome.
#include "evolution/archives/archive.hpp"
#include "evolution/genome_blob.hpp"
#include "evolution/novelty/nslc.hpp"

#include <nlohmann/json.hpp>

#include <span>

namespace morphogen {

nlohmann::json nslc_state_to_json(const NslcState& state, GenomeBlobWriter* genomes = nullptr);

// Reads and checks a state against the run's parameters: field types,
// parameter counts, finite values; members and the best valid with one
// descriptor per range; ids unique and below the birth counter; at most
// population members and novelty.archive points, the points in birth order;
// no more invalid births than births in the generation. Throws
// std::invalid_argument naming the first defect (with its JSON path under
// "nslc"). With `genomes`, every genome of the blob must belong to exactly
// one individual.
NslcState nslc_state_from_json(const nlohmann::json& document, const GaParams& params, const NoveltyParams& novelty,
                               std::span<const DescriptorRange> ranges, std::size_t dimension,
                               GenomeBlobReader* genomes = nullptr);

}  // namespace morphogen
