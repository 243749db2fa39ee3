#include "evolution/emitters/emitters.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace morphogen {

std::vector<std::uint64_t> births_per_generation(std::span<const EmitterSpec> emitters, std::uint64_t population) {
    if (emitters.empty()) throw std::invalid_argument("MAP-Elites needs at least one emitter");
    double total = 0.0;
    for (const EmitterSpec& e : emitters) {
        if (!(e.share > 0) || !std::isfinite(e.share)) throw std::invalid_argument("an emitter's share must be > 0");
        total += e.share;
    }
    std::vector<std::uint64_t> out(emitters.size());
    std::vector<double> remainder(emitters.size());
    std::uint64_t given = 0;
    for (std::size_t k = 0; k < emitters.size(); ++k) {
        const double exact = static_cast<double>(population) * emitters[k].share / total;
        out[k] = static_cast<std::uint64_t>(std::floor(exact));
        remainder[k] = exact - static_cast<double>(out[k]);
        given += out[k];
    }
    std::vector<std::size_t> order(emitters.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
    for (std::size_t i = 0; given < population; ++i, ++given) ++out[order[i % order.size()]];
    return out;
}

std::size_t emitter_of(std::uint64_t birth, std::span<const std::uint64_t> per_generation, std::uint64_t population) {
    std::uint64_t offset = birth % population;
    for (std::size_t k = 0; k < per_generation.size(); ++k) {
        if (offset < per_generation[k]) return k;
        offset -= per_generation[k];
    }
    throw std::logic_error("births per generation do not add up to the population");
}

ParentPool::ParentPool(std::vector<const Individual*> elites) : elites_(std::move(elites)) {
    if (elites_.empty()) return;
    double low = elites_.front()->fitness, high = low;
    for (const Individual* e : elites_) {
        low = std::min(low, e->fitness);
        high = std::max(high, e->fitness);
    }
    const double delta = std::max(1e-12, (high - low) / 20.0);
    cumulative_.reserve(elites_.size());
    double sum = 0.0;
    for (const Individual* e : elites_) cumulative_.push_back(sum += e->fitness - low + delta);
}

const Individual& ParentPool::pick(ParentSelection selection, RandomStream& stream) const {
    if (selection == ParentSelection::uniform) return *elites_[stream.below(elites_.size())];
    const double target = stream.uniform() * cumulative_.back();
    const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), target);
    const std::size_t index = std::min<std::size_t>(static_cast<std::size_t>(it - cumulative_.begin()), elites_.size() - 1);
    return *elites_[index];
}

ParentPicker ParentPool::picker(ParentSelection selection) const {
    if (empty()) return {};
    return [this, selection](RandomStream& stream) -> const Individual& { return pick(selection, stream); };
}

void Emitter::state_from_json(const nlohmann::json& entry, const EmitterStateShape&, const std::string& path,
                              GenomeBlobReader*) {
    if (!entry.is_null()) throw std::invalid_argument(path + ": a stateless emitter's entry must be null");
}

std::vector<EmitterSlot> fresh_emitters(std::span<const EmitterSpec> specs) {
    std::vector<EmitterSlot> out;
    out.reserve(specs.size());
    for (const EmitterSpec& spec : specs) {
        if (!spec.emitter) throw std::invalid_argument("an emitter spec without an emitter");
        out.emplace_back(spec.emitter->clone());
    }
    return out;
}

std::optional<ThresholdParams> archive_thresholds(std::span<const EmitterSpec> specs) {
    std::optional<ThresholdParams> out;
    for (std::size_t k = 0; k < specs.size(); ++k) {
        const std::optional<ThresholdParams> own = specs[k].emitter ? specs[k].emitter->thresholds() : std::nullopt;
        if (!own) continue;
        if (out && *out != *own)
            throw std::invalid_argument("emitter " + std::to_string(k) +
                                        ": every cma_mae emitter must have the same learning_rate and threshold_min "
                                        "(they share one threshold archive)");
        out = own;
    }
    return out;
}

}  // namespace morphogen
