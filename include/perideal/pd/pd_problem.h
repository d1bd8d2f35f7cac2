// ---------------------------------------------------------------------
// PeriDeal: a peridynamic problem driven by a parameter file.
// ---------------------------------------------------------------------
#ifndef perideal_pd_pd_problem_h
#define perideal_pd_pd_problem_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

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
   * @brief How CoupledProblem::run() solves (<Solver/Type>).
   *
   * - explicit: velocity-Verlet time stepping to the end time (dynamics);
   * - adaptive_dynamic_relaxation: quasi-static equilibrium by AdaptiveDynamicRelaxation, in
   *   load steps, with bond breaking;
   * - static: quasi-static equilibrium of the model linearized about the reference
   *   configuration (CoupledStaticSolver), in load steps, with bond breaking.
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
   * @brief The particle region of a problem: its parameters (discretization, regions, material
   * and damage model, boundary conditions, initial conditions, the solver and output entries),
   * the particles with their bonds, and the particle state and output. CoupledProblem, the one
   * driver of every run, reads the file through it and advances its state together with the FE
   * region's.
   *
   * An empty <Discretization/Body> gives no particles (an FE-only problem): only the entries the
   * FE region shares are read then (<Material/Planar assumption>, <Discretization/Thickness>,
   * the solver, time-stepping and output entries).
   *
   * Use: declare_parameters() with the region and boundary-condition names of a first pass,
   * parse the file, parse_parameters() (checks every entry), setup() (particles, bonds, model
   * constants, stable time step).
   */
  template <int dim>
  class PDProblem
  {
  public:
    /**
     * @brief A particle region on @p comm that prints its log to @p log (rank 0 only).
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
     * @brief Generate the particles and bonds, initialize the model, find the stable time step.
     * Particles fill the lattice points of the body that also satisfy @p keep (if given; a
     * coupled problem keeps only the PD region); @p energy_weight (if given) weights each
     * particle's energy (ParticleSystem::set_energy_weights()).
     */
    void
    setup(const std::function<bool(const dealii::Point<dim> &)>   &keep          = {},
          const std::function<double(const dealii::Point<dim> &)> &energy_weight = {});

    /// Whether <Discretization/Body> names regions (otherwise there are no particles).
    bool
    has_body() const;

  private:
    // The driver advances the particle state and writes its output.
    friend class CoupledProblem<dim>;

    /**
     * @brief Create <Output/Directory>, open its statistics file into @p statistics_file and
     * the particle output.
     */
    void
    open_output(std::unique_ptr<StatisticsFile> &statistics_file);
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
    unsigned int                                 output_interval = 0, statistics_interval = 1;
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
    double                               stable_dt        = 0.;
    ParticleVector                       u, v, a, internal_force, external_force;
    std::vector<double>                  energy_density;
    ParticleVector                       previous_u, previous_load;
    std::unique_ptr<ParticleOutput<dim>> particle_output;
    // Per probe: the position of its particle, and the particle's local index on the rank that
    // owns it (numbers::invalid_unsigned_int elsewhere).
    std::vector<dealii::Point<dim>> probe_particles;
    std::vector<unsigned int>       probe_local_index;
  };
} // namespace perideal

#endif
