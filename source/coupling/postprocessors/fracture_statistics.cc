// ---------------------------------------------------------------------
// PeriDeal: the load, load-point displacement and crack length of quasi-static runs.
// ---------------------------------------------------------------------
#include <perideal/base/statistics_file.h>
#include <perideal/coupling/postprocessors/fracture_statistics.h>

#include <iomanip>

namespace perideal
{
  template <int dim>
  void
  FractureStatistics<dim>::set_inputs(const PostprocessorInputs<dim> &inputs)
  {
    control = inputs.control;
  }

  template <int dim>
  void
  FractureStatistics<dim>::initialize(const CoupledState<dim> &state)
  {
    if (state.settings().solver_type != SolverType::explicit_dynamics &&
        state.settings().solver_type != SolverType::implicit)
      measures.initialize(state, control);
  }

  template <int dim>
  void
  FractureStatistics<dim>::execute(const CoupledState<dim> &state,
                                   const StepData          &data,
                                   StatisticsFile          &statistics)
  {
    if (!data.quasi_static || !data.write_statistics || !measures.has_load_point())
      return;
    const auto values = measures.measure(state);
    statistics.add_value("load", values.load);
    statistics.add_value("load_point_displacement", values.displacement);
    if (state.pd().has_body())
      statistics.add_value("crack_length", values.crack_length);
    if (state.is_root() && data.final_row)
      {
        const auto flags = state.log().flags();
        state.log() << std::scientific << std::setprecision(6) << "Load point "
                    << control.load_point << " (" << control.load_component << "): load "
                    << values.load << " N, displacement " << values.displacement << " m\n";
        if (state.pd().has_body())
          state.log() << "Crack length measure: " << values.crack_length
                      << (dim == 2 ? " m\n" : " m^2\n");
        state.log() << std::flush;
        state.log().flags(flags);
      }
  }

  template class FractureStatistics<2>;
  template class FractureStatistics<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(
  perideal::FractureStatistics,
  "fracture statistics",
  "quasi-static runs with a <Solver/Control/Load point>: columns load, load_point_displacement, crack_length.")
