#include "breed/session.hpp"

#include "core/base/append_file.hpp"
#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"
#include "breed/breed_errors.hpp"
#include "engine/plant_record.hpp"
#include "evolution/operators.hpp"
#include "evolution/rng.hpp"
#include "core/growth/genome_io.hpp"
#include "core/io/mesh_file_types.hpp"
#include "core/growth/network/network.hpp"
#include "run/exports/plant_exports.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

namespace morphogen {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
constexpr const char* kStateFormat = "morphogen-breed-session";
constexpr int kStateVersion = 1;

std::string plant_id(std::uint64_t number) {
    char text[32];
    std::snprintf(text, sizeof text, "p%06llu", static_cast<unsigned long long>(number));
    return text;
}

std::uint64_t plant_number(const std::string& id) {
    std::uint64_t n = 0;
    std::from_chars(id.data() + 1, id.data() + id.size(), n);
    return n;
}

json read_json_file(const fs::path& path) {
    const std::string text = read_file_bytes(path, memory_bound("session files (this machine's memory)"));
    try {
        return read_json_object(text);
    } catch (const JsonTextError& e) {
        throw CheckpointError("invalid JSON at " + path.string() + ", " + e.what());
    }
}

void write_json_file(const fs::path& path, const json& document) {
    write_file_atomically(path, document.dump(1) + "\n");
}

// A PNG written beside its place, then renamed over it (write_png is not atomic).
void write_png_atomically(const Image& image, const fs::path& path) {
    const fs::path temporary = temporary_path(path);
    write_png(image, temporary.string());
    fs::rename(temporary, path);
}

std::vector<double> load_genome_for_session(const PlantGrowth& growth, const fs::path& path) {
    Genome genome = load_genome(path.string());
    if (genome.layers != growth.grower().layers())
        throw CheckpointError(path.string() + ": its network's layers do not match the session's config");
    return std::move(genome.params);
}

std::string csv_list(const std::vector<std::string>& parents, std::size_t i) {
    return i < parents.size() ? parents[i] : std::string();
}
}  // namespace

namespace {

// The session directory's lock (RunLock, as run directories have), with a
// message that names a session: a second server on one session would give
// two genomes the same id and lose the session.
std::unique_ptr<RunLock> lock_session(const fs::path& dir) {
    try {
        return std::make_unique<RunLock>(dir);
    } catch (const IoError&) {
        throw IoError("breeding session " + dir.string() +
                      " is in use by another morphogen process (one server per session); it was left as it is");
    }
}

}  // namespace

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
    if (options_.threads > 0) return options_.threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

std::string BreedSession::name() const {
    const fs::path normal = dir_.lexically_normal();
    return normal.has_filename() ? normal.filename().string() : normal.parent_path().filename().string();
}

