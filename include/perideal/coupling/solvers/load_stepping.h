// ---------------------------------------------------------------------
// PeriDeal: quasi-static load stepping with bond breaking.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_load_stepping_h
#define perideal_coupling_solvers_load_stepping_h

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
    /// @p type is static_linear or adaptive_dynamic_relaxation.
    explicit LoadStepping(const SolverType type);

    void
    setup(CoupledState<dim> &state) override;

    void
    run(CoupledState<dim>   &state,
        Postprocessors<dim> &postprocessors,
        Checkpoint<dim>     &checkpoint) override;

  private:
    /**
     * @brief Load step @p step did not converge (@p failure): write its last iterate and the
     * checkpoint of the last converged step, then throw ExcNotConverged with @p failure's
     * message and how to continue. Collective.
     */
    [[noreturn]] void
    stop_without_convergence(CoupledState<dim>     &state,
                             Postprocessors<dim>   &postprocessors,
                             Checkpoint<dim>       &checkpoint,
                             const unsigned int     step,
                             const ExcNotConverged &failure) const;

    SolverType type;
    /// 1 on the prescribed components of owned free particles.
    ParticleVector prescribed;
  };
} // namespace perideal

#endif
