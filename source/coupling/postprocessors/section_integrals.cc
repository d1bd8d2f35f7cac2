// ---------------------------------------------------------------------
// PeriDeal: the section integrals of the FE physics and the particle model (torsion's torque).
// ---------------------------------------------------------------------
#include <perideal/coupling/postprocessors/section_integrals.h>

#include <iomanip>

namespace perideal
{
  template <int dim>
  void
  SectionIntegrals<dim>::execute(const CoupledState<dim> &state,
                                 const StepData          &data,
                                 StatisticsFile          &statistics)
  {
    if (!data.write_statistics || !data.quasi_static)
      return;
    std::ostream &log   = state.log;
    const auto    flags = log.flags();
    log << std::scientific << std::setprecision(6);
    const auto report = [&](const std::string              &region,
                            const std::vector<std::string> &names,
                            const std::vector<double>      &values) {
      for (unsigned int k = 0; k < names.size(); ++k)
        statistics.add_value(region + "_" + names[k], values[k]);
      if (!state.is_root || !data.final_row || names.empty())
        return;
      log << "Section integrals (" << region << "):";
      for (unsigned int k = 0; k < names.size(); ++k)
        log << (k == 0 ? " " : ", ") << names[k] << " = " << values[k];
      log << "\n";
    };
    if (state.fe.n_dofs() > 0)
      report("fe", state.fe.physics().integral_names(), state.fe.section_integrals(state.U));
    if (state.has_particles())
      {
        const auto &model = state.pd.material();
        state.u.update_ghost_values();
        report("pd",
               model.integral_names(),
               model.section_integrals(state.pd.particles(), state.u, data.pd_energy));
      }
    log.flags(flags);
  }

  template class SectionIntegrals<2>;
  template class SectionIntegrals<3>;
} // namespace perideal
