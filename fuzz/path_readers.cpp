#include "path_readers.hpp"

#include "fuzz_target.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace morphogen::fuzz {
namespace {

namespace fs = std::filesystem;

// A directory of this process's own (several fuzzers or replays may run at
// once), removed at a normal exit; a crash leaves it behind. In /dev/shm where
// there is one: a file per input on disk made the mesh and checkpoint targets
// 14 times slower (214 against 3000 inputs/s).
fs::path scratch_base() {
    std::error_code ec;
    if (fs::is_directory("/dev/shm", ec) && ::access("/dev/shm", W_OK) == 0) return "/dev/shm";
    const fs::path temp = fs::temp_directory_path(ec);
    return ec ? fs::path("/tmp") : temp;
}

class ScratchDirectory {
public:
    ScratchDirectory() {
        std::error_code ec;
        dir_ = scratch_base() / ("morphogen-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(dir_, ec);
        if (ec) finding("harness: cannot create scratch directory " + dir_.string() + ": " + ec.message());
    }
    ~ScratchDirectory() {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    ScratchDirectory(const ScratchDirectory&) = delete;
    ScratchDirectory& operator=(const ScratchDirectory&) = delete;

    // Writes `bytes` to <dir>/input<extension> and returns that path.
    fs::path write(std::string_view bytes, const std::string& extension) const {
        const fs::path path = dir_ / ("input" + extension);
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.close();
        if (!out) finding("harness: cannot write scratch file " + path.string());
        return path;
    }

private:
    fs::path dir_;
};

const ScratchDirectory& scratch() {
    static const ScratchDirectory directory;
    return directory;
}

std::string extension_of(MeshFormat format) {
    switch (format) {
        case MeshFormat::obj: return ".obj";
        case MeshFormat::ply: return ".ply";
        case MeshFormat::off: return ".off";
        case MeshFormat::stl: return ".stl";
        case MeshFormat::glb: return ".glb";
    }
    return ".bin";
}

}  // namespace

MeshArrays read_mesh_bytes(std::string_view bytes, MeshFormat format) {
    return read_mesh(scratch().write(bytes, extension_of(format)).string());
}

RunState load_checkpoint_bytes(std::string_view bytes) {
    return load_checkpoint(scratch().write(bytes, ".json"));
}

}  // namespace morphogen::fuzz
