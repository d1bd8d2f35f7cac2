// ---------------------------------------------------------------------
// PeriDeal: what the solvers that step through the static solve of the coupling method share.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_equilibrium_state_h
#define perideal_coupling_solvers_equilibrium_state_h

#include <perideal/coupling/coupled_state.h>

#include <string>

namespace perideal
{
  /**
   * @brief The names of the FE and the particle boundary conditions of @p state, separated by
   * ', ' (for the messages of the static solves).
   */
  template <int dim>
  std::string
  condition_names(const CoupledState<dim> &state);

  /**
   * @brief After an equilibrium solve of the coupling method under the loads state.f_ext and
   * state.external_force: the method's forces of the state (CouplingMethod::
   * equilibrium_forces(): state.residual, the reactions, state.internal_force,
   * CoupledState::fe_support), the work of the loads and supports and that of a changing
   * temperature (CoupledState::accumulate_temperature_work()); returns the particles' strain
   * energy. Used by the load stepping and the implicit time steps. Collective.
   */
  template <int dim>
  double
  equilibrium_state(CoupledState<dim> &state);

  /**
   * @brief Stop, naming <Solver/Type> = @p solver, if a particle 'convection' condition acts on
   * particles slaved to the FE field: the linear solves hold its conductance in the diagonal of
   * the free particle components only (CouplingMethod::set_equilibrium_diagonal()). Collective.
   */
  template <int dim>
  void
  check_convection_on_free_particles(const CoupledState<dim> &state, const std::string &solver);
} // namespace perideal

#endif
