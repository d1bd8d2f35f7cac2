// ---------------------------------------------------------------------
// PeriDeal: broken bonds and the largest displacements of a run.
// ---------------------------------------------------------------------
#include <perideal/coupling/postprocessors/displacement_statistics.h>
#include <perideal/pd/damage_model.h>

#include <iomanip>
#include <string>

namespace perideal
{
  template <int dim>
  void
  DisplacementStatistics<dim>::execute(const CoupledState<dim> &state,
                                       const StepData          &data,
                                       StatisticsFile          &statistics)
  {
    if (!data.write_statistics)
      return;
    const auto   broken    = n_broken_bonds(state.pd().particles());
    const double max_u     = state.max_particle_displacement();
    const double max_fe_u  = state.U.linfty_norm();
    const bool   particles = state.has_particles(), fe = state.fe().n_dofs() > 0;
    // A temperature field: the largest |T| [K] under its own name.
    const bool        temperature = state.layout().has_temperature();
    const std::string name        = temperature ? "temperature" : "displacement";
    const std::string unit        = temperature ? " K" : " m";
    if (particles)
      {
        statistics.add_value("broken_bonds", broken);
        statistics.add_value("max_particle_" + name, max_u);
      }
    if (fe)
      statistics.add_value("max_fe_" + name, max_fe_u);
    if (!state.is_root() || !data.final_row)
      return;
    std::ostream &log   = state.log();
    const auto    flags = log.flags();
    log << std::scientific << std::setprecision(6);
    if (particles)
      log << "Broken bonds: " << broken << "\n"
          << "Max particle " << name << ": " << max_u << unit << "\n";
    if (fe)
      log << "Max FE " << name << ": " << max_fe_u << unit << " (largest nodal component)\n";
    log.flags(flags);
  }

  template class DisplacementStatistics<2>;
  template class DisplacementStatistics<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(perideal::DisplacementStatistics,
                                "displacement statistics",
                                "the broken bonds and the largest displacements.")
