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
    std::ostream &log   = state.log();
    const auto    flags = log.flags();
    log << std::scientific << std::setprecision(6);
    const auto report = [&](const std::string              &region,
                            const std::vector<std::string> &names,
                            const std::vector<double>      &values) {
      for (unsigned int k = 0; k < names.size(); ++k)
        statistics.add_value(region + "_" + names[k], values[k]);
      if (!state.is_root() || !data.final_row || names.empty())
        return;
      log << "Section integrals (" << region << "):";
      for (unsigned int k = 0; k < names.size(); ++k)
        log << (k == 0 ? " " : ", ") << names[k] << " = " << values[k];
      log << "\n";
    };
    std::vector<std::string> fe_names, pd_names;
    std::vector<double>      fe_values, pd_values;
    if (state.fe().n_dofs() > 0)
      {
        fe_names  = state.fe().physics().integral_names();
        fe_values = state.fe().section_integrals(state.U);
        report("fe", fe_names, fe_values);
      }
    if (state.has_particles())
      {
        const auto &model = state.pd().material();
        state.u.update_ghost_values();
        pd_names  = model.integral_names();
        pd_values = model.section_integrals(state.pd().particles(), state.u, data.pd_energy);
        report("pd", pd_names, pd_values);
      }
    // A coupled body: the FE integrands carry 1 - beta, the particles beta, so an integral both
    // regions name is the body's as their sum.
    std::vector<std::string> names;
    std::vector<double>      totals;
    for (unsigned int k = 0; k < fe_names.size(); ++k)
      for (unsigned int l = 0; l < pd_names.size(); ++l)
        if (fe_names[k] == pd_names[l])
          {
            names.push_back(fe_names[k]);
            totals.push_back(fe_values[k] + pd_values[l]);
          }
    report("total", names, totals);
    log.flags(flags);
  }

  template class SectionIntegrals<2>;
  template class SectionIntegrals<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(
  perideal::SectionIntegrals,
  "section integrals",
  "quasi-static: the section integrals of the FE physics and the particle model (the torque of torsion).")
