#pragma once
// Files for tests: whole-file text reads and writes, and TempDir, a fresh
// directory per test case under the system temp dir, removed by the
// destructor. Unique per process and per instance, so parallel CTest runs do
// not collide; `label` only makes a leftover directory easy to recognise.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace morphogen::testing {

inline std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

struct TempDir {
    std::filesystem::path path;
    explicit TempDir(const std::string& label = "test") {
        static int counter = 0;
        path = std::filesystem::temp_directory_path() / ("morphogen_" + label + "_" + std::to_string(::getpid()) +
                                                         "_" + std::to_string(counter++));
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string file(const std::string& name) const { return (path / name).string(); }
    // Writes `bytes` to file(name) and returns its path.
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::string path = file(name);
        write_text(path, bytes);
        return path;
    }
};

}  // namespace morphogen::testing
