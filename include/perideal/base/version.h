// ---------------------------------------------------------------------
// PeriDeal: the line that names this build.
// ---------------------------------------------------------------------
#ifndef perideal_base_version_h
#define perideal_base_version_h

#include <string>

namespace perideal
{
  /**
   * @brief One line naming the build: the PeriDeal version, its git revision (read at configure
   * time, "unknown" outside a git clone) and the versions of deal.II, Trilinos and the MPI
   * library, e.g. "PeriDeal 0.1.0 (git 46c2630a1b2c), deal.II 9.4.2, Trilinos 13.2.0, MPI 3.1
   * (Open MPI v4.1.4)". perideal-solid --version prints it, and every run's log starts with it.
   * Callable before MPI_Init.
   */
  std::string
  version_line();
} // namespace perideal

#endif
