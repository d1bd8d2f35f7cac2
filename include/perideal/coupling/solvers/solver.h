// ---------------------------------------------------------------------
// PeriDeal: what a solver of a problem provides.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_solver_h
#define perideal_coupling_solvers_solver_h

#include <perideal/base/problem_settings.h>
#include <perideal/coupling/checkpoint.h>
#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/postprocessors/postprocessor.h>
#include <perideal/coupling/solvers/quasi_static_control.h>

#include <memory>

namespace perideal
{
  /**
   * @brief A solver advances the state of a problem (CoupledState) from its initial conditions
   * to the end of the run, calling the postprocessors after the steps it chooses. Chosen by
   * <Solver/Type> (create_solver()); the coupling method does what is specific to the coupling
   * (masses, equilibrium solves), so a solver works for particles only, FE only and coupled
   * problems alike.
   */
  template <int dim>
  class Solver
  {
  public:
    virtual ~Solver() = default;

    /**
     * @brief The checks of setup() that need no matrix and write nothing (the boundary
     * conditions against what the solver can apply, the rigid motions they leave free), after
     * CoupledState::setup(); CoupledProblem::check() runs them, so perideal-solid --validate
     * does too. setup() runs them first. None by default.
     */
    virtual void
    check(const CoupledState<dim> &state) const;

    /**
     * @brief What the solver needs from the set-up (masses, time step, checks of the boundary
     * conditions against what the solver can apply), after CoupledState::setup(); stops with a
     * message naming the entry to fix before anything is written.
     */
    virtual void
    setup(CoupledState<dim> &state) = 0;

    /**
     * @brief Run from the initial conditions, or from the checkpoint if @p checkpoint is
     * restarting, to the end (or to the checkpoint's stop step); @p postprocessors are
     * initialized. After each step @p checkpoint writes a checkpoint if one is due.
     */
    virtual void
    run(CoupledState<dim>   &state,
        Postprocessors<dim> &postprocessors,
        Checkpoint<dim>     &checkpoint) = 0;

    /**
     * @brief Operator splitting (a physics of <Physics/List>, advanced by CoupledProblem
     * within the steps of the first one): set the initial state. Refused by default; the
     * explicit, implicit and load-stepping solvers provide it.
     */
    virtual void
    start_state(CoupledState<dim> &state);

    /**
     * @brief Operator splitting: advance @p state by one step @p dt from @p time, its energies
     * computed if @p with_energy. Refused by default; the explicit, implicit and
     * load-stepping solvers provide it.
     */
    virtual void
    advance(CoupledState<dim> &state, const double time, const double dt, const bool with_energy);

    /**
     * @brief Operator splitting, after a restart (Checkpoint::load() restored @p state at
     * @p time): derive what the solver keeps beside the state before its next advance(). Nothing
     * by default (an explicit step needs only the state).
     */
    virtual void
    resume_state(CoupledState<dim> &state, const double time);

    /**
     * @brief Operator splitting, after a conversion of the adaptive PD region at @p time (the
     * regions of @p state rebuilt, CoupledState::setup() run and the unknowns carried over):
     * what setup() derives from the regions again (masses and stable step, or the matrix), the
     * forces at @p time and the previous state of the work. The caller sets the step again.
     * Refused by default; the explicit and implicit solvers provide it.
     */
    virtual void
    renew_regions(CoupledState<dim> &state, const double time);

    /**
     * @brief Operator splitting, after another physics changed the field of @p state at @p time
     * (the adiabatic heating of a two-way coupling, ThermoelasticHeating::heat_step()): the rates
     * the step starts from. Refused by default; the explicit solver provides it.
     */
    virtual void
    renew_rates(CoupledState<dim> &state, const double time);
  };

  /// The solver of <Solver/Type> = @p type and, for quasi-static runs, <Solver/Control> =
  /// @p control.
  template <int dim>
  std::unique_ptr<Solver<dim>>
  create_solver(const SolverType type, const QuasiStaticControl &control);
} // namespace perideal

#endif
