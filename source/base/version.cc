// ---------------------------------------------------------------------
// PeriDeal: the line that names this build.
// ---------------------------------------------------------------------
#include <deal.II/base/config.h>

#include <perideal/base/revision.h>
#include <perideal/base/version.h>

#include <string>

#include <mpi.h>

namespace perideal
{
  std::string
  version_line()
  {
    // The MPI standard and the library's name up to its first comma ("Open MPI v4.1.4, package:
    // ..."); both calls are allowed before MPI_Init.
    int major = 0, minor = 0;
    MPI_Get_version(&major, &minor);
    char library[MPI_MAX_LIBRARY_VERSION_STRING];
    int  length = 0;
    MPI_Get_library_version(library, &length);
    std::string mpi_library(library, length);
    mpi_library = mpi_library.substr(0, mpi_library.find_first_of(",\n"));
    return std::string("PeriDeal ") + PERIDEAL_VERSION + " (git " + PERIDEAL_GIT_REVISION +
           "), deal.II " + DEAL_II_PACKAGE_VERSION + ", Trilinos " +
           std::to_string(DEAL_II_TRILINOS_VERSION_MAJOR) + "." +
           std::to_string(DEAL_II_TRILINOS_VERSION_MINOR) + "." +
           std::to_string(DEAL_II_TRILINOS_VERSION_SUBMINOR) + ", MPI " + std::to_string(major) +
           "." + std::to_string(minor) + " (" + mpi_library + ")";
  }
} // namespace perideal
