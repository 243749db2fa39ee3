#include "tests/breed/server_process.hpp"

#include "tests/breed/breed_test_support.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>

extern char** environ;

namespace morphogen::testing {

namespace {
pid_t spawn(const std::vector<std::string>& args, int stdout_fd, int stderr_fd = -1) {
    std::vector<std::string> all = {MORPHOGEN_EXE, "breed"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (stdout_fd >= 0) posix_spawn_file_actions_adddup2(&actions, stdout_fd, 1);
    if (stderr_fd >= 0) posix_spawn_file_actions_adddup2(&actions, stderr_fd, 2);
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, MORPHOGEN_EXE, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) throw std::runtime_error("cannot start " MORPHOGEN_EXE);
    return pid;
}

int exit_code_of(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status); }

int exit_status(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
    }
    return exit_code_of(status);
}

// A file opened for writing (-1 for none), for a child's stdout or stderr.
int open_output(const std::filesystem::path& file) {
    if (file.empty()) return -1;
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error("cannot write " + file.string());
    return fd;
}
}  // namespace

BreedProcess::BreedProcess(const std::vector<std::string>& args, const std::filesystem::path& stderr_file) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::vector<std::string> all = args;
    all.insert(all.end(), {"--no-browser", "--port", "0"});
    const int err = open_output(stderr_file);
    pid_ = spawn(all, fds[1], err);
    if (err >= 0) close(err);
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

std::string replay_difference(const std::filesystem::path& session, const std::filesystem::path& out) {
    if (const int status = run_breed_command({"--replay", session.string(), "--out", out.string()}); status != 0)
        return "--replay exited with " + std::to_string(status);
    return session_difference(session, out);
}

pid_t start_breed_command(const std::vector<std::string>& args, const std::filesystem::path& stdout_file,
                          const std::filesystem::path& stderr_file) {
    const int out = open_output(stdout_file), err = open_output(stderr_file);
    const pid_t pid = spawn(args, out, err);
    close(out);
    close(err);
    return pid;
}

int exit_status_if_ended(pid_t pid) {
    int status = 0;
    return waitpid(pid, &status, WNOHANG) == pid ? exit_code_of(status) : -1;
}

}  // namespace morphogen::testing
