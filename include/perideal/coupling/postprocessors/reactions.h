// ---------------------------------------------------------------------
// PeriDeal: the reactions of the boundary conditions and the force balance.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_postprocessors_reactions_h
#define perideal_coupling_postprocessors_reactions_h

#include <perideal/coupling/postprocessors/postprocessor.h>

#include <vector>

namespace perideal
{
  /**
   * @brief The reaction of every particle boundary condition (the sum of V_i times the internal
   * force density over its particles) and of every FE displacement or velocity condition (the
   * force its supports exert, CoupledState::fe_support); quasi-static runs also the applied load
   * (FE loads and particle force densities) and the force balance |applied + reactions of the
   * displacement conditions| relative to the largest force involved. Columns
   * reaction_<condition>_<axis>, applied_load_<axis>, force_balance.
   */
  template <int dim>
  class Reactions : public Postprocessor<dim>
  {
  public:
    void
    initialize(const CoupledState<dim> &state) override;

    void
    execute(const CoupledState<dim> &state,
            const StepData          &data,
            StatisticsFile          &statistics) override;

  private:
    /// The component (axis) of each owned FE dof.
    std::vector<unsigned int> fe_dof_component;
  };
} // namespace perideal

#endif
