#pragma once
// checkpoint.json: everything needed to continue a run bit-exactly.
//
// File format (one line, keys sorted, compact, then "\n"):
//   {"content":{...},"format":"morphogen-checkpoint","hash":"<16 hex>","version":1}
// `hash` is the FNV-1a 64 of content.dump(). A file is accepted only if it
// parses, has this format and version, the hash matches, and the file is
// byte for byte the canonical dump of what was parsed — so any truncation or
// single changed byte is refused. Writes are atomic (atomic_file.hpp).
//
// `content` holds the resolved config, the GA state (seed, birth counter,
// population with ids, parents, genomes and fitness, best so far) or, for a
// MAP-Elites run, its state (map_elites_state_json.hpp: the archive's elites
// with genomes, descriptors, fitness, ids and parents, the CVT centroids, the
// best ever, the generation counters), every
// history row so far, the length and hash of lineage.csv at checkpoint time,
// and the elapsed run time.
#include "run_records.hpp"
#include "map_elites.hpp"
#include "steady_state.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace morphogen {

inline constexpr int checkpoint_version = 1;

struct RunState {
    nlohmann::json config;  // the resolved config
    std::uint64_t seed = 0; // == config.run.seed; stored on its own for readers
    GaState ga;                          // steady_state runs ("ga" in the content)
    std::optional<MapElitesState> elites; // map_elites runs ("map_elites" in the content, instead of "ga")
    std::vector<HistoryRow> history;
    std::uint64_t lineage_bytes = 0;  // lineage.csv length at checkpoint time
    std::string lineage_hash;         // FNV-1a 64 (hex) of those bytes
    double elapsed_s = 0.0;           // run time so far, over all sessions

    std::uint64_t births() const { return elites ? elites->births : ga.births; }
};

// Atomically writes the checkpoint. Throws IoError.
void save_checkpoint(const std::filesystem::path& path, const RunState& state);

// Reads and verifies a checkpoint: envelope (see above), then the content
// against its own config (parameter counts, population size, ...) and against
// itself (checkpoint_checks.hpp; lineage.csv is the caller's part). Throws
// CheckpointError whose message contains "checkpoint" and says why; never
// modifies the file.
RunState load_checkpoint(const std::filesystem::path& path);

// The envelope alone (for tests): the text of a checkpoint holding `content`,
// and the verified content of such a text (CheckpointError otherwise).
std::string checkpoint_text(const nlohmann::json& content);
nlohmann::json checkpoint_content(const std::string& text, const std::string& source);

}  // namespace morphogen
