#pragma once
// checkpoint.json: everything needed to continue a run bit-exactly.
//
// File format 3 (written): format 2 below with "version":3, whose content's
// config carries its format (`format_version`, run/config/config_migration.hpp).
//
// File format 2 (read: morphogen 0.1.0 wrote it): a JSON header line (keys sorted, compact), "\n",
// then the genomes as raw bytes:
//   {"content":{...},"format":"morphogen-checkpoint",
//    "genomes":{"count":N,"dimension":D,"encoding":"f64le"},"hash":"<16 hex>","version":2}\n
//   <N x D little-endian IEEE-754 doubles, genome after genome>
// Every individual in the content holds "genome": k (its parameters are the
// k-th run of D doubles) instead of a "params" array (genome_blob.hpp), so
// genomes are exact bits and never pass through JSON text. D is the network's
// parameter count (0 when N is 0). `hash` is the FNV-1a 64 of content.dump()
// followed by the binary part. `head -n 1 checkpoint.json` is the readable
// part (jq reads it); the file as a whole is not JSON.
//
// File format 1 (read, so runs from older builds resume; the next save writes
// format 3): the same header with "version":1, no "genomes", genomes inline
// as "params" arrays, nothing after the "\n"; `hash` is FNV-1a 64 of
// content.dump().
//
// A file is accepted only if its header parses, has this format and a known
// version, the hash matches, the binary part has exactly the announced size,
// the config has format_version exactly in version 3, and the header is byte for byte the canonical dump of what was parsed — so
// any truncation or single changed byte is refused. Writes are atomic
// (atomic_file.hpp): one file, so new genomes never meet an old header.
//
// `content` holds the resolved config, the GA state (seed, birth counter,
// population with ids, parents, genomes and fitness, best so far) or, for a
// MAP-Elites run, its state (map_elites_state_json.hpp: the archive's elites
// with genomes, descriptors, fitness, ids and parents, the CVT centroids, the
// best ever, the generation counters), every
// history row so far, the length and hash of lineage.csv at checkpoint time,
// and the elapsed run time. Formats 1 and 2 hold a config of format 1, which
// is migrated on reading (the state holds the current format; the next save
// writes it).
#include "run/loop/run_state.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace morphogen {

inline constexpr int checkpoint_version = 3;  // written; 1 to 3 are read

// Atomically writes the checkpoint (format 3). Throws IoError.
void save_checkpoint(const std::filesystem::path& path, const RunState& state);
// The bytes save_checkpoint writes.
std::string checkpoint_bytes(const RunState& state);

// Reads and verifies a checkpoint: envelope (see above), then the content
// against its own config (parameter counts, population size, ...) and against
// itself (checkpoint_checks.hpp; lineage.csv is the caller's part). Throws
// CheckpointError whose message contains "checkpoint" and says why; never
// modifies the file.
RunState load_checkpoint(const std::filesystem::path& path);

// The envelope alone (for tests and tools that edit a checkpoint):
// checkpoint_text is the format-1 text of a content with inline genomes
// ("params" arrays; still read, so an edited content can be sealed again);
// checkpoint_content verifies a checkpoint of any format and returns its
// content as stored, with the genomes inline as in format 1 (CheckpointError
// otherwise).
std::string checkpoint_text(const nlohmann::json& content);
nlohmann::json checkpoint_content(const std::string& text, const std::string& source);

// The parts of a checkpoint of format 2 or later as stored (genomes by
// reference), and the file holding them in format 3 with a correct hash: for
// tests that edit one.
struct CheckpointParts {
    nlohmann::json content;
    std::string genomes;  // the binary part
    std::uint64_t count = 0;
    std::uint64_t dimension = 0;
};
CheckpointParts checkpoint_parts(const std::string& bytes, const std::string& source);
std::string checkpoint_bytes(const CheckpointParts& parts);

}  // namespace morphogen
