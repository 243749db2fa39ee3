#pragma once
// A real `morphogen breed` process for the API tests: started with
// --no-browser --port 0, its first line of stdout read for the address.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace morphogen::testing {

class BreedProcess {
public:
    // Runs MORPHOGEN_EXE breed <args> --no-browser --port 0 and waits for the
    // address line (throws std::runtime_error if the process ends first).
    // Its stderr goes to `stderr_file` when one is given.
    explicit BreedProcess(const std::vector<std::string>& args, const std::filesystem::path& stderr_file = {});
    ~BreedProcess();  // SIGKILL if still running
    BreedProcess(const BreedProcess&) = delete;
    BreedProcess& operator=(const BreedProcess&) = delete;

    const std::string& address() const { return address_; }  // http://127.0.0.1:PORT/?token=T
    int port() const { return port_; }
    const std::string& token() const { return token_; }
    pid_t pid() const { return pid_; }

    void signal(int sig);  // kill(pid, sig)
    // Waits for the exit; returns the exit status (128 + signal when killed).
    int wait();

private:
    pid_t pid_ = -1;
    int out_ = -1;
    std::string address_, token_;
    int port_ = 0;
};

// `morphogen breed ARGS` run to the end (e.g. --replay): its exit status.
int run_breed_command(const std::vector<std::string>& args);

// Runs `morphogen breed --replay SESSION --out OUT`: "" when it succeeds and
// OUT holds SESSION's files byte for byte, else what went wrong.
std::string replay_difference(const std::filesystem::path& session, const std::filesystem::path& out);

// `morphogen breed ARGS` started and left running, its stdout and stderr
// into these files (several servers started at once): its process id.
pid_t start_breed_command(const std::vector<std::string>& args, const std::filesystem::path& stdout_file,
                          const std::filesystem::path& stderr_file);
// The exit status of a process start_breed_command() started, once it has
// ended; -1 while it runs.
int exit_status_if_ended(pid_t pid);

}  // namespace morphogen::testing
