#pragma once
// A MAP-Elites archive (docs/algorithm.md §9.2-§9.5): cells over a space of behaviour
// descriptors, each holding at most one elite, the best individual found
// whose descriptors fall in it. Two ways to map descriptors to a cell:
//
// - grid (1 to 3 descriptors): per descriptor
//     b_k = clamp(floor((x_k - min_k) / (max_k - min_k) * bins_k), 0, bins_k - 1)
//   and cell = row-major index of (b_0, b_1, ...), the first descriptor slowest;
// - CVT (any number of descriptors): every descriptor is scaled to
//   s_k = clamp((x_k - min_k) / (max_k - min_k), 0, 1) and the cell is the
//   nearest centroid (cvt.hpp; ties: the lower index).
//
// In both, values outside [min, max] land in the edge cells. A non-finite
// descriptor, or a wrong number of them, places nowhere. Nothing here knows
// what the descriptors measure.
//
// An archive may also keep thresholds (CMA-MAE's annealing, §9.9, as in
// pyribs' archives): every cell has one, threshold_min until a child beats
// it, then moved toward each child that beats it by the learning rate. They
// never decide who enters a cell; emitters rank their children by them.
#include "evolution/individual.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace morphogen {

struct DescriptorRange {
    std::string name;  // for reports (archive.csv's header); not interpreted
    double min = 0.0;
    double max = 1.0;  // min < max, both finite, max - min finite
    int bins = 1;      // grid archives only; >= 1
};

// The most cells a grid may have (cell indices and counts stay exact).
inline constexpr std::uint64_t kMaxGridCells = std::uint64_t{1} << 40;

enum class ArchiveKind { grid, cvt };

// The thresholds' rule (docs/algorithm.md §9.9): a valid child of fitness f
// in a cell of threshold t moves it to (1 - learning_rate) t +
// learning_rate f when f > t.
struct ThresholdParams {
    double learning_rate = 0.01;  // alpha, in [0, 1]
    double threshold_min = 0.0;   // the threshold of a cell no child has beaten yet
    bool operator==(const ThresholdParams&) const = default;
};

class Archive {
public:
    // Throws std::invalid_argument (naming the descriptor) unless there are 1
    // to 3 ranges, each with finite min < max and bins >= 1, and the product
    // of the bins is at most kMaxGridCells.
    static Archive grid(std::vector<DescriptorRange> ranges);
    // `centroids`: row-major, cells x ranges.size(), in [0,1] (e.g. from
    // cvt_centroids, or a checkpoint). Throws std::invalid_argument for bad
    // ranges (bins are ignored), no centroids, more than kMaxCvtCells, a size
    // that is not a multiple of the dimension, or a value outside [0,1].
    static Archive cvt(std::vector<DescriptorRange> ranges, std::vector<double> centroids);

    ArchiveKind kind() const { return kind_; }
    const std::vector<DescriptorRange>& ranges() const { return ranges_; }
    std::size_t dimensions() const { return ranges_.size(); }
    std::uint64_t cells() const { return cells_; }
    // CVT: row-major cells x dimensions; grid: empty.
    const std::vector<double>& centroids() const { return centroids_; }

    // The cell of a descriptor vector, or none if it has the wrong length or
    // a non-finite value. Thread-safe (const, no caching).
    std::optional<std::uint64_t> cell_of(std::span<const double> descriptors) const;
    // Grid only: the per-descriptor bins b_k (throws std::logic_error for a
    // CVT archive, std::invalid_argument as cell_of gives none).
    std::vector<std::uint64_t> bins_of(std::span<const double> descriptors) const;

    enum class Placement { rejected, filled, replaced };
    // What inserting a child did, and what its cell held before: what an
    // emitter ranks the child by (emitters.hpp).
    struct Insertion {
        Placement placement = Placement::rejected;
        std::optional<std::uint64_t> cell;         // none if invalid or unplaceable
        std::optional<double> elite_fitness;       // the cell's elite's fitness before, if any
        double threshold = 0.0;                    // the cell's threshold before (with thresholds kept)
    };
    // docs/algorithm.md §9.5: a valid child that has a cell enters it if the cell is
    // empty (filled) or its fitness is >= the elite's (replaced: on equal
    // fitness the newcomer wins). Otherwise, or if invalid, rejected. With
    // thresholds kept, a valid child with a cell also moves its cell's
    // threshold when it beats it.
    Insertion insert(const Individual& child);
    // Puts `elite` in `cell` as a checkpoint stored it. Throws
    // std::invalid_argument if the cell is out of range or taken, the elite is
    // invalid, or its descriptors do not map to `cell`.
    void restore(std::uint64_t cell, Individual elite);

    // Keeps thresholds from now on. Throws std::invalid_argument if it keeps
    // them already with other parameters, or for a learning rate outside [0, 1].
    void keep_thresholds(ThresholdParams params);
    const std::optional<ThresholdParams>& threshold_params() const { return threshold_params_; }
    // The cells whose threshold rose above threshold_min, and that threshold.
    const std::map<std::uint64_t, double>& thresholds() const { return thresholds_; }
    // Sets a cell's threshold as a checkpoint stored it (the caller checks it).
    // Throws std::logic_error when no thresholds are kept.
    void restore_threshold(std::uint64_t cell, double threshold);

    // Occupied cells in index order.
    const std::map<std::uint64_t, Individual>& elites() const { return elites_; }
    std::size_t occupied() const { return elites_.size(); }
    // The elites in cell-index order (pointers into this archive, valid until
    // it changes): the snapshot a batch draws its parents from.
    std::vector<const Individual*> snapshot() const;

private:
    Archive(ArchiveKind kind, std::vector<DescriptorRange> ranges, std::uint64_t cells, std::vector<double> centroids);

    ArchiveKind kind_;
    std::vector<DescriptorRange> ranges_;
    std::uint64_t cells_;
    std::vector<double> centroids_;
    std::map<std::uint64_t, Individual> elites_;
    std::optional<ThresholdParams> threshold_params_;
    std::map<std::uint64_t, double> thresholds_;
};

// Bytes the archive's genomes need when every cell is occupied, cells x
// dimension x 8 (a lower bound, for refusing archives too large for memory).
double archive_genome_bytes(std::uint64_t cells, std::size_t dimension);

}  // namespace morphogen
