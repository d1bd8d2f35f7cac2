// ---------------------------------------------------------------------
// PeriDeal: the ordered set of postprocessors a run executes.
// ---------------------------------------------------------------------
#include <perideal/coupling/postprocessors/postprocessor.h>

#include <filesystem>
#include <iomanip>

namespace perideal
{
  template <int dim>
  Postprocessors<dim>::Postprocessors(
    std::vector<std::unique_ptr<Postprocessor<dim>>> postprocessors)
    : postprocessors(std::move(postprocessors))
  {}

  template <int dim>
  void
  Postprocessors<dim>::initialize(const CoupledState<dim> &state)
  {
    for (const auto &postprocessor : postprocessors)
      postprocessor->initialize(state);
  }

  template <int dim>
  void
  Postprocessors<dim>::execute(const CoupledState<dim> &state, const StepData &data)
  {
    if (!statistics)
      {
        if (state.is_root)
          std::filesystem::create_directories(state.settings.output_directory);
        statistics =
          std::make_unique<StatisticsFile>(state.comm,
                                           state.settings.output_directory + "/statistics.csv");
      }
    if (data.write_statistics)
      {
        statistics->add_value("step", data.step);
        statistics->add_value("time", data.time);
        if (data.quasi_static)
          statistics->add_value("iterations", data.iterations);
      }
    if (data.final_row && state.is_root)
      {
        const auto flags = state.log.flags();
        state.log << std::scientific << std::setprecision(6);
        if (data.quasi_static)
          state.log << "Load factor: " << data.time << "\n";
        else
          state.log << "Final time: " << data.time << " s\n";
        state.log.flags(flags);
      }
    for (const auto &postprocessor : postprocessors)
      postprocessor->execute(state, data, *statistics);
    if (data.write_statistics)
      statistics->end_row();
  }

  template class Postprocessors<2>;
  template class Postprocessors<3>;
} // namespace perideal
