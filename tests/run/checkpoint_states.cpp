#include "tests/run/checkpoint_states.hpp"

#include "core/growth/network/network.hpp"
#include "evolution/emitters/emitters.hpp"
#include "evolution/ga/ga_state_json.hpp"
#include "evolution/schedulers/map_elites_state_json.hpp"
#include "run/config/experiment_config.hpp"
#include "run/loop/run_records.hpp"
#include "run/persistence/checkpoint.hpp"
#include "tests/run/search_states.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <random>

namespace morphogen::test {

RunState generation0_state(const std::string& config_text, std::uint64_t members) {
    const ExperimentConfig config = read_experiment_config(nlohmann::json::parse(config_text), "bench");
    const std::size_t D = parameter_count(config.network.layers());
    std::mt19937_64 random(12345);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<Individual> born(members);
    for (std::uint64_t i = 0; i < members; ++i) {
        born[i].id = i;
        born[i].params.resize(D);
        for (double& p : born[i].params) p = normal(random);
        born[i].fitness = static_cast<double>((i * 7919) % 10007) / 100.0;
        born[i].size = 100;
    }
    RunState state;
    state.config = config.resolved;
    state.seed = config.run.seed;
    state.lineage_bytes = std::string_view(lineage_header).size();
    state.lineage_hash = "0123456789abcdef";
    const auto best = std::max_element(born.begin(), born.end(),
                                       [](const Individual& a, const Individual& b) { return a.fitness < b.fitness; });
    if (config.algorithm == Algorithm::map_elites) {
        Archive archive = Archive::grid(config.qd.descriptors);
        for (std::uint64_t i = 0; i < members; ++i) {
            born[i].descriptors = {static_cast<double>(i / 100) + 0.5, static_cast<double>(i % 100) + 0.5};
            archive.restore(i, born[i]);
        }
        state.search = std::make_unique<ElitesSearchState>(
            MapElitesState{members, std::move(archive), *best, 0, members, fresh_emitters(config.qd.emitters)});
    } else {
        ga_of(state).births = members;
        ga_of(state).best = *best;
        ga_of(state).population = std::move(born);
    }
    return state;
}

std::string archive_config(std::uint64_t population) {
    return R"({"evolution": {"algorithm": "map_elites", "population": )" + std::to_string(population) +
           R"(}, "descriptors": [{"measure": "height", "min": 0, "max": 100, "bins": 100},
           {"measure": "footprint", "min": 0, "max": 100, "bins": 100}], "run": {"generations": 1}})";
}
std::string ga_config(std::uint64_t population) {
    return R"({"evolution": {"population": )" + std::to_string(population) + R"(}, "run": {"generations": 1}})";
}

std::string format1_text(const RunState& s) {
    nlohmann::json history = nlohmann::json::array();
    for (const HistoryRow& row : s.history) history.push_back(history_row_to_json(row));
    nlohmann::json content{{"config", s.config},
                           {"seed", s.seed},
                           {"history", std::move(history)},
                           {"lineage", {{"bytes", s.lineage_bytes}, {"hash", s.lineage_hash}}},
                           {"elapsed_s", s.elapsed_s}};
    if (const MapElitesState* elites = elites_state(*s.search))
        content["map_elites"] = map_elites_state_to_json(*elites);
    else
        content["ga"] = ga_state_to_json(ga_of(s));
    return checkpoint_text(content);
}

}  // namespace morphogen::test
