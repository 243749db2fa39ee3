// `evolve` and `resume` over MPI (cluster/): the same files as the plain run
// for any number of processes and threads, a stop and resume with another
// number, SIGTERM to mpirun, a killed worker. mpirun runs with --oversubscribe
// (more processes than this machine's cores) and Open MPI's run-as-root
// permission (CI runs as root). Skipped, with a message, in a build without MPI.
#include "tests/app/evolve_test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <thread>

using namespace morphogen::test;

namespace {

const char* const mpirun_exe = MORPHOGEN_MPIRUN;

bool have_mpi() {
    if (MORPHOGEN_HAVE_MPI && mpirun_exe[0] != '\0') {
        // Inherited by mpirun and every rank: root is allowed (CI).
        ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
        ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
        return true;
    }
    WARN("skipped: this build has no MPI (MORPHOGEN_MPI=OFF or Open MPI not found)");
    return false;
}

// Under ASan, LeakSanitizer is off for the processes mpirun starts (only
// them: the plain runs here keep it): Open MPI keeps allocations from
// MPI_Init past MPI_Finalize in components it has unloaded by then, which no
// suppression can name.
std::string mpirun(int processes) {
    return "env ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" " + std::string(mpirun_exe) + " --oversubscribe -np " +
           std::to_string(processes) + " " + MORPHOGEN_EXE + " ";
}

CliResult run_shell(const std::string& command, const fs::path& log) {
    const int status = std::system((command + " > " + q(log) + " 2>&1").c_str());
    CliResult result;
    result.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.output = read_text(log);
    return result;
}

std::string elite_config(int generations) {
    return R"({"network": {"outputs": 4, "hidden": [5]},
 "growth": {"steps": 12, "max_vertices": 300},
 "fitness": {"type": "canopy", "height": 1, "cell": 0.1},
 "evolution": {"algorithm": "map_elites", "population": 12, "lag": 5, "mutation_rate": 0.2},
 "descriptors": [{"measure": "height", "min": 0, "max": 3, "bins": 6},
                 {"measure": "footprint", "min": 0, "max": 10, "bins": 5}],
 "archive": {"type": "grid", "qd_offset": -1},
 "run": {"seed": 3, "generations": )" + std::to_string(generations) + R"(, "export_every": 2}})";
}

void check_same_dirs(const fs::path& a, const fs::path& b) {
    check_same_results(a, b);
    CHECK(read_text(a / "archive.csv") == read_text(b / "archive.csv"));
    if (fs::exists(a / "best")) {
        for (const auto& entry : fs::directory_iterator(a / "best")) {
            INFO(entry.path().filename());
            CHECK(read_text(entry.path()) == read_text(b / "best" / entry.path().filename()));
        }
    }
}

// Starts `mpirun ...` (argv split on spaces) without waiting.
int spawn(const std::string& command, const fs::path& log) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        ::execl("/bin/sh", "sh", "-c", ("exec " + command).c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    return pid;
}

