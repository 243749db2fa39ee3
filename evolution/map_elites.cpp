#include "evolution/map_elites.hpp"

#include "evolution/batch.hpp"
#include "evolution/operators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
    emitters_ = params_.emitters.empty() ? std::vector<EmitterSpec>{EmitterSpec{}} : params_.emitters;
    per_generation_ = births_per_generation(emitters_, population());
    for (const EmitterSpec& e : emitters_) weighs_fitness_ = weighs_fitness_ || e.selection == ParentSelection::fitness_proportional;
}

Individual MapElites::conceive_from(const ParentPool& pool, std::uint64_t birth) const {
    const std::size_t k = birth < population() ? 0 : emitter_of(birth, per_generation_, population());
    return emit(emitters_[k], rules(), blocks_, problem_.dimension(), seed_, birth, pool);
}

Individual MapElites::conceive(std::uint64_t birth) const {
    if (!pool_) pool_.emplace(state_.archive.snapshot());
    return conceive_from(*pool_, birth);
}

Inserted MapElites::insert(Individual& child, std::string& error) {
    last_cell_.reset();
    if (child.valid()) {
        last_cell_ = state_.archive.cell_of(child.descriptors);
        if (!last_cell_) {
            error = std::to_string(child.descriptors.size()) + " descriptors, the archive has " +
                    std::to_string(state_.archive.dimensions());
            child.fitness = invalid_fitness;
            child.size = 0.0;
            child.descriptors.clear();
        }
    }
    if (!child.valid()) ++state_.invalid_in_generation;
    keep_best(state_.best, child);
    last_placement_ = state_.archive.insert(child);
    if (last_placement_ == Archive::Placement::filled) ++state_.new_cells_in_generation;
    if (last_placement_ == Archive::Placement::filled ||
        (weighs_fitness_ && last_placement_ == Archive::Placement::replaced))
        pool_.reset();
    ++state_.births;
    Inserted what;
    if (at_generation_end()) {
        what.ends_generation = true;
        what.generation_invalid = state_.invalid_in_generation;
        what.generation_new_cells = state_.new_cells_in_generation;
        state_.invalid_in_generation = 0;
        state_.new_cells_in_generation = 0;
    }
    return what;
}

double MapElites::export_floor() const {
    double floor = -std::numeric_limits<double>::infinity();
    for (const auto& [cell, elite] : state_.archive.elites()) floor = std::max(floor, elite.fitness);
    return floor;
}

EliteBatchOutcome MapElites::step(int threads) {
    const std::size_t count = batch_size(state_.births, population(), params_.batch);
    // The parents of the whole batch: the elites before it, in cell-index order.
    const ParentPool pool(state_.archive.snapshot());
    BredBatch bred = breed_batch(problem_, state_.births, count, threads,
                                 [&](std::uint64_t birth) { return conceive_from(pool, birth); });
    EliteBatchOutcome out;
    out.children = std::move(bred.children);
    out.errors = std::move(bred.errors);
    out.cells.resize(count);
    out.placements.resize(count, Archive::Placement::rejected);
    for (std::size_t i = 0; i < count; ++i) {
        const Inserted what = insert(out.children[i], out.errors[i]);
        out.cells[i] = last_cell_;
        out.placements[i] = last_placement_;
        out.ends_generation = what.ends_generation;
        out.generation_invalid = what.generation_invalid;
        out.generation_new_cells = what.generation_new_cells;
    }
    return out;
}

}  // namespace morphogen
