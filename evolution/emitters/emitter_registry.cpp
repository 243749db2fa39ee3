#include "evolution/emitters/emitter_registry.hpp"

#include "evolution/emitters/cma/cma_emitter.hpp"
#include "evolution/emitters/gaussian_emitter.hpp"
#include "evolution/emitters/iso_line_emitter.hpp"

#include <algorithm>
#include <stdexcept>

namespace morphogen {

using nlohmann::json;

namespace {

using ReadEmitter = std::shared_ptr<const Emitter> (*)(ObjectReader& reader, ParentSelection selection);

struct EmitterRow {
    const char* kind;
    std::vector<std::string> keys;  // its own keys, besides kind, share and selection
    ReadEmitter read;
};

std::shared_ptr<const Emitter> read_gaussian(ObjectReader&, ParentSelection selection) {
    return std::make_shared<GaussianEmitter>(selection);
}

std::shared_ptr<const Emitter> read_iso_line(ObjectReader& r, ParentSelection selection) {
    IsoLineSettings s;
    s.sigma_iso = r.number("sigma_iso", s.sigma_iso, 0.0, 1000.0);
    s.sigma_line = r.number("sigma_line", s.sigma_line, 0.0, 1000.0);
    return std::make_shared<IsoLineEmitter>(selection, s);
}

// The keys both CMA kinds read; `ranking` gives their defaults.
CmaSettings read_cma(ObjectReader& r, CmaRanking ranking) {
    const bool annealing = ranking == CmaRanking::threshold;
    CmaSettings s;
    s.ranking = ranking;
    s.sigma0 = r.number("sigma0", s.sigma0, 0.0, 1000.0, /*min_exclusive=*/true);
    s.parents = r.choice("parents", annealing ? "mu" : "filter", {"filter", "mu"}) == "mu" ? CmaParents::mu
                                                                                          : CmaParents::filter;
    s.restart = r.choice("restart", annealing ? "basic" : "no_improvement", {"no_improvement", "basic"}) == "basic"
                    ? CmaRestart::basic
                    : CmaRestart::no_improvement;
    s.covariance =
        r.choice("covariance", "diagonal", {"diagonal", "full"}) == "full" ? CmaCovariance::full : CmaCovariance::diagonal;
    return s;
}

std::shared_ptr<const Emitter> read_cma_me(ObjectReader& r, ParentSelection selection) {
    return std::make_shared<CmaEmitter>(selection, read_cma(r, CmaRanking::improvement));
}

std::shared_ptr<const Emitter> read_cma_mae(ObjectReader& r, ParentSelection selection) {
    CmaSettings s = read_cma(r, CmaRanking::threshold);
    s.thresholds.learning_rate = r.number("learning_rate", s.thresholds.learning_rate, 0.0, 1.0);
    s.thresholds.threshold_min = r.number("threshold_min", s.thresholds.threshold_min, -1e12, 1e12);
    return std::make_shared<CmaEmitter>(selection, s);
}

const std::vector<EmitterRow>& rows() {
    static const std::vector<EmitterRow> table{
        {"gaussian", {}, read_gaussian},
        {"iso_line", {"sigma_iso", "sigma_line"}, read_iso_line},
        {"cma_me", {"sigma0", "parents", "restart", "covariance"}, read_cma_me},
        {"cma_mae", {"sigma0", "parents", "restart", "covariance", "learning_rate", "threshold_min"}, read_cma_mae},
    };
    return table;
}

// A key of other kinds than `row`'s is an issue naming the kinds it is for.
void refuse_foreign_keys(ObjectReader& r, const EmitterRow& row) {
    std::vector<std::string> foreign;
    for (const EmitterRow& other : rows())
        for (const std::string& key : other.keys)
            if (std::find(row.keys.begin(), row.keys.end(), key) == row.keys.end() &&
                std::find(foreign.begin(), foreign.end(), key) == foreign.end())
                foreign.push_back(key);
    for (const std::string& key : foreign) {
        if (r.raw(key) == nullptr) continue;
        std::vector<std::string> kinds;
        for (const EmitterRow& other : rows())
            if (std::find(other.keys.begin(), other.keys.end(), key) != other.keys.end())
                kinds.push_back("\"" + std::string(other.kind) + "\"");
        std::string list = kinds.front();
        for (std::size_t i = 1; i < kinds.size(); ++i) list += (i + 1 == kinds.size() ? " and " : ", ") + kinds[i];
        r.issues().add(r.path_of(key), std::string(kinds.size() == 1 ? "only for kind " : "only for kinds ") + list);
    }
}

}  // namespace

std::vector<std::string> emitter_kind_names() {
    std::vector<std::string> names;
    for (const EmitterRow& row : rows()) names.emplace_back(row.kind);
    return names;
}

std::vector<EmitterSpec> read_emitters(const json& list, ConfigIssues& issues, json& resolved) {
    std::vector<EmitterSpec> out;
    resolved = json::array();
    if (!list.is_array() || list.empty()) {
        issues.add("emitters", "expected a non-empty array of {\"kind\": \"gaussian\", \"iso_line\", \"cma_me\" or "
                               "\"cma_mae\", \"share\", \"selection\", ...} objects, got " + list.dump());
        return out;
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
        ObjectReader r(&list[i], "emitters[" + std::to_string(i) + "]", issues);
        const std::string kind = r.choice("kind", "gaussian", emitter_kind_names());
        EmitterSpec spec;
        spec.share = r.number("share", 1.0, 0.0, 1e6, /*min_exclusive=*/true);
        const ParentSelection selection =
            r.choice("selection", "uniform", {"uniform", "fitness_proportional"}) == "fitness_proportional"
                ? ParentSelection::fitness_proportional
                : ParentSelection::uniform;
        const auto row = std::find_if(rows().begin(), rows().end(), [&](const EmitterRow& x) { return x.kind == kind; });
        const EmitterRow& chosen = row == rows().end() ? rows().front() : *row;
        spec.emitter = chosen.read(r, selection);
        refuse_foreign_keys(r, chosen);
        r.finish();
        resolved.push_back(r.resolved());
        out.push_back(std::move(spec));
    }
    try {
        (void)archive_thresholds(out);
    } catch (const std::invalid_argument& e) {
        issues.add("emitters", e.what());
    }
    return out;
}

json default_emitters_config() {
    return json::parse(R"([{"kind": "cma_me", "sigma0": 0.2}, {"kind": "cma_me", "sigma0": 0.2}])");
}

std::vector<EmitterSpec> default_emitters() {
    ConfigIssues issues;
    json resolved;
    std::vector<EmitterSpec> specs = read_emitters(default_emitters_config(), issues, resolved);
    if (!issues.empty()) throw std::logic_error("the default emitters do not read: " + issues.format("default"));
    return specs;
}

}  // namespace morphogen
