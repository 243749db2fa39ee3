#pragma once
// A fresh directory per test case under the system temp dir, removed by the
// destructor. Unique per process and per instance, so parallel CTest runs do
// not collide; `label` only makes a leftover directory easy to recognise.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace morphogen::testing {

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
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }
};

}  // namespace morphogen::testing
