// ---------------------------------------------------------------------
// PeriDeal: the wall time of the stages of a run's set-up, for the run summary.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/base/setup_times.h>

#include <array>
#include <ctime>
#include <sstream>

namespace perideal
{
  namespace SetupTimes
  {
    namespace
    {
      constexpr unsigned int n_stages = static_cast<unsigned int>(SetupStage::n_stages);

      /// The totals of this process [s]: wall time, then CPU time.
      std::array<double, 2 * n_stages> totals{};
      /// The scopes of each stage open now: only the outermost adds its time (FERegion::
      /// reweight() times its assemble_matrices() too, which counted twice before).
      std::array<unsigned int, n_stages> open_scopes{};

      const char *
      name(const unsigned int stage)
      {
        static const char *const names[n_stages] = {"lattice",
                                                    "neighbour search",
                                                    "surface correction",
                                                    "kernel blocks",
                                                    "transfer operator",
                                                    "FE assembly",
                                                    "stable time step"};
        return names[stage];
      }
    } // namespace

    Scope::Scope(const SetupStage stage)
      : stage(stage)
      , start(std::chrono::steady_clock::now())
      , start_cpu(std::clock())
    {
      ++open_scopes[static_cast<unsigned int>(stage)];
    }

    Scope::~Scope()
    {
      const auto s = static_cast<unsigned int>(stage);
      if (--open_scopes[s] > 0)
        return;
      totals[s] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      totals[n_stages + s] += double(std::clock() - start_cpu) / CLOCKS_PER_SEC;
    }

    std::string
    summary(const MPI_Comm comm, const std::string &title)
    {
      std::array<double, 2 * n_stages> largest{};
      const int                        ierr =
        MPI_Allreduce(totals.data(), largest.data(), 2 * n_stages, MPI_DOUBLE, MPI_MAX, comm);
      AssertThrowMPI(ierr);
      std::ostringstream line;
      line.precision(3);
      line << title << " [s], wall (CPU):";
      const char *separator = " ";
      for (unsigned int s = 0; s < n_stages; ++s)
        if (largest[s] > 0.)
          {
            line << separator << name(s) << " " << largest[s] << " (" << largest[n_stages + s]
                 << ")";
            separator = ", ";
          }
      return line.str();
    }
  } // namespace SetupTimes
} // namespace perideal
