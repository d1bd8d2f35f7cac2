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
    for (const auto &c : state.fe.conditions())
      names += (names.empty() ? "" : ", ") + c.name;
    for (const auto &name : state.pd.boundary_conditions().names())
      names += (names.empty() ? "" : ", ") + name;
    return names;
  }

  template <int dim>
  double
  equilibrium_state(CoupledState<dim> &state)
  {
    const double pd_energy = state.method.equilibrium_forces(state.U,
                                                             state.u,
                                                             state.f_ext,
                                                             state.external_force,
                                                             state.residual,
                                                             state.internal_force);

    // The loads that do work: the applied ones, and on prescribed components the support
    // forces (the FE residual K z - F there; minus the internal force on particles).
    const auto &mask = state.fe.prescribed_mask();
    for (unsigned int k = 0; k < state.U.locally_owned_size(); ++k)
      state.fe_load.local_element(k) =
        state.f_ext.local_element(k) + (mask[k] ? state.residual.local_element(k) : 0.);
    state.accumulate_work();
    state.fe_support = state.residual;
    return pd_energy;
  }

  template std::string
  condition_names(const CoupledState<2> &);
  template std::string
  condition_names(const CoupledState<3> &);
  template double
  equilibrium_state(CoupledState<2> &);
  template double
  equilibrium_state(CoupledState<3> &);
} // namespace perideal
