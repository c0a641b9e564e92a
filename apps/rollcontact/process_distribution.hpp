#pragma once
// The processes of this run for batch::Distribution: the ranks of the MPI job when the CLI was
// built with MPI and started by mpirun/srun, otherwise this one process. Made first in main()
// (MPI_Init may edit argc/argv) and destroyed last (MPI_Finalize).

#include <memory>

#include "batch/distribution.hpp"

namespace rollcontact::cli {

std::unique_ptr<batch::Distribution> make_process_distribution(int& argc, char**& argv);

/// True when the environment says an MPI launcher started this process (Open MPI, PMIx, PMI).
bool launched_by_mpi();

}  // namespace rollcontact::cli
