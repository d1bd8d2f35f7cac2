// ---------------------------------------------------------------------
// PeriDeal: quasi-static load stepping with bond breaking.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_load_stepping_h
#define perideal_coupling_solvers_load_stepping_h

#include <perideal/coupling/solvers/quasi_static_control.h>
#include <perideal/coupling/solvers/solver.h>

namespace perideal
{
  /**
   * @brief <Solver/Type> = static or adaptive dynamic relaxation: the boundary conditions at
   * <Time stepping/End time> applied in <Solver/Load steps> equal increments; at each load
   * step the coupling method finds equilibrium (CouplingMethod::solve_equilibrium(): a linear
   * solve of the model linearized about the reference configuration, or adaptive dynamic
   * relaxation with the model's own forces), bonds break at the converged state, and the step
   * is solved again while bonds break (breaking_settled()).
   *
   * With <Solver/Control/Cut above broken bonds> = T > 0 the increment adapts: a step that
   * breaks more than T bonds, or whose solve does not converge, is undone (Checkpoint::
   * restore_kept()) and solved again with half the increment, at most <Maximum step cuts> times in
   * a row (then a step that breaks too many is kept, one that does not converge stops the run as
   * below); after a step that breaks at most T/2 bonds the increment doubles, up to 1/<Load
   * steps>. The load factor is then the time column of the statistics (rows numbered by step),
   * and checkpoints are refused (the increment is not stored).
   *
   * With <Coupling/Adaptive region> the region may grow after every <Check interval>-th load
   * step that converged (convert_regions()): the step is then solved again at its load factor
   * on the grown region.
   *
   * With several physics (<Physics/List>) the others advance before each solve
   * (CoupledState::advance_other_physics), from the time of the last converged load factor to
   * that of the one solved (load factor x <Time stepping/End time>); a step that is undone
   * takes them back too, and they advance again to the cut load factor's time.
   *
   * Refused before any work: velocity conditions (a quasi-static solve applies displacements),
   * no displacement condition at all, and for the static solve a translation that no
   * displacement condition holds (a singular system). After each step the postprocessors see
   * the reactions (the FE residual K z - F on prescribed dofs, the particles' internal forces)
   * and the particles' energy in the method's model of equilibrium.
   *
   * A load step whose solve does not converge (ExcNotConverged: <Solver/Maximum iterations>
   * reached, or a failed linear solve) stops the run after writing its last iterate for
   * inspection (FieldOutput's files *_not_converged, no statistics row) and the checkpoint of
   * the last converged load step (Checkpoint::keep() before each step, write_kept()), whatever
   * <Output/Checkpoint interval>; the exception then names the files and how to continue with
   * other solver settings (perideal-solid --restart).
   */
  template <int dim>
  class LoadStepping : public Solver<dim>
  {
  public:
    /// @p type is static_linear or adaptive_dynamic_relaxation; @p control is <Solver/Control>.
    LoadStepping(const SolverType type, const QuasiStaticControl &control);

    void
    check(const CoupledState<dim> &state) const override;

    void
    setup(CoupledState<dim> &state) override;

    void
    run(CoupledState<dim>   &state,
        Postprocessors<dim> &postprocessors,
        Checkpoint<dim>     &checkpoint) override;

    /**
     * @brief Operator splitting (a physics of <Physics/List> within a quasi-static first
     * physics): the state before the first load step, at rest with the work started.
     */
    void
    start_state(CoupledState<dim> &state) override;

    /**
     * @brief Operator splitting: the solve at the load factor of the time reached, (@p time +
     * @p dt) / <Time stepping/End time> (the first physics' load factor: k/N of load step k of
     * N, or a cut one), as run() solves a load step, and its equilibrium forces.
     */
    void
    advance(CoupledState<dim> &state,
            const double       time,
            const double       dt,
            const bool         with_energy) override;

  protected:
    /**
     * @brief The conditions at time @p time: the prescribed values of the particles and FE dofs
     * and the loads, kept for apply_load_factor().
     */
    void
    conditions_at(CoupledState<dim> &state, const double time);

    /**
     * @brief Load factor @p factor: the loads (CoupledState::f_ext, external_force) and the
     * prescribed values (owned entries of U and u). Proportional history: @p factor times those
     * at End time (conditions_at() End time once before); time history: those at @p factor x
     * End time.
     */
    void
    apply_load_factor(CoupledState<dim> &state, const double factor);

    /**
     * @brief The loads of apply_load_factor() alone: for a solution scaled as a whole (a linear
     * solve at load factor 1 times @p factor), whose prescribed values are scaled with it,
     * including those a coupling method sets itself (FERegion::set_interior_values(): the FE
     * dofs of overlapping Schwarz that the PD field prescribes), which the End-time values
     * do not hold.
     */
    void
    scale_loads(CoupledState<dim> &state, const double factor) const;

    /**
     * @brief The solve of @p what (step @p step, load factor @p factor) did not converge: write
     * its last iterate for inspection (FieldOutput's files *_not_converged, no statistics row),
     * log it and return the files written. Collective.
     */
    std::string
    write_last_iterate(CoupledState<dim>   &state,
                       Postprocessors<dim> &postprocessors,
                       const unsigned int   step,
                       const double         factor,
                       const std::string   &what) const;

    /// The message of @p failure without surrounding blanks.
    static std::string
    failure_text(const ExcNotConverged &failure);

    /// <Solver/Type> (static or adaptive dynamic relaxation) and <Solver/Control>.
    ///@{
    SolverType         type;
    QuasiStaticControl control;
    ///@}
    /// 1 on the prescribed components of owned free particles.
    ParticleVector prescribed;

  private:
    /// Solves and iterations of a load step.
    struct StepSolves
    {
      unsigned int passes = 0, iterations = 0;
    };

    /**
     * @brief Load step @p step at load factor @p factor: apply it, solve the method's
     * equilibrium and evaluate the model's forces at the solution (breaking bonds), again while
     * bonds break (breaking_settled()). Throws ExcNotConverged if a solve fails.
     */
    StepSolves
    solve_load_step(CoupledState<dim> &state, const double factor, const unsigned int step);

    /**
     * @brief The adaptive PD region (CoupledState::adapt_regions(), Coupling/Adaptive region)
     * after the converged load step @p step at load factor @p factor: if it grew, set up again
     * what setup() derived from the regions and solve the same load factor again on the grown
     * region (its new particles hold the FE field, not their equilibrium). Collective.
     */
    void
    convert_regions(CoupledState<dim> &state, const unsigned int step, const double factor);

    /**
     * @brief Load step @p step (load factor @p factor) did not converge (@p failure): write its
     * last iterate and the
     * checkpoint of the last converged step, then throw ExcNotConverged with @p failure's
     * message and how to continue. Collective.
     */
    [[noreturn]] void
    stop_without_convergence(CoupledState<dim>     &state,
                             Postprocessors<dim>   &postprocessors,
                             Checkpoint<dim>       &checkpoint,
                             const unsigned int     step,
                             const double           factor,
                             const ExcNotConverged &failure) const;

    /// The prescribed values and the loads at End time (particles, FE dofs).
    ParticleVector target, full_load;
    FEVector       fe_target, fe_full_load;
  };
} // namespace perideal

#endif
