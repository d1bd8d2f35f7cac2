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
   * unit length of torsion. The final summary prints one line per region. Nothing if neither
   * names an integral, or in explicit runs.
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
