#include "evolution/ga/ga_state_json.hpp"

#include "core/base/checked_json.hpp"

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

namespace {
std::optional<std::uint64_t> read_parent(const json& value, const std::string& path) {
    if (value.is_null()) return std::nullopt;
    return read_u64(value, path);
}

}  // namespace

std::vector<double> genome_from_json(const json& object, std::size_t dimension, const std::string& path,
                                     GenomeBlobReader* genomes) {
    if (!object.is_object()) fail(path, "expected an object");
    if (genomes) {
        if (object.contains("params")) fail(path + ".params", "genomes are stored in the binary part");
        if (genomes->dimension() != dimension)
            fail(path + ".genome", std::to_string(genomes->dimension()) + " parameters per genome, the problem has " +
                                       std::to_string(dimension));
        return genomes->take(read_u64(member(object, "genome", path), path + ".genome"), path + ".genome");
    }
    const json& params = member(object, "params", path);
    if (!params.is_array()) fail(path + ".params", "expected an array");
    if (params.size() != dimension)
        fail(path + ".params", std::to_string(params.size()) + " parameters, the problem has " + std::to_string(dimension));
    std::vector<double> out;
    out.reserve(dimension);
    for (std::size_t i = 0; i < params.size(); ++i)
        out.push_back(read_finite(params[i], path + ".params[" + std::to_string(i) + "]"));
    return out;
}

void genome_to_json(json& object, const std::vector<double>& params, GenomeBlobWriter* genomes) {
    if (genomes)
        object["genome"] = genomes->add(params);
    else
        object["params"] = params;
}

namespace {
Individual read_individual(const json& object, std::size_t dimension, const std::string& path,
                           GenomeBlobReader* genomes) {
    Individual ind;
    ind.id = read_u64(member(object, "id", path), path + ".id");
    ind.parent1 = read_parent(member(object, "parent1", path), path + ".parent1");
    ind.parent2 = read_parent(member(object, "parent2", path), path + ".parent2");
    const json& fitness = member(object, "fitness", path);
    ind.fitness = fitness.is_null() ? invalid_fitness : read_finite(fitness, path + ".fitness");
    ind.size = read_finite(member(object, "size", path), path + ".size");
    ind.params = genome_from_json(object, dimension, path, genomes);
    if ((ind.parent1 && *ind.parent1 >= ind.id) || (ind.parent2 && *ind.parent2 >= ind.id))
        fail(path, "a parent is not older than its child");
    if (ind.parent2 && !ind.parent1) fail(path, "parent2 without parent1");
    return ind;
}
}  // namespace

Individual individual_from_json(const json& object, std::size_t dimension, const std::string& path,
                                GenomeBlobReader* genomes) {
    return read_individual(object, dimension, path, genomes);
}

json individual_to_json(const Individual& ind, GenomeBlobWriter* genomes) {
    json out = json::object();
    out["id"] = ind.id;
    out["parent1"] = ind.parent1 ? json(*ind.parent1) : json(nullptr);
    out["parent2"] = ind.parent2 ? json(*ind.parent2) : json(nullptr);
    out["fitness"] = ind.valid() ? json(ind.fitness) : json(nullptr);
    out["size"] = ind.size;
    genome_to_json(out, ind.params, genomes);
    return out;
}

json ga_state_to_json(const GaState& state, GenomeBlobWriter* genomes) {
    json out = json::object();
    out["births"] = state.births;
    out["invalid_in_generation"] = state.invalid_in_generation;
    json population = json::array();
    for (const Individual& ind : state.population) population.push_back(individual_to_json(ind, genomes));
    out["population"] = std::move(population);
    out["best"] = state.best ? individual_to_json(*state.best, genomes) : json(nullptr);
    return out;
}

GaState ga_state_from_json(const json& document, const GaParams& params, std::size_t dimension,
                           GenomeBlobReader* genomes) {
    GaState state;
    const std::string root = "ga";
    state.births = read_u64(member(document, "births", root), "ga.births");
    state.invalid_in_generation =
        read_u64(member(document, "invalid_in_generation", root), "ga.invalid_in_generation");
    const auto P = static_cast<std::uint64_t>(params.population);
    if (state.invalid_in_generation > state.births % P)
        fail("ga.invalid_in_generation", "more invalid births than births in the generation");

    const json& population = member(document, "population", root);
    if (!population.is_array()) fail("ga.population", "expected an array");
    const std::uint64_t expected = std::min(state.births, P);
    if (population.size() != expected)
        fail("ga.population", std::to_string(population.size()) + " members, expected " + std::to_string(expected) +
                                  " after " + std::to_string(state.births) + " births");
    std::set<std::uint64_t> ids;
    for (std::size_t i = 0; i < population.size(); ++i) {
        const std::string path = "ga.population[" + std::to_string(i) + "]";
        Individual ind = read_individual(population[i], dimension, path, genomes);
        if (ind.id >= state.births) fail(path + ".id", "not below the birth counter");
        if (!ids.insert(ind.id).second) fail(path + ".id", "duplicate id " + std::to_string(ind.id));
        state.population.push_back(std::move(ind));
    }
    const json& best = member(document, "best", root);
    if (!best.is_null()) {
        state.best = read_individual(best, dimension, "ga.best", genomes);
        if (!state.best->valid()) fail("ga.best", "the best individual must be valid");
        if (state.best->id >= state.births) fail("ga.best.id", "not below the birth counter");
    }
    if (genomes) genomes->check_all_taken("ga");
    return state;
}

}  // namespace morphogen
