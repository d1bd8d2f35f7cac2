// ---------------------------------------------------------------------
// PeriDeal: whether the bonds of a lattice fit in the memory of the nodes of a run.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/memory_estimate.h>
#include <perideal/base/parameter_utilities.h>

#include <fstream>
#include <sstream>

#ifdef __GLIBC__
#  include <malloc.h>
#endif

namespace perideal
{
  namespace MemoryEstimate
  {
    namespace
    {
      // MemAvailable of /proc/meminfo [B]; 0 if the file or the line is missing.
      double
      node_available_memory()
      {
        std::ifstream in("/proc/meminfo");
        std::string   key, unit;
        double        value = 0.;
        while (in >> key >> value >> unit)
          if (key == "MemAvailable:")
            return value * 1024.;
        return 0.;
      }

      std::string
      gigabytes(const double bytes)
      {
        std::ostringstream text;
        text.precision(3);
        text << bytes / 1e9 << " GB";
        return text.str();
      }
    } // namespace

    double
    available_memory(const MPI_Comm comm)
    {
      MPI_Comm  node;
      const int ierr = MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
      AssertThrowMPI(ierr);
      const bool first_on_node = dealii::Utilities::MPI::this_mpi_process(node) == 0;
      dealii::Utilities::MPI::free_communicator(node);
      const double mine = first_on_node ? node_available_memory() : 0.;
      // Unknown on one node: unknown for the run.
      if (dealii::Utilities::MPI::min(first_on_node ? mine : 1., comm) == 0.)
        return 0.;
      return dealii::Utilities::MPI::sum(mine, comm);
    }

    std::string
    warning(const double n_bonds, const double available, const double spacing)
    {
      const double needed = n_bonds * bytes_per_bond;
      if (available == 0. || needed <= available)
        return "";
      std::ostringstream text;
      text.precision(3);
      text << "Warning: the lattice of <Discretization/Lattice spacing> = "
           << ParameterUtilities::format_number(spacing) << " m has about " << n_bonds
           << " bonds (half an interior particle's family each), about " << gigabytes(needed)
           << " at " << bytes_per_bond
           << " B per bond (explicit PMB, the leanest run measured; other models and solvers "
              "keep more), above the "
           << gigabytes(available)
           << " available on the nodes of this run. It may fail for lack of memory: raise "
              "<Discretization/Lattice spacing>, make the PD region smaller (a coupled run, an "
              "adaptive PD region), or run on more nodes.";
      return text.str();
    }

    std::string
    peak_summary(const MPI_Comm      comm,
                 const std::uint64_t resident_before,
                 const std::uint64_t n_bonds,
                 const std::uint64_t n_particles)
    {
      dealii::Utilities::System::MemoryStats memory;
      dealii::Utilities::System::get_memory_stats(memory);
      const double peak  = dealii::Utilities::MPI::sum(static_cast<double>(memory.VmHWM), comm);
      const double above = peak - dealii::Utilities::MPI::sum(double(resident_before), comm);
      std::ostringstream line;
      line << "Peak memory: " << peak / 1024. << " MiB";
      if (n_bonds > 0)
        line << ", " << 1024. * above / double(n_bonds) << " B per bond, "
             << 1024. * above / double(n_particles) << " B per particle (resident, summed over "
             << "the ranks; per bond and particle the part above the " << (peak - above) / 1024.
             << " MiB before the particles)";
      else
        line << " (resident, summed over the ranks)";
      return line.str();
    }

    bool
    restore_allocator_defaults()
    {
#ifdef __GLIBC__
      // glibc's DEFAULT_MMAP_MAX and DEFAULT_TRIM_THRESHOLD (malloc/malloc.c). Setting them
      // fixes the mmap threshold at its default of 128 KiB (no dynamic threshold), as it already
      // is after the calls this undoes.
      const bool mmap_ok = mallopt(M_MMAP_MAX, 65536) == 1;
      const bool trim_ok = mallopt(M_TRIM_THRESHOLD, 128 * 1024) == 1;
      return mmap_ok && trim_ok;
#else
      return false;
#endif
    }

    namespace
    {
      // Runs when perideal-base is loaded, after the static initializers of deal.II's
      // dependencies (libsuperlu_dist among them): see restore_allocator_defaults().
      const bool allocator_defaults_restored = restore_allocator_defaults();
    } // namespace
  }   // namespace MemoryEstimate
} // namespace perideal
