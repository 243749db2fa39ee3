// `morphogen render MESH... -o SHEET.png [--columns C] [--size PX] [--own-scale]`:
// draws meshes (OBJ/PLY/OFF/STL/GLB) side by side on one PNG contact sheet,
// in a GLB's vertex colours (COLOR_0, `--colour` exports) unless --no-colour.
#include "app/commands.hpp"
#include "core/io/mesh_io.hpp"
#include "report/render.hpp"
#include "run/exit_codes.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace morphogen {
namespace {

struct RenderArgs {
    std::vector<std::string> meshes;
    std::string output;
    RenderOptions options;
    bool own_scale = false;
    bool no_colour = false;
};

int run_render(const RenderArgs& args) {
    std::vector<MeshArrays> meshes;
    std::vector<std::vector<float>> colours;
    std::vector<std::string> captions;
    meshes.reserve(args.meshes.size());
    for (const std::string& path : args.meshes) {
        ColouredMesh read = read_coloured_mesh(path);  // IoError names the file
        meshes.push_back(std::move(read.mesh));
        colours.push_back(args.no_colour ? std::vector<float>{} : std::move(read.colours));
        captions.push_back(std::filesystem::path(path).stem().string());
    }
    RenderOptions options = args.options;
    options.shared_scale = !args.own_scale;
    render_contact_sheet(meshes, captions, args.output, options, colours);
    std::cout << "wrote " << args.output << " (" << meshes.size() << " mesh" << (meshes.size() == 1 ? "" : "es")
              << ")\n";
    return exit_code::ok;
}

}  // namespace

void add_render_command(CLI::App& root, CommandRunner& selected) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = root.add_subcommand(
        "render", "Draw meshes (OBJ, PLY, OFF, STL or GLB) on a PNG contact sheet, all at one scale");
    // No ExistingFile check: read_mesh reports unreadable files as I/O errors (exit 3).
    cmd->add_option("meshes", args->meshes, "Mesh files, one cell each, in order")->required();
    cmd->add_option("-o,--output", args->output, "PNG file to write")->required();
    cmd->add_option("--columns", args->options.columns, "Cells per row")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    cmd->add_option("--size", args->options.size, "Width and height of one cell's picture, pixels")
        ->check(CLI::Range(32, 4096))
        ->capture_default_str();
    cmd->add_flag("--own-scale", args->own_scale,
                  "Frame every mesh to fill its cell (sizes are then not comparable)");
    cmd->add_flag("--no-colour", args->no_colour,
                  "Draw every mesh in the plain green, not in a GLB's vertex colours (COLOR_0)");
    select_on_pick(cmd, selected, args, run_render);
}

}  // namespace morphogen
