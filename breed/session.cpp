// BreedSession's grids and their history: the first grid, breeding, undo
// and redo, a choice undone in memory when it cannot be saved, and the state
// the API shows (breed/session.hpp). Its files: session_files.cpp and
// session_plants.cpp; explore: session_explore.cpp; export: session_export.cpp.
#include "breed/session.hpp"

#include "core/base/parallel_for.hpp"
#include "breed/breed_errors.hpp"
#include "core/base/append_file.hpp"
#include "core/base/errors.hpp"
#include "core/growth/network/network.hpp"
#include "core/growth/random_genome_centre.hpp"
#include "evolution/operators.hpp"
#include "evolution/rng.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace morphogen {

namespace fs = std::filesystem;
using nlohmann::json;

BreedSession::BreedSession(fs::path dir, ExperimentConfig config, BreedSessionOptions options)
    : dir_(std::move(dir)),
      config_(std::move(config)),
      options_(options),
      explore_settings_(explore_settings(config_, kBreedGridSize)),
      growth_(config_, [this] {
          std::vector<std::string> names;
          for (const DescriptorRange& r : explore_settings_.descriptors) names.push_back(r.name);
          return names;
      }(), options.colour) {}

BreedSession::~BreedSession() {
    {
        std::lock_guard lock(mutex_);
        if (search_) search_->stop();
    }
    if (search_thread_.joinable()) search_thread_.join();
}

int BreedSession::threads() const {
    return resolve_threads(options_.threads);
}

std::string BreedSession::name() const {
    const fs::path normal = dir_.lexically_normal();
    return normal.has_filename() ? normal.filename().string() : normal.parent_path().filename().string();
}

std::vector<std::string> BreedSession::start_grid(const std::vector<std::vector<double>>& from) {
    std::vector<std::vector<double>> genomes;
    std::vector<std::vector<std::string>> parents;
    const std::size_t given = std::min<std::size_t>(from.size(), kBreedGridSize);
    for (std::size_t i = 0; i < given; ++i) {
        if (from[i].size() != growth_.dimension())
            throw ConfigError("a --from genome has " + std::to_string(from[i].size()) + " parameters; the config's network has " +
                              std::to_string(growth_.dimension()));
        genomes.push_back(from[i]);
        parents.emplace_back();
    }
    std::vector<std::string> ids = add_plants(genomes, parents, 0);
    genomes.clear();
    parents.clear();
    for (std::size_t i = given; i < static_cast<std::size_t>(kBreedGridSize); ++i) {
        const std::uint64_t number = next_plant_ + genomes.size();
        if (given == 0) {
            RandomStream stream(config_.run.seed, number);
            genomes.push_back(random_parameters(growth_.dimension(), config_.evolution.init_range, stream,
                                                random_genome_centre(growth_.grower().layers(),
                                                                     growth_.grower().params().mode)));
            parents.emplace_back();
        } else {
            // Plants were added above under the lock the caller holds.
            const std::vector<std::string> parent{ids[(i - given) % given]};
            genomes.push_back(child_of(parent, 0.5, number));
            parents.push_back(parent);
        }
    }
    const std::vector<std::string> rest = add_plants(genomes, parents, 0);
    ids.insert(ids.end(), rest.begin(), rest.end());
    return ids;
}

std::vector<double> BreedSession::child_of(const std::vector<std::string>& parents, double strength,
                                           std::uint64_t number) const {
    RandomStream stream(config_.run.seed, number);
    const std::vector<Block> blocks = neuron_blocks(growth_.grower().layers());
    std::vector<double> child = plant(parents.at(0)).params;
    if (parents.size() == 2) child = crossover(child, plant(parents[1]).params, blocks, stream);
    // strength 0.5 is the config's own mutation step; 1 doubles it.
    const double sigma = config_.evolution.mutation_sigma * 2.0 * strength;
    if (mutate(child, config_.evolution.mutation_rate, sigma, stream) == 0) {
        // Never a clone: one parameter moves when the coin left them all.
        child[stream.below(child.size())] += sigma * stream.normal();
    }
    return child;
}

const BreedPlant& BreedSession::plant(const std::string& id) const {
    const auto it = plants_.find(id);
    if (it == plants_.end()) throw not_found("no plant " + quoted(id) + " in this session");
    return it->second;
}

void BreedSession::check_parents(const std::vector<std::string>& parents) const {
    if (search_ && search_->running()) throw conflict("a search is running: stop it first (POST /api/explore/stop)");
    if (parents.empty() || parents.size() > 2)
        throw bad_request("\"parents\" must name 1 or 2 plants, not " + std::to_string(parents.size()));
    if (parents.size() == 2 && parents[0] == parents[1]) throw bad_request("the two parents are the same plant");
    const std::vector<std::string>& grid = steps_[cursor_].grid;
    for (const std::string& id : parents) {
        plant(id);
        if (std::find(grid.begin(), grid.end(), id) == grid.end())
            throw bad_request("plant " + quoted(id) + " is not in the current grid");
    }
}

struct BreedSession::Saved {
    std::uint64_t next_plant = 0;
    std::vector<BreedStep> steps;
    std::size_t cursor = 0;
    std::uint64_t choices = 0;
    std::uint64_t choices_bytes = 0;
    std::string choices_hash;
};

BreedSession::Saved BreedSession::saved_point() const {
    return {next_plant_, steps_, cursor_, choices_, choices_file_->size(), choices_file_->hash_hex()};
}

