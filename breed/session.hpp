#pragma once
// A breeding session (docs/breed.md): a grid of plants a person chooses
// parents from, the history of grids (undo/redo), the lineage, and the
// session directory that keeps it all:
//   config.json     the resolved config (its run.seed is the session's seed)
//   choices.jsonl   one line per choice: start, breed, undo, redo, explore
//   state.json      the grids and plants, written atomically after every choice
//   lineage.csv     every plant shown: id, parents, generation, chosen
//   genomes/ID.genome.json, meshes/ID.glb, thumbs/ID.png, exports/
// A plant is a pure function of the seed and the choices before it: plant
// number n draws only from RandomStream(seed, n) (evolution/rng.hpp), with
// the project's mutation and crossover (evolution/operators.hpp). So
// replaying choices.jsonl gives the same ids, genomes and files.
//
// Every public member is thread-safe (one mutex); the explore search runs on
// a thread of its own and takes the mutex only to start and to finish.
#include "breed/explore.hpp"
#include "breed/plant_growth.hpp"
#include "engine/plant_export.hpp"
#include "run/config/experiment_config.hpp"
#include "run/persistence/run_directory.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace morphogen {

class AppendFile;

inline constexpr int kBreedGridSize = 12;

struct BreedPlant {
    std::string id;                    // "p" and 6 digits: its plant number
    std::vector<std::string> parents;  // 0, 1 or 2 ids
    int generation = 0;                // the grid it was born for
    std::vector<double> params;
    std::optional<double> fitness;
    std::map<std::string, double> measures;
    std::vector<double> descriptors;  // empty when not measurable
};

// One grid of the history: what was shown, and the parents it was bred from.
struct BreedStep {
    std::vector<std::string> grid;
    std::vector<std::string> chosen;
};

struct BreedSessionOptions {
    int threads = 0;     // threads that grow a grid's plants; 0: all cores (resolve_threads)
    bool colour = true;  // the page's GLBs and thumbnails in colours from growth history
};

class BreedSession {
public:
    // A new session in `dir` (created; refused with IoError if it holds
    // files). `from`: genomes for the first cells (the rest are their
    // mutants); empty: kBreedGridSize random genomes.
    static std::unique_ptr<BreedSession> create(const std::filesystem::path& dir, const ExperimentConfig& config,
                                                const std::vector<std::vector<double>>& from,
                                                BreedSessionOptions options = {});
    // Continues the session in `dir` as its state.json left it: a choice
    // whose state.json was never written is dropped from choices.jsonl, and
    // its plants' files removed (removed_on_resume() names them).
    // Refused with IoError, nothing read or written, while another session
    // (in this or another process) holds the directory; a process killed
    // with kill -9 holds nothing (the lock is flock(2) on <dir>/.lock).
    static std::unique_ptr<BreedSession> resume(const std::filesystem::path& dir, BreedSessionOptions options = {});
    // Replays `from`'s choices.jsonl into the new session `out`.
    static std::unique_ptr<BreedSession> replay(const std::filesystem::path& from, const std::filesystem::path& out,
                                                BreedSessionOptions options = {});
    ~BreedSession();

    // The API's state (docs/breed.md): grid, chosen, can_undo/redo, search.
    nlohmann::json state_json() const;
    nlohmann::json lineage_json() const;

    // The choices; each returns after state.json holds it. BreedRequestError
    // (breed_errors.hpp) for bad arguments, unknown ids, nothing to undo, a
    // search running.
    void breed(const std::vector<std::string>& parents, double strength);
    void undo();
    void redo();
    // Starts the explore search on its own thread, along the architecture
    // or the config's descriptors (breed/explore.hpp); the next grid comes
    // when it ends (or stop_explore()).
    void start_explore(const std::vector<std::string>& parents, int births,
                       ExploreAlong along = ExploreAlong::architecture);
    void stop_explore();
    // Waits for a running search to end and its grid to be saved (tests, shutdown).
    void wait_explore();

