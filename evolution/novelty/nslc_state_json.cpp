#include "evolution/novelty/nslc_state_json.hpp"

#include "core/base/checked_json.hpp"
#include "evolution/ga/ga_state_json.hpp"

#include <set>
#include <string>

namespace morphogen {

using nlohmann::json;
using checked_json::fail;
using checked_json::member;
using checked_json::read_finite;
using checked_json::read_finite_array;
using checked_json::read_u64;

namespace {
std::vector<double> read_descriptors(const json& object, std::size_t dimensions, const std::string& path) {
    std::vector<double> out = read_finite_array(member(object, "descriptors", path), path + ".descriptors");
    if (out.size() != dimensions)
        fail(path + ".descriptors", std::to_string(out.size()) + " values, the run has " + std::to_string(dimensions) +
                                        " descriptors");
    return out;
}

// A population member or the best: valid, born before `births`, with descriptors.
Individual read_member(const json& object, std::size_t dimension, std::size_t dimensions, std::uint64_t births,
                       const std::string& path, GenomeBlobReader* genomes) {
    Individual ind = individual_from_json(object, dimension, path, genomes);
    if (!ind.valid()) fail(path + ".fitness", "an invalid birth never enters the search");
    if (ind.id >= births) fail(path + ".id", "not below the birth counter");
    ind.descriptors = read_descriptors(object, dimensions, path);
    return ind;
}
}  // namespace

json nslc_state_to_json(const NslcState& state, GenomeBlobWriter* genomes) {
    // The GA's form, each individual with its descriptors, and the archive.
    json out = ga_state_to_json(GaState{state.births, state.population, state.best, state.invalid_in_generation}, genomes);
    for (std::size_t i = 0; i < state.population.size(); ++i)
        out["population"][i]["descriptors"] = state.population[i].descriptors;
    if (state.best) out["best"]["descriptors"] = state.best->descriptors;
    json archive = json::array();
    for (const Individual& point : state.archive)
        archive.push_back(json{{"id", point.id}, {"fitness", point.fitness}, {"descriptors", point.descriptors}});
    out["archive"] = std::move(archive);
    return out;
}

NslcState nslc_state_from_json(const json& document, const GaParams& params, const NoveltyParams& novelty,
                               std::span<const DescriptorRange> ranges, std::size_t dimension,
                               GenomeBlobReader* genomes) {
    NslcState state;
    const std::string root = "nslc";
    const std::size_t dimensions = ranges.size();
    state.births = read_u64(member(document, "births", root), root + ".births");
    state.invalid_in_generation =
        read_u64(member(document, "invalid_in_generation", root), root + ".invalid_in_generation");
    const auto P = static_cast<std::uint64_t>(params.population);
    if (state.invalid_in_generation > state.births % P)
        fail(root + ".invalid_in_generation", "more invalid births than births in the generation");

    const json& population = member(document, "population", root);
    if (!population.is_array()) fail(root + ".population", "expected an array");
    if (population.size() > std::min(state.births, P))
        fail(root + ".population", std::to_string(population.size()) + " members, more than " +
                                       std::to_string(std::min(state.births, P)) + " after " +
                                       std::to_string(state.births) + " births");
    std::set<std::uint64_t> ids;
    for (std::size_t i = 0; i < population.size(); ++i) {
        const std::string path = root + ".population[" + std::to_string(i) + "]";
        Individual ind = read_member(population[i], dimension, dimensions, state.births, path, genomes);
        if (!ids.insert(ind.id).second) fail(path + ".id", "duplicate id " + std::to_string(ind.id));
        state.population.push_back(std::move(ind));
    }
    const json& archive = member(document, "archive", root);
    if (!archive.is_array()) fail(root + ".archive", "expected an array");
    if (archive.size() > novelty.archive)
        fail(root + ".archive", std::to_string(archive.size()) + " points, more than novelty_archive " +
                                    std::to_string(novelty.archive));
    for (std::size_t i = 0; i < archive.size(); ++i) {
        const std::string path = root + ".archive[" + std::to_string(i) + "]";
        Individual point;
        point.id = read_u64(member(archive[i], "id", path), path + ".id");
        if (point.id >= state.births) fail(path + ".id", "not below the birth counter");
        if (!state.archive.empty() && point.id <= state.archive.back().id)
            fail(path + ".id", "not after the point before it (the archive is in birth order)");
        point.fitness = read_finite(member(archive[i], "fitness", path), path + ".fitness");
        point.descriptors = read_descriptors(archive[i], dimensions, path);
        state.archive.push_back(std::move(point));
    }
    const json& best = member(document, "best", root);
    if (!best.is_null()) state.best = read_member(best, dimension, dimensions, state.births, root + ".best", genomes);
    if (genomes) genomes->check_all_taken(root);
    return state;
}

}  // namespace morphogen