void BreedSession::roll_back(const Saved& saved) {
    // Plants only ever gain ids, numbered from next_plant_: drop the new ones
    // and their files, so the directory holds only what state.json names.
    std::erase_if(plants_, [&](const auto& entry) {
        if (std::stoull(entry.first.substr(1)) < saved.next_plant) return false;
        remove_plant_files(entry.first);
        return true;
    });
    next_plant_ = saved.next_plant;
    steps_ = saved.steps;
    cursor_ = saved.cursor;
    choices_ = saved.choices;
    if (choices_file_->size() != saved.choices_bytes) {
        // Cut the unsaved line off, so the next choice follows the last saved one.
        const std::filesystem::path path = choices_file_->path();
        choices_file_.reset();
        choices_file_ = std::make_unique<AppendFile>(AppendFile::resume(path, saved.choices_bytes, saved.choices_hash));
    }
}

void BreedSession::as_one_choice(const std::function<void()>& change) {
    const Saved saved = saved_point();
    try {
        change();
    } catch (...) {
        roll_back(saved);
        throw;
    }
}

void BreedSession::push_step(BreedStep step) {
    steps_.resize(cursor_ + 1);
    steps_.push_back(std::move(step));
    ++cursor_;
}

void BreedSession::breed(const std::vector<std::string>& parents, double strength) {
    std::lock_guard lock(mutex_);
    as_one_choice([&] { breed_locked(parents, strength); });
}

void BreedSession::breed_locked(const std::vector<std::string>& parents, double strength) {
    check_parents(parents);
    if (!std::isfinite(strength) || strength <= 0.0 || strength > 1.0)
        throw bad_request("\"strength\" must be in (0, 1], not " + json(strength).dump());
    std::vector<std::vector<double>> genomes;
    std::vector<std::vector<std::string>> parent_lists;
    for (std::size_t i = parents.size(); i < static_cast<std::size_t>(kBreedGridSize); ++i) {
        genomes.push_back(child_of(parents, strength, next_plant_ + genomes.size()));
        parent_lists.push_back(parents);
    }
    std::vector<std::string> grid = parents;
    const std::vector<std::string> children = add_plants(genomes, parent_lists, static_cast<int>(cursor_ + 1));
    grid.insert(grid.end(), children.begin(), children.end());
    push_step({grid, parents});
    record({{"choice", "breed"}, {"parents", parents}, {"strength", strength}});
}

void BreedSession::undo() {
    std::lock_guard lock(mutex_);
    as_one_choice([&] { undo_locked(); });
}

void BreedSession::undo_locked() {
    if (search_ && search_->running()) throw conflict("a search is running: stop it first (POST /api/explore/stop)");
    if (cursor_ == 0) throw conflict("nothing to undo: this is the first grid");
    --cursor_;
    record({{"choice", "undo"}});
}

void BreedSession::redo() {
    std::lock_guard lock(mutex_);
    as_one_choice([&] { redo_locked(); });
}

void BreedSession::redo_locked() {
    if (search_ && search_->running()) throw conflict("a search is running: stop it first (POST /api/explore/stop)");
    if (cursor_ + 1 >= steps_.size()) throw conflict("nothing to redo: no undone grid follows this one");
    ++cursor_;
    record({{"choice", "redo"}});
}

std::vector<std::string> BreedSession::chosen_ever() const {
    std::set<std::string> chosen;
    for (std::size_t s = 1; s <= cursor_; ++s) chosen.insert(steps_[s].chosen.begin(), steps_[s].chosen.end());
    return {chosen.begin(), chosen.end()};
}

json BreedSession::state_json() const {
    std::lock_guard lock(mutex_);
    json grid = json::array();
    for (const std::string& id : steps_[cursor_].grid) {
        const BreedPlant& p = plant(id);
        grid.push_back({{"id", id},
                        {"parents", p.parents},
                        {"generation", p.generation},
                        {"fitness", p.fitness ? json(*p.fitness) : json()},
                        {"measures", p.measures},
                        {"mesh", "/api/mesh/" + id + ".glb"},
                        {"thumb", "/api/thumb/" + id + ".png"}});
    }
    const bool running = search_ && search_->running();
    json search = {{"running", running},
                   {"done", search_ ? search_->done() : 0},
                   {"total", search_ ? search_->total() : 0},
                   {"message", search_message_}};
    if (running)
        search["message"] = "exploring: " + std::to_string(search_->done()) + " of " + std::to_string(search_->total()) +
                            " births, " + std::to_string(search_->elites()) + " elites";
    return {{"session", name()},
            {"generation", cursor_},
            {"grid", grid},
            {"chosen", steps_[cursor_].chosen},
            {"can_undo", cursor_ > 0 && !running},
            {"can_redo", cursor_ + 1 < steps_.size() && !running},
            {"search", search}};
}

json BreedSession::lineage_json() const {
    std::lock_guard lock(mutex_);
    const std::vector<std::string> chosen = chosen_ever();
    std::set<std::string> nodes;
    std::vector<std::string> todo = chosen;
    while (!todo.empty()) {
        const std::string id = todo.back();
        todo.pop_back();
        if (!nodes.insert(id).second) continue;
        for (const std::string& parent : plant(id).parents) todo.push_back(parent);
    }
    json out = json::array();
    for (const std::string& id : nodes) {
        const BreedPlant& p = plant(id);
        out.push_back({{"id", id},
                       {"parents", p.parents},
                       {"generation", p.generation},
                       {"chosen", std::binary_search(chosen.begin(), chosen.end(), id)},
                       {"thumb", "/api/thumb/" + id + ".png"}});
    }
    return {{"nodes", out}};
}

}  // namespace morphogen
