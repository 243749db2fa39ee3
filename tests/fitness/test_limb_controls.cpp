// The architecture measures as `morphogen score --json` reports them, on
// labelled controls (tests/fitness/limb_controls.hpp) at 500 to 5,000
// vertices: every reading must be the label at every resolution.
#include "core/io/mesh_io.hpp"
#include "fitness/architecture/architecture.hpp"
#include "fitness/functions/plant_fitness.hpp"
#include "tests/fitness/limb_controls.hpp"
#include "tests/support/run_cli.hpp"
#include "tests/support/temp_dir.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

using namespace morphogen;
using namespace morphogen::testing;

TEST_CASE("limb controls: score --json reads tips, limbs and first fork as labelled at every resolution, and the "
          "plant fitness's finer skeleton the tips",
          "[fitness][architecture][plant][limb-controls]") {
    const TempDir tmp("limb_controls");
    ArchitectureParams plant_shoots = PlantFitnessParams{}.architecture;
    plant_shoots.with_solidity = false;
    for (const LimbControl& control : limb_controls()) {
        const std::vector<MeshArrays> meshes = limb_control_meshes(control.name);
        for (std::size_t i = 0; i < meshes.size(); ++i) {
            const int target = limb_control_resolutions()[i];
            const MeshArrays& mesh = meshes[i];
            const std::string path = (tmp.path / (control.name + "-" + std::to_string(target) + ".obj")).string();
            write_mesh(mesh.view(), path);
            const CliRun run = morphogen_run("score --mesh " + path + " --json");
            INFO(control.name << " (" << control.description << ") at " << mesh.positions.size() << " vertices\n"
                              << run.out);
            REQUIRE(run.code == 0);
            CHECK(mesh.positions.size() <= static_cast<std::size_t>(target));
            CHECK(mesh.positions.size() >= static_cast<std::size_t>(target) * 95 / 100);
            const nlohmann::json report = nlohmann::json::parse(run.out);
            const nlohmann::json& a = report["architecture"];
            CHECK_FALSE(a["solidity"].is_null());  // closed
            CHECK(a["tips"] == control.tips);
            CHECK(a["limbs"] == control.limbs);
            CHECK(measure_architecture(mesh.view(), plant_shoots).tips == control.tips);
            double zmin = mesh.positions[0].z(), zmax = zmin;
            for (const Vec3& p : mesh.positions) zmin = std::min(zmin, p.z()), zmax = std::max(zmax, p.z());
            CHECK(a["first_fork_height"].get<double>() / (zmax - zmin) ==
                  Approx(control.fork_fraction).margin(control.fork_tolerance));
        }
    }
}

TEST_CASE("limb controls: an unknown name is refused", "[fitness][limb-controls]") {
    CHECK_THROWS_AS(limb_control_fine_mesh("oak"), std::invalid_argument);
}
