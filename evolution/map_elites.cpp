#include "evolution/map_elites.hpp"

#include "evolution/batch.hpp"
#include "evolution/operators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace morphogen {

namespace {
constexpr std::size_t npos = static_cast<std::size_t>(-1);

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
    for (const EmitterSpec& e : emitters_) {
        weighs_fitness_ = weighs_fitness_ || e.selection == ParentSelection::fitness_proportional;
        has_cma_ = has_cma_ || is_cma(e.kind);
        if (e.kind != EmitterKind::cma_mae) continue;
        if (annealing_ && (learning_rate_ != e.learning_rate || threshold_min_ != e.threshold_min))
            throw std::invalid_argument("every cma_mae emitter must have the same learning_rate and threshold_min");
        annealing_ = true;
        learning_rate_ = e.learning_rate;
        threshold_min_ = e.threshold_min;
    }
    if (has_cma_ && state_.emitters.empty()) state_.emitters.resize(emitters_.size());
    if (state_.emitters.size() != (has_cma_ ? emitters_.size() : 0))
        throw std::invalid_argument("the state's emitters do not match the parameters'");
}

bool MapElites::ends_iteration(std::uint64_t birth, std::size_t emitter) const {
    std::uint64_t last = 0;
    for (std::size_t k = 0; k <= emitter; ++k) last += per_generation_[k];
    return per_generation_[emitter] > 0 && birth % population() == last - 1;
}

Individual MapElites::conceive_from(const ParentPool& pool, std::uint64_t birth) const {
    if (birth < population()) return conceive_birth(rules(), blocks_, problem_.dimension(), seed_, birth, ParentPicker{});
    const std::size_t k = emitter_index(birth);
    if (is_cma(emitters_[k].kind)) {
        // An emitter not yet started (no elite so far) makes random genomes.
        if (state_.emitters[k].started) return sample_cma_child(emitters_[k], state_.emitters[k], seed_, birth);
        return conceive_birth(rules(), blocks_, problem_.dimension(), seed_, birth, ParentPicker{});
    }
    return emit(emitters_[k], rules(), blocks_, problem_.dimension(), seed_, birth, pool);
}

CmaChild MapElites::rank_for_emitter(const Individual& child, std::uint64_t cell, std::size_t emitter) {
    CmaChild out;
    const auto elite = state_.archive.elites().find(cell);
    const bool empty = elite == state_.archive.elites().end();
    double threshold = 0.0;
    if (annealing_) {
        const auto t = state_.thresholds.find(cell);
        threshold = t == state_.thresholds.end() ? threshold_min_ : t->second;
        if (child.fitness > threshold)
            state_.thresholds[cell] = (1.0 - learning_rate_) * threshold + learning_rate_ * child.fitness;
    }
    if (emitter == npos || !is_cma(emitters_[emitter].kind)) return out;
    if (emitters_[emitter].kind == EmitterKind::cma_me) {
        out.value = empty ? child.fitness : child.fitness - elite->second.fitness;
        out.status = empty ? 2 : (out.value > 0.0 ? 1 : 0);
    } else {
        out.value = child.fitness - threshold;
        out.status = out.value > 0.0 ? 1 : 0;
    }
    return out;
}

void MapElites::start_emitter(std::size_t emitter, std::uint64_t birth) {
    if (!pool_) pool_.emplace(state_.archive.snapshot());
    if (pool_->empty()) return;
    RandomStream stream(seed_ ^ 0xc3a5c85c97cb3127ULL, birth * 1024 + emitter);
    start_cma_emitter(emitters_[emitter], state_.emitters[emitter], pool_->pick(emitters_[emitter].selection, stream));
}

void MapElites::update_emitters(std::uint64_t birth) {
    if (birth >= population()) {
        const std::size_t k = emitter_index(birth);
        CmaEmitterState& emitter = state_.emitters[k];
        if (is_cma(emitters_[k].kind) && emitter.started && ends_iteration(birth, k) &&
            finish_cma_iteration(emitters_[k], emitter))
            start_emitter(k, birth);
    }
    if ((birth + 1) % population() == 0)
        for (std::size_t k = 0; k < emitters_.size(); ++k)
            if (is_cma(emitters_[k].kind) && !state_.emitters[k].started) start_emitter(k, birth);
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
    const std::uint64_t birth = state_.births;
    const std::size_t emitter = birth >= population() ? emitter_index(birth) : npos;
    const bool collects = has_cma_ && emitter != npos && state_.emitters[emitter].started;
    CmaChild ranked;
    if (has_cma_ && child.valid()) ranked = rank_for_emitter(child, *last_cell_, emitter);
    if (collects && is_cma(emitters_[emitter].kind)) {
        ranked.params = child.params;
        state_.emitters[emitter].children.push_back(std::move(ranked));
    }
    if (!child.valid()) ++state_.invalid_in_generation;
    keep_best(state_.best, child);
    last_placement_ = state_.archive.insert(child);
    if (last_placement_ == Archive::Placement::filled) ++state_.new_cells_in_generation;
    if (last_placement_ == Archive::Placement::filled ||
        (weighs_fitness_ && last_placement_ == Archive::Placement::replaced))
        pool_.reset();
    if (has_cma_) update_emitters(birth);
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
