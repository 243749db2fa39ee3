// The emitter registry (emitter_registry.hpp): each kind reads its own keys
// with every default resolved, a key of another kind or a threshold clash is
// an issue at its path, and the default emitters.
#include "evolution/emitters/cma/cma_emitter.hpp"
#include "evolution/emitters/emitter_registry.hpp"
#include "evolution/emitters/iso_line_emitter.hpp"

#include <catch2/catch.hpp>

using namespace morphogen;
using nlohmann::json;

namespace {
struct ReadSpecs {
    std::vector<EmitterSpec> specs;
    json resolved;
    ConfigIssues issues;
};

ReadSpecs read_specs(const std::string& text) {
    ReadSpecs r;
    r.specs = read_emitters(json::parse(text), r.issues, r.resolved);
    return r;
}

std::string issues_of(const ReadSpecs& r) { return r.issues.format("config"); }
}  // namespace

TEST_CASE("every emitter kind reads its keys and resolves every default", "[evolution][emitters][registry]") {
    CHECK(emitter_kind_names() == std::vector<std::string>{"gaussian", "iso_line", "cma_me", "cma_mae"});
    const ReadSpecs r = read_specs(R"([{}, {"kind": "iso_line", "sigma_line": 0.5, "share": 3}, {"kind": "cma_me"},
                            {"kind": "cma_mae", "selection": "fitness_proportional", "learning_rate": 0.1}])");
    INFO(issues_of(r));
    REQUIRE(r.issues.empty());
    REQUIRE(r.specs.size() == 4);
    CHECK(r.specs[0].emitter->kind() == "gaussian");
    CHECK(r.specs[1].share == 3.0);
    CHECK(dynamic_cast<const IsoLineEmitter&>(*r.specs[1].emitter).settings().sigma_iso == 0.05);
    CHECK(dynamic_cast<const IsoLineEmitter&>(*r.specs[1].emitter).settings().sigma_line == 0.5);
    const auto& me = dynamic_cast<const CmaEmitter&>(*r.specs[2].emitter).settings();
    CHECK(me.ranking == CmaRanking::improvement);
    CHECK(me.parents == CmaParents::filter);
    CHECK(me.restart == CmaRestart::no_improvement);
    const CmaEmitter& mae = dynamic_cast<const CmaEmitter&>(*r.specs[3].emitter);
    CHECK(mae.selection() == ParentSelection::fitness_proportional);
    CHECK(mae.settings().parents == CmaParents::mu);
    CHECK(mae.settings().restart == CmaRestart::basic);
    CHECK(mae.thresholds() == ThresholdParams{0.1, 0.0});
    CHECK(r.resolved == json::parse(R"([
        {"kind": "gaussian", "share": 1.0, "selection": "uniform"},
        {"kind": "iso_line", "share": 3.0, "selection": "uniform", "sigma_iso": 0.05, "sigma_line": 0.5},
        {"kind": "cma_me", "share": 1.0, "selection": "uniform", "sigma0": 0.5, "parents": "filter",
         "restart": "no_improvement", "covariance": "diagonal"},
        {"kind": "cma_mae", "share": 1.0, "selection": "fitness_proportional", "sigma0": 0.5, "parents": "mu",
         "restart": "basic", "covariance": "diagonal", "learning_rate": 0.1, "threshold_min": 0.0}])"));
    // The resolved list reads back to itself.
    ConfigIssues again;
    json twice;
    (void)read_emitters(r.resolved, again, twice);
    CHECK(again.empty());
    CHECK(twice == r.resolved);
}

TEST_CASE("the emitter registry refuses keys of other kinds, bad values and threshold clashes",
          "[evolution][emitters][registry]") {
    auto refused = [](const std::string& text, const std::string& expected) {
        const ReadSpecs r = read_specs(text);
        INFO(text);
        CHECK_THAT(issues_of(r), Catch::Contains(expected));
    };
    refused(R"([{"kind": "cma_me", "learning_rate": 0.1}])", "emitters[0].learning_rate: only for kind \"cma_mae\"");
    refused(R"([{"kind": "gaussian", "sigma0": 0.1}])", "emitters[0].sigma0: only for kinds \"cma_me\" and \"cma_mae\"");
    refused(R"([{"kind": "cma_mae", "sigma_iso": 0.1}])", "only for kind \"iso_line\"");
    refused(R"([{"kind": "cma_mae", "learning_rate": 1.5}])", "emitters[0].learning_rate");
    refused(R"([{"kind": "cma_mae"}, {"kind": "cma_mae", "threshold_min": -5}])", "same learning_rate and threshold_min");
    refused(R"([{"kind": "cma"}])", "emitters[0].kind");
    refused(R"([{"kind": "gaussian", "sigma": 1}])", "emitters[0]");
    refused(R"([])", "non-empty array");
    refused(R"([{"share": 0}])", "emitters[0].share");
}

TEST_CASE("the default emitters are two cma_me with sigma0 0.2", "[evolution][emitters][registry]") {
    const std::vector<EmitterSpec> specs = default_emitters();
    REQUIRE(specs.size() == 2);
    for (const EmitterSpec& spec : specs) {
        CHECK(spec.share == 1.0);
        const CmaEmitter& cma = dynamic_cast<const CmaEmitter&>(*spec.emitter);
        CHECK(cma.kind() == "cma_me");
        CHECK(cma.settings().sigma0 == 0.2);
        CHECK(cma.settings().covariance == CmaCovariance::diagonal);
    }
}
