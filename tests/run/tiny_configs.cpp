#include "tests/run/tiny_configs.hpp"

#include <nlohmann/json.hpp>

namespace morphogen::test {

std::string tiny_config(int generations, int population, int batch) {
    return R"({"network": {"outputs": 4, "hidden": [4]},
 "growth": {"steps": 8, "max_vertices": 200},
 "fitness": {"type": "height"},
 "evolution": {"population": )" +
           std::to_string(population) + R"(, "batch": )" + std::to_string(batch) +
           R"(, "mutation_rate": 0.2},
 "run": {"generations": )" +
           std::to_string(generations) + R"(, "seed": 7, "export_every": 0}}
)";
}

std::string tiny_pipeline_config(int generations, int population, int lag) {
    auto config = nlohmann::json::parse(tiny_config(generations, population));
    config["evolution"].erase("batch");
    config["evolution"]["lag"] = lag;
    return config.dump(1) + "\n";
}

}  // namespace morphogen::test
