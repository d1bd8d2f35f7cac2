// ---------------------------------------------------------------------
// PeriDeal: the reactions of the boundary conditions and the force balance.
// ---------------------------------------------------------------------
#include <perideal/base/statistics_file.h>
#include <perideal/coupling/postprocessors/reactions.h>

#include <algorithm>
#include <iomanip>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /// "x", "y" or "z".
    std::string
    axis_name(const unsigned int d)
    {
      return std::string(1, "xyz"[d]);
    }
  } // namespace

  template <int dim>
  void
  Reactions<dim>::initialize(const CoupledState<dim> &state)
  {
    const auto modes = state.fe.component_masks();
    fe_dof_component.assign(state.U.locally_owned_size(), 0);
    for (unsigned int d = 0; d < modes.size(); ++d)
      for (unsigned int k = 0; k < fe_dof_component.size(); ++k)
        if (modes[d][k])
          fe_dof_component[k] = d;
  }

  template <int dim>
  void
  Reactions<dim>::execute(const CoupledState<dim> &state,
                          const StepData          &data,
                          StatisticsFile          &statistics)
  {
    if (!data.write_statistics)
      return;
    using FEType              = typename FESolid<dim>::ConditionType;
    const auto &fe_conditions = state.fe.conditions();
    const auto &pd_conditions = state.pd.boundary_conditions();
    const auto  fe_reactions  = state.fe.reactions(state.fe_support);
    const auto  pd_reactions  = pd_conditions.reactions(state.internal_force);
    const auto &pd_names      = pd_conditions.names();
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        statistics.add_value("reaction_" + pd_names[k] + "_" + axis_name(d), pd_reactions[k][d]);
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe_conditions[k].type != FEType::traction)
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add_value("reaction_" + fe_conditions[k].name + "_" + axis_name(d),
                               fe_reactions[k][d]);

    // Quasi-static: the applied loads against the reactions of the displacement conditions.
    Tensor<1, dim> applied, reaction_sum;
    double         imbalance = 0., balance = 0.;
    if (data.quasi_static)
      {
        const auto        &ps     = state.pd.particles();
        const auto        &volume = ps.volumes();
        const unsigned int nc     = state.n_components();
        for (unsigned int k = 0; k < state.f_ext.locally_owned_size(); ++k)
          applied[fe_dof_component[k]] += state.f_ext.local_element(k);
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            applied[d] += state.external_force.local_element(i * nc + d) * volume[i];
        applied = Utilities::MPI::sum(applied, state.comm);
        const auto pd_types =
          pd_conditions.names_of_type(BoundaryConditions<dim>::Type::displacement);
        double largest = applied.norm();
        for (unsigned int k = 0; k < fe_reactions.size(); ++k)
          if (fe_conditions[k].type == FEType::displacement)
            {
              reaction_sum += fe_reactions[k];
              largest = std::max(largest, fe_reactions[k].norm());
            }
        for (unsigned int k = 0; k < pd_reactions.size(); ++k)
          if (std::find(pd_types.begin(), pd_types.end(), pd_names[k]) != pd_types.end())
            {
              reaction_sum += pd_reactions[k];
              largest = std::max(largest, pd_reactions[k].norm());
            }
        // Relative to the largest force involved; loads below 1e-10 of the internal-force scale
        // (a rigid motion) are round-off and give no ratio.
        state.U.update_ghost_values();
        const double scale = state.fe_force_scale();
        imbalance          = (applied + reaction_sum).norm();
        balance            = largest > 1e-10 * scale ? imbalance / largest : 0.;
        for (unsigned int d = 0; d < dim; ++d)
          statistics.add_value("applied_load_" + axis_name(d), applied[d]);
        statistics.add_value("force_balance", balance);
      }

    if (!state.is_root || !data.final_row)
      return;
    std::ostream &log   = state.log;
    const auto    flags = log.flags();
    log << std::scientific << std::setprecision(6);
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      log << "Reaction " << pd_names[k] << ": " << without_round_off(pd_reactions[k]) << " N\n";
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe_conditions[k].type != FEType::traction)
        log << "Reaction " << fe_conditions[k].name << ": " << without_round_off(fe_reactions[k])
            << " N\n";
    if (data.quasi_static)
      log << "Applied load: " << without_round_off(applied) << " N\n"
          << "Force balance: |applied + reactions| = " << imbalance
          << " N, relative to the largest force: " << balance << "\n";
    log << std::flush;
    log.flags(flags);
  }

  template class Reactions<2>;
  template class Reactions<3>;
} // namespace perideal
