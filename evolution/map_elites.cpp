#include "evolution/map_elites.hpp"

#include "evolution/batch.hpp"
#include "evolution/operators.hpp"

#include <cmath>
#include <stdexcept>

namespace morphogen {

namespace {
void check_params(const MapElitesParams& p) {
    if (p.population < 1) throw std::invalid_argument("MAP-Elites parameter out of range: population >= 1");
}
}  // namespace

MapElites::MapElites(const MapElitesParams& params, std::uint64_t seed, Problem& problem, MapElitesState state)
    : params_(params), seed_(seed), problem_(problem), state_(std::move(state)) {
    check_params(params_);
    check_shared_params(rules(), params_.batch, "MAP-Elites");
    blocks_ = check_blocks(problem_.blocks(), problem_.dimension());
}

EliteBatchOutcome MapElites::step(int threads, BatchEvaluator* remote) {
    const std::size_t count = batch_size(state_.births, population(), params_.batch);
    const std::size_t dimension = problem_.dimension();
    const BirthRules rules = this->rules();
    // The parents of the whole batch: the elites before it, in cell-index order.
    const std::vector<const Individual*> snapshot = state_.archive.snapshot();
    ParentPicker pick;
    if (!snapshot.empty()) {
        pick = [&snapshot](RandomStream& stream) -> const Individual& { return *snapshot[stream.below(snapshot.size())]; };
    }
    BredBatch bred = breed_batch(problem_, state_.births, count, threads, [&](std::uint64_t birth) {
        return conceive_birth(rules, blocks_, dimension, seed_, birth, pick);
    }, remote);

    EliteBatchOutcome out;
    out.children = std::move(bred.children);
    out.errors = std::move(bred.errors);
    out.cells.resize(count);
    out.placements.resize(count, Archive::Placement::rejected);
    for (std::size_t i = 0; i < count; ++i) {
        Individual& child = out.children[i];
        if (child.valid()) {
            out.cells[i] = state_.archive.cell_of(child.descriptors);
            if (!out.cells[i]) {
                out.errors[i] = std::to_string(child.descriptors.size()) + " descriptors, the archive has " +
                                std::to_string(state_.archive.dimensions());
                child.fitness = invalid_fitness;
                child.size = 0.0;
                child.descriptors.clear();
            }
        }
        if (!child.valid()) ++state_.invalid_in_generation;
        keep_best(state_.best, child);
        out.placements[i] = state_.archive.insert(child);
        if (out.placements[i] == Archive::Placement::filled) ++state_.new_cells_in_generation;
        ++state_.births;
    }
    if (at_generation_end()) {
        out.ends_generation = true;
        out.generation_invalid = state_.invalid_in_generation;
        out.generation_new_cells = state_.new_cells_in_generation;
        state_.invalid_in_generation = 0;
        state_.new_cells_in_generation = 0;
    }
    return out;
}

}  // namespace morphogen
