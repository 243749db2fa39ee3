#include "evolution/emitters/cma/cma_emitter.hpp"

#include "evolution/emitters/emitter_state_json.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace morphogen {

void start_cma_emitter(const CmaSettings& spec, CmaEmitterState& state, const Individual& elite) {
    if (state.started) ++state.restarts;
    state.started = true;
    if (spec.covariance == CmaCovariance::full)
        state.full = full_cma_start(elite.params, spec.sigma0);
    else
        state.cma = sep_cma_start(elite.params, spec.sigma0);
    state.origin = elite.id;
    state.children.clear();
}

Individual sample_cma_child(const CmaSettings& spec, const CmaEmitterState& state, std::uint64_t seed,
                            std::uint64_t birth) {
    RandomStream stream(seed, birth);
    Individual child;
    child.id = birth;
    child.parent1 = state.origin;
    child.params = spec.covariance == CmaCovariance::full ? full_cma_sample(state.full, stream)
                                                          : sep_cma_sample(state.cma, stream);
    return child;
}

bool finish_cma_iteration(const CmaSettings& spec, CmaEmitterState& state) {
    std::vector<CmaChild> children = std::move(state.children);
    state.children.clear();
    std::vector<std::size_t> order(children.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (children[a].status != children[b].status) return children[a].status > children[b].status;
        return children[a].value > children[b].value;
    });
    std::size_t valid = 0, improving = 0;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const CmaChild& c : children) {
        if (!std::isfinite(c.value)) continue;
        ++valid;
        improving += c.status > 0 ? 1 : 0;
        low = std::min(low, c.value);
        high = std::max(high, c.value);
    }
    const std::size_t mu = spec.parents == CmaParents::filter
                               ? improving
                               : std::min(valid, std::max<std::size_t>(1, children.size() / 2));
    if (mu == 0) return true;
    std::vector<const std::vector<double>*> parents;
    parents.reserve(mu);
    for (std::size_t k = 0; k < mu; ++k) parents.push_back(&children[order[k]].params);
    const bool full = spec.covariance == CmaCovariance::full;
    if (full && spec.full_update)
        spec.full_update(state.full, parents, children.size());
    else if (full)
        full_cma_update(state.full, parents);
    else
        sep_cma_update(state.cma, parents);
    const bool flat = valid > 1 && high - low < 1e-12;
    const bool stalled = spec.restart == CmaRestart::no_improvement && improving == 0;
    return stalled || flat || (full ? full_cma_converged(state.full) : sep_cma_converged(state.cma));
}

CmaChild rank_cma_child(CmaRanking ranking, const Individual& child, const Archive::Insertion& insertion) {
    CmaChild out;
    out.params = child.params;
    if (!child.valid() || !insertion.cell) return out;
    if (ranking == CmaRanking::improvement) {
        const bool empty = !insertion.elite_fitness;
        out.value = empty ? child.fitness : child.fitness - *insertion.elite_fitness;
        out.status = empty ? 2 : (out.value > 0.0 ? 1 : 0);
    } else {
        out.value = child.fitness - insertion.threshold;
        out.status = out.value > 0.0 ? 1 : 0;
    }
    return out;
}

std::string_view CmaEmitter::kind() const {
    return settings_.ranking == CmaRanking::threshold ? "cma_mae" : "cma_me";
}

Individual CmaEmitter::conceive(const EmitterSource& s, std::uint64_t birth) const {
    if (state_.started) return sample_cma_child(settings_, state_, s.seed, birth);
    return conceive_birth(s.rules, s.blocks, s.dimension, s.seed, birth, ParentPicker{});
}

void CmaEmitter::start(const ElitePicker& pick) {
    if (const Individual* elite = pick(selection())) start_cma_emitter(settings_, state_, *elite);
}

void CmaEmitter::told(const Individual& child, const Archive::Insertion& insertion, bool last,
                      const ElitePicker& pick) {
    if (!state_.started) return;
    state_.children.push_back(rank_cma_child(settings_.ranking, child, insertion));
    if (last && finish_cma_iteration(settings_, state_)) start(pick);
}

void CmaEmitter::generation_ended(const ElitePicker& pick) {
    if (!state_.started) start(pick);
}

std::optional<ThresholdParams> CmaEmitter::thresholds() const {
    if (settings_.ranking != CmaRanking::threshold) return std::nullopt;
    return settings_.thresholds;
}

nlohmann::json CmaEmitter::state_to_json(GenomeBlobWriter* genomes) const {
    return cma_emitter_state_to_json(state_, genomes);
}

void CmaEmitter::state_from_json(const nlohmann::json& entry, const EmitterStateShape& shape, const std::string& path,
                                 GenomeBlobReader* genomes) {
    state_ = cma_emitter_state_from_json(entry, settings_.covariance == CmaCovariance::full, shape, path, genomes);
}

}  // namespace morphogen
