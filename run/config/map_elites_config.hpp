#pragma once
// The config keys of MAP-Elites runs (docs/algorithm.md §9, docs/map-elites.md):
// `evolution.algorithm`, the top-level `descriptors` list, `archive` section
// and `emitters` list. They appear in the resolved config, every default
// written out, when the algorithm is "map_elites" (and `descriptors` when a
// steady-state config gives it); they do not apply to a steady-state run.
#include "core/base/config_reader.hpp"
#include "evolution/archives/archive.hpp"
#include "evolution/emitters/emitters.hpp"
#include "evolution/evolution_params.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace morphogen {

struct QdParams {
    std::vector<DescriptorRange> descriptors;  // name = the measure (fitness/descriptors.hpp)
    ArchiveKind archive = ArchiveKind::grid;
    std::uint64_t cvt_cells = 1000;            // archive.cells, CVT only
    double qd_offset = 0.0;                    // archive.qd_offset: QD-score sums fitness - offset
    std::vector<EmitterSpec> emitters;         // `emitters` (emitter_registry.hpp); map_elites only

    std::vector<std::string> measure_names() const;
    // Cells of the archive: the product of the bins (grid) or cvt_cells.
    std::uint64_t cells() const;
};

// Reads `descriptors` and `archive` from the top-level reader for a run with
// `algorithm`, adding every problem to the reader's issues with its key path:
// an unknown measure (with the nearest name), min >= max, bins < 1, a grid
// with no or more than 3 descriptors or more than kMaxGridCells cells, a CVT
// with more than kMaxCvtCells cells, and `archive` given for a steady-state
// run (it would be ignored). A steady-state run may give `descriptors` (any
// number, no archive limits): its births' measures are then recorded in
// lineage.csv, so it can be binned like a MAP-Elites run. Records
// `descriptors` in the resolved config when it is given or the run is
// map_elites, `archive` only for map_elites. `emitters` (MAP-Elites only;
// docs/algorithm.md §9.8): a non-empty list of {kind, share, selection,
// sigma_iso, sigma_line}, recorded in the resolved config of every
// map_elites run (the default emitters when not given). Whether a full
// archive fits in memory is resource_estimate's part (search_genomes counts
// its cells), with the other limits. Novelty search ("nslc", docs/algorithm.md
// §14) needs `descriptors` as MAP-Elites does, refuses their `bins` (it bins
// nothing) and, as the GA, `archive` and `emitters`.
QdParams read_qd_params(ObjectReader& top, Algorithm algorithm);

// "steady_state" | "map_elites" | "nslc".
const char* algorithm_name(Algorithm algorithm);

}  // namespace morphogen
