#include "evolution/archives/archive.hpp"

#include "evolution/archives/cvt.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace morphogen {

namespace {
[[noreturn]] void refuse(const std::string& what) { throw std::invalid_argument(what); }

std::string label(const DescriptorRange& range, std::size_t k) {
    return "descriptor " + std::to_string(k) + (range.name.empty() ? "" : " (" + range.name + ")");
}

void check_ranges(const std::vector<DescriptorRange>& ranges, bool grid) {
    if (ranges.empty()) refuse("an archive needs at least one descriptor");
    for (std::size_t k = 0; k < ranges.size(); ++k) {
        const DescriptorRange& r = ranges[k];
        if (!std::isfinite(r.min) || !std::isfinite(r.max) || !(r.min < r.max) || !std::isfinite(r.max - r.min))
            refuse(label(r, k) + ": needs finite min < max, got [" + std::to_string(r.min) + ", " +
                   std::to_string(r.max) + "]");
        if (grid && r.bins < 1) refuse(label(r, k) + ": needs bins >= 1, got " + std::to_string(r.bins));
    }
}

bool all_finite(std::span<const double> values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// floor((x - min) / (max - min) * bins) clamped to [0, bins - 1], in double
// until clamped so a huge value cannot overflow the conversion.
std::uint64_t bin_of(double x, const DescriptorRange& r) {
    const double t = std::floor((x - r.min) / (r.max - r.min) * static_cast<double>(r.bins));
    if (!(t > 0.0)) return 0;  // also catches -0.0
    const auto last = static_cast<double>(r.bins - 1);
    return static_cast<std::uint64_t>(std::min(t, last));
}
}  // namespace

Archive::Archive(ArchiveKind kind, std::vector<DescriptorRange> ranges, std::uint64_t cells,
                 std::vector<double> centroids)
    : kind_(kind), ranges_(std::move(ranges)), cells_(cells), centroids_(std::move(centroids)) {}

Archive Archive::grid(std::vector<DescriptorRange> ranges) {
    check_ranges(ranges, true);
    if (ranges.size() > 3)
        refuse("a grid archive has 1 to 3 descriptors, not " + std::to_string(ranges.size()) + " (use a CVT archive)");
    std::uint64_t cells = 1;
    for (const DescriptorRange& r : ranges) {
        if (static_cast<std::uint64_t>(r.bins) > kMaxGridCells / cells)
            refuse("a grid archive of more than " + std::to_string(kMaxGridCells) + " cells");
        cells *= static_cast<std::uint64_t>(r.bins);
    }
    return Archive(ArchiveKind::grid, std::move(ranges), cells, {});
}

Archive Archive::cvt(std::vector<DescriptorRange> ranges, std::vector<double> centroids) {
    check_ranges(ranges, false);
    const std::size_t d = ranges.size();
    if (centroids.empty() || centroids.size() % d != 0)
        refuse("a CVT archive needs cells x " + std::to_string(d) + " centroid coordinates, got " +
               std::to_string(centroids.size()));
    const std::uint64_t cells = centroids.size() / d;
    if (cells > kMaxCvtCells)
        refuse("a CVT archive places at most " + std::to_string(kMaxCvtCells) + " cells, not " + std::to_string(cells));
    for (std::size_t i = 0; i < centroids.size(); ++i)
        if (!(centroids[i] >= 0.0 && centroids[i] <= 1.0))
            refuse("CVT centroid " + std::to_string(i / d) + " has a coordinate outside [0, 1]");
    return Archive(ArchiveKind::cvt, std::move(ranges), cells, std::move(centroids));
}

std::optional<std::uint64_t> Archive::cell_of(std::span<const double> x) const {
    if (x.size() != ranges_.size() || !all_finite(x)) return std::nullopt;
    if (kind_ == ArchiveKind::grid) {
        std::uint64_t cell = 0;
        for (std::size_t k = 0; k < x.size(); ++k)
            cell = cell * static_cast<std::uint64_t>(ranges_[k].bins) + bin_of(x[k], ranges_[k]);
        return cell;
    }
    std::vector<double> scaled(x.size());
    for (std::size_t k = 0; k < x.size(); ++k)
        scaled[k] = std::clamp((x[k] - ranges_[k].min) / (ranges_[k].max - ranges_[k].min), 0.0, 1.0);
    return nearest_centroid(centroids_, scaled);
}

std::vector<std::uint64_t> Archive::bins_of(std::span<const double> x) const {
    if (kind_ != ArchiveKind::grid) throw std::logic_error("bins_of: not a grid archive");
    if (x.size() != ranges_.size() || !all_finite(x))
        refuse("bins_of: " + std::to_string(x.size()) + " descriptors (need " + std::to_string(ranges_.size()) +
               ", finite)");
    std::vector<std::uint64_t> bins(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) bins[k] = bin_of(x[k], ranges_[k]);
    return bins;
}

Archive::Insertion Archive::insert(const Individual& child) {
    Insertion out;
    if (!child.valid()) return out;
    out.cell = cell_of(child.descriptors);
    if (!out.cell) return out;
    if (threshold_params_) {
        const auto t = thresholds_.find(*out.cell);
        out.threshold = t == thresholds_.end() ? threshold_params_->threshold_min : t->second;
        const double rate = threshold_params_->learning_rate;
        if (child.fitness > out.threshold) thresholds_[*out.cell] = (1.0 - rate) * out.threshold + rate * child.fitness;
    }
    auto [it, fresh] = elites_.try_emplace(*out.cell, child);
    if (fresh) {
        out.placement = Placement::filled;
        return out;
    }
    out.elite_fitness = it->second.fitness;
    if (!(child.fitness >= it->second.fitness)) return out;
    it->second = child;
    out.placement = Placement::replaced;
    return out;
}

void Archive::keep_thresholds(ThresholdParams params) {
    if (!(params.learning_rate >= 0.0 && params.learning_rate <= 1.0) || !std::isfinite(params.threshold_min))
        refuse("thresholds need a learning rate in [0, 1] and a finite threshold_min");
    if (threshold_params_ && *threshold_params_ != params)
        refuse("the archive keeps thresholds with another learning_rate or threshold_min");
    threshold_params_ = params;
}

void Archive::restore_threshold(std::uint64_t cell, double threshold) {
    if (!threshold_params_) throw std::logic_error("restore_threshold: the archive keeps no thresholds");
    thresholds_[cell] = threshold;
}

void Archive::restore(std::uint64_t cell, Individual elite) {
    if (cell >= cells_) refuse("cell " + std::to_string(cell) + " is out of range (" + std::to_string(cells_) + " cells)");
    if (!elite.valid()) refuse("the elite of cell " + std::to_string(cell) + " is invalid");
    const std::optional<std::uint64_t> placed = cell_of(elite.descriptors);
    if (placed != cell)
        refuse("the elite of cell " + std::to_string(cell) + " has descriptors that map to " +
               (placed ? "cell " + std::to_string(*placed) : std::string("no cell")));
    if (!elites_.try_emplace(cell, std::move(elite)).second)
        refuse("cell " + std::to_string(cell) + " is given twice");
}

std::vector<const Individual*> Archive::snapshot() const {
    std::vector<const Individual*> out;
    out.reserve(elites_.size());
    for (const auto& [cell, elite] : elites_) out.push_back(&elite);
    return out;
}

double archive_genome_bytes(std::uint64_t cells, std::size_t dimension) {
    return static_cast<double>(cells) * static_cast<double>(dimension) * static_cast<double>(sizeof(double));
}

}  // namespace morphogen
