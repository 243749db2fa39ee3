// The morphogen executable: parses the command line, runs the chosen verb,
// and turns errors into a one-line reason on stderr and a meaningful exit code.
#include "commands.hpp"
#include "errors.hpp"
#include "exit_codes.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
    using namespace morphogen;
    CLI::App app{"morphogen: evolve 3-D shapes grown by a cellular neural network"};
    app.set_version_flag("--version", "morphogen 0.1.0");
    app.require_subcommand(1);
    CommandRunner selected;
    add_grow_command(app, selected);
    add_gallery_command(app, selected);
    add_render_command(app, selected);
    add_bench_command(app, selected);
    add_evolve_command(app, selected);
    add_resume_command(app, selected);
    add_validate_command(app, selected);
    add_score_command(app, selected);
    add_archive_command(app, selected);
    add_report_command(app, selected);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? exit_code::ok : exit_code::usage;
    }
    try {
        return selected ? selected() : exit_code::usage;
    } catch (const ConfigError& e) {
        std::cerr << "morphogen: config error: " << e.what() << '\n';
        return exit_code::usage;
    } catch (const CheckpointError& e) {
        std::cerr << "morphogen: " << e.what() << '\n';
        return exit_code::checkpoint;
    } catch (const MeshError& e) {
        std::cerr << "morphogen: mesh error: " << e.what() << '\n';
        return exit_code::mesh;
    } catch (const IoError& e) {
        std::cerr << "morphogen: " << e.what() << '\n';
        return exit_code::io;
    } catch (const std::exception& e) {
        std::cerr << "morphogen: " << e.what() << '\n';
        return exit_code::failure;
    }
}
