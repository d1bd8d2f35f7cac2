// ---------------------------------------------------------------------
// PeriDeal: whether the bonds of a lattice fit in the memory of the nodes of a run.
// ---------------------------------------------------------------------
#ifndef perideal_base_memory_estimate_h
#define perideal_base_memory_estimate_h

#include <deal.II/base/mpi.h>

#include <cstdint>
#include <string>

namespace perideal
{
  namespace MemoryEstimate
  {
    /**
     * @brief The bytes per bond of the leanest run measured, explicit PMB at its peak
     * (doc/benchmarks/performance/README.md, "Memory"): every other model and solver keeps more
     * per bond.
     */
    constexpr double bytes_per_bond = 38.;

    /**
     * @brief The memory the nodes of @p comm have available [B]: MemAvailable of /proc/meminfo,
     * read by one rank per node (MPI_COMM_TYPE_SHARED) and summed; 0 where it cannot be read.
     * Collective.
     */
    double
    available_memory(const MPI_Comm comm);

    /**
     * @brief The warning for @p n_bonds bonds of the lattice of spacing @p spacing when their
     * estimated memory (bytes_per_bond each) exceeds @p available bytes; empty when they fit or
     * when @p available is 0 (unknown). It names <Discretization/Lattice spacing> and what to
     * change.
     */
    std::string
    warning(const double n_bonds, const double available, const double spacing);

    /**
     * @brief The run summary's line of the peak memory: the peak resident size (VmHWM) summed
     * over the ranks of @p comm in MiB and, with bonds, the part above the resident size
     * @p resident_before [kiB, this rank's] the process had before the particles were
     * generated, per bond and per particle: "Peak memory: X MiB, Y B per bond, Z B per
     * particle (...)". Collective.
     */
    std::string
    peak_summary(const MPI_Comm      comm,
                 const std::uint64_t resident_before,
                 const std::uint64_t n_bonds,
                 const std::uint64_t n_particles);
  } // namespace MemoryEstimate
} // namespace perideal

#endif
