#include "evolution/schedulers/map_elites_state_json.hpp"

#include "evolution/emitters/emitter_registry.hpp"
#include "evolution/emitters/emitter_state_json.hpp"
#include "evolution/ga/ga_state_json.hpp"
#include "core/base/checked_json.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace morphogen {

using nlohmann::json;
using checked_json::fail;
using checked_json::member;
using checked_json::read_finite;
using checked_json::read_u64;

using checked_json::read_finite_array;

json map_elites_state_to_json(const MapElitesState& state, GenomeBlobWriter* genomes) {
    json archive = json::object();
    archive["type"] = state.archive.kind() == ArchiveKind::cvt ? "cvt" : "grid";
    if (state.archive.kind() == ArchiveKind::cvt) archive["centroids"] = state.archive.centroids();
    json elites = json::array();
    for (const auto& [cell, elite] : state.archive.elites()) {
        json row = individual_to_json(elite, genomes);
        row["cell"] = cell;
        row["descriptors"] = elite.descriptors;
        const auto& thresholds = state.archive.thresholds();
        if (const auto t = thresholds.find(cell); t != thresholds.end()) row["threshold"] = t->second;
        elites.push_back(std::move(row));
    }
    archive["elites"] = std::move(elites);
    json out = json::object();
    out["births"] = state.births;
    out["invalid_in_generation"] = state.invalid_in_generation;
    out["new_cells_in_generation"] = state.new_cells_in_generation;
    out["best"] = state.best ? individual_to_json(*state.best, genomes) : json(nullptr);
    if (state.best) out["best"]["descriptors"] = state.best->descriptors;
    out["archive"] = std::move(archive);
    if (keeps_emitter_states(state.emitters)) out["emitters"] = emitter_states_to_json(state.emitters, genomes);
    return out;
}

MapElitesState map_elites_state_from_json(const json& document, ArchiveKind kind,
                                          const std::vector<DescriptorRange>& ranges, std::uint64_t cells,
                                          std::uint64_t population, std::size_t dimension,
                                          std::span<const EmitterSpec> emitters, GenomeBlobReader* genomes) {
    const std::string root = "map_elites";
    const std::vector<EmitterSpec> specs =
        emitters.empty() ? default_emitters() : std::vector<EmitterSpec>(emitters.begin(), emitters.end());
    const std::optional<ThresholdParams> annealing = archive_thresholds(specs);
    const bool lists_emitters = std::any_of(specs.begin(), specs.end(), [](const EmitterSpec& e) { return e.emitter->keeps_state(); });
    const std::uint64_t births = read_u64(member(document, "births", root), root + ".births");
    const std::uint64_t invalid =
        read_u64(member(document, "invalid_in_generation", root), root + ".invalid_in_generation");
    const std::uint64_t new_cells =
        read_u64(member(document, "new_cells_in_generation", root), root + ".new_cells_in_generation");
    if (invalid + new_cells > births % population)
        fail(root, "more invalid births and new cells than births in the current generation");

    const json& archive = member(document, "archive", root);
    const json& type = member(archive, "type", root + ".archive");
    const char* expected_type = kind == ArchiveKind::cvt ? "cvt" : "grid";
    if (type != expected_type) fail(root + ".archive.type", std::string("not \"") + expected_type + "\" as the config says");
    auto make_archive = [&]() -> Archive {
        if (kind == ArchiveKind::grid) {
            if (archive.contains("centroids")) fail(root + ".archive.centroids", "a grid archive has none");
            return Archive::grid(ranges);
        }
        std::vector<double> centroids = read_finite_array(member(archive, "centroids", root + ".archive"),
                                                         root + ".archive.centroids");
        if (centroids.size() != cells * ranges.size())
                fail(root + ".archive.centroids", std::to_string(centroids.size()) + " numbers, the config's " +
                                                      std::to_string(cells) + " cells x " +
                                                      std::to_string(ranges.size()) + " descriptors need " +
                                                      std::to_string(cells * ranges.size()));
        return Archive::cvt(ranges, std::move(centroids));
    };
    std::optional<Archive> built;
    try {
        built.emplace(make_archive());
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        if (what.rfind(root, 0) == 0) throw;
        fail(root + ".archive", what);
    }
    MapElitesState state{births, std::move(*built), std::nullopt, invalid, new_cells};
    if (annealing) state.archive.keep_thresholds(*annealing);
    if (archive.size() != (kind == ArchiveKind::cvt ? 3u : 2u)) fail(root + ".archive", "unexpected keys");

    const json& elites = member(archive, "elites", root + ".archive");
    if (!elites.is_array()) fail(root + ".archive.elites", "expected an array");
    std::set<std::uint64_t> ids;
    std::optional<std::uint64_t> previous;
    for (std::size_t i = 0; i < elites.size(); ++i) {
        const std::string path = root + ".archive.elites[" + std::to_string(i) + "]";
        Individual elite = individual_from_json(elites[i], dimension, path, genomes);
        const std::uint64_t cell = read_u64(member(elites[i], "cell", path), path + ".cell");
        elite.descriptors = read_finite_array(member(elites[i], "descriptors", path), path + ".descriptors");
        const bool has_threshold = elites[i].contains("threshold");
        if (elites[i].size() != (has_threshold ? 9u : 8u)) fail(path, "unexpected keys");
        if (has_threshold) {
            if (!annealing) fail(path + ".threshold", "only a run with a cma_mae emitter keeps thresholds");
            const double threshold = read_finite(elites[i]["threshold"], path + ".threshold");
            if (!(threshold > annealing->threshold_min))
                fail(path + ".threshold", "not above threshold_min (such cells are not stored)");
            if (threshold > elite.fitness && threshold - elite.fitness > 1e-12 * std::max(1.0, std::fabs(elite.fitness)))
                fail(path + ".threshold", "above its elite's fitness");
        }
        if (!elite.valid()) fail(path, "an elite must be valid");
        if (elite.id >= state.births) fail(path + ".id", "not below the birth counter");
        if (!ids.insert(elite.id).second) fail(path + ".id", "duplicate id " + std::to_string(elite.id));
        if (previous && cell <= *previous) fail(path + ".cell", "cells are not in increasing order");
        previous = cell;
        try {
            state.archive.restore(cell, std::move(elite));
        } catch (const std::invalid_argument& e) {
            fail(path, e.what());
        }
        if (has_threshold) state.archive.restore_threshold(cell, elites[i]["threshold"].get<double>());
    }
    const json& best = member(document, "best", root);
    if (!best.is_null()) {
        state.best = individual_from_json(best, dimension, root + ".best", genomes);
        state.best->descriptors = read_finite_array(member(best, "descriptors", root + ".best"), root + ".best.descriptors");
        if (!state.best->valid()) fail(root + ".best", "the best individual must be valid");
        if (state.best->id >= state.births) fail(root + ".best.id", "not below the birth counter");
        for (const auto& [cell, elite] : state.archive.elites())
            if (elite.fitness > state.best->fitness)
                fail(root + ".best", "elite " + std::to_string(elite.id) + " is fitter than the best ever born");
    } else if (state.archive.occupied() > 0) {
        fail(root + ".best", "null though the archive holds elites");
    }
    if (lists_emitters) {
        const EmitterListShape shape{specs, population, births, dimension};
        state.emitters = emitter_states_from_json(member(document, "emitters", root), shape, root + ".emitters", genomes);
    } else {
        state.emitters = fresh_emitters(specs);
    }
    if (document.size() != (lists_emitters ? 6u : 5u)) fail(root, "unexpected keys");
    if (genomes) genomes->check_all_taken(root);
    return state;
}

}  // namespace morphogen
