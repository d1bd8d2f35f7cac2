// ---------------------------------------------------------------------
// PeriDeal: the state of a problem that the solvers advance and the postprocessors read.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_coupled_state_h
#define perideal_coupling_coupled_state_h

#include <deal.II/lac/la_parallel_vector.h>

#include <perideal/base/checkpoint_file.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/base/problem_settings.h>
#include <perideal/coupling/coupling_method.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/particle_region.h>

#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace perideal
{
  /**
   * @brief Everything a solver advances and a postprocessor reads (in the manner of ASPECT's
   * SimulatorAccess): the two regions and the coupling method (owned by CoupledProblem; the
   * solvers and postprocessors reach the coupling only through the method), the problem's
   * settings, and the unknowns of both regions with what they derive from the set-up: how each
   * particle component moves, the factors of the work of the loads, the masses.
   *
   * Vectors are laid out by the field (FieldLayout): component c of local particle i is entry
   * i * n_components() + c of the particle vectors; the FE vectors are the FE region's.
   */
  template <int dim>
  class CoupledState
  {
  public:
    /// How an owned particle component moves.
    enum class Motion : unsigned char
    {
      /// with the FE field (CouplingMethod::slaved_particles())
      slaved,
      /// by its acceleration (a free particle)
      moves,
      /// by a displacement or velocity condition (a free particle)
      prescribed
    };

    /// The state of a problem whose points have the unknowns @p layout.
    CoupledState(const MPI_Comm              comm,
                 std::ostream               &log,
                 const ProblemSettings<dim> &settings,
                 const FieldLayout          &layout,
                 ParticleRegion<dim>        &pd,
                 FERegion<dim>              &fe,
                 CouplingMethod<dim>        &method);

    /**
     * @brief Once both regions and the method are set up: the motion of every owned particle
     * component (refusing PD displacement or velocity conditions on particles that follow the
     * FE field) and the factors of the work of the loads; every vector sized and zero.
     */
    void
    setup();

    /// Whether the problem has both regions (particles and an FE mesh).
    bool
    is_coupled() const;

    /// Whether there are particles (on any rank).
    bool
    has_particles() const;

    /// Unknowns per particle (the field's components).
    unsigned int
    n_components() const
    {
      return field_layout.n_components();
    }

    /**
     * @brief The initial conditions (<Initial conditions>) on both regions: the same function
     * of x for FE nodes and particles; then the values the conditions prescribe at t = 0.
     */
    void
    apply_initial_conditions();

    /**
     * @brief Start the work of the loads and the dissipated energy at 0 from the current state
     * (bonds broken before do not count).
     */
    void
    start_work();

    /**
     * @brief Add the work of the loads from the previous state to the current one (trapezoidal
     * rule in the loads) and make the current state the previous one. The loads are fe_load on
     * the FE dofs and, on the particles, internal_work_factor f_int + applied_work_factor
     * external_force. On the particles it passes over the components whose load can be
     * nonzero only (the prescribed ones, all moving ones if a load acts); the previous
     * displacement of the others is kept only if a temperature change strains the material.
     */
    void
    accumulate_work();

    /**
     * @brief After the regions changed (a conversion of the adaptive region): make the current
     * state the previous one of the work of the loads, keeping the sums so far.
     */
    void
    carry_work();

    /// The work of the loads since start_work(), summed over the ranks [J].
    double
    external_work() const;

    /**
     * @brief Add the energy that the bonds broken by the last force evaluation released at the
     * particle displacement u (MaterialModel::released_energy(): nothing to do unless bonds
     * broke), recording the bonds for the other physics (set_broken_bond_record()). Call it on
     * every rank after each force evaluation that may break bonds.
     */
    void
    accumulate_dissipated_energy();

    /// The energy the broken bonds released since start_work(), summed over the ranks [J].
    double
    dissipated_energy() const;

    /**
     * @brief Add the heat that enters the body over a time @p dt at the current heat flows:
     * dt times, on the particles' temperature components, sum (V_i q_ext on the free and
     * slaved components, -V_i q_int on the held ones, i.e. what their conditions supply), and
     * on the FE dofs of a temperature field sum_k (fe_load_k - r_k U_k): the loads and the
     * supports' heat, less the convection faces' h T (r the column sums of the FE stiffness,
     * its convection conductance). The conduction inside and through the overlap cancels in
     * the sum. Forward Euler adds its step dt at the flows of the step's start, the theta
     * scheme (1 - theta) dt at t_n and theta dt at t_{n+1}: so the sum is the change of
     * stored_heat() that the steps make (to round-off, to the solver tolerance). Nothing
     * without a temperature.
     */
    void
    accumulate_heat(const double dt);

    /// Add @p heat [J] (this rank's part) to heat_in(): heat another physics put into the
    /// state's temperature directly (the adiabatic heating of a two-way coupling).
    void
    add_heat_in(const double heat);

    /// The heat in through the conditions since start_work(), summed over the ranks [J].
    double
    heat_in() const;

    /**
     * @brief The heat stored in the body, summed over the ranks [J]: sum m_i c T_i over the
     * free particle temperature components and sum C_k T_k over the free dofs of an FE
     * temperature field, with the method's lumped masses (CouplingMethod::lumped_masses(): the
     * FE capacity weighted by the method plus that of the slaved particles, so that the overlap
     * counts once). 0 without a temperature or without masses (quasi-static).
     */
    double
    stored_heat() const;

    /// @brief stored_heat() at the last start_work() [J].
    double
    initial_stored_heat() const
    {
      return stored_heat_at_start;
    }

    /// Kinetic energy of an explicit run, and the part of it on prescribed dofs and components.
    struct KineticEnergy
    {
      /// The whole kinetic energy and its part on prescribed dofs and components [J].
      ///@{
      double total = 0., prescribed = 0.;
      ///@}
    };

    /**
     * @brief The kinetic energy of the FE dofs and of the particle components not
     * slaved to the FE field (lumped masses of the method), summed over the ranks [J].
     */
    KineticEnergy
    kinetic_energy() const;

    /**
     * @brief The strain energy of an explicit run, each part of the body counted once by the
     * method, from the FE displacement and the particles' energy density of the last force
     * evaluation that computed it, summed over the ranks [J].
     */
    CoupledEnergy
    strain_energy() const;

    /**
     * @brief The strain energy of the FE displacement and the particles' strain energy
     * @p particle_energy [J] (summed over the ranks), each part counted once by the method; with
     * a thermal strain of the FE region, the FE part is that of the mechanical strain,
     * 1/2 U.K.U - U.thermal_load + thermal_energy. Collective.
     */
    CoupledEnergy
    strain_energy(const double particle_energy) const;

    /// The largest particle displacement (norm of the translations) over the ranks [m].
    double
    max_particle_displacement() const;

    /**
     * @brief The internal-force scale of the FE rows, max_k sum_j |K_kj U_j| over the ranks
     * (U's ghost values must be current); 0 without FE unknowns.
     */
    double
    fe_force_scale() const;

    /**
     * @brief The accuracy of a quasi-static solution relative to its largest force, the
     * solver's and the coupling method's (ProblemSettings::solution_accuracy(),
     * CouplingMethod::solution_accuracy()): printed summaries show forces and energy errors to
     * it.
     */
    double
    solution_accuracy() const;

    /**
     * @brief Print "@p what: R N ..., relative to the FE internal-force scale: R / S" with R, S
     * the largest of @p local_largest and @p local_scale over the ranks (root only; R below
     * 1e-12 S is round-off and printed as 0; without FE unknowns only R).
     */
    void
    log_residual(const std::string &what,
                 const double       local_largest,
                 const double       local_scale) const;

    /// Pointers to the parts of the state that change during a run (stored_parts()), to const
    /// parts if @p constant.
    template <bool constant>
    struct Parts
    {
      /// A pointer to a part.
      template <typename T>
      using Pointer = std::conditional_t<constant, const T *, T *>;
      /// Every particle vector, and the particles' strain-energy density.
      ///@{
      std::vector<Pointer<ParticleVector>> particle_vectors;
      Pointer<std::vector<double>>         energy_density;
      ///@}
      /// Every FE vector.
      std::vector<Pointer<FEVector>> fe_vectors;
      /// This rank's sums of the work of the loads, of the dissipated energy, of the heat in
      /// through the conditions, of the work of the changing temperature and of the energy it
      /// moved.
      std::vector<Pointer<double>> sums;
      /// What is the same on every rank: the stored heat at start_work().
      std::vector<Pointer<double>> totals;
    };
    /// The parts to change (a restart) and the parts to read (a checkpoint).
    ///@{
    using StoredParts      = Parts<false>;
    using ConstStoredParts = Parts<true>;
    ///@}

    /**
     * @brief What a checkpoint holds of this state: everything that changes during a run, the
     * previous state of the work of the loads and this rank's partial sums included, so that a
     * restarted run repeats the uninterrupted one bit for bit on the same number of ranks.
     */
    ///@{
    StoredParts
    stored_parts();

    ConstStoredParts
    stored_parts() const;
    ///@}

    /**
     * @brief The lines "key = value" of this state in a checkpoint's fingerprint, each key
     * prefixed by @p prefix: the unknowns, the counts of particles, bonds, FE cells and dofs,
     * the stored vectors and the values per bond history of the model. Collective.
     */
    std::string
    fingerprint(const std::string &prefix) const;

    /**
     * @brief Add the sections of this state to @p writer, named with @p prefix: this rank's sums,
     * the particle records (ParticleRegion::save_particle_records()), the bond histories of the
     * model (ParticleRegion::save_bond_histories()) and the FE dof values
     * (FERegion::save_dof_values()). The bond states are the particles' owner's (the first
     * physics). Collective.
     */
    void
    save(CheckpointWriter &writer, const std::string &prefix) const;

    /**
     * @brief Restore what save() wrote with @p prefix from @p reader (on another number of ranks
     * the sums go to rank 0); the ghost values of u and U are updated. Collective.
     */
    void
    load(CheckpointReader &reader, const std::string &prefix);

    /**
     * @brief Keep in memory what save() writes of this state (its stored parts and sums, the
     * bond histories of its model, the held temperature of hold_temperature()), for
     * restore_kept(): a quasi-static run keeps each converged
     * load step (Checkpoint::keep()). The bond states are the bond list's, which the physics
     * share: Checkpoint keeps them once.
     */
    void
    keep();

    /**
     * @brief Put the state of the last keep() back; after the bond states (the model's
     * histories belong to them). The record of the bonds broken since (set_broken_bond_record())
     * is dropped: they are intact again.
     */
    void
    restore_kept();

    /// @name The problem's parts
    /// The parts of the problem the state works on, each behind an accessor (a const and a
    /// non-const one for the parts that change: pd(), fe(), method()): a
    /// <tt>const CoupledState &</tt> (every postprocessor's) gives them const.
    ///@{

    /// The communicator of the problem.
    MPI_Comm
    comm() const
    {
      return mpi_communicator;
    }

    /**
     * @brief The log of the run (written on rank 0, is_root()). Not a part of the state: a
     * const state writes to it too.
     */
    std::ostream &
    log() const
    {
      return log_stream;
    }

    /// Whether this rank writes the log (rank 0 of comm()).
    bool
    is_root() const
    {
      return root;
    }

    /// The problem's settings (this physics' initial conditions and body force).
    const ProblemSettings<dim> &
    settings() const
    {
      return problem_settings;
    }

    /// The particle region.
    ///@{
    const ParticleRegion<dim> &
    pd() const
    {
      return particle_region;
    }

    ParticleRegion<dim> &
    pd()
    {
      return particle_region;
    }
    ///@}

    /// The FE region.
    ///@{
    const FERegion<dim> &
    fe() const
    {
      return fe_region;
    }

    FERegion<dim> &
    fe()
    {
      return fe_region;
    }
    ///@}

    /// The coupling method.
    ///@{
    const CouplingMethod<dim> &
    method() const
    {
      return coupling_method;
    }

    CouplingMethod<dim> &
    method()
    {
      return coupling_method;
    }
    ///@}

    /// The particles' unknowns (the FE nodes' are its first components:
    /// FERegion::field_layout()).
    const FieldLayout &
    layout() const
    {
      return field_layout;
    }
    ///@}

    /// @name What setup() derives
    ///@{

    /// The motion of each owned particle component.
    const std::vector<Motion> &
    motion() const
    {
      return component_motion;
    }

    /// Whether any particle (on any rank) is slaved to the FE field.
    bool
    any_particle_slaved() const
    {
      return slaved_anywhere;
    }

    /**
     * @brief Per component of the layout: its inertia over the mass (1 for translations and
     * scalars; for a rotation the model's rotational inertia density over the mass density
     * [m^2], MaterialModel::inertia_densities()); the inertia of component c of particle i is
     * particle_mass[i] * inertia_ratio()[c].
     */
    const std::vector<double> &
    inertia_ratio() const
    {
      return inertia_ratios;
    }
    ///@}

    /// @name The hooks CoupledProblem wires
    ///@{

    /**
     * @brief Explicit runs with an adaptive PD region (<Coupling/Adaptive region>), set by
     * CoupledProblem: @p adapt is called every @p interval steps after the postprocessors,
     * with the step and the time; it grows the PD region if the criterion asks for it and
     * carries the unknowns over; it returns whether the regions changed (then the solver
     * renews what it derives from them: masses, forces, the previous state of the work).
     * On the states of the other physics of <Physics/List>, whose regions the first physics'
     * conversions rebuild, @p adapt is empty and @p interval the first physics'.
     */
    void
    set_adaptive_region(std::function<bool(unsigned int, double)> adapt,
                        const unsigned int                        interval);

    /// Whether set_adaptive_region() set an adaptive PD region that this state's solver calls.
    bool
    has_adaptive_region() const;

    /// The hook of set_adaptive_region() (empty without one; a test may wrap it).
    const std::function<bool(unsigned int, double)> &
    adaptive_region() const;

    /// The steps between two calls of adapt_regions() (Coupling/Adaptive region/Check
    /// interval; 0 without an adaptive region); set on the states of the other physics too.
    unsigned int
    adaptation_interval() const;

    /// Call the adaptive region of set_adaptive_region() (which must be set) after step
    /// @p step at @p time: whether the regions changed.
    bool
    adapt_regions(const unsigned int step, const double time);

    /**
     * @brief Runs with several physics (<Physics/List>), set by CoupledProblem on the first
     * physics' state: @p advance advances the other physics over a step by operator splitting
     * (advance_other_physics()): after the step of the first physics, or, @p within_step, inside
     * an explicit step of it, once its displacements reached the step's end and before its forces
     * there are computed (the adiabatic split of a two-way thermoelastic coupling,
     * ThermoelasticHeating).
     */
    void
    set_other_physics(std::function<void(unsigned int, double, double, bool)> advance,
                      const bool                                              within_step);

    /// Whether the explicit solver advances the other physics inside its step
    /// (set_other_physics()).
    bool
    other_physics_within_step() const;

    /// The hook of set_other_physics() (empty without one; a test may wrap it).
    const std::function<void(unsigned int, double, double, bool)> &
    other_physics() const;

    /**
     * @brief Runs with several physics: accumulate_dissipated_energy() records the bonds the
     * force evaluation broke in @p broken_bonds, for the physics that share them
     * (PhysicsExchange::record()); restore_kept() clears it.
     */
    void
    set_broken_bond_record(std::vector<unsigned int> &broken_bonds);

    /**
     * @brief Advance the other physics of set_other_physics() (nothing without): the solver
     * calls it with step 0 once the initial state is set, then with each step, the @p time it
     * starts at and its length @p dt [s], and whether the step computes energies (explicit:
     * after the step, when it writes statistics or fields; quasi-static: before the load
     * step's solve, over the time from the last converged load factor to the one solved, each
     * times <Time stepping/End time>).
     */
    void
    advance_other_physics(const unsigned int step,
                          const double       time,
                          const double       dt,
                          const bool         with_energy);

    /**
     * @brief A thermal strain (<Temperature>, doc/architecture/16_multiphysics.md "Thermal
     * strain"), set by CoupledProblem: @p update brings the temperature change of the particles
     * and of the FE cells to a time (TemperatureSource::update()).
     */
    void
    set_temperature(std::function<void(double)> update);

    /// Whether the state has a thermal strain (set_temperature()).
    bool
    has_temperature() const;

    /**
     * @brief The temperature change at @p time [s] (nothing without set_temperature()): the
     * particles' model reads it in its next force evaluation, and the FE thermal load
     * (thermal_load, thermal_energy) is assembled at it if the FE region has a thermal strain.
     * The solvers call it before each force evaluation, with its time.
     */
    void
    update_temperature(const double time);

    /**
     * @brief Make the temperature of the present state (the particles' temperature change, the
     * FE thermal load and energy) the one the next accumulate_temperature_work() starts from:
     * at start_work() and after every equilibrium that accumulated the work.
     */
    void
    hold_temperature();

    /**
     * @brief Add the work the change of the temperature since hold_temperature() did on the
     * body over the step from the previous state of the work of the loads (u_0) to the present
     * one (u_1), then hold the present temperature (quasi-static runs: equilibrium_state();
     * explicit steps: accumulate_temperature_jump()).
     * With E(u, T) the strain energy in the coupling method's model of equilibrium, the
     * symmetric difference 1/2 [E(u_1, T_1) - E(u_1, T_0) + E(u_0, T_1) - E(u_0, T_0)], exact
     * for an energy quadratic in u and T along the straight path of the step, as the
     * trapezoidal rule of the loads' work is (doc/architecture/16_multiphysics.md): the FE part
     * from the thermal loads, the particles' from the coupling method's energies
     * (CouplingMethod::equilibrium_particle_energies()). Nothing without a temperature.
     * Collective.
     */
    void
    accumulate_temperature_work();

    /**
     * @brief Explicit steps: whether update_temperature() changed the temperature from the held
     * one (hold_temperature(); false after a conversion laid the fields out anew, and without a
     * temperature). Collective.
     */
    bool
    temperature_changed() const;

    /**
     * @brief Explicit steps, where the temperature changes at fixed displacements: add
     * E(u, T) - E(u, T_held) to the work of the temperature and hold the present temperature;
     * the particles' E(u, T) from energy_density, which the caller's force evaluation at T wrote,
     * E(u, T_held) from one more evaluation of the model. Collective.
     */
    void
    accumulate_temperature_jump();

    /// The work of the changing temperature since start_work(), summed over the ranks [J].
    double
    temperature_work() const;

    /**
     * @brief The energy the changing temperature moved since start_work(): per step the mean of
     * |E(u, T_1) - E(u, T_0)| at the step's start and end, summed over the steps and the ranks
     * [J]. What the energy error is relative to where the temperature's work is a small
     * difference of large changes (a free expansion).
     */
    double
    temperature_energy_scale() const;

    /**
     * @brief The FE loads an equilibrium solve takes: the applied f_ext, plus the thermal load
     * if the FE region has a thermal strain (then in a vector of the state's own).
     */
    const FEVector &
    fe_equation_load() const;
    ///@}

    /// @name The values the solvers advance and derive
    /// Public members: they are values, so a <tt>const CoupledState &</tt> gives them const
    /// (doc/architecture/07_driver.md).
    ///@{

    /// The particles' masses of explicit runs (per owned particle; for free particles).
    std::vector<double> particle_mass;
    /// The lumped FE masses of explicit runs.
    FEVector mass;
    /// The stable explicit time step of the coupled system and the one taken [s] (explicit
    /// runs).
    ///@{
    double stable_dt = 0., time_step = 0.;
    ///@}
    /// The coupling numbers delta = T_0 beta : alpha / (rho c) of a two-way thermoelastic
    /// coupling (<Temperature/Coupling> = two way) at the particles and in the FE region, which
    /// lower the stable explicit step to 1 / sqrt(1 + delta) of the mechanics' own
    /// (doc/theory/thermoelasticity.md, "The stable time step"; set by CoupledProblem before the
    /// solver's set-up); 0 without it.
    ///@{
    double particle_coupling_number = 0., fe_coupling_number = 0.;
    ///@}
    /// The change at the conversions of the adaptive region so far (summed) [J]: of the kinetic
    /// plus strain energy, or of a temperature's stored_heat() (the interpolation of the old FE
    /// field into the new particles), which the heat balance takes out.
    double conversion_energy = 0.;

    /// FE region: displacement, velocity, acceleration; the external load; the residual
    /// f_ext - K U + P^T f (explicit) or K U - f - P^T f (quasi-static); the loads that do work
    /// (fe_load); the force of the supports on prescribed dofs (fe_support, for the reactions).
    ///@{
    FEVector U, V, A, f_ext, residual, fe_load, fe_support;
    ///@}
    /// Particles: displacement, velocity, acceleration, internal and applied force density.
    ///@{
    ParticleVector u, v, a, internal_force, external_force;
    ///@}
    /// The particles' strain-energy density (per owned particle) [J/m^3].
    std::vector<double> energy_density;
    /// The FE thermal load at the time of the last update_temperature() (zero without a
    /// thermal strain of the FE region): internal, part of K U - thermal_load, not external
    /// work; and the energy of the thermal strain, int (1 - beta) 1/2 eps_th : C : eps_th, so
    /// that the FE strain energy of the mechanical strain is 1/2 U.K.U - U.thermal_load +
    /// thermal_energy (FERegion::assemble_thermal_load()).
    ///@{
    FEVector thermal_load;
    double   thermal_energy = 0.;
    ///@}
    /// Quasi-static runs: the particles' strain energy at the last equilibrium (the method's
    /// equilibrium_forces(), set by equilibrium_state()) [J], for a physics of <Physics/List>
    /// whose statistics its own solver does not write.
    double equilibrium_particle_energy = 0.;
    ///@}

  private:
    /// What keep() keeps: copies of the stored parts, of the sums, of the bond histories and of
    /// the held temperature (hold_temperature()).
    struct Kept
    {
      std::vector<ParticleVector> particle_vectors;
      std::vector<double>         energy_density;
      std::vector<FEVector>       fe_vectors;
      std::vector<double>         sums;
      std::vector<double>         history;
      ParticleVector              held_temperature_change;
      FEVector                    held_thermal_load;
      double                      held_thermal_energy = 0.;
    };
    /// The copy of the last keep().
    Kept kept;

    // Whether the held temperature has the layout of the present fields on every rank (not
    // after a conversion of the adaptive region). Collective.
    bool
    holds_layout() const;

    // The change of the FE energy from the held temperature to the present one at the state of
    // the work of the loads (U_0) and at the present one (U_1) [J].
    std::array<double, 2>
    fe_temperature_changes() const;

    // Add the mean of @p changes, E(u, T_1) - E(u, T_0) at the step's start and end, to the
    // temperature's work (and their mean magnitude to the energy it moved), then hold the
    // present temperature.
    void
    add_temperature_work(const std::array<double, 2> &changes);

    // The parts of stored_parts() of @p state, a CoupledState or a const one.
    template <typename State>
    static Parts<std::is_const_v<State>>
    parts_of(State &state);

    // The problem's parts (the accessors above).
    const MPI_Comm              mpi_communicator;
    std::ostream               &log_stream;
    const bool                  root;
    const ProblemSettings<dim> &problem_settings;
    ParticleRegion<dim>        &particle_region;
    FERegion<dim>              &fe_region;
    CouplingMethod<dim>        &coupling_method;
    const FieldLayout           field_layout;

    // What setup() derives: motion(), any_particle_slaved(), inertia_ratio(), and the factors
    // from the internal and the applied force density to the load that does work: -V_i and 0
    // on prescribed components (the support balances the internal force), 0 and V_i on the
    // others (particles slaved to the FE field too: they move with it); in runs in time
    // (explicit, implicit) 0 on temperature components, whose heat flows the heat factors take
    // instead (empty without a temperature and in quasi-static runs, whose temperature's
    // balance is that of the work).
    std::vector<Motion> component_motion;
    bool                slaved_anywhere = false;
    std::vector<double> inertia_ratios;
    std::vector<double> internal_work_factor, applied_work_factor;
    std::vector<double> internal_heat_factor, applied_heat_factor;
    // The particle components whose load can do work (accumulate_work()): those with an
    // internal work factor, and those with an applied one if a load acts.
    std::vector<std::size_t> work_components;

    // The hooks of set_adaptive_region(), set_other_physics() and set_broken_bond_record().
    std::function<bool(unsigned int, double)>               adaptation;
    unsigned int                                            check_interval = 0;
    std::function<void(unsigned int, double, double, bool)> advance_physics;
    bool                                                    physics_within_step = false;
    std::vector<unsigned int>                              *broken_bond_record  = nullptr;
    // The hook of set_temperature(), whether the FE thermal load is assembled, and the applied
    // plus thermal FE loads of fe_equation_load().
    std::function<void(double)> temperature_update;
    bool                        fe_thermal = false;
    mutable FEVector            fe_total_load;

    // The state at the previous accumulate_work() and the work done so far on this rank.
    FEVector       previous_fe_load, previous_U;
    ParticleVector previous_u, previous_load;
    double         local_work = 0.;
    // The energy released by the bonds broken on this rank since start_work(), the work of the
    // changing temperature and the energy it moved (on rank 0).
    double local_dissipated = 0., local_temperature_work = 0., local_temperature_scale = 0.;
    // The temperature of hold_temperature(): the particles' temperature change, the FE thermal
    // load and energy.
    ParticleVector held_temperature_change;
    FEVector       held_thermal_load;
    double         held_thermal_energy = 0.;
    // Scratch of accumulate_temperature_jump(): the model's forces and energy density at the
    // held temperature.
    ParticleVector      held_force;
    std::vector<double> held_energy_density;
    // The heat in through the conditions on this rank since start_work(), and the stored heat
    // then.
    double local_heat_in = 0., stored_heat_at_start = 0.;
    // The FE field of a temperature: per dof the column sum of the FE stiffness, the conductance
    // of its convection faces (empty otherwise).
    FEVector fe_convection;
  };
} // namespace perideal

#endif
