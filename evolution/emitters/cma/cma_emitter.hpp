#pragma once
// The CMA emitters of MAP-Elites (docs/algorithm.md §9.9): each runs its own
// separable CMA-ES (sep_cma.hpp) whose iterations are the emitter's births in
// one generation (lambda = its births_per_generation), ranked by what they did
// to the archive. With `covariance: "full"` the distribution is full CMA-ES
// (full_cma.hpp) instead.
//
// - cma_me (Fontaine et al. 2020, the improvement emitter): a child that
//   filled a cell ranks before one that improved an elite, each group by
//   fitness gain (a new cell's gain is its fitness), then the rest.
// - cma_mae (Fontaine & Nikolaidis 2023): every valid child ranks by
//   fitness - threshold of its cell (the archive's thresholds, archive.hpp);
//   status 1 when that is > 0.
// Parents (CmaSettings::parents): "filter", the children with status > 0, or
// "mu", the best floor(lambda / 2) valid ones. Restart (CmaSettings::restart)
// when CMA-ES's own stop tests fire (sep_cma_converged), or the valid
// children's ranking values span less than 1e-12, or there are no parents,
// and with "no_improvement" also when no child has status > 0. A (re)start
// takes an elite (the emitter's parent selection, from its own stream) as the
// mean, sigma0 as the step size and C = I. Until the first start (no elite
// yet) the emitter's births are random genomes.
#include "evolution/emitters/emitters.hpp"
#include "evolution/emitters/cma/cma_emitter_state.hpp"
#include "evolution/emitters/cma/full_cma.hpp"
#include "evolution/individual.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace morphogen {

// What a child's rank measures: its gain over its cell's elite (cma_me) or
// over its cell's threshold (cma_mae).
enum class CmaRanking { improvement, threshold };
// A CMA emitter's parents: the children that filled or improved a cell
// ("filter"), or the best half of the valid ones ("mu").
enum class CmaParents { filter, mu };
// When a CMA emitter restarts besides CMA-ES's own stop tests ("basic"):
// also after an iteration in which no child filled or improved a cell.
enum class CmaRestart { no_improvement, basic };
// A CMA emitter's covariance model (algorithm.md §9.9): separable (a
// diagonal C, sep_cma.hpp; O(n) a child) or full (full_cma.hpp; O(n^2) a
// child and an O(n^3) eigendecomposition an iteration).
enum class CmaCovariance { diagonal, full };

struct CmaSettings {
    CmaRanking ranking = CmaRanking::improvement;
    double sigma0 = 0.5;  // the step size of a (re)start
    // cma_me's defaults (Fontaine et al. 2020); cma_mae's are mu and basic.
    CmaParents parents = CmaParents::filter;
    CmaRestart restart = CmaRestart::no_improvement;
    CmaCovariance covariance = CmaCovariance::diagonal;
    // With the threshold ranking: the archive's thresholds it ranks by.
    ThresholdParams thresholds = {};
    // With the full model: another update rule than full_cma_update (§9.9),
    // set by code that links the library (bench/); empty: the textbook's.
    // Never read from a config or a checkpoint.
    FullCmaUpdate full_update = {};
};

// Starts (or restarts) `state` from `elite`: mean = its parameters, sigma =
// settings.sigma0, C = I, paths zero, origin = its id, no children.
void start_cma_emitter(const CmaSettings& settings, CmaEmitterState& state, const Individual& elite);

// Birth `birth` of a started emitter: sep_cma_sample (or full_cma_sample)
// from RandomStream(seed, birth).
Individual sample_cma_child(const CmaSettings& settings, const CmaEmitterState& state, std::uint64_t seed,
                            std::uint64_t birth);

// How the emitter ranks a child after the archive took it (valid or not).
CmaChild rank_cma_child(CmaRanking ranking, const Individual& child, const Archive::Insertion& insertion);

// Ends an iteration: ranks the children (status, then value, both
// descending; ties in birth order), updates the distribution from the
// parents, clears the children. True when the emitter must restart.
bool finish_cma_iteration(const CmaSettings& settings, CmaEmitterState& state);

// cma_me (ranking by improvement) and cma_mae (by threshold).
class CmaEmitter final : public Emitter {
public:
    CmaEmitter(ParentSelection selection, CmaSettings settings) : Emitter(selection), settings_(std::move(settings)) {}
    std::unique_ptr<Emitter> clone() const override { return std::make_unique<CmaEmitter>(*this); }
    std::string_view kind() const override;
    // A sample of its distribution once started, a random genome before.
    Individual conceive(const EmitterSource& source, std::uint64_t birth) const override;
    // Collects the child (once started); after its last birth of the
    // generation ends the iteration, restarting from pick() when it must.
    void told(const Individual& child, const Archive::Insertion& insertion, bool last,
              const ElitePicker& pick) override;
    // Starts from pick() if not started yet.
    void generation_ended(const ElitePicker& pick) override;
    std::optional<ThresholdParams> thresholds() const override;
    std::size_t square_matrices() const override { return settings_.covariance == CmaCovariance::full ? 1 : 0; }
    bool keeps_state() const override { return true; }
    // emitter_state_json.hpp.
    nlohmann::json state_to_json(GenomeBlobWriter* genomes) const override;
    void state_from_json(const nlohmann::json& entry, const EmitterStateShape& shape, const std::string& path,
                         GenomeBlobReader* genomes) override;

    const CmaSettings& settings() const { return settings_; }
    const CmaEmitterState& state() const { return state_; }

private:
    void start(const ElitePicker& pick);

    CmaSettings settings_;
    CmaEmitterState state_;
};

}  // namespace morphogen
