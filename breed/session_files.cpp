// BreedSession's directory (breed/session.hpp): creating it, recording a
// choice (choices.jsonl, state.json, lineage.csv), and opening it again by
// resume or by replaying its choices.
#include "breed/session.hpp"

#include "breed/breed_errors.hpp"
#include "core/base/append_file.hpp"
#include "core/base/atomic_file.hpp"
#include "core/base/config_reader.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"
#include "core/growth/genome_io.hpp"

#include <algorithm>
#include <set>
#include <string_view>

namespace morphogen {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {
constexpr const char* kStateFormat = "morphogen-breed-session";
constexpr int kStateVersion = 1;

std::vector<double> load_genome_for_session(const PlantGrowth& growth, const fs::path& path) {
    Genome genome = load_genome(path.string());
    if (genome.layers != growth.grower().layers())
        throw CheckpointError(path.string() + ": its network's layers do not match the session's config");
    return std::move(genome.params);
}

std::string csv_list(const std::vector<std::string>& parents, std::size_t i) {
    return i < parents.size() ? parents[i] : std::string();
}

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

std::unique_ptr<BreedSession> BreedSession::create(const fs::path& dir, const ExperimentConfig& config,
                                                   const std::vector<std::vector<double>>& from,
                                                   BreedSessionOptions options) {
    if (fs::exists(dir) && !(fs::is_directory(dir) && fs::is_empty(dir)))
        throw IoError(dir.string() + ": already exists and is not an empty directory (continue a session with --resume " +
                      dir.string() + ")");
    for (const char* sub : {"genomes", "meshes", "thumbs", "exports"}) fs::create_directories(dir / sub);
    auto held = lock_session(dir);
    write_file_atomically(dir / "config.json", config.resolved.dump(1) + "\n");
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

void BreedSession::record(const json& choice) {
    choices_file_->write(choice.dump() + "\n");
    choices_file_->sync();
    ++choices_;
    write_file_atomically(dir_ / "state.json", saved_state().dump(1) + "\n");
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

std::unique_ptr<BreedSession> BreedSession::resume(const fs::path& dir, BreedSessionOptions options) {
    const fs::path config_path = dir / "config.json";
    if (!fs::exists(dir / "state.json"))
        throw CheckpointError((dir / "state.json").string() + ": missing: " + dir.string() + " is not a breeding session");
    auto held = lock_session(dir);
    const ExperimentConfig config = read_experiment_config(load_json_file(config_path.string()), config_path.string());
    const std::string where = (dir / "state.json").string();
    json state;
    try {
        state = read_json_object(read_file_bytes(dir / "state.json", memory_bound("session files (this machine's memory)")));
    } catch (const JsonTextError& e) {
        throw CheckpointError("invalid JSON at " + where + ", " + e.what());
    }
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
        session->removed_on_resume_ = session->remove_unowned_plant_files();
        write_file_atomically(dir / "lineage.csv", session->lineage_csv());
        return session;
    } catch (const json::exception& e) {
        throw CheckpointError(where + ": " + e.what());
    } catch (const BreedRequestError& e) {
        throw CheckpointError(where + ": " + e.message);
    }
}

std::unique_ptr<BreedSession> BreedSession::replay(const fs::path& from, const fs::path& out,
                                                   BreedSessionOptions options) {
    const fs::path config_path = from / "config.json";
    const ExperimentConfig config = read_experiment_config(load_json_file(config_path.string()), config_path.string());
    const std::string log = read_file_bytes(from / "choices.jsonl", memory_bound("choices.jsonl (this machine's memory)"));
    std::vector<json> choices;
    for (std::size_t at = 0, end; at < log.size(); at = end + 1) {
        end = std::min(log.find('\n', at), log.size());
        try {
            choices.push_back(read_json_object(std::string_view(log).substr(at, end - at)));
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
            throw CheckpointError((from / "choices.jsonl").string() + ": line " + std::to_string(i + 1) + ": " + e.message);
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
        // A line without "along" is from before the architecture explore.
        const std::string name = choice.value("along", std::string("descriptors"));
        const std::optional<ExploreAlong> along = explore_along_from(name);
        if (!along) throw bad_request("unknown explore \"along\" " + quoted(name));
        replay_explore(choice.at("parents").get<std::vector<std::string>>(), choice.at("births").get<int>(),
                       choice.at("done").get<std::uint64_t>(), *along);
    } else {
        throw bad_request("unknown choice " + quoted(kind));
    }
}

}  // namespace morphogen
