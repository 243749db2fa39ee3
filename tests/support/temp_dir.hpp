#pragma once
// A fresh directory per test case under the system temp dir, removed by the
// destructor. Unique per process and per instance, so parallel CTest runs do
// not collide.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace morphogen::testing {

struct TempDir {
    std::filesystem::path dir;
    TempDir() {
        static int counter = 0;
        dir = std::filesystem::temp_directory_path() /
              ("morphogen_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        std::filesystem::create_directories(dir);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string file(const std::string& name) const { return (dir / name).string(); }
    // Writes `bytes` to file(name) and returns its path.
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::string path = file(name);
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }
};

}  // namespace morphogen::testing
