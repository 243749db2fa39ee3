#pragma once
// The genomes an `evolve --from` run starts from (run.from): where they are
// read from, and their copies in RUN_DIR/seeds/ (one genome file each and
// manifest.json with its origin and FNV-1a hash), which `resume` reads so a
// run needs nothing outside its directory.
#include <filesystem>
#include <string>
#include <vector>

namespace morphogen {

// A given genome and where it came from ("FILE", or "DIR (best)" / "DIR (elite 3)").
struct GivenGenome {
    std::vector<double> params;
    std::string origin;
};

// The genomes `sources` name, in order. A source is a genome file (as `grow
// --genome` reads), a run directory (a GA run's best; a MAP-Elites run's
// elites in cell order, from its checkpoint), a breed session (the genomes of
// its exports/) or a directory of *.genome.json files (by name). Throws
// ConfigError naming the source and both shapes when a genome's layers are not
// `layers`, IoError when a source is missing or holds no genome.
std::vector<GivenGenome> read_given_genomes(const std::vector<std::string>& sources, const std::vector<int>& layers);

// Writes RUN_DIR/seeds/ afresh (seed_NNN.genome.json and manifest.json).
void record_given_genomes(const std::filesystem::path& run_dir, const std::vector<GivenGenome>& genomes,
                          const std::vector<int>& layers);

// The recorded genomes in order; empty when RUN_DIR/seeds/manifest.json does
// not exist. Throws CheckpointError when a listed file is missing, changed
// (its hash differs) or of another shape.
std::vector<std::vector<double>> load_recorded_genomes(const std::filesystem::path& run_dir,
                                                       const std::vector<int>& layers);

}  // namespace morphogen
