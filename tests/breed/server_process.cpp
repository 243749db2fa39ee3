#include "tests/breed/server_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>

extern char** environ;

namespace morphogen::testing {

namespace {
pid_t spawn(const std::vector<std::string>& args, int stdout_fd) {
    std::vector<std::string> all = {MORPHOGEN_EXE, "breed"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (stdout_fd >= 0) posix_spawn_file_actions_adddup2(&actions, stdout_fd, 1);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, MORPHOGEN_EXE, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw std::runtime_error("cannot start " MORPHOGEN_EXE);
    return pid;
}

int exit_status(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}
}  // namespace

BreedProcess::BreedProcess(const std::vector<std::string>& args) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::vector<std::string> all = args;
    all.insert(all.end(), {"--no-browser", "--port", "0"});
    pid_ = spawn(all, fds[1]);
    close(fds[1]);
    out_ = fds[0];
    std::string line;
    char c = 0;
    while (read(out_, &c, 1) == 1 && c != '\n') line += c;
    const std::string start = "http://127.0.0.1:";
    const auto token_at = line.find("/?token=");
    if (!line.starts_with(start) || token_at == std::string::npos) {
        wait();
        throw std::runtime_error("morphogen breed printed \"" + line + "\" instead of its address");
    }
    address_ = line;
    port_ = std::stoi(line.substr(start.size(), token_at - start.size()));
    token_ = line.substr(token_at + 8);
}

BreedProcess::~BreedProcess() {
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        exit_status(pid_);
    }
    if (out_ >= 0) close(out_);
}

void BreedProcess::signal(int sig) { ::kill(pid_, sig); }

int BreedProcess::wait() {
    const int status = exit_status(pid_);
    pid_ = -1;
    return status;
}

int run_breed_command(const std::vector<std::string>& args) { return exit_status(spawn(args, -1)); }

}  // namespace morphogen::testing
