#pragma once
// MAP-Elites emitters (docs/algorithm.md §9.8): who makes the births after
// generation 0, from the archive. MAP-Elites is three parts, as in pyribs:
// the archive (archive.hpp: cells, elites, and the thresholds CMA-MAE ranks
// by), the emitters (this interface), and the scheduler (map_elites.hpp)
// that hands each birth to its emitter and tells it what the archive did
// with the child.
//
// An emitter conceives a birth as a pure function of (the elites at the
// birth's source, its own state, seed, birth), drawing only from
// RandomStream(seed, birth) (§8.4), and changes its state only when told
// about its children, in birth order. The kinds (emitter_registry.hpp):
// gaussian_emitter.hpp, iso_line_emitter.hpp, cma_emitter.hpp (cma_me and
// cma_mae). A new kind is one class implementing Emitter and one row of the
// registry.
#include "evolution/archives/archive.hpp"
#include "evolution/genome_blob.hpp"
#include "evolution/individual.hpp"
#include "evolution/operators.hpp"
#include "evolution/rng.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

// How an emitter picks parents (or the elite it starts from): uniform over
// the occupied cells, or fitness-proportional over the elites.
enum class ParentSelection { uniform, fitness_proportional };

// The elites a birth may draw from, in cell-index order, with what
// fitness-proportional selection needs (built once per archive state).
class ParentPool {
public:
    explicit ParentPool(std::vector<const Individual*> elites);
    bool empty() const { return elites_.empty(); }
    // One parent, drawing one number from `stream`: uniform is
    // elites[below(n)]; fitness-proportional weighs elite e by
    // f_e - f_min + delta, delta = max(1e-12, (f_max - f_min) / 20), so the
    // worst elite keeps a chance, and takes the first whose running sum
    // exceeds uniform() x the total.
    const Individual& pick(ParentSelection selection, RandomStream& stream) const;
    // pick() as conceive_birth's picker; empty (random genomes) for an empty pool.
    ParentPicker picker(ParentSelection selection) const;

private:
    std::vector<const Individual*> elites_;
    std::vector<double> cumulative_;  // running sums of the weights
};

// What an emitter conceives a birth from.
struct EmitterSource {
    const BirthRules& rules;
    std::span<const Block> blocks;
    std::size_t dimension = 0;
    std::uint64_t seed = 0;
    const ParentPool& pool;  // the elites at the birth's source
};

// The elite an emitter (re)starts from, picked with the emitter's own stream
// from the archive as it is; null while the archive is empty.
using ElitePicker = std::function<const Individual*(ParentSelection)>;

// Where an emitter's births fall, for checking a state read back.
struct EmitterStateShape {
    std::uint64_t population = 0;
    std::uint64_t births = 0;        // the run's births so far
    std::uint64_t first = 0;         // the offset of its first birth in a generation
    std::uint64_t per_generation = 0;  // its births per generation
    std::size_t dimension = 0;
};

class Emitter {
public:
    explicit Emitter(ParentSelection selection) : selection_(selection) {}
    virtual ~Emitter() = default;
    // A copy with the same settings and state.
    virtual std::unique_ptr<Emitter> clone() const = 0;
    // Its registry row's name ("gaussian", "cma_me", ...).
    virtual std::string_view kind() const = 0;
    ParentSelection selection() const { return selection_; }

    // Birth `birth` (at least the population), not yet evaluated.
    virtual Individual conceive(const EmitterSource& source, std::uint64_t birth) const = 0;
    // One of its children after the archive took it (valid or not), in birth
    // order; `last`: its last birth of the generation. `pick` gives the
    // elite to restart from (the archive after this child).
    virtual void told(const Individual& child, const Archive::Insertion& insertion, bool last,
                      const ElitePicker& pick) {
        (void)child, (void)insertion, (void)last, (void)pick;
    }
    // At the end of every generation, after told().
    virtual void generation_ended(const ElitePicker& pick) { (void)pick; }

    // The thresholds it ranks by (cma_mae), which the archive must keep.
    virtual std::optional<ThresholdParams> thresholds() const { return std::nullopt; }
    // Full n x n matrices its state holds (memory and checkpoint size).
    virtual std::size_t square_matrices() const { return 0; }

    // Whether the kind has a state a checkpoint must keep; a run's
    // checkpoint lists its emitters (emitter_state_json.hpp) when any has.
    virtual bool keeps_state() const { return false; }
    // Its state as JSON, null when it has none yet.
    virtual nlohmann::json state_to_json(GenomeBlobWriter* genomes) const {
        (void)genomes;
        return nullptr;
    }
    // Reads and checks `entry` (at `path`) into this fresh emitter; throws
    // std::invalid_argument naming the first defect. A kind without state
    // takes only null.
    virtual void state_from_json(const nlohmann::json& entry, const EmitterStateShape& shape, const std::string& path,
                                 GenomeBlobReader* genomes);

private:
    ParentSelection selection_;
};

// One emitter of a run's list: its settings (not started) and its part of
// each generation.
struct EmitterSpec {
    double share = 1.0;  // > 0: its part of every generation's births, relative to the others
    std::shared_ptr<const Emitter> emitter;  // clone() gives a fresh one
};

// An emitter as a value: copying clones it, so a search's state copies.
class EmitterSlot {
public:
    EmitterSlot() = default;
    explicit EmitterSlot(std::unique_ptr<Emitter> emitter) : emitter_(std::move(emitter)) {}
    EmitterSlot(const EmitterSlot& other) : emitter_(other.emitter_ ? other.emitter_->clone() : nullptr) {}
    EmitterSlot& operator=(const EmitterSlot& other) {
        if (this != &other) emitter_ = other.emitter_ ? other.emitter_->clone() : nullptr;
        return *this;
    }
    EmitterSlot(EmitterSlot&&) noexcept = default;
    EmitterSlot& operator=(EmitterSlot&&) noexcept = default;
    Emitter& operator*() const { return *emitter_; }
    Emitter* operator->() const { return emitter_.get(); }
    Emitter* get() const { return emitter_.get(); }

private:
    std::unique_ptr<Emitter> emitter_;
};

// Fresh emitters of `specs`, in order.
std::vector<EmitterSlot> fresh_emitters(std::span<const EmitterSpec> specs);

// The thresholds the archive must keep for `specs`: those of the emitters
// that rank by thresholds, which must all be equal (they share one archive;
// std::invalid_argument otherwise), or none.
std::optional<ThresholdParams> archive_thresholds(std::span<const EmitterSpec> specs);

// Births of one generation for each emitter: P x share / (sum of shares),
// rounded by largest remainders (ties: the earlier emitter), so they add up
// to P exactly. Throws std::invalid_argument for no emitters or a share that
// is not positive and finite.
std::vector<std::uint64_t> births_per_generation(std::span<const EmitterSpec> emitters, std::uint64_t population);

// Which emitter makes birth `birth` (>= population): the emitters take
// consecutive runs of each generation's births in list order.
std::size_t emitter_of(std::uint64_t birth, std::span<const std::uint64_t> per_generation, std::uint64_t population);

}  // namespace morphogen
