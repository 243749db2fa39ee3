// Launcher detection (cluster/launch.hpp) reads only the environment.
#include "cluster/launch.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>

using namespace morphogen::cluster;

namespace {
// Sets variables for one test and restores the previous values.
struct EnvGuard {
    std::vector<std::pair<std::string, std::optional<std::string>>> saved;
    void set(const std::string& name, const char* value) {
        const char* old = std::getenv(name.c_str());
        saved.emplace_back(name, old ? std::optional<std::string>(old) : std::nullopt);
        if (value)
            ::setenv(name.c_str(), value, 1);
        else
            ::unsetenv(name.c_str());
    }
    ~EnvGuard() {
        for (auto it = saved.rbegin(); it != saved.rend(); ++it) {
            if (it->second)
                ::setenv(it->first.c_str(), it->second->c_str(), 1);
            else
                ::unsetenv(it->first.c_str());
        }
    }
};
const char* const all_names[] = {"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK", "PMI_SIZE",    "PMI_RANK",
                                 "PMIX_SIZE",            "PMIX_RANK",            "SLURM_STEP_NUM_TASKS", "SLURM_PROCID"};
}  // namespace

TEST_CASE("a launcher is recognised by its environment", "[cluster][launch]") {
    EnvGuard env;
    for (const char* name : all_names) env.set(name, nullptr);
    CHECK_FALSE(detect_launch());

    env.set("SLURM_STEP_NUM_TASKS", "4");
    env.set("SLURM_PROCID", "2");
    auto launch = detect_launch();
    REQUIRE(launch);
    CHECK(launch->size == 4);
    CHECK(launch->rank == 2);

    env.set("OMPI_COMM_WORLD_SIZE", "3");  // Open MPI's own word comes first
    env.set("OMPI_COMM_WORLD_RANK", "0");
    launch = detect_launch();
    REQUIRE(launch);
    CHECK(launch->size == 3);
    CHECK(launch->rank == 0);
    CHECK(launch->launcher == "OMPI_COMM_WORLD_SIZE=3");
}

TEST_CASE("malformed launcher variables count as absent", "[cluster][launch]") {
    EnvGuard env;
    for (const char* name : all_names) env.set(name, nullptr);
    for (const char* bad : {"", "x", "3x", "-2", "0", "99999999999999999999"}) {
        CAPTURE(bad);
        env.set("PMI_SIZE", bad);
        CHECK_FALSE(detect_launch());
    }
    env.set("PMI_SIZE", "2");
    env.set("PMI_RANK", "one");
    const auto launch = detect_launch();
    REQUIRE(launch);
    CHECK(launch->rank == 0);
}
