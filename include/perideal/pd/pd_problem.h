// ---------------------------------------------------------------------
// PeriDeal: a peridynamic problem driven by a parameter file.
// ---------------------------------------------------------------------
#ifndef perideal_pd_pd_problem_h
#define perideal_pd_pd_problem_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/energy_balance.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/base/particle_output.h>
#include <perideal/base/region.h>
#include <perideal/base/statistics_file.h>
#include <perideal/pd/boundary_conditions.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>
#include <perideal/pd/static_solver.h>

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace perideal
{
  template <int dim>
  class CoupledProblem;

  /**
   * @brief How PDProblem::run() solves (<Solver/Type>).
   *
   * - explicit: velocity-Verlet time stepping to the end time (dynamics);
   * - adaptive_dynamic_relaxation: quasi-static equilibrium by AdaptiveDynamicRelaxation, in
   *   load steps, with bond breaking;
   * - static: quasi-static equilibrium of the model linearized about the reference
   *   configuration (StaticSolver), in load steps, with bond breaking.
   */
  enum class SolverType
  {
    explicit_dynamics,
    adaptive_dynamic_relaxation,
    static_linear
  };

  /**
   * @brief The solver type named by a value of <Solver/Type> (the one place that maps names).
   */
  SolverType
  solver_type_from_name(const std::string &name);

  /**
   * @brief A peridynamic problem: particles, a material and damage model, boundary conditions,
   * explicit time stepping or a quasi-static solve, and output, all read from a parameter file.
   *
   * Quasi-static solves (<Solver/Type> = adaptive dynamic relaxation or static) apply the
   * prescribed displacements and the loads of the boundary conditions, evaluated at t = End
   * time, scaled by the load factor k/N in N load steps. After each converged step the bonds are
   * checked against the critical stretch; while bonds break, the step is solved again (at most
   * 100 times). A statistics row is written per load step (column 'time' holds the load factor)
   * and the particle fields at the end.
   *
   * Use: declare_parameters() with the region and boundary-condition names of a first pass,
   * parse the file, parse_parameters() (checks every entry), setup() (particles, bonds, model
   * constants, stable time step; checks the time step), run().
   */
  template <int dim>
  class PDProblem
  {
  public:
    /**
     * @brief A problem on @p comm that prints its log to @p log (rank 0 only).
     */
    PDProblem(const MPI_Comm comm, std::ostream &log);

    /**
     * @brief Declare every entry; the subsections of regions and boundary conditions are those
     * named in @p region_names and @p condition_names.
     */
    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &region_names,
                       const std::vector<std::string> &condition_names);

    /**
     * @brief Read and check all parameters; creates nothing on disk.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Generate the particles and bonds, initialize the model, choose the time step.
     * Particles fill the lattice points of the body that also satisfy @p keep (if given; a
     * coupled problem keeps only the PD region); @p energy_weight (if given) weights each
     * particle's energy (ParticleSystem::set_energy_weights()).
     */
    void
    setup(const std::function<bool(const dealii::Point<dim> &)>   &keep          = {},
          const std::function<double(const dealii::Point<dim> &)> &energy_weight = {});

    /**
     * @brief Integrate to the end time or solve the load steps, writing statistics and particle
     * output.
     */
    void
    run();

    /// The particles.
    const ParticleSystem<dim> &
    particles() const;
    /// The displacement (owned and ghost values).
    const ParticleVector &
    displacement() const;
    /// The time step in use [s].
    double
    time_step() const;

  private:
    // A coupled problem drives the particle side through the same state and output.
    friend class CoupledProblem<dim>;

    void
    run_explicit();
    void
    run_quasi_static();
    /**
     * @brief The load that does work on the body, per particle [N]: the applied loads, and on
     * prescribed components the force the constraint exerts (minus the internal force; the
     * constrained particles' inertia is accounted for through their kinetic energy).
     */
    void
    compute_work_load(ParticleVector &load) const;
    /**
     * @brief Add the work done from previous_u to u (trapezoidal rule in the loads), then keep
     * the current load in previous_load and u in previous_u for the next step (one pass).
     */
    void
    accumulate_external_work();
    void
    compute_acceleration(const double time, ParticleVector &u, ParticleVector &a);
    /**
     * @brief Size the state vectors, set the initial conditions (the initial velocity only for
     * explicit runs) and open the output: shared by every solver type.
     */
    void
    start_run();
    /**
     * @brief Create <Output/Directory>, open its statistics file into @p statistics_file and
     * the particle output (also used by the coupled problem, which keeps its own statistics).
     */
    void
    open_output(std::unique_ptr<StatisticsFile> &statistics_file);
    void
    write_statistics(const unsigned int step, const double time, const bool final_row);
    void
    write_particles(const unsigned int step, const double time);
    /**
     * @brief Find the particle nearest to each of <Output/Probe points> (ties go to the
     * lexicographically smallest position, so the choice does not depend on the partition);
     * throws, naming the entry, if a point has no particle within one lattice spacing.
     * Collective.
     */
    void
    locate_probes();
    /**
     * @brief Print the displacement of each probe's particle (rank 0, in micrometres: the final
     * summaries' values that application tests compare must lie above numdiff's absolute
     * tolerance of 1e-6). Collective.
     */
    void
    log_probes() const;

    MPI_Comm      communicator;
    std::ostream &log;
    bool          is_root;

    // Parameters.
    typename ParticleSystem<dim>::Settings       discretization;
    double                                       horizon_factor     = 0.;
    bool                                         surface_correction = true;
    PlanarAssumption                             planar = PlanarAssumption::three_dimensional;
    RegionCollection<dim>                        regions;
    std::vector<std::string>                     body_regions;
    std::vector<std::string>                     no_fail_regions;
    std::vector<PreCrack<dim>>                   pre_cracks;
    std::unique_ptr<MaterialModel<dim>>          material;
    std::unique_ptr<DamageModel<dim>>            damage;
    double                                       density = 0.;
    BoundaryConditions<dim>                      boundary_conditions;
    std::unique_ptr<dealii::FunctionParser<dim>> initial_displacement, initial_velocity;
    double                                       end_time = 0., requested_time_step = 0.;
    double                                       safety_factor = 0.8, damping = 0.;
    std::string                                  output_directory, base_name;
    std::vector<dealii::Point<dim>>              probe_points;
    unsigned int                                 particle_interval = 0, statistics_interval = 1;
    bool                                 write_hdf5 = true, write_vtu = false, show_progress = true;
    SolverType                           solver_type               = SolverType::explicit_dynamics;
    double                               relaxation_tolerance      = 1e-8;
    unsigned int                         relaxation_max_iterations = 100000;
    double                               relaxation_safety         = 1.;
    unsigned int                         load_steps                = 1;
    typename StaticSolver<dim>::Settings static_settings;

    // State.
    ParticleSystem<dim>                  particle_system;
    double                               critical_stretch = 0.;
    double                               dt               = 0.;
    double                               stable_dt        = 0.;
    ParticleVector                       u, v, a, internal_force, external_force;
    std::vector<double>                  energy_density;
    double                               local_external_work = 0.;
    EnergyBalance                        energy_balance;
    ParticleVector                       previous_u, previous_load;
    std::unique_ptr<StatisticsFile>      statistics;
    std::unique_ptr<ParticleOutput<dim>> particle_output;
    // Per probe: the position of its particle, and the particle's local index on the rank that
    // owns it (numbers::invalid_unsigned_int elsewhere).
    std::vector<dealii::Point<dim>> probe_particles;
    std::vector<unsigned int>       probe_local_index;
  };
} // namespace perideal

#endif
