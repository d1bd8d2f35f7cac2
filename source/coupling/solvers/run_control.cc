// ---------------------------------------------------------------------
// PeriDeal: the per-step plumbing every solver shares.
// ---------------------------------------------------------------------
#include <perideal/coupling/solvers/run_control.h>

namespace perideal
{
  template <int dim>
  RunControl<dim>::RunControl(CoupledState<dim>   &state,
                              Postprocessors<dim> &postprocessors,
                              Checkpoint<dim>     &checkpoint,
                              const bool           quasi_static)
    : state(state)
    , postprocessors(postprocessors)
    , checkpoints(checkpoint)
    , quasi_static(quasi_static)
  {}

  template <int dim>
  RunPosition
  RunControl<dim>::start(const std::string           &description,
                         const unsigned int           n_steps,
                         const std::function<void()> &initial_state)
  {
    checkpoints.set_run(description, n_steps);
    RunPosition start;
    if (checkpoints.restarting())
      start = checkpoints.load(state, postprocessors);
    else
      {
        initial_state();
        StepData data;
        data.quasi_static     = quasi_static;
        data.write_statistics = true;
        data.write_fields     = !quasi_static;
        postprocessors.execute(state, data);
      }
    next_output = start.next_output;
    return start;
  }

  template <int dim>
  StepData
  RunControl<dim>::plan(const unsigned int step, const double time, const bool final_row) const
  {
    const auto &settings = state.settings();
    StepData    data;
    data.quasi_static     = quasi_static;
    data.step             = step;
    data.time             = time;
    data.final_row        = final_row;
    data.write_statistics = quasi_static || final_row || step % settings.statistics_interval == 0;
    data.write_fields =
      final_row || (settings.output_interval > 0 && step % settings.output_interval == 0);
    return data;
  }

  template <int dim>
  void
  RunControl<dim>::write(StepData &data)
  {
    if (quasi_static)
      {
        data.output_index = data.step;
        next_output       = data.step + 1;
      }
    else if (data.write_fields)
      data.output_index = next_output++;
    postprocessors.execute(state, data);
  }

  template <int dim>
  bool
  RunControl<dim>::checkpoint(const StepData &data)
  {
    return checkpoints.after_step(state, postprocessors, {data.step, data.time, next_output});
  }

  template class RunControl<2>;
  template class RunControl<3>;
} // namespace perideal
