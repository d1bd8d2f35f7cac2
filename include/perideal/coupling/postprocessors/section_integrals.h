// ---------------------------------------------------------------------
// PeriDeal: the section integrals of the FE physics and the particle model (torsion's torque).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_section_integrals_h
#define perideal_coupling_postprocessors_section_integrals_h

#include <perideal/coupling/postprocessors/postprocessor.h>

namespace perideal
{
  /**
   * @brief The section integrals of a quasi-static state: those of the FE physics
   * (FEPhysics::integral_names(), FERegion::section_integrals(); columns fe_<name>) and of the
   * particles' model (MaterialModel::integral_names(), section_integrals() with the particles'
   * strain energy of the step; columns pd_<name>), e.g. the torque and the strain energy per
   * unit length of torsion. In a coupled problem an integral both regions name is also given
   * as their sum (columns total_<name>): the FE integrand is weighted by 1 - beta and the
   * particles' by beta, so the sum is the integral over the blended body (the torque of the
   * whole section). The final summary prints one line per region and one for the totals.
   * Nothing if neither names an integral, or in explicit runs.
   */
  template <int dim>
  class SectionIntegrals : public Postprocessor<dim>
  {
  public:
    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;
  };
} // namespace perideal

#endif
