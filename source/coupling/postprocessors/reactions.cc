// ---------------------------------------------------------------------
// PeriDeal: the reactions of the boundary conditions and the force balance.
// ---------------------------------------------------------------------
#include <perideal/base/statistics_file.h>
#include <perideal/coupling/postprocessors/reactions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  Reactions<dim>::initialize(const CoupledState<dim> &state)
  {
    const auto modes = state.fe().component_masks();
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
    const FieldLayout &layout        = state.layout();
    const unsigned int nc            = state.n_components();
    const auto        &pd_conditions = state.pd().boundary_conditions();
    const auto        &pd_names      = pd_conditions.names();
    const auto         pd_reactions  = pd_conditions.reactions(state.internal_force);
    const auto        &fe_conditions = state.fe().conditions();
    // The FE region's reactions per component of the layout (its dofs' components).
    const auto fe_reactions = state.fe().reactions(state.fe_support);
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      for (unsigned int j = 0; j < pd_reactions[k].size(); ++j)
        statistics.add_value("reaction_" + pd_names[k] + "_" +
                               layout.name(pd_conditions.reaction_components(k)[j]),
                             pd_reactions[k][j]);
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe_conditions[k].type != Quantity::load)
        for (unsigned int c = 0; c < fe_reactions[k].size(); ++c)
          statistics.add_value("reaction_" + fe_conditions[k].name + "_" + layout.name(c),
                               fe_reactions[k][c]);

    // Quasi-static: per component (rotations aside: their balance involves the moments of the
    // forces), the applied loads against the reactions of the value conditions.
    std::vector<double> applied(nc, 0.), balanced(nc, 0.);
    double              imbalance = 0., balance = 0.;
    // Forces below the solution's accuracy (CoupledState::solution_accuracy()) print as 0.
    const double accuracy = state.solution_accuracy();
    double       floor    = 0.;
    if (data.quasi_static)
      {
        const auto &ps     = state.pd().particles();
        const auto &volume = ps.volumes();
        for (unsigned int k = 0; k < state.f_ext.locally_owned_size(); ++k)
          applied[fe_dof_component[k]] += state.f_ext.local_element(k);
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          for (unsigned int c = 0; c < nc; ++c)
            applied[c] += state.external_force.local_element(i * nc + c) * volume[i];
        Utilities::MPI::sum(applied, state.comm(), applied);
        const auto norm = [&](const std::vector<double>       &values,
                              const std::vector<unsigned int> *components) {
          double sum = 0.;
          for (unsigned int j = 0; j < values.size(); ++j)
            if (layout.kind(components ? (*components)[j] : j) != ComponentKind::rotation)
              sum += values[j] * values[j];
          return std::sqrt(sum);
        };
        double largest = norm(applied, nullptr);
        for (unsigned int k = 0; k < fe_reactions.size(); ++k)
          if (fe_conditions[k].type == Quantity::value)
            {
              for (unsigned int c = 0; c < fe_reactions[k].size(); ++c)
                balanced[c] += fe_reactions[k][c];
              largest = std::max(largest, norm(fe_reactions[k], nullptr));
            }
        const auto held = pd_conditions.names_of(Quantity::value);
        for (unsigned int k = 0; k < pd_reactions.size(); ++k)
          if (std::find(held.begin(), held.end(), pd_names[k]) != held.end())
            {
              const auto &components = pd_conditions.reaction_components(k);
              for (unsigned int j = 0; j < components.size(); ++j)
                balanced[components[j]] += pd_reactions[k][j];
              largest = std::max(largest, norm(pd_reactions[k], &components));
            }
        for (unsigned int c = 0; c < nc; ++c)
          balanced[c] += applied[c];
        // Relative to the largest force involved; loads below 1e-10 of the internal-force scale
        // (a rigid motion) are round-off and give no ratio.
        state.U.update_ghost_values();
        const double scale = state.fe_force_scale();
        imbalance          = norm(balanced, nullptr);
        balance            = largest > 1e-10 * scale ? imbalance / largest : 0.;
        // The round-off and the solver's error of a nodal force are relative to the internal
        // forces that sum to it (a backward-stable solve leaves |b - K U| of order eps |K| |U|),
        // not to the net load: the floor is relative to the internal-force scale too. A rigid
        // motion (no load, round-off reactions), a thermal strain (a free expansion) and a body
        // cut almost through (a small load on large internal forces) print the same on every
        // number of ranks.
        floor = accuracy * std::max(largest, scale);
        for (unsigned int c = 0; c < nc; ++c)
          if (layout.kind(c) != ComponentKind::rotation)
            statistics.add_value("applied_load_" + layout.name(c), applied[c]);
        statistics.add_value("force_balance", balance);
      }

    if (!state.is_root() || !data.final_row)
      return;
    std::ostream &log   = state.log();
    const auto    flags = log.flags();
    log << std::scientific << std::setprecision(6);
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      {
        // Forces [N], moments [N m]; a 'value' condition on a micropolar field reports both; the
        // heat flow [W] into the held particles of a temperature.
        unsigned int n_rotations = 0;
        for (const unsigned int c : pd_conditions.reaction_components(k))
          n_rotations += (layout.kind(c) == ComponentKind::rotation);
        log << "Reaction " << pd_names[k] << ": ";
        print_without_round_off(log, pd_reactions[k], floor);
        log << (layout.has_temperature()              ? " W\n" :
                n_rotations == 0                      ? " N\n" :
                n_rotations == pd_reactions[k].size() ? " N m\n" :
                                                        " N (N m for rotations)\n");
      }
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe_conditions[k].type != Quantity::load)
        {
          log << "Reaction " << fe_conditions[k].name << ": ";
          print_without_round_off(log, fe_reactions[k], floor);
          log << (layout.has_temperature() ? " W\n" : " N\n");
        }
    if (data.quasi_static)
      {
        std::vector<double> applied_forces;
        for (unsigned int c = 0; c < nc; ++c)
          if (layout.kind(c) != ComponentKind::rotation)
            applied_forces.push_back(applied[c]);
        // A temperature's loads and reactions are heat flows [W].
        const bool        heat         = layout.has_temperature();
        const std::string unit         = heat ? " W" : " N";
        const std::string balance_name = heat ? "Heat balance" : "Force balance";
        const std::string largest      = heat ? "the largest heat flow" : "the largest force";
        log << "Applied load: ";
        print_without_round_off(log, applied_forces, floor);
        log << unit << "\n";
        if (imbalance <= floor)
          log << balance_name << ": |applied + reactions| below the accuracy of the solution, "
              << accuracy << " of " << largest << "\n";
        else // to the accuracy, as the reactions
          log << balance_name << ": |applied + reactions| = " << to_accuracy(imbalance, floor)
              << unit << ", relative to " << largest << ": " << to_accuracy(balance, accuracy)
              << "\n";
      }
    log << std::flush;
    log.flags(flags);
  }

  template class Reactions<2>;
  template class Reactions<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(
  perideal::Reactions,
  "reactions",
  "the reactions per condition and component; quasi-static: the applied load and the force balance.")
