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

    /**
     * @brief Give glibc's malloc back its default policy: blocks of 128 KiB and more in their own
     * mappings, returned to the system when freed, and the top of the heap trimmed above
     * 128 KiB free (mallopt M_MMAP_MAX = 65536, M_TRIM_THRESHOLD = 128 KiB).
     *
     * A static initializer of Debian's libsuperlu_dist.so.8 (loaded with deal.II through PETSc)
     * calls mallopt(M_MMAP_MAX, 0) and mallopt(M_TRIM_THRESHOLD, -1): every allocation then
     * comes from the brk heap and the heap never shrinks, so the large temporaries of each output
     * (about 1 kB per particle) fragmented it and the resident size grew by 0.1–0.2 GB per output
     * on 0.7 M particles while the memory in use stayed the same
     * (doc/benchmarks/performance/README.md, "Memory"). perideal-base calls this function from
     * a static initializer, which runs after those of the libraries it depends on; calling it
     * again is harmless. Returns whether both settings were accepted (false without glibc).
     */
    bool
    restore_allocator_defaults();
  } // namespace MemoryEstimate
} // namespace perideal

#endif
