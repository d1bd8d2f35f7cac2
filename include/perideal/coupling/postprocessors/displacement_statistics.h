// ---------------------------------------------------------------------
// PeriDeal: broken bonds and the largest displacements of a run.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_displacement_statistics_h
#define perideal_coupling_postprocessors_displacement_statistics_h

#include <perideal/coupling/postprocessors/postprocessor.h>

namespace perideal
{
  /**
   * @brief The number of broken bonds and the largest particle displacement (if there are
   * particles), the largest FE nodal displacement component (if there are FE unknowns).
   * Columns broken_bonds, max_particle_displacement, max_fe_displacement.
   */
  template <int dim>
  class DisplacementStatistics : public Postprocessor<dim>
  {
  public:
    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;
  };
} // namespace perideal

#endif
