#include "run/config/map_elites_config.hpp"

#include "evolution/archives/cvt.hpp"
#include "evolution/emitters/emitter_registry.hpp"
#include "fitness/descriptors.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>

namespace morphogen {

using nlohmann::json;

namespace {

// One entry of `descriptors`; a bad measure, range or bin count is an issue.
// `binned`: the run bins the range (bins is read); novelty search does not
// (bins is refused).
DescriptorRange read_descriptor(const json& item, const std::string& path, ConfigIssues& issues, json& resolved,
                                bool binned) {
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
    if (binned)
        range.bins = static_cast<int>(reader.integer("bins", 10, 1, 1'000'000));
    else if (reader.raw("bins") != nullptr)
        issues.add(reader.path_of("bins"), "not used by evolution.algorithm \"nslc\", which measures distances in "
                                           "units of max - min: leave it out");
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
    switch (algorithm) {
        case Algorithm::map_elites: return "map_elites";
        case Algorithm::nslc: return "nslc";
        case Algorithm::steady_state: break;
    }
    return "steady_state";
}

QdParams read_qd_params(ObjectReader& top, Algorithm algorithm) {
    ConfigIssues& issues = top.issues();
    QdParams qd;
    const json* descriptors = top.raw("descriptors");
    const json* archive = top.raw("archive");
    const bool ga = algorithm != Algorithm::map_elites;
    if (ga && archive != nullptr) issues.add("archive", "used only when evolution.algorithm is \"map_elites\"");
    const json* emitters = top.raw("emitters");
    if (ga && emitters != nullptr) issues.add("emitters", "used only when evolution.algorithm is \"map_elites\"");
    if (!ga) {
        json resolved_emitters;
        qd.emitters = read_emitters(emitters != nullptr ? *emitters : default_emitters_config(), issues, resolved_emitters);
        top.set_resolved("emitters", std::move(resolved_emitters));
    }
    // A steady-state run may declare descriptors only to record them in
    // lineage.csv (to bin a GA run into a MAP-Elites grid afterwards).
    const bool nslc = algorithm == Algorithm::nslc;
    if (algorithm == Algorithm::steady_state && descriptors == nullptr) return qd;

    // descriptors: a non-empty array of {measure, min, max, bins}
    json resolved_descriptors = json::array();
    if (descriptors == nullptr) {
        issues.add("descriptors", std::string("required when evolution.algorithm is \"") + algorithm_name(algorithm) +
                                      "\": a list of {\"measure\": ..., \"min\": ..., \"max\": ...}" +
                                      (nslc ? "" : " with \"bins\""));
    } else if (!descriptors->is_array() || descriptors->empty()) {
        issues.add("descriptors", "expected a non-empty array of {\"measure\", \"min\", \"max\", \"bins\"} objects, got " +
                                      descriptors->dump());
    } else {
        for (std::size_t i = 0; i < descriptors->size(); ++i) {
            json resolved;
            qd.descriptors.push_back(
                read_descriptor((*descriptors)[i], "descriptors[" + std::to_string(i) + "]", issues, resolved, !nslc));
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
    top.set_resolved("archive", reader.resolved());

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
