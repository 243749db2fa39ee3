// "Explore around this one" in a BreedSession (breed/session.hpp): the
// search on its own thread, its grid when it ends, and its replay.
#include "breed/session.hpp"

#include "breed/breed_errors.hpp"
#include "evolution/rng.hpp"

#include <algorithm>
#include <limits>

namespace morphogen {

ExploreSettings BreedSession::explore_settings_for(const std::vector<std::string>& parents, ExploreAlong along) const {
    if (along == ExploreAlong::descriptors) return explore_settings_;
    ExploreSettings settings = explore_settings(config_, kBreedGridSize, along);
    double lowest = std::numeric_limits<double>::infinity();
    for (const std::string& id : parents) lowest = std::min(lowest, plant(id).measures.at("height"));
    settings.min_height = kCollapsedHeight * lowest;
    return settings;
}

namespace {
constexpr std::uint64_t kFillTries = 8;  // children drawn for one cell the search left empty
}  // namespace

std::vector<ExploreSeed> BreedSession::explore_seeds(const std::vector<std::string>& parents, ExploreAlong along) const {
    std::vector<ExploreSeed> seeds;
    for (const std::string& id : parents) {
        const BreedPlant& p = plant(id);
        if (along == ExploreAlong::architecture) {
            // Measured again: a session saved before these measures lacks them.
            const Evaluation e = growth_.evaluate_architecture(p.params, 0.0);
            if (!e.valid)
                throw bad_request("plant " + quoted(id) + " cannot seed the search: " + e.error);
            seeds.push_back({p.params, e.score, e.descriptors});
            continue;
        }
        if (!p.fitness || p.descriptors.empty())
            throw bad_request("plant " + quoted(id) + " has no valid fitness or descriptors: the search cannot place it");
        seeds.push_back({p.params, *p.fitness, p.descriptors});
    }
    return seeds;
}

// Drawn from a stream no plant number reaches (bit 62), so the search's
// randomness is its own and the same on replay.
std::uint64_t BreedSession::explore_seed() const {
    return RandomStream(config_.run.seed, next_plant_ | (std::uint64_t{1} << 62)).next_u64() >> 11;
}

void BreedSession::start_explore(const std::vector<std::string>& parents, int births, ExploreAlong along) {
    std::unique_lock lock(mutex_);
    check_parents(parents);
    if (births < 1 || births > kMaxExploreBirths)
        throw bad_request("\"births\" must be 1 to " + std::to_string(kMaxExploreBirths) + ", not " +
                          std::to_string(births));
    std::vector<ExploreSeed> seeds = explore_seeds(parents, along);
    // Finished searches are joined here, outside the thread that runs them.
    if (search_thread_.joinable()) {
        lock.unlock();
        search_thread_.join();
        lock.lock();
        check_parents(parents);  // a choice may have come meanwhile
    }
    search_ = std::make_unique<ExploreSearch>(growth_, explore_settings_for(parents, along), std::move(seeds), explore_seed(),
                                              static_cast<std::uint64_t>(births),
                                              kBreedGridSize - parents.size());
    search_message_.clear();
    search_->set_running();
    search_thread_ = std::thread([this, parents, births, along] {
        ExploreResult result;
        std::string error;
        try {
            result = search_->run();
        } catch (const std::exception& e) {
            error = e.what();
        }
        std::lock_guard guard(mutex_);
        try {
            if (error.empty()) as_one_choice([&] { finish_explore(std::move(result), parents, births, along); });
        } catch (const std::exception& e) {
            error = e.what();
        }
        if (!error.empty()) search_message_ = "the search failed: " + error;
        search_->set_finished();
        explored_.notify_all();
    });
}

void BreedSession::finish_explore(ExploreResult result, std::vector<std::string> parents, int births,
                                  ExploreAlong along) {
    std::vector<std::vector<double>> genomes;
    for (std::vector<double>& g : result.picked) {
        bool is_parent = false;
        for (const std::string& id : parents) is_parent = is_parent || plant(id).params == g;
        if (!is_parent && genomes.size() + parents.size() < static_cast<std::size_t>(kBreedGridSize))
            genomes.push_back(std::move(g));
    }
    // Fewer elites than cells: the rest are the parents' children; along the
    // architecture, not collapsed ones where one of a few tries stands.
    const double min_height = along == ExploreAlong::architecture ? explore_settings_for(parents, along).min_height : 0.0;
    while (genomes.size() + parents.size() < static_cast<std::size_t>(kBreedGridSize)) {
        const std::uint64_t number = next_plant_ + genomes.size();
        std::vector<double> child = child_of(parents, 0.5, number);
        // Further tries draw from streams no plant number reaches (bit 61).
        for (std::uint64_t attempt = 1; min_height > 0.0 && attempt < kFillTries; ++attempt) {
            if (growth_.evaluate_architecture(child, min_height).valid) break;
            child = child_of(parents, 0.5, number | (std::uint64_t{1} << 61) | (attempt << 40));
        }
        genomes.push_back(std::move(child));
    }
    const std::vector<std::vector<std::string>> parent_lists(genomes.size(), parents);
    std::vector<std::string> grid = parents;
    const std::vector<std::string> found = add_plants(genomes, parent_lists, static_cast<int>(cursor_ + 1));
    grid.insert(grid.end(), found.begin(), found.end());
    push_step({grid, parents});
    search_message_ = "explored " + std::to_string(result.done) + " births";
    record({{"choice", "explore"},
            {"along", explore_along_name(along)},
            {"parents", parents},
            {"births", births},
            {"done", result.done}});
}

void BreedSession::stop_explore() {
    std::lock_guard lock(mutex_);
    if (!search_ || !search_->running()) throw conflict("no search is running");
    search_->stop();
}

void BreedSession::wait_explore() {
    std::unique_lock lock(mutex_);
    explored_.wait(lock, [this] { return !search_ || !search_->running(); });
}

void BreedSession::replay_explore(const std::vector<std::string>& parents, int births, std::uint64_t done,
                                  ExploreAlong along) {
    ExploreResult result;
    if (done > 0) {
        ExploreSearch search(growth_, explore_settings_for(parents, along), explore_seeds(parents, along),
                             explore_seed(), done, kBreedGridSize - parents.size());
        result = search.run();
    }
    finish_explore(std::move(result), parents, births, along);
}

}  // namespace morphogen
