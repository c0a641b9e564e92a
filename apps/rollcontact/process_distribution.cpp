#include "process_distribution.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "rollcontact/errors.hpp"

#ifdef ROLLCONTACT_HAVE_MPI
#include <dlfcn.h>

#include <cstdio>
#include <filesystem>
#endif

namespace rollcontact::cli {

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

#ifdef ROLLCONTACT_HAVE_MPI

namespace {

/// The MPI plugin (rollcontact_mpi.so) next to the executable (build tree) or in the installed
/// library folder; null with `error` set when neither loads.
void* load_mpi_plugin(std::string& error) {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::filesystem::path dir = ec ? std::filesystem::path(".") : exe.parent_path();
  for (const std::filesystem::path& candidate :
       {dir / "rollcontact_mpi.so", dir / ROLLCONTACT_MPI_PLUGIN_INSTALLED}) {
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (handle != nullptr) return handle;
    error += std::string(error.empty() ? "" : "; ") + dlerror();
  }
  return nullptr;
}

/// MPI_Init through the plugin; exits (status 3) when it cannot be loaded, since running every
/// case on every rank would write the same files from all of them.
std::unique_ptr<batch::Distribution> mpi_distribution(int& argc, char**& argv) {
  std::string error;
  void* plugin = load_mpi_plugin(error);
  using Make = batch::Distribution* (*)(int*, char***);
  Make make = plugin == nullptr
                  ? nullptr
                  : reinterpret_cast<Make>(dlsym(plugin, "rollcontact_mpi_distribution"));
  if (make == nullptr) {
    std::fprintf(stderr,
                 "rollcontact: internal error: launched by mpirun, but the MPI module "
                 "cannot be loaded: %s\n",
                 plugin == nullptr ? error.c_str() : dlerror());
    std::exit(3);
  }
  return std::unique_ptr<batch::Distribution>(make(&argc, &argv));
}

}  // namespace

#endif

std::unique_ptr<batch::Distribution> make_process_distribution(int& argc, char**& argv) {
#ifdef ROLLCONTACT_HAVE_MPI
  if (launched_by_mpi()) return mpi_distribution(argc, argv);
#endif
  (void)argc;
  (void)argv;
  return std::make_unique<batch::SerialDistribution>();
}

}  // namespace rollcontact::cli
