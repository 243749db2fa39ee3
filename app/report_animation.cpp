#include "report_animation.hpp"

namespace morphogen {

bool write_report_animation(const ExperimentConfig& /*config*/, const Genome& /*genome*/, int /*frames*/,
                            const std::filesystem::path& /*path*/, std::string& why) {
    // LEAD: once app/growth_animation.hpp (branch anim) is merged, replace this body with
    //   write_growth_animation(path, record_growth_frames(config, genome, frames), 0.1);
    //   return true;
    why = "growth animation: this build has no animated glTF writer yet (grow --animate)";
    return false;
}

}  // namespace morphogen
