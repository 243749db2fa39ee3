#include "tests/app/evolve_test_support.hpp"

#include "run/persistence/checkpoint.hpp"

#include <catch2/catch.hpp>

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <sstream>
#include <thread>
#include <vector>

namespace morphogen::test {

namespace {
int decode_status(int status) {
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return -1;
}
}  // namespace

CliResult run_morphogen(const std::string& args) {
    const fs::path out = fs::temp_directory_path() / ("morphogen-test-out-" + std::to_string(::getpid()));
    const std::string command = std::string(MORPHOGEN_EXE) + " " + args + " > " + out.string() + " 2>&1";
    CliResult result;
    result.code = decode_status(std::system(command.c_str()));
    result.output = read_text(out);
    fs::remove(out);
    return result;
}

int spawn_morphogen(const std::vector<std::string>& args, const fs::path& log, bool block_stop_signals) {
    // Blocked around fork, so a signal never meets the child while it is still
    // a copy of this test (with Catch's handlers): it gets the default action
    // first, and the signals are unblocked again unless the caller asked.
    sigset_t stops, before;
    sigemptyset(&stops);
    sigaddset(&stops, SIGINT);
    sigaddset(&stops, SIGTERM);
    ::pthread_sigmask(SIG_BLOCK, &stops, &before);
    const pid_t pid = ::fork();
    if (pid != 0) ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
    if (pid == 0) {
        ::signal(SIGINT, SIG_DFL);
        ::signal(SIGTERM, SIG_DFL);
        if (!block_stop_signals) ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(fd, 1);
        ::dup2(fd, 2);
        std::vector<std::string> all{MORPHOGEN_EXE};
        all.insert(all.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (auto& a : all) argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execv(MORPHOGEN_EXE, argv.data());
        ::_exit(127);
    }
    return pid;
}

int wait_for(int pid, bool* killed) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (killed != nullptr) *killed = WIFSIGNALED(status);
    return decode_status(status);
}

std::string history_without_times(const fs::path& run_dir) {
    std::istringstream in(read_text(run_dir / "history.csv"));
    std::string line, out;
    while (std::getline(in, line)) {
        for (int cut = 0; cut < 2; ++cut) line = line.substr(0, line.rfind(','));
        out += line + "\n";
    }
    return out;
}

nlohmann::json checkpoint_without_times(const fs::path& run_dir) {
    nlohmann::json content = checkpoint_content(read_text(run_dir / "checkpoint.json"), run_dir.string());
    content.erase("elapsed_s");
    for (auto& row : content["history"]) {
        row.erase("births_per_s");
        row.erase("elapsed_s");
    }
    // run.generations / threads may legitimately differ between sessions.
    content["config"]["run"].erase("threads");
    content["config"]["run"].erase("generations");
    content["config"]["run"].erase("name");
    return content;
}

void check_same_results(const fs::path& a, const fs::path& b) {
    CHECK(read_text(a / "lineage.csv") == read_text(b / "lineage.csv"));
    CHECK(history_without_times(a) == history_without_times(b));
    CHECK(checkpoint_without_times(a) == checkpoint_without_times(b));
}

void wait_for_rows(const fs::path& dir, std::size_t rows) {
    for (int i = 0; i < 2000; ++i) {
        const std::string text = read_text(dir / "history.csv");
        if (static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) >= rows + 1) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

// Appending, not "'" + string: GCC 12 warns falsely (-Wrestrict).
std::string q(const fs::path& p) {
    std::string quoted(1, '\'');
    quoted += p.string();
    quoted += '\'';
    return quoted;
}

}  // namespace morphogen::test