// Waits at most `seconds`; a process still running then is killed (the test fails).
int wait_at_most(int pid, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    int status = 0;
    while (::waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > end) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            FAIL("still running after " << seconds << " s");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::size_t lineage_rows(const fs::path& dir) {
    const std::string text = read_text(dir / "lineage.csv");
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

void wait_for_lineage_rows(const fs::path& dir, std::size_t rows) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (lineage_rows(dir) < rows) {
        REQUIRE(std::chrono::steady_clock::now() < end);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

// The pid of the process with OMPI_COMM_WORLD_RANK=`rank` whose command line
// names `dir`; 0 if there is none.
int rank_pid(int rank, const fs::path& dir) {
    const std::string want = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
    for (const auto& entry : fs::directory_iterator("/proc")) {
        const std::string name = entry.path().filename();
        if (name.find_first_not_of("0123456789") != std::string::npos) continue;
        const std::string cmdline = read_text(entry.path() / "cmdline");
        if (cmdline.find(dir.string()) == std::string::npos || cmdline.find("mpirun") != std::string::npos) continue;
        std::string environ = read_text(entry.path() / "environ");
        for (char& c : environ)
            if (c == '\0') c = '\n';
        if (("\n" + environ).find("\n" + want + "\n") != std::string::npos) return std::stoi(name);
    }
    return 0;
}

int generations_done(const fs::path& dir) {
    return static_cast<int>(checkpoint_without_times(dir)["history"].size()) - 1;
}

}  // namespace

TEST_CASE("a GA run over 1, 2, 3 and 5 processes gives the plain run's files", "[cluster][mpi]") {
    if (!have_mpi()) return;
    TempDir tmp("mpi-ga");
    const fs::path config = tmp.path / "c.json";
    // The batch schedule of older runs, over 3 processes.
    write_text(config, tiny_config(6, 10, 4));
    REQUIRE(run_morphogen("evolve " + q(config) + " --out " + q(tmp.path / "batch")).code == 0);
    REQUIRE(run_shell(mpirun(3) + "evolve " + q(config) + " --out " + q(tmp.path / "batch3"), tmp.path / "log").code == 0);
    check_same_dirs(tmp.path / "batch", tmp.path / "batch3");
    // The pipeline.
    write_text(config, tiny_pipeline_config(6, 10, 6));
    REQUIRE(run_morphogen("evolve " + q(config) + " --out " + q(tmp.path / "plain")).code == 0);
    for (int n : {1, 2, 3, 5}) {
        for (int threads : {1, 2}) {
            if (n == 5 && threads == 2) continue;  // keep the suite small
            CAPTURE(n, threads);
            const fs::path dir = tmp.path / ("np" + std::to_string(n) + "t" + std::to_string(threads));
            const CliResult r = run_shell(mpirun(n) + "evolve " + q(config) + " --out " + q(dir) + " --threads " +
                                              std::to_string(threads),
                                          tmp.path / "log");
            INFO(r.output);
            REQUIRE(r.code == 0);
            check_same_dirs(tmp.path / "plain", dir);
            if (n > 1) CHECK(read_text(dir / "log.txt").find(std::to_string(n - 1) + " worker process") !=
                             std::string::npos);
        }
    }
}

TEST_CASE("a MAP-Elites run over 1, 2, 3 and 5 processes gives the plain run's files", "[cluster][mpi]") {
    if (!have_mpi()) return;
    TempDir tmp("mpi-me");
    const fs::path config = tmp.path / "c.json";
    write_text(config, elite_config(5));
    REQUIRE(run_morphogen("evolve " + q(config) + " --out " + q(tmp.path / "plain")).code == 0);
    for (int n : {1, 2, 3, 5}) {
        CAPTURE(n);
        const fs::path dir = tmp.path / ("np" + std::to_string(n));
        const CliResult r = run_shell(mpirun(n) + "evolve " + q(config) + " --out " + q(dir), tmp.path / "log");
        INFO(r.output);
        REQUIRE(r.code == 0);
        check_same_dirs(tmp.path / "plain", dir);
    }
    // With CMA emitters (their distributions change at insertions on rank 0).
    nlohmann::json with_cma = nlohmann::json::parse(elite_config(5));
    with_cma["emitters"] = nlohmann::json::parse(R"([{"kind": "cma_me", "sigma0": 0.2},
        {"kind": "cma_mae", "sigma0": 0.3, "learning_rate": 0.2, "threshold_min": -1}, {"kind": "iso_line"}])");
    const fs::path cma_config = tmp.path / "cma.json";
    write_text(cma_config, with_cma.dump());
    REQUIRE(run_morphogen("evolve " + q(cma_config) + " --out " + q(tmp.path / "cma-plain")).code == 0);
    const CliResult r = run_shell(mpirun(3) + "evolve " + q(cma_config) + " --out " + q(tmp.path / "cma-np3"),
                                  tmp.path / "log");
    INFO(r.output);
    REQUIRE(r.code == 0);
    check_same_dirs(tmp.path / "cma-plain", tmp.path / "cma-np3");
    CHECK(read_text(tmp.path / "cma-plain" / "archive.csv") != read_text(tmp.path / "plain" / "archive.csv"));
}

TEST_CASE("stopped with one number of processes, resumed with another: the uninterrupted run's files",
          "[cluster][mpi]") {
    if (!have_mpi()) return;
    TempDir tmp("mpi-resume");
    const fs::path config = tmp.path / "c.json";
    write_text(config, elite_config(6));
    REQUIRE(run_morphogen("evolve " + q(config) + " --out " + q(tmp.path / "plain")).code == 0);
    const fs::path dir = tmp.path / "run";
    CliResult r = run_shell(mpirun(3) + "evolve " + q(config) + " --out " + q(dir) + " --generations 2",
                            tmp.path / "log");
    INFO(r.output);
    REQUIRE(r.code == 0);
    r = run_shell(mpirun(2) + "resume " + q(dir) + " --generations 4", tmp.path / "log");
    INFO(r.output);
    REQUIRE(r.code == 0);
    // And a run directory written by several processes is an ordinary one.
    REQUIRE(run_morphogen("resume " + q(dir) + " --generations 6").code == 0);
    check_same_dirs(tmp.path / "plain", dir);
}

TEST_CASE("SIGTERM to mpirun: rank 0 checkpoints with births in flight, every process exits 130, resume continues",
          "[cluster][mpi][signals]") {
    if (!have_mpi()) return;
    TempDir tmp("mpi-sigterm");
    const fs::path config = tmp.path / "c.json";
    write_text(config, tiny_pipeline_config(100000, 10, 6));
    const fs::path dir = tmp.path / "run";
    const int pid = spawn(mpirun(3) + "evolve " + config.string() + " --out " + dir.string() + " --threads 1",
                          tmp.path / "log");
    wait_for_lineage_rows(dir, 200);
    ::kill(pid, SIGTERM);
    const int code = wait_at_most(pid, 60);
    const std::string output = read_text(tmp.path / "log");
    INFO(output);
    // Open MPI's mpirun reports a forwarded signal as its own failure (1); the
    // ranks exit 130 (log.txt), which srun passes on.
    CHECK(code != 0);
    const std::string log = read_text(dir / "log.txt");
    CHECK(log.find("stopped by signal 15") != std::string::npos);
    CHECK(output.find("morphogen resume") != std::string::npos);

    // Continued with another number of processes, to the bytes of an uninterrupted run.
    const int done = generations_done(dir);
    const std::string target = std::to_string(done + 2);
    REQUIRE(run_shell(mpirun(2) + "resume " + q(dir) + " --generations " + target, tmp.path / "log2").code == 0);
    REQUIRE(run_morphogen("evolve " + q(config) + " --out " + q(tmp.path / "plain") + " --generations " + target)
                .code == 0);
    check_same_results(tmp.path / "plain", dir);
}

TEST_CASE("a killed worker ends the job naming its rank; the run resumes from its checkpoint", "[cluster][mpi][faults]") {
    if (!have_mpi()) return;
    TempDir tmp("mpi-killed");
    const fs::path config = tmp.path / "c.json";
    write_text(config, tiny_config(100000, 10, 4));
    const fs::path dir = tmp.path / "run";
    const int pid = spawn(mpirun(3) + "evolve " + config.string() + " --out " + dir.string() + " --threads 1",
                          tmp.path / "log");
    wait_for_lineage_rows(dir, 200);
    const int worker = rank_pid(1, dir);
    REQUIRE(worker > 0);
    ::kill(worker, SIGKILL);
    const int code = wait_at_most(pid, 60);  // nobody waits forever
    const std::string output = read_text(tmp.path / "log");
    INFO(output);
    CHECK(code != 0);
    CHECK(output.find("rank 1") != std::string::npos);
    CHECK(output.find("can be resumed") != std::string::npos);

    const int done = generations_done(dir);
    const std::string target = std::to_string(done + 2);
    REQUIRE(run_morphogen("resume " + q(dir) + " --generations " + target).code == 0);
    REQUIRE(run_morphogen("evolve " + q(config) + " --out " + q(tmp.path / "plain") + " --generations " + target)
                .code == 0);
    check_same_results(tmp.path / "plain", dir);
}

TEST_CASE("only evolve and resume run over several processes", "[cluster][mpi]") {
    if (!have_mpi()) return;
    TempDir tmp("mpi-other");
    const CliResult r = run_shell(mpirun(2) + "validate " + q(tmp.path / "none.json"), tmp.path / "log");
    INFO(r.output);
    CHECK(r.code == 2);
    CHECK(r.output.find("only evolve and resume run over several processes") != std::string::npos);
}

TEST_CASE("a build without MPI started as several processes says so and exits 2", "[cluster][launch]") {
    if (MORPHOGEN_HAVE_MPI) return;  // only a build without MPI can show it (an MPI build would start MPI)
    TempDir tmp("nompi-launched");
    const fs::path config = tmp.path / "c.json";
    write_text(config, tiny_config(2));
    for (const std::string launcher : {"OMPI_COMM_WORLD_SIZE=3 OMPI_COMM_WORLD_RANK=0", "SLURM_STEP_NUM_TASKS=2"}) {
        CAPTURE(launcher);
        const CliResult r = run_shell("env " + launcher + " " + MORPHOGEN_EXE + " evolve " + q(config) + " --out " +
                                          q(tmp.path / "run"),
                                      tmp.path / "log");
        CHECK(r.code == 2);
        CHECK(r.output.find("this build has no MPI") != std::string::npos);
        CHECK_FALSE(fs::exists(tmp.path / "run"));
    }
    // Rank 1 stays silent (rank 0 speaks for the job), and one process is no job.
    CHECK(run_shell("env OMPI_COMM_WORLD_SIZE=3 OMPI_COMM_WORLD_RANK=1 " + std::string(MORPHOGEN_EXE) + " --version",
                    tmp.path / "log")
              .output.empty());
    CHECK(run_shell("env OMPI_COMM_WORLD_SIZE=1 " + std::string(MORPHOGEN_EXE) + " --version", tmp.path / "log").code ==
          0);
}
