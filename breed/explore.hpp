#pragma once
// "Explore around this one" (docs/breed.md): a short MAP-Elites search
// (evolution/schedulers/map_elites.hpp, docs/algorithm.md §9) seeded with the chosen
// plants, whose most different good elites become the next grid.
//
// The archive starts holding only the seeds and the births start after
// generation 0 (no random genomes), so every birth descends from the seeds.
// Births are made and inserted one after another on the search's thread:
// the elites after n births are a pure function of (seeds, seed, n), so a
// replay that runs the recorded number of births gets the same grid.
//
// Along the config's descriptors (the first kind, and every explore line of
// choices.jsonl without "along"), the pick: the elites whose fitness is at least the median elite fitness
// (and above the lowest, when any elite is: a plateau of plants scoring 0
// must not make every elite "good"), then farthest-point sampling over their descriptors (each scaled by its
// range): the fittest first, then repeatedly the one farthest from all
// picked so far (ties: the lower cell). Fewer good elites than cells: the
// rest by fitness.
//
// Along the architecture (breed/plant_growth.hpp, "along": "architecture"):
// the archive's cells are limbs, first_fork (the first fork's share of the
// height) and tips; a birth shorter than kCollapsedHeight x the lowest seed's
// height counts as collapsed (invalid, never an elite); the pick is
// pick_tree_like below.
#include "breed/plant_growth.hpp"
#include "evolution/archives/archive.hpp"
#include "evolution/individual.hpp"
#include "evolution/schedulers/map_elites.hpp"

#include <atomic>
#include <optional>
#include <string>
#include <cstdint>
#include <vector>

namespace morphogen {

enum class ExploreAlong { descriptors, architecture };
// The name in the API and in choices.jsonl ("descriptors", "architecture"),
// and back (std::nullopt for an unknown name).
std::string explore_along_name(ExploreAlong along);
std::optional<ExploreAlong> explore_along_from(const std::string& name);

inline constexpr double kCollapsedHeight = 0.5;

struct ExploreSettings {
    ExploreAlong along = ExploreAlong::descriptors;
    // descriptors: the config's `descriptors`, or spread and slenderness;
    // architecture: limbs, first_fork, tips.
    std::vector<DescriptorRange> descriptors;
    MapElitesParams params;  // the config's mutation and crossover, default emitters
    double min_height = 0.0;  // architecture: a birth below it collapsed (set per search)
};
// The settings for a session's config.
ExploreSettings explore_settings(const ExperimentConfig& config, int grid, ExploreAlong along = ExploreAlong::descriptors);
inline constexpr int kMaxExploreBirths = 100000;

struct ExploreSeed {
    std::vector<double> params;
    double fitness = 0.0;            // valid
    std::vector<double> descriptors;  // measurable
};

struct ExploreResult {
    std::vector<std::vector<double>> picked;  // at most `picks` genomes, most different first
    std::uint64_t done = 0;                   // births made
};

class ExploreSearch {
public:
    // Throws std::invalid_argument if no seed, births < 1, or picks < 1.
    ExploreSearch(const PlantGrowth& growth, const ExploreSettings& settings, std::vector<ExploreSeed> seeds,
                  std::uint64_t seed, std::uint64_t births, std::size_t picks);

    // Runs births until `births` are done or stop() is called (checked
    // between births); returns the pick. Call once.
    ExploreResult run();
    void stop() { stop_ = true; }
    std::uint64_t done() const { return done_; }
    std::uint64_t total() const { return births_; }
    std::size_t elites() const { return elites_; }
    // Whether the search's thread has it (the session sets these around run()).
    bool running() const { return running_; }
    void set_running() { running_ = true; }
    void set_finished() { running_ = false; }

private:
    class Scorer;
    const PlantGrowth& growth_;
    ExploreSettings settings_;
    std::vector<ExploreSeed> seeds_;
    std::uint64_t seed_;
    std::uint64_t births_;
    std::size_t picks_;
    std::atomic<bool> stop_{false};
    std::atomic<std::uint64_t> done_{0};
    std::atomic<std::size_t> elites_{0};
    std::atomic<bool> running_{false};
};

// The pick described above, from `elites`, at most `count` of them (their indices).
std::vector<std::size_t> pick_different_good(const std::vector<const Individual*>& elites,
                                             const std::vector<DescriptorRange>& ranges, std::size_t count);

// The architecture pick, from `elites` whose descriptors are (limbs,
// first_fork, tips), at most `count` of them (their indices): the first half
// (rounded up) the most tree-like, by most limbs, then lowest first fork, then
// fitness (ties: the lower index); the rest by farthest-point sampling over
// the scaled descriptors from those picked, so the grid also spreads.
std::vector<std::size_t> pick_tree_like(const std::vector<const Individual*>& elites,
                                        const std::vector<DescriptorRange>& ranges, std::size_t count);

}  // namespace morphogen
