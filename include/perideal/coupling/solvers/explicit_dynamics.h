// ---------------------------------------------------------------------
// PeriDeal: explicit dynamics (velocity Verlet) of the coupled system.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_solvers_explicit_dynamics_h
#define perideal_coupling_solvers_explicit_dynamics_h

#include <perideal/coupling/solvers/solver.h>

#include <cstdint>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief <Solver/Type> = explicit: velocity Verlet on (FE dofs, free particle components) to
   * <Time stepping/End time> in equal steps, with the lumped masses of the coupling method and
   * the mass-proportional damping of <Time stepping/Damping>.
   *
   * The stable step is the smaller of the FE region's (Gershgorin bound of M^-1 K with the full
   * coupled mass) and the particles'; a requested step above it is refused. Per step: half a
   * step of the velocities, the positions (particles slaved to the FE field from it, by the
   * method's P), the forces of both regions (their forces to the FE dofs by the method's P^T)
   * and the energy of the bonds they broke (CoupledState::accumulate_dissipated_energy()), the
   * second half step, the work of the loads. The
   * acceleration works on contiguous arrays: per particle component the factor from force
   * density to acceleration is V_i / m_i where the component moves by its acceleration and 0
   * where it is slaved to the FE field or prescribed, so the pass has no branches.
   *
   * With an adaptive PD region (CoupledState::adapt_regions()), every check step computes the
   * energies, lets the region grow and, if it did, renews the masses and factors (the step stays;
   * a conversion that lowers the stable step below it stops the run), the forces and the previous
   * state of the work, and logs the change of kinetic plus strain energy, which the energy
   * balance carries as its own term.
   */
  template <int dim>
  class ExplicitDynamics : public Solver<dim>
  {
  public:
    void
    setup(CoupledState<dim> &state) override;

    void
    run(CoupledState<dim>   &state,
        Postprocessors<dim> &postprocessors,
        Checkpoint<dim>     &checkpoint) override;

    /**
     * @brief The initial state of a run: the initial conditions, the prescribed values at
     * t = 0, the forces and rates, the start of the work; then (CoupledState::
     * advance_other_physics()) the initial state of the other physics.
     */
    void
    start_state(CoupledState<dim> &state) override;

    /**
     * @brief One step @p dt from @p time (velocity Verlet; forward Euler for a temperature),
     * the particles' energy density computed if @p with_energy, the work of the loads added.
     */
    void
    advance(CoupledState<dim> &state,
            const double       time,
            const double       dt,
            const bool         with_energy) override;

    /**
     * @brief After a conversion (a physics of <Physics/List>): setup() again (masses, factors,
     * the stable step and the step it chooses), the forces at @p time and the previous state
     * of the work.
     */
    void
    renew_regions(CoupledState<dim> &state, const double time) override;

    /// The accelerations (the rates of a temperature) at @p time of the changed field: forward
    /// Euler takes the rate at the step's start.
    void
    renew_rates(CoupledState<dim> &state, const double time) override;

  private:
    /**
     * @brief What the step derives from the regions: the masses of the method, the factors from
     * force density to acceleration and the stable step (CoupledState::stable_dt).
     */
    void
    derive_from_regions(CoupledState<dim> &state);

    /**
     * @brief After step @p step at @p time: let the adaptive region grow
     * (CoupledState::adapt_regions()) and, if it did, renew what the step derives from the
     * regions and log the energy change.
     */
    void
    adapt_regions(CoupledState<dim> &state, const unsigned int step, const double time);

    /**
     * @brief After the regions changed: the forces and accelerations at @p time (with the
     * damping) and the previous state of the work of the loads.
     */
    void
    renew_forces(CoupledState<dim> &state, const double time);

    /**
     * @brief The particles slaved to the FE field from it (the method's P U), ghost values
     * updated: before every compute_acceleration(), and before another physics reads the
     * displacements inside a step.
     */
    void
    slave_particles(CoupledState<dim> &state) const;

    /**
     * @brief Forces and accelerations of both regions at @p time, at the present displacements
     * (the slaved particles' set by slave_particles()); the particles' energy density only if
     * @p with_energy. A positive @p kick also adds @p kick a to the particles' velocities in
     * the pass that computes a (the closing half step of advance(), when no damping changes a
     * before it).
     */
    void
    compute_acceleration(CoupledState<dim> &state,
                         const double       time,
                         const bool         with_energy,
                         const double       kick = 0.);

    /**
     * @brief The mass-proportional damping of <Time stepping/Damping>: A -= c V on the free FE
     * dofs, a -= c v on the free components of free particles.
     */
    void
    add_damping(CoupledState<dim> &state) const;

    /**
     * @brief Print the largest unbalanced force at t = 0 relative to the FE internal-force
     * scale: the ghost force when the initial state is one the model reproduces exactly.
     */
    void
    report_initial_residual(const CoupledState<dim> &state) const;

    /**
     * @brief The rate of the first-order (temperature) unknowns that move: V = A and v = a
     * (forward Euler, T += dt dT/dt with dT/dt at the start of the step), after every update
     * of the velocities by velocity Verlet's half steps; nothing without a temperature.
     */
    void
    set_first_order_rates(CoupledState<dim> &state) const;

    /// Per owned particle component: force density to acceleration.
    std::vector<double> acceleration_factor;
    /// The moving particle components of the temperature kind (first order in time), and
    /// whether the FE dofs are (a problem whose field is a temperature).
    ///@{
    std::vector<std::size_t> first_order_components;
    bool                     fe_first_order = false;
    ///@}
    /// The particles' nodal forces V_i f_i that the method's P^T carries to the FE dofs.
    ParticleVector nodal_force;
    /// The stable steps of the FE region and of the particles [s].
    double fe_dt = 0., pd_dt = 0.;

    /**
     * What the adaptive region cost during run() (its summary with <Output/Progress>): the wall
     * time on this rank and the CPU time of the process (std::clock()) of the checks that
     * converted (the whole of adapt_regions(): proposals, rebuild, masses, forces) and of those
     * that did not, the particles the conversions added, and the particles summed over the
     * steps (the work of the steps).
     */
    struct AdaptiveCost
    {
      /// Conversions: their number, wall and CPU time [s], the particles they added.
      ///@{
      unsigned int  conversions     = 0;
      double        conversion_wall = 0., conversion_cpu = 0.;
      std::uint64_t added = 0;
      ///@}
      /// Checks without a conversion: their number, wall and CPU time [s].
      ///@{
      unsigned int checks     = 0;
      double       check_wall = 0., check_cpu = 0.;
      ///@}
      /// The number of particles summed over the steps.
      double particle_steps = 0.;
    };
    /// The adaptive region's cost so far.
    AdaptiveCost adaptive_cost;

    /**
     * @brief The summary line of the adaptive region's cost (collective; the CPU times the
     * largest over the ranks): the conversions' wall and CPU time and share of the time loop's
     * @p loop_seconds, per converted particle against a step per particle.
     */
    std::string
    adaptive_cost_summary(const CoupledState<dim> &state, const double loop_seconds) const;
  };
} // namespace perideal

#endif
