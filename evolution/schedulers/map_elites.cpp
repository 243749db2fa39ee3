#include "evolution/schedulers/map_elites.hpp"

#include "evolution/execution/safe_evaluation.hpp"
#include "evolution/emitters/emitter_registry.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace morphogen {

MapElites::MapElites(const MapElitesParams& params, std::uint64_t seed, Problem& problem, MapElitesState state)
    : params_(params), seed_(seed), problem_(problem), state_(std::move(state)) {
    if (params_.population < 1) throw std::invalid_argument("MAP-Elites parameter out of range: population >= 1");
    check_shared_params(rules(), params_.batch, "MAP-Elites");
    blocks_ = check_blocks(problem_.blocks(), problem_.dimension());
    centre_ = check_centre(problem_.random_centre(), problem_.dimension(), "MAP-Elites");
    seeds_ = check_seeds(problem_.seed_genomes(), problem_.dimension(), "MAP-Elites");
    if (params_.emitters.empty()) params_.emitters = default_emitters();
    per_generation_ = births_per_generation(params_.emitters, population());
    if (state_.emitters.empty()) state_.emitters = fresh_emitters(params_.emitters);
    if (state_.emitters.size() != params_.emitters.size())
        throw std::invalid_argument("the state's emitters do not match the parameters'");
    for (std::size_t k = 0; k < state_.emitters.size(); ++k) {
        if (state_.emitters[k].get() == nullptr || state_.emitters[k]->kind() != params_.emitters[k].emitter->kind())
            throw std::invalid_argument("the state's emitter " + std::to_string(k) + " is not of its parameters' kind");
        weighs_fitness_ = weighs_fitness_ || state_.emitters[k]->selection() == ParentSelection::fitness_proportional;
    }
    if (const std::optional<ThresholdParams> t = archive_thresholds(params_.emitters)) state_.archive.keep_thresholds(*t);
}

bool MapElites::ends_turn(std::uint64_t birth, std::size_t emitter) const {
    std::uint64_t last = 0;
    for (std::size_t k = 0; k <= emitter; ++k) last += per_generation_[k];
    return per_generation_[emitter] > 0 && birth % population() == last - 1;
}

const ParentPool& MapElites::pool() const {
    if (!pool_) pool_.emplace(state_.archive.snapshot());
    return *pool_;
}

ElitePicker MapElites::picker(std::uint64_t birth, std::size_t emitter) {
    return [this, birth, emitter](ParentSelection selection) -> const Individual* {
        if (pool().empty()) return nullptr;
        RandomStream stream(seed_ ^ 0xc3a5c85c97cb3127ULL, birth * 1024 + emitter);
        return &pool().pick(selection, stream);
    };
}

Individual MapElites::conceive(std::uint64_t birth) const {
    if (birth < population()) return conceive_birth(rules(), blocks_, problem_.dimension(), seed_, birth, ParentPicker{});
    const BirthRules r = rules();
    const EmitterSource source{r, blocks_, problem_.dimension(), seed_, pool()};
    return state_.emitters[emitter_index(birth)]->conceive(source, birth);
}

Inserted MapElites::insert(Individual& child, std::string& error) {
    if (child.valid() && !state_.archive.cell_of(child.descriptors)) {
        error = std::to_string(child.descriptors.size()) + " descriptors, the archive has " +
                std::to_string(state_.archive.dimensions());
        child.fitness = invalid_fitness;
        child.size = 0.0;
        child.descriptors.clear();
    }
    const std::uint64_t birth = state_.births;
    if (!child.valid()) ++state_.invalid_in_generation;
    keep_best(state_.best, child);
    last_ = state_.archive.insert(child);
    if (last_.placement == Archive::Placement::filled) ++state_.new_cells_in_generation;
    if (last_.placement == Archive::Placement::filled ||
        (weighs_fitness_ && last_.placement == Archive::Placement::replaced))
        pool_.reset();
    if (birth >= population()) {
        const std::size_t k = emitter_index(birth);
        state_.emitters[k]->told(child, last_, ends_turn(birth, k), picker(birth, k));
    }
    if ((birth + 1) % population() == 0)
        for (std::size_t k = 0; k < state_.emitters.size(); ++k) state_.emitters[k]->generation_ended(picker(birth, k));
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
    // The fittest elite is the best ever born (a child at least as fit as its
    // cell's elite replaces it), so this costs nothing per birth.
    return state_.best ? state_.best->fitness : -std::numeric_limits<double>::infinity();
}

}  // namespace morphogen
