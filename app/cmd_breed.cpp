// `morphogen breed`: breed plants by hand on a local page (docs/breed.md):
// the session (breed/session.hpp) behind the HTTP server (breed/server.hpp).
#include "app/commands.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_text.hpp"
#include "breed/breed_assets.hpp"
#include "breed/server.hpp"
#include "breed/session.hpp"
#include "core/growth/network/network.hpp"
#include "run/exit_codes.hpp"
#include "run/config/experiment_config.hpp"
#include "run/genome_source.hpp"
#include "run/loop/stop_signals.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

extern char** environ;

namespace morphogen {

namespace {

namespace fs = std::filesystem;

struct BreedOptions {
    std::string config;
    std::vector<std::string> from;
    std::string out, resume, replay;
    int port = 0;
    std::string bind = "127.0.0.1";
    bool no_browser = false;
    std::optional<std::uint64_t> seed;
    int threads = 0;
    bool no_colour = false;
};

// The genome files a --from names: a file itself, or a directory's
// *.genome.json (recursively), the last kBreedGridSize by name.
std::vector<fs::path> genome_files(const std::vector<std::string>& from) {
    std::vector<fs::path> files;
    for (const std::string& f : from) {
        if (!fs::is_directory(f)) {
            files.emplace_back(f);
            continue;
        }
        std::vector<fs::path> found;
        for (const auto& entry : fs::recursive_directory_iterator(f))
            if (entry.is_regular_file() && entry.path().filename().string().ends_with(".genome.json"))
                found.push_back(entry.path());
        if (found.empty()) throw IoError(f + ": holds no *.genome.json file");
        std::sort(found.begin(), found.end());
        const std::size_t keep = std::min<std::size_t>(found.size(), kBreedGridSize);
        files.insert(files.end(), found.end() - static_cast<std::ptrdiff_t>(keep), found.end());
    }
    return files;
}

ExperimentConfig breed_config(const BreedOptions& o) {
    ConfigOverrides overrides;
    overrides.seed = o.seed;
    if (!o.config.empty()) return load_experiment_config(o.config, overrides);
    for (const std::string& f : o.from)
        if (fs::is_directory(f) && fs::exists(fs::path(f) / "config.json"))
            return load_experiment_config((fs::path(f) / "config.json").string(), overrides);
    return read_experiment_config(read_json_object(breed_default_config()), "the built-in breed config (configs/breed.json)",
                                  overrides);
}

std::string default_out() {
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    return (fs::path("runs") / (std::string("breed-") + stamp)).string();
}

// xdg-open, quietly, when there is a display to open a browser on.
void open_browser(const std::string& address) {
    if (!std::getenv("DISPLAY") && !std::getenv("WAYLAND_DISPLAY")) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    const std::string program = "xdg-open";
    char* argv[] = {const_cast<char*>(program.c_str()), const_cast<char*>(address.c_str()), nullptr};
    pid_t pid = 0;
    if (posix_spawnp(&pid, "xdg-open", &actions, nullptr, argv, environ) != 0)
        std::cerr << "morphogen breed: no browser opened (xdg-open not found); open the address above\n";
    posix_spawn_file_actions_destroy(&actions);
}

int run_breed(const BreedOptions& o) {
    BreedSessionOptions session_options;
    session_options.threads = o.threads;
    session_options.colour = !o.no_colour;
    if (!o.replay.empty()) {
        const auto session = BreedSession::replay(o.replay, o.out, session_options);
        std::cout << "replayed " << o.replay << "/choices.jsonl into " << o.out << "\n";
        return exit_code::ok;
    }
    StopSignals signals;
    std::unique_ptr<BreedSession> session;
    if (!o.resume.empty()) {
        session = BreedSession::resume(o.resume, session_options);
        if (const std::vector<std::string>& removed = session->removed_on_resume(); !removed.empty()) {
            std::cerr << "morphogen breed: removed " << removed.size()
                      << " plant files that no recorded choice owns (a choice cut short):";
            for (const std::string& file : removed) std::cerr << " " << file;
            std::cerr << "\n";
        }
    } else {
        const ExperimentConfig config = breed_config(o);
        std::vector<std::vector<double>> from;
        for (const fs::path& file : genome_files(o.from))
            from.push_back(load_genome_for(config.network.layers(), file.string()).params);
        session = BreedSession::create(o.out.empty() ? default_out() : o.out, config, from, session_options);
    }
    BreedServerOptions server_options;
    server_options.bind = o.bind;
    server_options.port = o.port;
    server_options.token = new_breed_token();
    BreedServer server(*session, server_options);
    std::cout << server.address() << std::endl;
    if (o.bind != "127.0.0.1")
        std::cerr << "morphogen breed: warning: listening on " << o.bind
                  << ", not only this machine: anyone who can reach it and has the token can breed and write files\n";
    std::cerr << "morphogen breed: session " << session->dir().string() << "; Ctrl-C saves and stops\n";
    if (!o.no_browser) open_browser(server.address());
    std::atomic<bool> served{false};
    std::thread serving([&server, &served] {
        server.run();
        served = true;
    });
    while (!StopSignals::requested()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    // A stop that comes before the server listens does nothing: ask until it ends.
    while (!served) {
        server.stop();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    serving.join();
    session.reset();  // a search in flight stops, and its grid is saved
    std::cerr << "morphogen breed: saved " << (o.resume.empty() ? "the session" : o.resume) << "\n";
    return exit_code::ok;
}

}  // namespace

void add_breed_command(CLI::App& root, CommandRunner& selected) {
    auto o = std::make_shared<BreedOptions>();
    CLI::App* cmd = root.add_subcommand("breed", "Breed plants by hand on a local page (docs/breed.md)");
    cmd->add_option("config", o->config, "Experiment config (default: the built-in configs/breed.json)")
        ->check(CLI::ExistingFile);
    cmd->add_option("--from", o->from, "Start from these genome files, or a run directory's *.genome.json")
        ->check(CLI::ExistingPath);
    cmd->add_option("--out", o->out, "Session directory (default runs/breed-DATE-TIME); with --replay, where it goes");
    cmd->add_option("--port", o->port, "Port; 0 picks a free one")->check(CLI::Range(0, 65535))->capture_default_str();
    cmd->add_option("--bind", o->bind, "Address to listen on (anything but 127.0.0.1 gets a warning)")
        ->capture_default_str();
    cmd->add_flag("--no-browser", o->no_browser, "Do not open a browser");
    cmd->add_flag("--no-colour", o->no_colour,
                  "Draw the page's plants in plain green, not in colours from growth history");
    cmd->add_option("--seed", o->seed, "The session's seed (run.seed)");
    cmd->add_option("--threads", o->threads, "Threads that grow a grid (0: all cores)")->check(CLI::Range(0, 1024));
    auto* resume = cmd->add_option("--resume", o->resume, "Continue the session in this directory")
                       ->check(CLI::ExistingDirectory);
    auto* replay = cmd->add_option("--replay", o->replay, "Replay this session's choices into --out (no server)")
                       ->check(CLI::ExistingDirectory);
    resume->excludes(replay);
    select_on_pick(cmd, selected, o, run_breed, [o] {
        if (!o->replay.empty() && o->out.empty()) throw CLI::ValidationError("--replay", "needs --out DIR2");
        if ((!o->resume.empty() || !o->replay.empty()) && (!o->config.empty() || !o->from.empty() || o->seed))
            throw CLI::ValidationError("--resume/--replay", "take the session's own config, seed and plants: "
                                                            "drop CONFIG, --from and --seed");
        if (!o->resume.empty() && !o->out.empty())
            throw CLI::ValidationError("--resume", "continues in its own directory: drop --out");
    });
}

}  // namespace morphogen
