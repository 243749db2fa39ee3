#pragma once
// Whether this process was started by an MPI launcher (mpirun, srun), read
// from the environment only: plain `morphogen` makes no MPI call at all and
// pays no MPI start-up cost. Works the same whether or not the build has MPI,
// so a build without it can refuse to run as N copies.
#include <optional>
#include <string>

namespace morphogen::cluster {

struct Launch {
    std::string launcher;  // the variable that told us ("OMPI_COMM_WORLD_SIZE=3")
    int size = 1;          // processes in the job, as the launcher says
    int rank = 0;          // this process's rank, as the launcher says (0 if it does not)
};

// Open MPI's OMPI_COMM_WORLD_SIZE/RANK, then PMI(x) (MPICH, Slurm's
// --mpi=pmi2/pmix), then Slurm's step (SLURM_STEP_NUM_TASKS/SLURM_PROCID,
// set by srun for every task, not by sbatch for the batch script itself).
// None: started without a launcher. A malformed value counts as absent.
std::optional<Launch> detect_launch();

// Whether this build has Open MPI (CMake option MORPHOGEN_MPI).
bool built_with_mpi();

}  // namespace morphogen::cluster
