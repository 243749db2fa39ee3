// The morphogen executable: parses the command line, runs the chosen verb,
// and turns errors into a one-line reason on stderr and a meaningful exit code.
// Under mpirun/srun (cluster/launch.hpp) `evolve` and `resume` run as one job:
// rank 0 runs the command, the other ranks score its genomes (cluster/).
#include "app/commands.hpp"
#include "app/numeric_options.hpp"
#include "core/base/errors.hpp"
#include "cluster/launch.hpp"
#include "cluster/protocol.hpp"
#include "cluster/remote_evaluator.hpp"
#include "cluster/worker.hpp"
#include "cluster/world.hpp"
#include "run/loop/run_session.hpp"
#include "run/exit_codes.hpp"

#include <CLI/CLI.hpp>

#include <csignal>
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>

namespace {
using namespace morphogen;

int run_selected(const CommandRunner& selected) {
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

// Rank 0 of a job of several processes: runs the command (its genomes scored
// by the workers: remote_evaluators), then tells every worker to exit with
// its code.
int run_rank0(cluster::World& world, const CommandRunner& selected) {
    const int code = run_selected(selected);
    try {
        for (int w = 1; w < world.size(); ++w) world.send(w, cluster::tag_quit, cluster::encode_int(code));
    } catch (const std::exception& e) {
        std::cerr << "morphogen: " << e.what() << '\n';
        world.abort(code == exit_code::ok ? exit_code::failure : code);
    }
    return code;
}

// A worker: a failure here would leave rank 0 waiting, so it ends the job.
int run_worker(cluster::World& world) {
    try {
        return cluster::serve(world);
    } catch (const std::exception& e) {
        std::cerr << "morphogen: worker rank " << world.rank() << ": " << e.what() << '\n';
        world.abort(exit_code::failure);
    }
}
}  // namespace

int main(int argc, char** argv) {
    // A file-size limit (ulimit -f) then makes a write fail with EFBIG, which
    // names the file and exits 3 like a full disk, instead of killing the
    // process by SIGXFSZ mid-write with no message.
    std::signal(SIGXFSZ, SIG_IGN);
    // Before anything else: plain `morphogen` never touches MPI.
    const std::optional<cluster::Launch> launch = cluster::detect_launch();
    if (launch && launch->size > 1 && !cluster::built_with_mpi()) {
        if (launch->rank == 0)
            std::cerr << "morphogen: started as " << launch->size << " processes (" << launch->launcher
                      << "), but this build has no MPI: they would race for one run directory; rebuild with Open "
                         "MPI (cmake -DMORPHOGEN_MPI=ON) or start morphogen without mpirun/srun\n";
        return exit_code::usage;
    }
    std::optional<cluster::World> world;
    if (launch && cluster::built_with_mpi()) world.emplace(argc, argv);
    const bool several = world && world->size() > 1;
    const bool worker = several && world->rank() > 0;

    CLI::App app{"morphogen: evolve 3-D shapes grown by a cellular neural network"};
    app.set_version_flag("--version", "morphogen 0.1.0");
    app.require_subcommand(1);
    // Rank 0 of several has the workers score its genomes; one process scores its own.
    const EvaluatorFactory evaluators =
        several && !worker ? cluster::remote_evaluators(*world) : EvaluatorFactory(local_evaluator);
    CommandRunner selected;
    add_grow_command(app, selected);
    add_gallery_command(app, selected);
    add_render_command(app, selected);
    add_bench_command(app, selected);
    add_evolve_command(app, selected, evaluators);
    add_resume_command(app, selected, evaluators);
    add_validate_command(app, selected);
    add_score_command(app, selected);
    add_archive_command(app, selected);
    add_report_command(app, selected);
    add_breed_command(app, selected);
    check_numeric_options(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        std::ostringstream quiet;  // every rank parses the same line: rank 0 speaks for all
        const int code = worker ? app.exit(e, quiet, quiet) : app.exit(e);
        return code == 0 ? exit_code::ok : exit_code::usage;
    }
    if (!several) return run_selected(selected);

    if (!app.got_subcommand("evolve") && !app.got_subcommand("resume")) {
        if (!worker)
            std::cerr << "morphogen: only evolve and resume run over several processes (" << world->size()
                      << " were started); start other commands without mpirun/srun\n";
        return exit_code::usage;
    }
    return worker ? run_worker(*world) : run_rank0(*world, selected);
}
