// ---------------------------------------------------------------------
// PeriDeal: the wall time of the stages of a run's set-up, for the run summary.
// ---------------------------------------------------------------------
#ifndef perideal_base_setup_times_h
#define perideal_base_setup_times_h

#include <deal.II/base/mpi.h>

#include <chrono>
#include <ctime>
#include <string>

namespace perideal
{
  /**
   * @brief The stages of the set-up whose wall time the run summary prints
   * (doc/benchmarks/performance/README.md, "Set-up that scales").
   */
  enum class SetupStage
  {
    /// The lattice points of the body and their partition (ParticleSystem::generate()).
    lattice,
    /// The bonds: the family of every owned particle (ParticleSystem::find_bonds()).
    neighbor_search,
    /// The surface correction's factors, energy method or stiffness fit
    /// (apply_surface_correction()).
    surface_correction,
    /// The force kernels' lanes and blocks (BondBlocks::reinit()).
    kernel_blocks,
    /// The operator between the FE region and the particles (TransferOperator).
    transfer_operator,
    /// The FE region's mesh, dofs and matrices (FERegion).
    fe_assembly,
    /// The stable time steps' stiffness bounds (MaterialModel::stable_time_step(),
    /// FERegion::stable_time_step()).
    stable_time_step,
    n_stages
  };

  namespace SetupTimes
  {
    /**
     * @brief Adds the wall time and the CPU time of the process (std::clock(): robust to other
     * processes on the same core) between its construction and its destruction to @p stage's
     * totals (nested scopes of different stages count in both; a scope inside one of the same
     * stage adds nothing, the outer one counts its time once).
     */
    class Scope
    {
    public:
      /// Start timing @p stage.
      explicit Scope(const SetupStage stage);
      /// Add the time since the construction to the stage's totals.
      ~Scope();
      Scope(const Scope &) = delete;
      Scope &
      operator=(const Scope &) = delete;

    private:
      const SetupStage                            stage;
      const std::chrono::steady_clock::time_point start;
      const std::clock_t                          start_cpu;
    };

    /**
     * @brief The line of the run summary: each stage's total wall time and CPU time so far
     * [s], the largest over the ranks of @p comm, the stages that took no time left out,
     * after @p title. Collective.
     */
    std::string
    summary(const MPI_Comm comm, const std::string &title = "Set-up time");
  } // namespace SetupTimes
} // namespace perideal

#endif
