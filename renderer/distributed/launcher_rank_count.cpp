#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "renderer/distributed/render_ranks.h"

namespace isotrace {

int launcher_rank_count() {
    // Open MPI's mpirun, Hydra/PMI launchers (MPICH, Intel MPI) and Slurm's srun (whatever the MPI plugin).
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"}) {
        const char* value = std::getenv(variable);
        if (!value) continue;
        try {
            return std::max(1, std::stoi(value));
        } catch (const std::logic_error&) {  // not a number: not a launcher we know
        }
    }
    return 1;
}

}  // namespace isotrace
