// ---------------------------------------------------------------------
// PeriDeal: what the solvers that step through the static solve of the coupling method share.
// ---------------------------------------------------------------------
#include <perideal/coupling/solvers/equilibrium_state.h>

namespace perideal
{
  template <int dim>
  std::string
  condition_names(const CoupledState<dim> &state)
  {
    std::string names;
    for (const auto &c : state.fe().conditions())
      names += (names.empty() ? "" : ", ") + c.name;
    for (const auto &name : state.pd().boundary_conditions().names())
      names += (names.empty() ? "" : ", ") + name;
    return names;
  }

  template <int dim>
  double
  equilibrium_state(CoupledState<dim> &state)
  {
    // The work of the temperature over the step, from the state the loads' work starts from.
    state.accumulate_temperature_work();
    const double pd_energy = state.method().equilibrium_forces(state.U,
                                                               state.u,
                                                               state.fe_equation_load(),
                                                               state.external_force,
                                                               state.residual,
                                                               state.internal_force);

    // The loads that do work: the applied ones, and on prescribed components the support
    // forces (the FE residual K z - F there; minus the internal force on particles).
    const auto &mask = state.fe().prescribed_mask();
    for (unsigned int k = 0; k < state.U.locally_owned_size(); ++k)
      state.fe_load.local_element(k) =
        state.f_ext.local_element(k) + (mask[k] ? state.residual.local_element(k) : 0.);
    state.accumulate_work();
    state.fe_support                  = state.residual;
    state.equilibrium_particle_energy = pd_energy;
    return pd_energy;
  }

  template <int dim>
  void
  check_convection_on_free_particles(const CoupledState<dim> &state, const std::string &solver)
  {
    const auto &conditions = state.pd().boundary_conditions();
    if (!conditions.has_convection())
      return;
    ParticleVector conductance;
    state.pd().particles().reinit_vector(conductance, state.n_components());
    conditions.add_convection_conductance(conductance);
    std::uint64_t n_slaved = 0;
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      n_slaved += (state.motion()[k] == CoupledState<dim>::Motion::slaved &&
                   conductance.local_element(k) > 0.);
    n_slaved = dealii::Utilities::MPI::sum(n_slaved, state.comm());
    AssertThrow(n_slaved == 0,
                dealii::ExcMessage(
                  "A 'convection' condition of <Boundary conditions> acts on " +
                  std::to_string(n_slaved) +
                  " particles slaved to the FE field, where <Solver/Type> = " + solver +
                  " has no matrix term for it; put the convection on the FE boundary (<Finite "
                  "elements/Boundary conditions>, type 'convection') or move its region into the "
                  "PD-only zone (beta = 1)."));
  }

  template std::string
  condition_names(const CoupledState<2> &);
  template std::string
  condition_names(const CoupledState<3> &);
  template double
  equilibrium_state(CoupledState<2> &);
  template double
  equilibrium_state(CoupledState<3> &);
  template void
  check_convection_on_free_particles(const CoupledState<2> &, const std::string &);
  template void
  check_convection_on_free_particles(const CoupledState<3> &, const std::string &);
} // namespace perideal
