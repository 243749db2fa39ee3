#include "evolution/emitters/emitter_state_json.hpp"

#include "evolution/emitters/cma/full_cma.hpp"
#include "evolution/ga/ga_state_json.hpp"
#include "core/base/checked_json.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen {

using nlohmann::json;
using checked_json::fail;
using checked_json::member;
using checked_json::read_finite;
using checked_json::read_u64;

namespace {
constexpr const char* kVectors[] = {"mean", "variances", "path_c", "path_sigma"};

// A full covariance matrix as its rows, each stored as a genome is.
json matrix_json(const std::vector<double>& matrix, std::size_t n, GenomeBlobWriter* genomes) {
    json rows = json::array();
    for (std::size_t r = 0; r < n; ++r) {
        const std::vector<double> row(matrix.begin() + static_cast<std::ptrdiff_t>(r * n),
                                      matrix.begin() + static_cast<std::ptrdiff_t>((r + 1) * n));
        json holder = json::object();
        genome_to_json(holder, row, genomes);
        rows.push_back(std::move(holder));
    }
    return rows;
}

json vector_json(const std::vector<double>& v, GenomeBlobWriter* genomes) {
    json out = json::object();
    genome_to_json(out, v, genomes);
    return out;
}

// The children a started emitter holds after `births` births: its births so
// far in the current generation, until its iteration ends (then none).
std::uint64_t expected_children(const EmitterStateShape& shape) {
    if (shape.births < shape.population) return 0;
    const std::uint64_t done = shape.births % shape.population;
    if (done <= shape.first) return 0;
    const std::uint64_t made = done - shape.first;
    return made >= shape.per_generation ? 0 : made;
}
}  // namespace

bool keeps_emitter_states(std::span<const EmitterSlot> emitters) {
    return std::any_of(emitters.begin(), emitters.end(), [](const EmitterSlot& e) { return e->keeps_state(); });
}

json emitter_states_to_json(std::span<const EmitterSlot> emitters, GenomeBlobWriter* genomes) {
    json list = json::array();
    for (const EmitterSlot& e : emitters) list.push_back(e->state_to_json(genomes));
    return list;
}

json cma_emitter_state_to_json(const CmaEmitterState& s, GenomeBlobWriter* genomes) {
    if (!s.started) return nullptr;
    json e = json::object();
    e["restarts"] = s.restarts;
    e["origin"] = s.origin ? json(*s.origin) : json(nullptr);
    const bool full = !s.full.covariance.empty();  // the model start_cma_emitter chose
    e["sigma"] = full ? s.full.sigma : s.cma.sigma;
    e["updates"] = full ? s.full.updates : s.cma.updates;
    e["mean"] = vector_json(full ? s.full.mean : s.cma.mean, genomes);
    if (full)
        e["covariance"] = matrix_json(s.full.covariance, s.full.mean.size(), genomes);
    else
        e["variances"] = vector_json(s.cma.variances, genomes);
    e["path_c"] = vector_json(full ? s.full.path_c : s.cma.path_c, genomes);
    e["path_sigma"] = vector_json(full ? s.full.path_sigma : s.cma.path_sigma, genomes);
    json children = json::array();
    for (const CmaChild& c : s.children) {
        json row = vector_json(c.params, genomes);
        row["status"] = static_cast<unsigned>(c.status);
        row["value"] = std::isfinite(c.value) ? json(c.value) : json(nullptr);
        children.push_back(std::move(row));
    }
    e["children"] = std::move(children);
    return e;
}

std::vector<EmitterSlot> emitter_states_from_json(const json& list, const EmitterListShape& shape,
                                                  const std::string& path, GenomeBlobReader* genomes) {
    if (!list.is_array()) fail(path, "expected an array");
    if (list.size() != shape.specs.size())
        fail(path, std::to_string(list.size()) + " entries, the config has " + std::to_string(shape.specs.size()) +
                       " emitters");
    const std::vector<std::uint64_t> per_generation = births_per_generation(shape.specs, shape.population);
    std::vector<EmitterSlot> out = fresh_emitters(shape.specs);
    std::uint64_t first = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
        const EmitterStateShape own{shape.population, shape.births, first, per_generation[k], shape.dimension};
        out[k]->state_from_json(list[k], own, path + "[" + std::to_string(k) + "]", genomes);
        first += per_generation[k];
    }
    return out;
}

