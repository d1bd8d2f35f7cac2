// ---------------------------------------------------------------------
// PeriDeal: implicit theta-scheme time steps of a first-order field (heat conduction).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_theta_scheme_h
#define perideal_coupling_solvers_theta_scheme_h

#include <perideal/coupling/solvers/solver.h>

#include <vector>

namespace perideal
{
  /**
   * @brief <Solver/Type> = implicit: the theta scheme of a first-order field (every component
   * a temperature), C dT/dt = Q - K T, in equal steps of <Time stepping/Time step> to <Time
   * stepping/End time>:
   *
   *   (C/dt + theta K) T_{n+1} = (C/dt - (1 - theta) K) T_n + theta Q_{n+1} + (1 - theta) Q_n,
   *
   * theta = <Time stepping/Theta> in [1/2, 1] (1: backward Euler, first order; 1/2:
   * Crank-Nicolson, second order; unconditionally stable for both). C is the lumped capacity of
   * the coupling method (CouplingMethod::lumped_masses() times the components' inertia ratio:
   * rho c), K the linearized operator of the static solve (the FE stiffness with its Robin
   * terms, the PD model's linearize()), Q the loads. Divided by theta, a step is one static
   * solve of the coupling method with the diagonal D = C / (theta dt) added
   * (CouplingMethod::set_equilibrium_diagonal()):
   *
   *   (D + K) T_{n+1} = Q_{n+1} + D T_n + (1 - theta) / theta (Q_n - K T_n),
   *
   * with Q_n - K T_n from CouplingMethod::equilibrium_forces() of the previous step. So FE-only,
   * particles-only and blended problems step alike, with CG + AMG (or the direct solver) of
   * <Solver/Linear solver>; prescribed temperatures are those of the conditions at t_{n+1}.
   */
  template <int dim>
  class ThetaScheme : public Solver<dim>
  {
  public:
    /// @brief Refuse a field that is not first order (every component a temperature).
    void
    check(const CoupledState<dim> &state) const override;

    /// @brief The capacities, the static solve of the method with its diagonal D.
    void
    setup(CoupledState<dim> &state) override;

    /// @brief The steps to the end time.
    void
    run(CoupledState<dim>   &state,
        Postprocessors<dim> &postprocessors,
        Checkpoint<dim>     &checkpoint) override;

    /**
     * @brief The initial state (initial conditions, prescribed values at t = 0, the start of
     * the work, the forces of the first step).
     */
    void
    start_state(CoupledState<dim> &state) override;

    /**
     * @brief One step from @p time to @p time + @p dt; a @p dt other than the last step's
     * (CoupledState::time_step, which the diagonal D holds: a cut load step of the first
     * physics) sets D anew (set_step()); the energies are always computed.
     */
    void
    advance(CoupledState<dim> &state,
            const double       time,
            const double       dt,
            const bool         with_energy) override;

    /// After a restart at @p time: the forces of the next step (first_forces()).
    void
    resume_state(CoupledState<dim> &state, const double time) override;

    /**
     * @brief After a conversion (a physics of <Physics/List>): setup() again (the method's
     * solve and the diagonal of the step), the forces at @p time (as resume_state()) and the
     * previous state of the work.
     */
    void
    renew_regions(CoupledState<dim> &state, const double time) override;

  private:
    /// The forces of the first step at @p time (after the initial state or a restart).
    void
    first_forces(CoupledState<dim> &state, const double time);

    /// Steps of @p dt: CoupledState::time_step and the diagonal D = C / (theta dt) with the
    /// particle convection's conductance, given to the method.
    void
    set_step(CoupledState<dim> &state, const double dt);

    /// The step that ends at @p time, from the state of the previous one.
    void
    step_to(CoupledState<dim> &state, const double time);

    /**
     * @brief The forces of the state at @p time: the loads (state.f_ext, state.external_force)
     * and equilibrium_state() (state.residual = K U - Q on the FE dofs, state.internal_force,
     * the work of the loads).
     */
    void
    forces_at(CoupledState<dim> &state, const double time);

    /// The diagonal D = C / (theta dt) on the FE dofs.
    FEVector fe_diagonal;
    /// Per owned particle component: D / V on the components not slaved to the FE field (whose
    /// capacity is the FE dofs'), 0 on the slaved ones.
    ParticleVector particle_diagonal;
    /// Per owned particle component: 1 if not slaved to the FE field, else 0 (the slaved
    /// particles' forces reach the FE dofs through P^T in state.residual).
    std::vector<double> free_factor;
    /// The right-hand side of a step: FE load and particle force density.
    FEVector       fe_rhs;
    ParticleVector pd_rhs;
    /// The iterations of the last step's solve.
    unsigned int iterations = 0;
  };
} // namespace perideal

#endif
