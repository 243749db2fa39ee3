#pragma once
// Runs the morphogen executable under test (MORPHOGEN_EXE, set by
// tests/CMakeLists.txt) and captures what it prints.
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace morphogen::testing {

struct CliRun {
    int code;
    std::string out;
};

// `arguments` in shell syntax; stderr joins stdout.
inline CliRun morphogen_run(const std::string& arguments) {
    const std::string command = std::string("\"") + MORPHOGEN_EXE + "\" " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe != nullptr);
    std::string out;
    char buffer[4096];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
    const int status = pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

}  // namespace morphogen::testing