CmaEmitterState cma_emitter_state_from_json(const json& e, bool full, const EmitterStateShape& shape,
                                            const std::string& at, GenomeBlobReader* genomes) {
    if (e.is_null()) return {};
    if (!e.is_object() || e.size() != 9) fail(at, "expected an object with the 9 keys of a CMA emitter");
    CmaEmitterState s;
    s.started = true;
    s.restarts = read_u64(member(e, "restarts", at), at + ".restarts");
    const json& origin = member(e, "origin", at);
    if (!origin.is_null()) {
        s.origin = read_u64(origin, at + ".origin");
        if (*s.origin >= shape.births) fail(at + ".origin", "not below the birth counter");
    }
    const double sigma = read_finite(member(e, "sigma", at), at + ".sigma");
    if (!(sigma > 0.0)) fail(at + ".sigma", "must be > 0");
    const std::uint64_t updates = read_u64(member(e, "updates", at), at + ".updates");
    auto vector_at = [&](const char* key) {
        return genome_from_json(member(e, key, at), shape.dimension, at + "." + key, genomes);
    };
    if (full) {
        FullCmaState& f = s.full;
        f.sigma = sigma;
        f.updates = updates;
        f.mean = vector_at("mean");
        const json& rows = member(e, "covariance", at);
        if (!rows.is_array() || rows.size() != shape.dimension)
            fail(at + ".covariance", "expected " + std::to_string(shape.dimension) + " rows");
        f.covariance.reserve(shape.dimension * shape.dimension);
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const std::vector<double> row =
                genome_from_json(rows[r], shape.dimension, at + ".covariance[" + std::to_string(r) + "]", genomes);
            f.covariance.insert(f.covariance.end(), row.begin(), row.end());
        }
        f.path_c = vector_at("path_c");
        f.path_sigma = vector_at("path_sigma");
        if (!full_cma_decompose(f)) fail(at + ".covariance", "not a symmetric positive definite matrix");
    } else {
        s.cma.sigma = sigma;
        s.cma.updates = updates;
        std::vector<double>* targets[] = {&s.cma.mean, &s.cma.variances, &s.cma.path_c, &s.cma.path_sigma};
        for (std::size_t v = 0; v < 4; ++v) *targets[v] = vector_at(kVectors[v]);
        for (std::size_t i = 0; i < s.cma.variances.size(); ++i)
            if (!(s.cma.variances[i] > 0.0))
                fail(at + ".variances", "value " + std::to_string(i) + " is not > 0");
    }
    const json& children = member(e, "children", at);
    if (!children.is_array()) fail(at + ".children", "expected an array");
    const std::uint64_t expected = expected_children(shape);
    if (children.size() != expected)
        fail(at + ".children", std::to_string(children.size()) + " children, its births so far in this iteration are " +
                                   std::to_string(expected));
    for (std::size_t c = 0; c < children.size(); ++c) {
        const std::string cat = at + ".children[" + std::to_string(c) + "]";
        const json& row = children[c];
        if (!row.is_object() || row.size() != 3) fail(cat, "expected {status, value, genome}");
        CmaChild child;
        const std::uint64_t status = read_u64(member(row, "status", cat), cat + ".status");
        if (status > 2) fail(cat + ".status", "must be 0, 1 or 2");
        child.status = static_cast<int>(status);
        const json& value = member(row, "value", cat);
        child.value = value.is_null() ? invalid_fitness : read_finite(value, cat + ".value");
        if (value.is_null() && child.status != 0) fail(cat + ".status", "an invalid child must have status 0");
        child.params = genome_from_json(row, shape.dimension, cat, genomes);
        s.children.push_back(std::move(child));
    }
    return s;
}

void for_each_emitter_vector(json& list, const std::string& path,
                             const std::function<void(json&, const std::string&)>& each) {
    if (!list.is_array()) return;
    for (std::size_t k = 0; k < list.size(); ++k) {
        json& e = list[k];
        if (!e.is_object()) continue;
        const std::string at = path + "[" + std::to_string(k) + "]";
        for (const char* key : kVectors)
            if (e.contains(key)) each(e[key], at + "." + key);
        if (e.contains("covariance") && e["covariance"].is_array())
            for (std::size_t r = 0; r < e["covariance"].size(); ++r)
                each(e["covariance"][r], at + ".covariance[" + std::to_string(r) + "]");
        if (e.contains("children") && e["children"].is_array())
            for (std::size_t c = 0; c < e["children"].size(); ++c)
                each(e["children"][c], at + ".children[" + std::to_string(c) + "]");
    }
}

}  // namespace morphogen
