#pragma once
// The run directory (docs/evolution.md "The run directory"): where its files live, how a
// new one is made, and a lock so two processes never write one run.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace morphogen {

struct RunPaths {
    std::filesystem::path dir, config, history, lineage, checkpoint, best, log;
    std::filesystem::path archive;  // archive.csv (MAP-Elites runs)
    // best/gen_NNNN (no extension): the stem of generation g's exports.
    std::filesystem::path best_stem(std::uint64_t generation) const;
};

RunPaths run_paths(const std::filesystem::path& dir);

// "gen_NNNN" (at least four digits): how generation g's exports are named.
std::string export_name(std::uint64_t generation);
// The generation of a name that begins "gen_<digits>" (export_name), if it
// does; with `extension`, only if the rest of the name is exactly that.
std::optional<std::uint64_t> export_generation(std::string_view name, std::string_view extension = {});

// runs/<name>-<YYYYmmdd-HHMMSS> (local time).
std::filesystem::path default_run_dir(const std::string& name, std::chrono::system_clock::time_point now);

// A run stopped before its first checkpoint (kill -9, power loss or a full
// disk during start-up): a non-empty directory with no checkpoint.json and
// nothing but morphogen's own names in it (config.json, history.csv,
// lineage.csv, log.txt, .lock, their .tmp files, an empty best/), where
// history.csv and lineage.csv hold no rows. Nothing of value is in it, so `evolve` may start over there.
bool is_stopped_start(const RunPaths& paths);

// For a new run: refuses (IoError saying it exists) an existing non-empty
// directory unless `force` or it is_stopped_start(), and a path that is not a
// directory; then creates the directory. Take the RunLock next, then
// clear_run_files().
void create_run_dir(const RunPaths& paths, bool force);
// Removes the files morphogen writes in a run directory (config.json,
// history.csv, lineage.csv, checkpoint.json, log.txt, archive.csv, best/gen_*, and their
// temporary files) and nothing else; creates best/.
void clear_run_files(const RunPaths& paths);
// For a resume: removes temporary files a crash left (<file>.tmp in the run
// directory and best/) and the exports of generations >= `first_generation`
// (written after the checkpoint; the resumed run writes them again); creates
// best/ if it is missing. Throws IoError naming the file and the reason.
void prepare_resumed_run_files(const RunPaths& paths, std::uint64_t first_generation);

// An exclusive advisory lock on <dir>/.lock for this object's life; throws
// IoError if another process holds it.
class RunLock {
public:
    explicit RunLock(const std::filesystem::path& dir);
    RunLock(const RunLock&) = delete;
    RunLock& operator=(const RunLock&) = delete;
    ~RunLock();

private:
    int fd_ = -1;
};

}  // namespace morphogen