    // Writes exports/ID.genome.json, ID.glb (engine-ready with `options`)
    // and ID.obj; returns the paths relative to the directory.
    std::pair<std::string, std::string> export_plant(const std::string& id, const PlantExportOptions& options);

    // The plain GLB and the PNG thumbnail of a plant (grown again if the
    // cached file is missing). BreedRequestError 404 for an unknown id.
    std::string mesh_glb(const std::string& id);
    std::string thumb_png(const std::string& id);

    const std::filesystem::path& dir() const { return dir_; }
    // The plant files resume() removed because no recorded choice owns them
    // (relative to dir(), sorted; empty for a session closed cleanly).
    const std::vector<std::string>& removed_on_resume() const { return removed_on_resume_; }
    std::string name() const;
    std::uint64_t seed() const { return config_.run.seed; }

private:
    BreedSession(std::filesystem::path dir, ExperimentConfig config, BreedSessionOptions options);
    // Born plants get ids, genome files, mesh and thumbnail files.
    std::vector<std::string> add_plants(std::vector<std::vector<double>> genomes,
                                        const std::vector<std::vector<std::string>>& parents, int generation);
    std::vector<double> child_of(const std::vector<std::string>& parents, double strength, std::uint64_t number) const;
    const BreedPlant& plant(const std::string& id) const;  // 404 if unknown
    void check_parents(const std::vector<std::string>& parents) const;
    void push_step(BreedStep step);
    // Appends the choice to choices.jsonl, then writes state.json and lineage.csv.
    void record(const nlohmann::json& choice);
    // A choice in memory is undone when it could not be saved (a full disk):
    // the session stays what state.json says.
    struct Saved;
    Saved saved_point() const;
    void roll_back(const Saved& saved);
    // Runs `change` (which ends with record()); if it throws, rolls back and rethrows.
    void as_one_choice(const std::function<void()>& change);
    void apply(const nlohmann::json& choice);  // replay: one line of choices.jsonl
    // The explore search's settings for these parents, its seeds (400 for a
    // parent it cannot place) and its random seed.
    ExploreSettings explore_settings_for(const std::vector<std::string>& parents, ExploreAlong along) const;
    std::vector<ExploreSeed> explore_seeds(const std::vector<std::string>& parents, ExploreAlong along) const;
    std::uint64_t explore_seed() const;
    void finish_explore(ExploreResult result, std::vector<std::string> parents, int births, ExploreAlong along);
    // Replay of an explore choice: the search run for the `done` births it made.
    void replay_explore(const std::vector<std::string>& parents, int births, std::uint64_t done, ExploreAlong along);
    // Plant files (session_plants.cpp): removes one plant's, best effort; and
    // those of plants not in plants_, returned relative to dir_, sorted.
    void remove_plant_files(const std::string& id) const;
    std::vector<std::string> remove_unowned_plant_files() const;
    void breed_locked(const std::vector<std::string>& parents, double strength);
    void undo_locked();
    void redo_locked();
    std::vector<std::string> start_grid(const std::vector<std::vector<double>>& from);
    nlohmann::json saved_state() const;
    std::string lineage_csv() const;
    std::vector<std::string> chosen_ever() const;
    int threads() const;

    std::filesystem::path dir_;
    ExperimentConfig config_;
    BreedSessionOptions options_;
    ExploreSettings explore_settings_;
    PlantGrowth growth_;
    std::map<std::string, BreedPlant> plants_;
    std::uint64_t next_plant_ = 0;
    std::vector<BreedStep> steps_;  // steps_[cursor_] is the grid shown
    std::size_t cursor_ = 0;
    std::uint64_t choices_ = 0;
    std::vector<std::string> removed_on_resume_;
    std::unique_ptr<RunLock> lock_;  // one writer per session directory, for the session's life
    std::unique_ptr<AppendFile> choices_file_;
    mutable std::mutex mutex_;

    // The explore search in flight, if any.
    std::unique_ptr<ExploreSearch> search_;
    std::thread search_thread_;
    std::string search_message_;
    std::condition_variable explored_;  // a search ended
};

}  // namespace morphogen
