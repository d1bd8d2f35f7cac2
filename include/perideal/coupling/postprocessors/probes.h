// ---------------------------------------------------------------------
// PeriDeal: the displacement of the particles nearest to given points.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_probes_h
#define perideal_coupling_postprocessors_probes_h

#include <deal.II/base/point.h>

#include <perideal/coupling/postprocessors/postprocessor.h>

#include <vector>

namespace perideal
{
  /**
   * @brief <Output/Probe points>: the field of the particle nearest to each point, in the
   * statistics columns probe<k>_<component> (k from 1, SI units) of every row, and in the final
   * summary in micrometres and microradians (the values application tests compare must lie
   * above numdiff's absolute tolerance).
   *
   * The particle is chosen once (initialize()): the nearest, ties going to the
   * lexicographically smallest position, so the choice does not depend on the partition; a
   * point without a particle within one lattice spacing stops the run, naming the entry.
   */
  template <int dim>
  class Probes : public Postprocessor<dim>
  {
  public:
    void
    initialize(const CoupledState<dim> &state) override;

    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;

  private:
    /// Per probe: the position of its particle, and the particle's local index on the rank
    /// that owns it (numbers::invalid_unsigned_int elsewhere).
    std::vector<dealii::Point<dim>> probe_particles;
    std::vector<unsigned int>       probe_local_index;
  };
} // namespace perideal

#endif
