// The corpus replay: calls a fuzz target's LLVMFuzzerTestOneInput on every
// file of the given folders (or on the given files), in name order, without
// libFuzzer, so the normal build (gcc, and the ASan+UBSan build) runs it as a
// CTest test. A finding aborts (fuzz_target.hpp); an input that runs longer
// than MORPHOGEN_REPLAY_TIMEOUT seconds (default 30) is a hang and fails too.
// Files whose names start with "README" or "." are skipped.
//
//   replay_<target> DIR_OR_FILE...
#include "fuzz/fuzz_target.hpp"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The file being replayed, for the alarm handler (which may only call
// async-signal-safe functions, so the message is prepared beforehand).
char timeout_message[4096];

extern "C" void on_alarm(int) {
    const ssize_t ignored = ::write(STDERR_FILENO, timeout_message, std::char_traits<char>::length(timeout_message));
    (void)ignored;
    ::_exit(1);
}

bool skipped(const fs::path& file) {
    const std::string name = file.filename().string();
    return name.empty() || name[0] == '.' || name.rfind("README", 0) == 0;
}

std::vector<fs::path> inputs_of(const std::vector<std::string>& arguments) {
    std::vector<fs::path> files;
    for (const std::string& argument : arguments) {
        const fs::path path(argument);
        if (fs::is_directory(path)) {
            std::vector<fs::path> here;
            for (const fs::directory_entry& entry : fs::directory_iterator(path))
                if (entry.is_regular_file() && !skipped(entry.path())) here.push_back(entry.path());
            std::sort(here.begin(), here.end());
            files.insert(files.end(), here.begin(), here.end());
        } else if (fs::is_regular_file(path)) {
            files.push_back(path);
        } else {
            std::cerr << "replay: " << argument << ": no such file or folder\n";
            std::exit(2);
        }
    }
    return files;
}

std::string bytes_of(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        std::cerr << "replay: " << file.string() << ": cannot read\n";
        std::exit(2);
    }
    return bytes;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: " << argv[0] << " DIR_OR_FILE...\n";
        return 2;
    }
    unsigned timeout_s = 30;
    if (const char* t = std::getenv("MORPHOGEN_REPLAY_TIMEOUT"); t != nullptr && std::atoi(t) > 0)
        timeout_s = static_cast<unsigned>(std::atoi(t));
    std::signal(SIGALRM, on_alarm);

    const std::vector<fs::path> files = inputs_of(std::vector<std::string>(argv + 1, argv + argc));
    if (files.empty()) {
        std::cerr << "replay: no corpus files found\n";
        return 2;
    }
    for (const fs::path& file : files) {
        const std::string input = morphogen::fuzz::input_from_file(file.string(), bytes_of(file));
        // Says which file a crash, sanitizer report or finding belongs to.
        std::cerr << "replay: " << file.string() << '\n';
        const std::string message = "fuzz finding: timeout: " + file.string() + " ran longer than " +
                                    std::to_string(timeout_s) + " s\n";
        message.copy(timeout_message, sizeof timeout_message - 1);
        timeout_message[std::min(message.size(), sizeof timeout_message - 1)] = '\0';
        ::alarm(timeout_s);
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
        ::alarm(0);
    }
    std::cout << "replay: " << files.size() << " corpus files, no findings\n";
    return 0;
}