std::unique_ptr<BreedSession> BreedSession::create(const fs::path& dir, const ExperimentConfig& config,
                                                   const std::vector<std::vector<double>>& from,
                                                   BreedSessionOptions options) {
    if (fs::exists(dir) && !(fs::is_directory(dir) && fs::is_empty(dir)))
        throw IoError(dir.string() + ": already exists and is not an empty directory (continue a session with --resume " +
                      dir.string() + ")");
    for (const char* sub : {"genomes", "meshes", "thumbs", "exports"}) fs::create_directories(dir / sub);
    auto held = lock_session(dir);
    write_json_file(dir / "config.json", config.resolved);
    std::unique_ptr<BreedSession> session(new BreedSession(dir, config, options));
    session->lock_ = std::move(held);
    session->choices_file_ = std::make_unique<AppendFile>(AppendFile::create(dir / "choices.jsonl", ""));
    std::lock_guard lock(session->mutex_);
    const std::vector<std::string> grid = session->start_grid(from);
    session->steps_ = {BreedStep{grid, {}}};
    json seeded = json::array();
    for (std::size_t i = 0; i < std::min(from.size(), grid.size()); ++i) seeded.push_back(grid[i]);
    session->record({{"choice", "start"}, {"from", seeded}});
    return session;
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
            genomes.push_back(random_parameters(growth_.dimension(), config_.evolution.init_range, stream));
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

std::vector<std::string> BreedSession::add_plants(std::vector<std::vector<double>> genomes,
                                                  const std::vector<std::vector<std::string>>& parents,
                                                  int generation) {
    const std::vector<PlantOutcome> grown = growth_.grow_all(genomes, threads());
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < genomes.size(); ++i) {
        BreedPlant p;
        p.id = plant_id(next_plant_++);
        p.parents = parents[i];
        p.generation = generation;
        p.params = std::move(genomes[i]);
        p.fitness = grown[i].fitness;
        p.measures = grown[i].measures;
        p.descriptors = grown[i].descriptors;
        save_genome(Genome{growth_.grower().layers(), p.params}, (dir_ / "genomes" / (p.id + ".genome.json")).string());
        write_file_atomically(dir_ / "meshes" / (p.id + ".glb"), grown[i].glb);
        write_png_atomically(grown[i].thumb, dir_ / "thumbs" / (p.id + ".png"));
        ids.push_back(p.id);
        plants_[p.id] = std::move(p);
    }
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
    if (it == plants_.end()) throw not_found("no plant \"" + id + "\" in this session");
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
            throw bad_request("plant \"" + id + "\" is not in the current grid");
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
        std::error_code ignored;  // best effort: a file never written is no loss
        fs::remove(dir_ / "genomes" / (entry.first + ".genome.json"), ignored);
        fs::remove(dir_ / "meshes" / (entry.first + ".glb"), ignored);
        fs::remove(dir_ / "thumbs" / (entry.first + ".png"), ignored);
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

template <class Change>
void BreedSession::as_one_choice(Change&& change) {
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

void BreedSession::record(const json& choice) {
    choices_file_->write(choice.dump() + "\n");
    choices_file_->sync();
    ++choices_;
    write_json_file(dir_ / "state.json", saved_state());
    write_file_atomically(dir_ / "lineage.csv", lineage_csv());
}

json BreedSession::saved_state() const {
    json steps = json::array();
    for (const BreedStep& s : steps_) steps.push_back({{"grid", s.grid}, {"chosen", s.chosen}});
    json plants = json::array();
    for (const auto& [id, p] : plants_) {
        plants.push_back({{"id", id},
                          {"parents", p.parents},
                          {"generation", p.generation},
                          {"fitness", p.fitness ? json(*p.fitness) : json()},
                          {"measures", p.measures},
                          {"descriptors", p.descriptors}});
    }
    return {{"format", kStateFormat},
            {"version", kStateVersion},
            {"next_plant", next_plant_},
            {"choices", choices_},
            {"choices_bytes", choices_file_->size()},
            {"choices_hash", choices_file_->hash_hex()},
            {"cursor", cursor_},
            {"steps", steps},
            {"plants", plants}};
}

std::vector<std::string> BreedSession::chosen_ever() const {
    std::set<std::string> chosen;
    for (std::size_t s = 1; s <= cursor_; ++s) chosen.insert(steps_[s].chosen.begin(), steps_[s].chosen.end());
    return {chosen.begin(), chosen.end()};
}

std::string BreedSession::lineage_csv() const {
    const std::vector<std::string> chosen = chosen_ever();
    std::string out = "id,parent1,parent2,generation,chosen\n";
    for (const auto& [id, p] : plants_) {
        const bool was_chosen = std::binary_search(chosen.begin(), chosen.end(), id);
        out += id + "," + csv_list(p.parents, 0) + "," + csv_list(p.parents, 1) + "," + std::to_string(p.generation) +
               "," + (was_chosen ? "1" : "0") + "\n";
    }
    return out;
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

void BreedSession::start_explore(const std::vector<std::string>& parents, int births) {
    std::unique_lock lock(mutex_);
    check_parents(parents);
    if (births < 1 || births > kMaxExploreBirths)
        throw bad_request("\"births\" must be 1 to " + std::to_string(kMaxExploreBirths) + ", not " +
                          std::to_string(births));
    std::vector<ExploreSeed> seeds;
    for (const std::string& id : parents) {
        const BreedPlant& p = plant(id);
        if (!p.fitness || p.descriptors.empty())
            throw bad_request("plant \"" + id + "\" has no valid fitness or descriptors: the search cannot place it");
        seeds.push_back({p.params, *p.fitness, p.descriptors});
    }
    // Finished searches are joined here, outside the thread that runs them.
    if (search_thread_.joinable()) {
        lock.unlock();
        search_thread_.join();
        lock.lock();
        check_parents(parents);  // a choice may have come meanwhile
    }
    const std::uint64_t seed = RandomStream(config_.run.seed, next_plant_ | (std::uint64_t{1} << 62)).next_u64() >> 11;
    search_ = std::make_unique<ExploreSearch>(growth_, explore_settings_, std::move(seeds), seed,
                                              static_cast<std::uint64_t>(births),
                                              kBreedGridSize - parents.size());
    search_message_.clear();
    search_->set_running();
    search_thread_ = std::thread([this, parents, births] {
        ExploreResult result;
        std::string error;
        try {
            result = search_->run();
        } catch (const std::exception& e) {
            error = e.what();
        }
        std::lock_guard guard(mutex_);
        try {
            if (error.empty()) as_one_choice([&] { finish_explore(std::move(result), parents, births); });
        } catch (const std::exception& e) {
            error = e.what();
        }
        if (!error.empty()) search_message_ = "the search failed: " + error;
        search_->set_finished();
        explored_.notify_all();
    });
}

void BreedSession::finish_explore(ExploreResult result, std::vector<std::string> parents, int births) {
    std::vector<std::vector<double>> genomes;
    for (std::vector<double>& g : result.picked) {
        bool is_parent = false;
        for (const std::string& id : parents) is_parent = is_parent || plant(id).params == g;
        if (!is_parent && genomes.size() + parents.size() < static_cast<std::size_t>(kBreedGridSize))
            genomes.push_back(std::move(g));
    }
    // Fewer elites than cells: the rest are the parents' children.
    while (genomes.size() + parents.size() < static_cast<std::size_t>(kBreedGridSize))
        genomes.push_back(child_of(parents, 0.5, next_plant_ + genomes.size()));
    const std::vector<std::vector<std::string>> parent_lists(genomes.size(), parents);
    std::vector<std::string> grid = parents;
    const std::vector<std::string> found = add_plants(genomes, parent_lists, static_cast<int>(cursor_ + 1));
    grid.insert(grid.end(), found.begin(), found.end());
    push_step({grid, parents});
    search_message_ = "explored " + std::to_string(result.done) + " births";
    record({{"choice", "explore"}, {"parents", parents}, {"births", births}, {"done", result.done}});
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

std::pair<std::string, std::string> BreedSession::export_plant(const std::string& id,
                                                              const PlantExportOptions& options) {
    std::lock_guard lock(mutex_);
    const BreedPlant& p = plant(id);
    if (const std::string problem = plant_export_problem(options); !problem.empty()) throw bad_request(problem);
    PlantRecord record;
    record.id = id;
    record.genome_hash = genome_hash(p.params);
    record.fitness = p.fitness;
    for (const auto& [name, value] : p.measures) record.measures.emplace_back(name, value);
    record.run = name();
    record.birth = plant_number(id);
    for (const std::string& parent : p.parents) record.parents.push_back(plant_number(parent));
    export_engine_plant(growth_.grower(), p.params, record, options, dir_ / "exports" / id);
    return {"exports/" + id + ".genome.json", "exports/" + id + ".glb"};
}

std::string BreedSession::mesh_glb(const std::string& id) {
    std::lock_guard lock(mutex_);
    const BreedPlant& p = plant(id);
    const fs::path path = dir_ / "meshes" / (id + ".glb");
    if (!fs::exists(path)) write_file_atomically(path, growth_.grow(p.params).glb);
    return read_file_bytes(path, {kMaxMeshFileBytes, "mesh files"});
}

std::string BreedSession::thumb_png(const std::string& id) {
    std::lock_guard lock(mutex_);
    const BreedPlant& p = plant(id);
    const fs::path path = dir_ / "thumbs" / (id + ".png");
    if (!fs::exists(path)) write_png_atomically(growth_.grow(p.params).thumb, path);
    return read_file_bytes(path, {std::uint64_t{64} << 20, "thumbnails"});
}

std::unique_ptr<BreedSession> BreedSession::resume(const fs::path& dir, BreedSessionOptions options) {
    const fs::path config_path = dir / "config.json";
    if (!fs::exists(dir / "state.json"))
        throw CheckpointError((dir / "state.json").string() + ": missing: " + dir.string() + " is not a breeding session");
    auto held = lock_session(dir);
    const ExperimentConfig config = read_experiment_config(read_json_file(config_path), config_path.string());
    const json state = read_json_file(dir / "state.json");
    const std::string where = (dir / "state.json").string();
    try {
        if (state.at("format") != kStateFormat || state.at("version") != kStateVersion)
            throw CheckpointError(where + ": not a version " + std::to_string(kStateVersion) + " breeding session");
        std::unique_ptr<BreedSession> session(new BreedSession(dir, config, options));
        session->lock_ = std::move(held);
        for (const json& p : state.at("plants")) {
            BreedPlant plant;
            plant.id = p.at("id").get<std::string>();
            plant.parents = p.at("parents").get<std::vector<std::string>>();
            plant.generation = p.at("generation").get<int>();
            if (!p.at("fitness").is_null()) plant.fitness = p.at("fitness").get<double>();
            plant.measures = p.at("measures").get<std::map<std::string, double>>();
            plant.descriptors = p.at("descriptors").get<std::vector<double>>();
            plant.params = load_genome_for_session(session->growth_, dir / "genomes" / (plant.id + ".genome.json"));
            session->plants_[plant.id] = std::move(plant);
        }
        for (const json& s : state.at("steps"))
            session->steps_.push_back({s.at("grid").get<std::vector<std::string>>(),
                                       s.at("chosen").get<std::vector<std::string>>()});
        session->cursor_ = state.at("cursor").get<std::size_t>();
        session->next_plant_ = state.at("next_plant").get<std::uint64_t>();
        session->choices_ = state.at("choices").get<std::uint64_t>();
        if (session->steps_.empty() || session->cursor_ >= session->steps_.size())
            throw CheckpointError(where + ": its cursor is outside its steps");
        for (const BreedStep& s : session->steps_)
            for (const std::string& id : s.grid) session->plant(id);
        session->choices_file_ = std::make_unique<AppendFile>(AppendFile::resume(
            dir / "choices.jsonl", state.at("choices_bytes").get<std::uint64_t>(),
            state.at("choices_hash").get<std::string>()));
        write_file_atomically(dir / "lineage.csv", session->lineage_csv());
        return session;
    } catch (const json::exception& e) {
        throw CheckpointError(where + ": " + e.what());
    } catch (const BreedRequestError& e) {
        throw CheckpointError(where + ": " + e.what());
    }
}

std::unique_ptr<BreedSession> BreedSession::replay(const fs::path& from, const fs::path& out,
                                                   BreedSessionOptions options) {
    const fs::path config_path = from / "config.json";
    const ExperimentConfig config = read_experiment_config(read_json_file(config_path), config_path.string());
    std::ifstream log(from / "choices.jsonl");
    if (!log) throw IoError((from / "choices.jsonl").string() + ": cannot open");
    std::vector<json> choices;
    std::string line;
    while (std::getline(log, line)) {
        try {
            choices.push_back(read_json_object(line));
        } catch (const JsonTextError& e) {
            throw CheckpointError((from / "choices.jsonl").string() + ": line " + std::to_string(choices.size() + 1) +
                                  ": " + e.what());
        }
    }
    if (choices.empty() || choices[0].value("choice", "") != "start")
        throw CheckpointError((from / "choices.jsonl").string() + ": does not begin with the \"start\" choice");
    // The genomes a session started from are its first plants' files.
    std::vector<std::vector<double>> seeded;
    {
        const PlantGrowth growth(config, {});
        for (const json& id : choices[0].at("from"))
            seeded.push_back(load_genome_for_session(growth, from / "genomes" / (id.get<std::string>() + ".genome.json")));
    }
    std::unique_ptr<BreedSession> session = create(out, config, seeded, options);
    for (std::size_t i = 1; i < choices.size(); ++i) {
        try {
            std::lock_guard lock(session->mutex_);
            session->apply(choices[i]);
        } catch (const BreedRequestError& e) {
            throw CheckpointError((from / "choices.jsonl").string() + ": line " + std::to_string(i + 1) + ": " + e.what());
        } catch (const json::exception& e) {
            throw CheckpointError((from / "choices.jsonl").string() + ": line " + std::to_string(i + 1) + ": " + e.what());
        }
    }
    return session;
}

void BreedSession::apply(const json& choice) {
    const std::string kind = choice.at("choice").get<std::string>();
    if (kind == "breed") {
        breed_locked(choice.at("parents").get<std::vector<std::string>>(), choice.at("strength").get<double>());
    } else if (kind == "undo") {
        undo_locked();
    } else if (kind == "redo") {
        redo_locked();
    } else if (kind == "explore") {
        const auto parents = choice.at("parents").get<std::vector<std::string>>();
        std::vector<ExploreSeed> seeds;
        for (const std::string& id : parents) {
            const BreedPlant& p = plant(id);
            if (!p.fitness || p.descriptors.empty()) throw bad_request("plant \"" + id + "\" cannot seed a search");
            seeds.push_back({p.params, *p.fitness, p.descriptors});
        }
        const std::uint64_t seed = RandomStream(config_.run.seed, next_plant_ | (std::uint64_t{1} << 62)).next_u64() >> 11;
        const std::uint64_t done = choice.at("done").get<std::uint64_t>();
        ExploreResult result;
        if (done > 0) {
            ExploreSearch search(growth_, explore_settings_, std::move(seeds), seed, done,
                                 kBreedGridSize - parents.size());
            result = search.run();
        }
        finish_explore(std::move(result), parents, choice.at("births").get<int>());
    } else {
        throw bad_request("unknown choice \"" + kind + "\"");
    }
}

}  // namespace morphogen
