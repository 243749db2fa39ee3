#include "run/persistence/run_directory.hpp"

#include "core/base/atomic_file.hpp"
#include "core/base/errors.hpp"
#include "run/loop/run_records.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <optional>
#include <string_view>
#include <system_error>
#include <vector>

namespace morphogen {

namespace fs = std::filesystem;

std::string export_name(std::uint64_t generation) {
    char name[32];
    std::snprintf(name, sizeof name, "gen_%04llu", static_cast<unsigned long long>(generation));
    return name;
}

std::optional<std::uint64_t> export_generation(std::string_view name, std::string_view extension) {
    if (!name.starts_with("gen_")) return std::nullopt;
    std::uint64_t generation = 0;
    const char* first = name.data() + 4;
    const char* last = name.data() + name.size();
    const auto [end, error] = std::from_chars(first, last, generation);
    if (error != std::errc() || end == first) return std::nullopt;
    if (!extension.empty() && std::string_view(end, static_cast<std::size_t>(last - end)) != extension)
        return std::nullopt;
    return generation;
}

fs::path RunPaths::best_stem(std::uint64_t generation) const { return best / export_name(generation); }

RunPaths run_paths(const fs::path& dir) {
    return {dir,
            dir / "config.json",
            dir / "history.csv",
            dir / "lineage.csv",
            dir / "checkpoint.json",
            dir / "best",
            dir / "log.txt",
            dir / "archive.csv"};
}

fs::path default_run_dir(const std::string& name, std::chrono::system_clock::time_point now) {
    const std::time_t t = std::chrono::system_clock::to_time_t(now);
    std::tm local{};
    localtime_r(&t, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    return fs::path("runs") / (name + "-" + stamp);
}

namespace {
[[noreturn]] void fail(const fs::path& path, const std::string& what, const std::error_code& ec) {
    throw IoError(path.string() + ": " + what + ": " + ec.message());
}

void remove_file(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(path, ec)) && !fs::remove(path, ec) && ec) fail(path, "cannot remove", ec);
}

// More than any header line of lineage.csv or archive.csv (a few names of
// measures): a file longer holds rows, and only this much of it is read.
constexpr std::size_t kHeaderBytes = 1 << 16;

// Whether `path` is missing or holds a prefix of `header` (no data row).
bool holds_no_rows(const fs::path& path, std::string_view header) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(path, ec))) return true;
    if (!fs::is_regular_file(fs::symlink_status(path, ec))) return false;
    try {
        const std::string bytes = read_file_head(path, header.size() + 1);
        return bytes.size() <= header.size() && header.substr(0, bytes.size()) == bytes;
    } catch (const IoError&) {
        return false;
    }
}

// Whether lineage.csv is missing or holds a prefix of its header, which has
// a descriptor column per name after lineage_header's when the config has
// descriptors (names of measures: no comma or newline in them).
bool holds_no_lineage_rows(const fs::path& path) {
    const std::string_view base(lineage_header, std::string_view(lineage_header).size() - 1);  // without '\n'
    if (holds_no_rows(path, lineage_header)) return true;
    std::error_code ec;
    if (!fs::is_regular_file(fs::symlink_status(path, ec))) return false;
    try {
        const std::string bytes = read_file_head(path, kHeaderBytes + 1);
        const std::size_t newline = bytes.find('\n');
        return bytes.size() > base.size() && bytes.compare(0, base.size(), base) == 0 && bytes[base.size()] == ',' &&
               (newline == std::string::npos || newline == bytes.size() - 1);
    } catch (const IoError&) {
        return false;
    }
}

// Whether archive.csv is missing or holds no elite: the empty archive that
// a MAP-Elites evolve writes just before its first checkpoint is one line,
// "cell,<descriptor names>,fitness,id" (written atomically, so whole).
bool holds_no_archive_rows(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(path, ec))) return true;
    if (!fs::is_regular_file(fs::symlink_status(path, ec))) return false;
    try {
        const std::string bytes = read_file_head(path, kHeaderBytes + 1);
        const std::string_view tail(archive_header_tail);
        return bytes.rfind("cell,", 0) == 0 && bytes.find('\n') == bytes.size() - 1 && bytes.size() >= tail.size() &&
               bytes.compare(bytes.size() - tail.size(), tail.size(), tail) == 0;
    } catch (const IoError&) {
        return false;
    }
}

