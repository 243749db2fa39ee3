#include "run/map_elites_config.hpp"

#include "evolution/cma_emitter.hpp"
#include "evolution/cvt.hpp"
#include "fitness/descriptors.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

namespace morphogen {

using nlohmann::json;

namespace {

// One entry of `descriptors`; a bad measure, range or bin count is an issue.
DescriptorRange read_descriptor(const json& item, const std::string& path, ConfigIssues& issues, json& resolved) {
    ObjectReader reader(&item, path, issues);
    DescriptorRange range;
    range.name = reader.string("measure", "");
    if (item.is_object() && !item.contains("measure")) {
        issues.add(reader.path_of("measure"), "required: the name of a shape measure (one of " + [] {
            std::string list;
            for (const std::string& n : descriptor_measure_names()) list += (list.empty() ? "" : ", ") + n;
            return list;
        }() + ")");
    } else if (item.is_object() && item["measure"].is_string()) {
        try {
            (void)find_descriptor_measure(range.name);
        } catch (const std::invalid_argument& e) {
            issues.add(reader.path_of("measure"), e.what());
        }
    }
    range.min = reader.number("min", 0.0, -1e12, 1e12);
    range.max = reader.number("max", 1.0, -1e12, 1e12);
    range.bins = static_cast<int>(reader.integer("bins", 10, 1, 1'000'000));
    bool bounds = true;
    for (const char* key : {"min", "max"})
        if (item.is_object() && !item.contains(key)) {
            issues.add(reader.path_of(key), "required: the descriptor's range is [min, max]");
            bounds = false;
        }
    if (bounds && item.is_object() && !(range.min < range.max))
        issues.add(path, "min (" + json(range.min).dump() + ") must be less than max (" + json(range.max).dump() + ")");
    reader.finish();
    resolved = reader.resolved();
    return range;
}

}  // namespace

std::vector<std::string> QdParams::measure_names() const {
    std::vector<std::string> names;
    for (const DescriptorRange& d : descriptors) names.push_back(d.name);
    return names;
}

std::uint64_t QdParams::cells() const {
    if (archive == ArchiveKind::cvt) return cvt_cells;
    std::uint64_t cells = 1;
    for (const DescriptorRange& d : descriptors) cells *= static_cast<std::uint64_t>(d.bins);
    return cells;
}

const char* algorithm_name(Algorithm algorithm) {
    return algorithm == Algorithm::map_elites ? "map_elites" : "steady_state";
}

namespace {
// `emitters`: a non-empty list of emitter objects (emitters.hpp).
std::vector<EmitterSpec> read_emitters(const json& list, ObjectReader& top, ConfigIssues& issues) {
    std::vector<EmitterSpec> out;
    if (!list.is_array() || list.empty()) {
        issues.add("emitters", "expected a non-empty array of {\"kind\": \"gaussian\", \"iso_line\", \"cma_me\" or \"cma_mae\", \"share\", "
                               "\"selection\", ...} objects, got " + list.dump());
        return out;
    }
    json resolved = json::array();
    std::optional<EmitterSpec> annealing_spec;
    for (std::size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(&list[i], "emitters[" + std::to_string(i) + "]", issues);
        EmitterSpec e;
        const std::string kind = r.choice("kind", "gaussian", {"gaussian", "iso_line", "cma_me", "cma_mae"});
        e.kind = kind == "iso_line" ? EmitterKind::iso_line
                 : kind == "cma_me" ? EmitterKind::cma_me
                 : kind == "cma_mae" ? EmitterKind::cma_mae
                                     : EmitterKind::gaussian;
        e.share = r.number("share", 1.0, 0.0, 1e6, /*min_exclusive=*/true);
        e.selection = r.choice("selection", "uniform", {"uniform", "fitness_proportional"}) == "fitness_proportional"
                          ? ParentSelection::fitness_proportional
                          : ParentSelection::uniform;
        if (e.kind == EmitterKind::iso_line) {
            e.sigma_iso = r.number("sigma_iso", e.sigma_iso, 0.0, 1000.0);
            e.sigma_line = r.number("sigma_line", e.sigma_line, 0.0, 1000.0);
        } else {
            for (const char* key : {"sigma_iso", "sigma_line"})
                if (r.raw(key) != nullptr) issues.add(r.path_of(key), "only for kind \"iso_line\"");
        }
        const bool cma = is_cma(e.kind), annealing = e.kind == EmitterKind::cma_mae;
        if (cma) {
            e.sigma0 = r.number("sigma0", e.sigma0, 0.0, 1000.0, /*min_exclusive=*/true);
            e.parents = r.choice("parents", annealing ? "mu" : "filter", {"filter", "mu"}) == "mu" ? CmaParents::mu
                                                                                                  : CmaParents::filter;
            e.restart = r.choice("restart", annealing ? "basic" : "no_improvement", {"no_improvement", "basic"}) == "basic"
                            ? CmaRestart::basic
                            : CmaRestart::no_improvement;
            e.covariance = r.choice("covariance", "diagonal", {"diagonal", "full"}) == "full" ? CmaCovariance::full
                                                                                              : CmaCovariance::diagonal;
        } else {
            for (const char* key : {"sigma0", "parents", "restart", "covariance"})
                if (r.raw(key) != nullptr) issues.add(r.path_of(key), "only for kinds \"cma_me\" and \"cma_mae\"");
        }
        if (annealing) {
            e.learning_rate = r.number("learning_rate", e.learning_rate, 0.0, 1.0);
            e.threshold_min = r.number("threshold_min", e.threshold_min, -1e12, 1e12);
            if (annealing_spec && (annealing_spec->learning_rate != e.learning_rate ||
                                   annealing_spec->threshold_min != e.threshold_min))
                issues.add(r.path_of("learning_rate"), "every cma_mae emitter must have the same learning_rate and "
                                                       "threshold_min (they share one threshold archive)");
            if (!annealing_spec) annealing_spec = e;
        } else {
            for (const char* key : {"learning_rate", "threshold_min"})
                if (r.raw(key) != nullptr) issues.add(r.path_of(key), "only for kind \"cma_mae\"");
        }
        r.finish();
        json item = r.resolved();
        if (e.kind != EmitterKind::iso_line) {
            item.erase("sigma_iso");
            item.erase("sigma_line");
        }
        if (!cma)
            for (const char* key : {"sigma0", "parents", "restart"}) item.erase(key);
        // The default model is left out, so runs begun before the key resume.
        if (e.covariance == CmaCovariance::diagonal) item.erase("covariance");
        if (!annealing)
            for (const char* key : {"learning_rate", "threshold_min"}) item.erase(key);
        resolved.push_back(std::move(item));
        out.push_back(e);
    }
    top.set_resolved("emitters", resolved);
    return out;
}
}  // namespace

QdParams read_qd_params(ObjectReader& top, Algorithm algorithm) {
    ConfigIssues& issues = top.issues();
    QdParams qd;
    const json* descriptors = top.raw("descriptors");
    const json* archive = top.raw("archive");
    const bool ga = algorithm != Algorithm::map_elites;
    if (ga && archive != nullptr) issues.add("archive", "used only when evolution.algorithm is \"map_elites\"");
    const json* emitters = top.raw("emitters");
    if (ga && emitters != nullptr) issues.add("emitters", "used only when evolution.algorithm is \"map_elites\"");
    if (!ga && emitters != nullptr) qd.emitters = read_emitters(*emitters, top, issues);
    // A steady-state run may declare descriptors only to record them in
    // lineage.csv (to bin a GA run into a MAP-Elites grid afterwards); without
    // them it resolves to the same bytes as before they existed.
    if (ga && descriptors == nullptr) return qd;

    // descriptors: a non-empty array of {measure, min, max, bins}
    json resolved_descriptors = json::array();
    if (descriptors == nullptr) {
        issues.add("descriptors", "required when evolution.algorithm is \"map_elites\": a list of "
                                  "{\"measure\": ..., \"min\": ..., \"max\": ..., \"bins\": ...}");
    } else if (!descriptors->is_array() || descriptors->empty()) {
        issues.add("descriptors", "expected a non-empty array of {\"measure\", \"min\", \"max\", \"bins\"} objects, got " +
                                      descriptors->dump());
    } else {
        for (std::size_t i = 0; i < descriptors->size(); ++i) {
            json resolved;
            qd.descriptors.push_back(
                read_descriptor((*descriptors)[i], "descriptors[" + std::to_string(i) + "]", issues, resolved));
            resolved_descriptors.push_back(std::move(resolved));
        }
    }
    top.set_resolved("descriptors", resolved_descriptors);
    if (ga) return qd;  // no archive: any number of descriptors, no grid limits

    // archive: {type, cells (CVT only), qd_offset}
    ObjectReader reader(archive, "archive", issues);
    const std::string type = reader.choice("type", "grid", {"grid", "cvt"});
    qd.archive = type == "cvt" ? ArchiveKind::cvt : ArchiveKind::grid;
    const bool has_cells = archive != nullptr && archive->is_object() && archive->contains("cells");
    if (qd.archive == ArchiveKind::cvt) {
        qd.cvt_cells = static_cast<std::uint64_t>(reader.integer("cells", 1000, 1, 1'000'000'000'000LL));
        if (qd.cvt_cells > kMaxCvtCells)
            issues.add("archive.cells", std::to_string(qd.cvt_cells) + " cells is more than a CVT archive places (at most " +
                                            std::to_string(kMaxCvtCells) +
                                            "; the centroids cost 20 x cells^2 distances per round): use fewer cells or a grid");
    } else if (has_cells) {
        (void)reader.raw("cells");
        issues.add("archive.cells", "only for a CVT archive (a grid has the product of its descriptors' bins)");
    }
    qd.qd_offset = reader.number("qd_offset", 0.0, -1e12, 1e12);
    reader.finish();
    json resolved_archive = reader.resolved();
    if (qd.archive == ArchiveKind::grid) resolved_archive.erase("cells");
    top.set_resolved("archive", resolved_archive);

    if (qd.descriptors.empty()) return qd;
    if (qd.archive == ArchiveKind::grid) {
        if (qd.descriptors.size() > 3) {
            issues.add("descriptors", std::to_string(qd.descriptors.size()) +
                                          " descriptors: a grid archive takes 1 to 3; use \"archive\": {\"type\": \"cvt\"} for more");
            return qd;
        }
        double cells = 1.0;
        for (const DescriptorRange& d : qd.descriptors) cells *= d.bins;
        if (cells > static_cast<double>(kMaxGridCells)) {
            issues.add("descriptors", "the grid has " + json(cells).dump() + " cells (the product of the bins), more than 2^40");
            return qd;
        }
    }
    return qd;
}

}  // namespace morphogen
