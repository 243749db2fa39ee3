#pragma once
// A real `morphogen breed` process for the API tests: started with
// --no-browser --port 0, its first line of stdout read for the address.
#include <sys/types.h>

#include <string>
#include <vector>

namespace morphogen::testing {

class BreedProcess {
public:
    // Runs MORPHOGEN_EXE breed <args> --no-browser --port 0 and waits for the
    // address line (throws std::runtime_error if the process ends first).
    explicit BreedProcess(const std::vector<std::string>& args);
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

}  // namespace morphogen::testing
