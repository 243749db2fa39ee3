// --smooth N through the executable: grow and archive write LOD0 with 4^N
// times the triangles; bad rounds (option or run.export_glb.smooth) are
// refused naming them, and nothing is written.
#include "tests/app/evolve_test_support.hpp"
#include "tests/engine/glb_reader.hpp"

#include "core/io/mesh_io.hpp"

#include <catch2/catch.hpp>

// In the namespace rather than `using` it: this file shares a unity batch.
namespace morphogen::test {

TEST_CASE("grow and archive --smooth N write LOD0 with 4^N the triangles; bad N is refused", "[cli][smooth]") {
    TempDir dir("smooth-cli");
    REQUIRE(run_morphogen("grow --random 4 --steps 60 -o " + q(dir.path / "plain.glb")).code == 0);
    REQUIRE(run_morphogen("grow --random 4 --steps 60 --smooth 2 --colour -o " + q(dir.path / "smooth.glb")).code == 0);
    const std::size_t plain = read_mesh((dir.path / "plain.glb").string()).faces.size();
    const ColouredMesh smooth = read_coloured_mesh((dir.path / "smooth.glb").string());
    CHECK(smooth.mesh.faces.size() == 16 * plain);
    CHECK(smooth.colours.size() == 4 * smooth.mesh.positions.size());
    CHECK(parse_glb(read_text(dir.path / "smooth.glb")).nodes.at(0).extras.Get("smooth").GetNumberAsInt() == 2);

    const std::string elites = std::string(MORPHOGEN_SOURCE_DIR) + "/tests/app/fixtures/engine_elites.json";
    REQUIRE(run_morphogen("evolve " + q(elites) + " --out " + q(dir.path / "run")).code == 0);
    const CliResult archived = run_morphogen("archive " + q(dir.path / "run") + " --out " + q(dir.path / "elites") + " --smooth 1");
    INFO(archived.output);
    REQUIRE(archived.code == 0);
    int files = 0;
    for (const auto& entry : fs::directory_iterator(dir.path / "elites")) {
        if (entry.path().extension() != ".glb") continue;
        const std::size_t grown = read_mesh(fs::path(entry.path()).replace_extension(".obj").string()).faces.size();
        CHECK(read_mesh(entry.path().string()).faces.size() == 4 * grown);
        ++files;
    }
    CHECK(files > 0);

    fs::create_directories(dir.path / "refused");
    for (const std::string bad : {"4", "-1", "x"}) {
        const CliResult r = run_morphogen("grow --random 3 --steps 20 --smooth " + bad + " -o " + q(dir.path / "refused" / "a.glb"));
        INFO(r.output);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains("--smooth"));
    }
    CHECK(fs::is_empty(dir.path / "refused"));
    write_text(dir.path / "bad.json", R"({"run": {"export_glb": {"smooth": 4}}})");
    const CliResult bad = run_morphogen("validate " + q(dir.path / "bad.json"));
    INFO(bad.output);
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("run.export_glb.smooth"));
}

}  // namespace morphogen::test