bool ends_with(const std::string& text, std::string_view tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace

bool is_stopped_start(const RunPaths& paths) {
    std::error_code ec;
    if (!fs::is_directory(paths.dir, ec) || fs::exists(fs::symlink_status(paths.checkpoint, ec))) return false;
    if (fs::is_empty(paths.dir, ec)) return false;
    const std::vector<fs::path> ours{paths.config, paths.history, paths.lineage, paths.log, paths.archive,
                                     paths.dir / ".lock"};
    for (const auto& entry : fs::directory_iterator(paths.dir, ec)) {
        const fs::path& p = entry.path();
        if (p == paths.dir / "seeds") continue;  // evolve --from's copies, written again by the next evolve
        if (p == paths.best) {
            if (!fs::is_directory(fs::symlink_status(p, ec)) || !fs::is_empty(p, ec)) return false;
            continue;
        }
        bool known = false;
        for (const fs::path& name : ours) known = known || p == name || p == temporary_path(name);
        known = known || p == temporary_path(paths.checkpoint) || p == temporary_path(paths.archive);
        if (!known) return false;
    }
    if (ec) return false;
    return (holds_no_rows(paths.history, history_header) || holds_no_rows(paths.history, history_header_qd)) &&
           holds_no_lineage_rows(paths.lineage) && holds_no_archive_rows(paths.archive);
}

void create_run_dir(const RunPaths& paths, bool force) {
    std::error_code ec;
    if (fs::exists(paths.dir, ec)) {
        if (!fs::is_directory(paths.dir, ec))
            throw IoError(paths.dir.string() + " exists and is not a directory");
        if (!fs::is_empty(paths.dir, ec) && !force && !is_stopped_start(paths))
            throw IoError("run directory " + paths.dir.string() +
                          " already exists and is not empty (use --force to overwrite it, or resume it)");
    }
    fs::create_directories(paths.dir, ec);
    if (ec) fail(paths.dir, "cannot create", ec);
}

void clear_run_files(const RunPaths& paths) {
    for (const fs::path& p : {paths.config, paths.history, paths.lineage, paths.checkpoint, paths.log, paths.archive}) {
        remove_file(p);
        remove_file(temporary_path(p));
    }
    std::error_code ec;
    fs::remove_all(paths.dir / "seeds", ec);  // a run's given genomes (seed_genomes.hpp)
    if (ec) fail(paths.dir / "seeds", "cannot remove", ec);
    if (fs::is_directory(paths.best, ec)) {
        for (const auto& entry : fs::directory_iterator(paths.best, ec))
            if (entry.path().filename().string().rfind("gen_", 0) == 0) remove_file(entry.path());
        if (ec) fail(paths.best, "cannot list", ec);
    }
    fs::create_directories(paths.best, ec);
    if (ec) fail(paths.best, "cannot create", ec);
}

void prepare_resumed_run_files(const RunPaths& paths, std::uint64_t first_generation) {
    for (const fs::path& p : {paths.config, paths.history, paths.lineage, paths.checkpoint, paths.archive})
        remove_file(temporary_path(p));
    std::error_code ec;
    fs::create_directories(paths.best, ec);
    if (ec) fail(paths.best, "cannot create", ec);
    for (const auto& entry : fs::directory_iterator(paths.best, ec)) {
        const std::string name = entry.path().filename().string();
        const std::optional<std::uint64_t> generation = export_generation(name);
        if (generation && (*generation >= first_generation || ends_with(name, ".tmp"))) remove_file(entry.path());
    }
    if (ec) fail(paths.best, "cannot list", ec);
}

RunLock::RunLock(const fs::path& dir) {
    const fs::path path = dir / ".lock";
    fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw IoError(path.string() + ": cannot open the run lock: " + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        ::close(fd_);
        fd_ = -1;
        throw IoError("run directory " + dir.string() + " is in use by another morphogen process");
    }
}

RunLock::~RunLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
}

}  // namespace morphogen
