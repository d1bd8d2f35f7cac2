// ---------------------------------------------------------------------
// PeriDeal: the per-step plumbing every solver shares (restart, initial output, statistics,
// fields, checkpoints).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_run_control_h
#define perideal_coupling_solvers_run_control_h

#include <perideal/coupling/checkpoint.h>
#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/postprocessors/postprocessor.h>

#include <functional>
#include <string>

namespace perideal
{
  /**
   * @brief What a solver does around its steps, in one place: the run's description for the
   * checkpoint, the restart or the initial state and its output, after each step the decision
   * what to write by the <Output> intervals, the postprocessors and the checkpoint.
   *
   * A solver calls start() once, then per step plan() (before it computes what the output
   * needs), write() and checkpoint(). Time steps write a statistics row every <Output/Statistics
   * interval> steps and fields every <Output/Output interval> steps (numbered in order);
   * quasi-static steps (load steps, events) a row every step and fields every <Output/Output
   * interval> steps (numbered by the step); both write both after the last step.
   */
  template <int dim>
  class RunControl
  {
  public:
    /**
     * @brief The plumbing of a run of @p state with @p postprocessors and @p checkpoint;
     * @p quasi_static: steps of a load factor (load steps, events) rather than time steps.
     */
    RunControl(CoupledState<dim>   &state,
               Postprocessors<dim> &postprocessors,
               Checkpoint<dim>     &checkpoint,
               const bool           quasi_static);

    /**
     * @brief Start the run described by @p description (part of the checkpoint's fingerprint)
     * of @p n_steps steps: on a restart load the checkpoint; otherwise set the initial state by
     * @p initial_state and write step 0 (its statistics row, and the fields of a time-stepping
     * run). Returns where the run continues. Collective.
     */
    RunPosition
    start(const std::string           &description,
          const unsigned int           n_steps,
          const std::function<void()> &initial_state);

    /**
     * @brief What to write after step @p step at @p time (a load factor for quasi-static steps),
     * the last one if @p final_row: the step data with the statistics and field flags of the
     * <Output> intervals.
     */
    StepData
    plan(const unsigned int step, const double time, const bool final_row) const;

    /**
     * @brief Number the field output of @p data and execute the postprocessors for it.
     * Collective.
     */
    void
    write(StepData &data);

    /**
     * @brief Hand the step of @p data (written by write()) to the checkpoint: a checkpoint if
     * one is due; returns whether the run ends here (the stop step of a restart test).
     * Collective.
     */
    bool
    checkpoint(const StepData &data);

  private:
    CoupledState<dim>   &state;
    Postprocessors<dim> &postprocessors;
    Checkpoint<dim>     &checkpoints;
    const bool           quasi_static;
    /// The index of the next field output.
    unsigned int next_output = 1;
  };
} // namespace perideal

#endif
