// ---------------------------------------------------------------------
// PeriDeal: the one driver of every problem (particles, an FE region, or both).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_coupled_problem_h
#define perideal_coupling_coupled_problem_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/problem_settings.h>
#include <perideal/coupling/adaptive_region.h>
#include <perideal/coupling/checkpoint.h>
#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/coupling_method.h>
#include <perideal/coupling/physics.h>
#include <perideal/coupling/physics_exchange.h>
#include <perideal/coupling/postprocessors/postprocessor.h>
#include <perideal/coupling/solvers/quasi_static_control.h>
#include <perideal/coupling/solvers/solver.h>
#include <perideal/coupling/temperature_source.h>
#include <perideal/coupling/thermoelastic_heating.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/particle_region.h>

#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace perideal
{
  /**
   * @brief The driver of every run: an FE far field and PD particles solving one problem,
   * joined in an overlap zone by a coupling method; either region may be empty.
   *
   * It only wires the parts together: the problem's settings (ProblemSettings), the particle
   * region (ParticleRegion), the FE region (FERegion), the coupling method (<Coupling/Method>,
   * which owns the coupling), the state both regions share (CoupledState), the solver of
   * <Solver/Type> (create_solver(): ExplicitDynamics or LoadStepping) and the postprocessors
   * (energies, displacements, reactions, the error against <Coupling/Exact displacement>,
   * probes, field output).
   *
   * The blending function beta(x) in [0, 1] (<Coupling/Blending function>: 1 where only PD
   * acts, 0 where only FE acts) gives, through the method's weights, where FE unknowns and
   * particles exist: particles fill the body (<Discretization/Body>) where the particle weight
   * is positive and within a horizon of it; FE cells where the FE weight vanishes carry
   * FE_Nothing. The method decides which particles are slaved to the FE field (the blended method:
   * those inside FE-carrying cells, u = P U), the others are free. Checked before any heavy
   * work: beta in [0, 1] (here), what the method needs of the overlap (its initialize(); the
   * blended method: a transition 0 < beta < 1 at least a horizon wide); PD boundary conditions
   * only on free particles.
   *
   * A file without a mesh is the coupled problem with beta = 1 and an FE region without
   * unknowns; a file without <Discretization/Body> is the one without particles
   * (tests/coupling/empty_region_01).
   *
   * The problem holds a list of physics (Physics): the first one, of the top-level sections,
   * and those of <Physics/List> (e.g. heat), which share its particles, their bonds and its
   * mesh, and are advanced by operator splitting within its steps
   * (doc/architecture/16_multiphysics.md). A file without <Physics/List> has one physics and
   * runs as before.
   */
  template <int dim>
  class CoupledProblem
  {
  public:
    /// @brief A problem on the ranks of @p comm that writes its log to @p log (on rank 0).
    CoupledProblem(const MPI_Comm comm, std::ostream &log);

    /**
     * @brief Declare every entry of a parameter file: the problem's settings, the particle
     * region with the regions @p region_names and the particle boundary conditions
     * @p condition_names, the FE region with its boundary conditions @p fe_condition_names, the
     * coupling, every registered plugin's subsection and the subsections of the physics of
     * <Physics/List> with their boundary conditions @p physics_condition_names.
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &region_names,
                       const std::vector<std::string> &condition_names,
                       const std::vector<std::string> &fe_condition_names,
                       const std::map<std::string, typename Physics<dim>::ConditionNames>
                         &physics_condition_names = {});

    /// Read and check every entry on its own; creates nothing on disk.
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Every check that needs the entries, the mesh and the regions' geometry but no
     * state, solver or output (what perideal-solid --validate runs after parse_parameters(),
     * and what setup() starts with): the FE mesh and its dofs (a held point inside the mesh),
     * the particles, their bonds and the model's calibration (the model's limits, e.g. the
     * Poisson ratio of timoshenko bond based, the Cauchy relations and the fracture energy
     * interpolation of anisotropic bond based, a twist axis inside the section), beta in
     * [0, 1], the adaptive region's seeds and the coupling method's overlap (a ramp at least a
     * horizon wide), the state (no condition on particles slaved to the FE field) and the
     * solver's checks (Solver::check(): conditions it can apply, rigid motions held, a
     * conforming mesh for quasi-static solves) and the postprocessors' (probe points on
     * particles, the fracture measures' load point). Builds no matrix and writes nothing on
     * disk.
     */
    void
    check();

    /// check(), then the solver's set-up (its matrices); writes nothing on disk.
    void
    setup();

    /**
     * @brief Continue from the checkpoint in <Output/Directory> (perideal-solid --restart)
     * instead of starting from the initial conditions. Before run().
     */
    void
    restart_from_checkpoint();

    /**
     * @brief End the run after writing the checkpoint of step @p step (a run interrupted
     * there, for the tests of the restart). Before run().
     */
    void
    stop_after_step(const unsigned int step);

    /**
     * @brief Call @p observer on every rank just before (with false) and just after (with true)
     * each conversion of the adaptive PD region, when the particles and their bond histories
     * (particles(), material()) are those of either side: what the tests of a conversion compare.
     * Before run().
     */
    void
    observe_conversions(std::function<void(bool after)> observer);

    /// Run the solver with the postprocessors (which create the output directory and files).
    void
    run();

    /// The particles (after setup()).
    const ParticleSystem<dim> &
    particles() const;

    /// The material model of the particles (after setup()).
    const MaterialModel<dim> &
    material() const;

    /// The particles' displacement after run() (owned entries).
    const ParticleVector &
    particle_displacement() const;

    /// The FE displacement after run() (owned entries).
    const FEVector &
    fe_displacement() const;

    /// The FE region (its mesh and dofs after setup()).
    const FERegion<dim> &
    fe_region() const;

    /// The explicit time step (after setup() of an explicit run) [s].
    double
    time_step() const;

    /// The physics of the problem, the first one first (after parse_parameters()).
    const std::vector<std::unique_ptr<Physics<dim>>> &
    get_physics() const;

    /// What the physics publish for each other (after check()).
    const PhysicsExchange<dim> &
    get_exchange() const;

    /// beta at @p x (values within 1e-10 of 0 or 1 snapped to them).
    double
    blending(const dealii::Point<dim> &x) const;

    /**
     * @brief Stop, naming the material model's <Twist axis>, unless its twist axis
     * (MaterialModel::torsion(), if any) lies in the whole body: the extent in x and y of the
     * particles' lattice cells and the FE mesh together (Torsion::check_axis()), so that a PD
     * region away from the axis, e.g. around an edge crack, is accepted. After the particles
     * are made (setup() calls it); collective.
     */
    void
    check_twist_axis() const;

  private:
    /**
     * @brief Stop, naming <Coupling/Blending function>, if beta leaves [0, 1] at a particle or
     * FE vertex.
     */
    void
    check_blending() const;

    /**
     * @brief The particles: where the method's particle weight is positive and a horizon
     * around; the summary lines in the log if @p log_summary.
     */
    void
    setup_particles(const bool log_summary = true);

    /// What the coupling method of @p field works on (CouplingMethod::initialize()).
    CoupledRegions<dim>
    coupled_regions(Physics<dim> &field);

    /**
     * @brief Read <Physics/List> and every listed physics' subsection, and refuse what the
     * physics of a list do not support yet (in parse_parameters()).
     */
    void
    parse_other_physics(dealii::ParameterHandler &prm);

    /**
     * @brief The checks and the state, solver and postprocessors of each physics of
     * <Physics/List> (in check(), after the first physics').
     */
    void
    check_other_physics();

    /**
     * @brief The solvers of the physics of <Physics/List> (their stable steps, their sub-steps
     * within a step of the first physics) and their hook into the first one's run: their
     * columns in its statistics, their advance within each of its steps.
     */
    void
    setup_other_physics();

    /**
     * @brief Read <Temperature> and check the thermal strain against the models, the FE
     * physics, the physics list and the solver (coupled_problem_thermal.cc): every refusal
     * before any heavy work, naming the entries.
     */
    void
    parse_thermal_strain(dealii::ParameterHandler &prm);

    /**
     * @brief Stop, naming the entry and the accepted values, if the problem cannot run
     * <Temperature/Coupling> = two way (ThermoelasticHeating): a model without the
     * thermoelastic measure, a quasi-static mechanics, a heat that is not explicit, checkpoints,
     * an adaptive PD region.
     */
    void
    check_two_way(dealii::ParameterHandler &prm) const;

    /**
     * @brief Give the first physics its temperature (TemperatureSource::connect()) and its
     * state the hook that updates it; nothing without a source. Again after a conversion of the
     * adaptive region.
     */
    void
    connect_temperature();

    /**
     * @brief A two-way coupling: the coupling numbers delta = T_0 beta : alpha / (rho c) of the
     * particles' model and of the FE elasticity with the heat's smallest capacity
     * (CoupledState::particle_coupling_number, fe_coupling_number), which lower the mechanics'
     * stable step (doc/theory/thermoelasticity.md, "The stable time step").
     */
    void
    set_coupling_numbers();

    /**
     * @brief The sub-steps of the physics @p k of <Physics/List> within a step of the first
     * physics: the fewest whose step is at most the one its solver chose (the safety factor
     * times its stable step); their length goes to its CoupledState::time_step and to
     * sub_steps; logged. At the set-up and after each conversion of the adaptive PD region.
     */
    void
    choose_sub_steps(const unsigned int k);

    /**
     * @brief Advance the physics of <Physics/List> by operator splitting over step @p step of
     * the first physics, from @p time by @p dt (step 0: their initial state), their energies
     * computed if @p with_energy (CoupledState::advance_other_physics()): the fewest equal
     * steps of at most its step of setup_other_physics() (the sub-steps of an explicit physics
     * in a step of split_step(); fewer over a cut load step).
     */
    void
    advance_other_physics(const unsigned int step,
                          const double       time,
                          const double       dt,
                          const bool         with_energy);

    /**
     * @brief The time a step of the first physics spans [s]: its explicit step as its run
     * takes it (equal steps to the end time), or <Time stepping/End time> over the load steps
     * of a quasi-static run.
     */
    double
    split_step() const;

    /**
     * @brief The adaptive PD region of an explicit run (CoupledState::adapt_regions()) after step
     * @p step at @p time: the criterion's seeds, if any, grow the PD region; the particles, the
     * FE spaces, the couplings and the states of every physics are rebuilt and the unknowns
     * carried over (free particles keep theirs and their broken bonds, the others take the FE
     * field's, the FE dofs keep their values cell by cell); the other physics' solvers renew
     * their masses or matrices, forces and sub-steps, and a temperature's stored heat change
     * is summed in its CoupledState::conversion_energy. Returns whether the regions changed. In
     * coupled_problem_conversion.cc.
     */
    bool
    convert_regions(const unsigned int step, const double time);

    MPI_Comm      comm;
    std::ostream &log;
    bool          is_root;

    /// The physics, the first one (of the top-level sections) first.
    std::vector<std::unique_ptr<Physics<dim>>> physics;
    /// The first physics' parts: its settings (the problem's), unknowns, regions (which own the
    /// geometry the other physics share) and <Coupling/Method>.
    ///@{
    ProblemSettings<dim> &settings;
    FieldLayout          &layout;
    ParticleRegion<dim>  &pd;
    FERegion<dim>        &fe;
    std::string          &method_name;
    ///@}
    /// <Solver/Control>: how a quasi-static run advances its load, and its load point.
    QuasiStaticControl control;
    /// Per physics of <Physics/List>: the length of its steps [s] (its explicit sub-step, which
    /// divides a step of the first physics; that step otherwise).
    std::vector<double> sub_steps;
    /// What the physics publish for each other, and the bonds they share.
    PhysicsExchange<dim> exchange;
    // The temperature of the first physics' thermal strain.
    TemperatureSource<dim> temperature;
    // The heating of the heat by the first physics' deformation (<Temperature/Coupling> = two
    // way; connected in setup_other_physics()).
    ThermoelasticHeating<dim> heating;
    std::string               blending_expression;
    /// <Coupling/Adaptive region>: where the PD region grows during an explicit run.
    AdaptiveRegion<dim> adaptive;
    /// observe_conversions().
    std::function<void(bool)> conversion_observer;
    /// The damage index of each owned particle with only the pre-cracks' bonds broken (runs
    /// with an adaptive region).
    std::vector<double>                          precrack_damage;
    std::unique_ptr<dealii::FunctionParser<dim>> beta;
    std::shared_ptr<dealii::FunctionParser<dim>> exact_displacement;
    double                                       exact_tolerance = 0.;
    /// <Postprocess/List>, with the mandatory postprocessor (Postprocessors::parse_parameters()).
    std::vector<std::string> postprocessor_names;

    bool         restart   = false;
    unsigned int stop_step = Checkpoint<dim>::no_step;
    /// Set by a restart with several physics: the other physics' solvers resume before their
    /// first step (Solver::resume_state()).
    bool resume_other_physics = false;

    /// The first physics' coupling method, state, solver and postprocessors (its accessors).
    ///@{
    CouplingMethod<dim> &
    method()
    {
      return physics[0]->method();
    }

    const CouplingMethod<dim> &
    method() const
    {
      return std::as_const(*physics[0]).method();
    }

    CoupledState<dim> &
    state()
    {
      return physics[0]->state();
    }

    const CoupledState<dim> &
    state() const
    {
      return std::as_const(*physics[0]).state();
    }

    Solver<dim> &
    solver()
    {
      return physics[0]->solver();
    }

    Postprocessors<dim> &
    postprocessors()
    {
      return physics[0]->postprocessors();
    }
    ///@}
  };
} // namespace perideal

#endif
