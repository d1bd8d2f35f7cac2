// ---------------------------------------------------------------------
// PeriDeal: the settings of a whole problem (solver, time stepping, initial conditions, output).
// ---------------------------------------------------------------------
#ifndef perideal_base_problem_settings_h
#define perideal_base_problem_settings_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief How a problem is solved (<Solver/Type>).
   *
   * - explicit_dynamics: velocity-Verlet time stepping to the end time (dynamics);
   * - adaptive_dynamic_relaxation: quasi-static equilibrium by adaptive dynamic relaxation, in
   *   load steps, with bond breaking;
   * - static_linear: quasi-static equilibrium of the model linearized about the reference
   *   configuration (a sparse linear solve), in load steps, with bond breaking;
   * - implicit: the theta scheme of a first-order field (a temperature) to the end time, a
   *   sparse linear solve of the linearized model plus the lumped capacity per time step.
   */
  enum class SolverType
  {
    explicit_dynamics,
    adaptive_dynamic_relaxation,
    static_linear,
    implicit
  };

  /**
   * @brief The solver type named by a value of <Solver/Type> (the one place that maps names).
   */
  SolverType
  solver_type_from_name(const std::string &name);

  /**
   * @brief The linear solver of static solves (<Solver/Linear solver>): conjugate gradients with
   * algebraic multigrid (Trilinos ML) or a direct solver (Amesos KLU).
   */
  enum class LinearSolverType
  {
    cg_amg,
    direct
  };

  /**
   * @brief A quasi-static solve that stopped without equilibrium: the relaxation or the linear
   * solver reached <Solver/Maximum iterations> before <Solver/Tolerance>, or the linear solve
   * failed (a singular or nearly singular system). The message names the entries to change.
   * The solvers throw it on every rank at once (their tests are on global quantities), so that
   * the load stepping can catch it and write, collectively, the state for inspection and the
   * checkpoint of the last converged load step before the run stops.
   */
  DeclException1(ExcNotConverged, std::string, << arg1);

  /**
   * @brief The settings of a problem that belong to neither region: the solver (<Solver>),
   * time stepping (<Time stepping>), initial conditions (<Initial conditions>), the body force
   * (<Body force>) and output (<Output>), plus <Dimension>. Declared and read in one place; the
   * regions, the solvers and the postprocessors read them from here.
   */
  template <int dim>
  struct ProblemSettings
  {
    /// Declare <Dimension>, <Solver>, <Time stepping>, <Initial conditions>, <Body force> and
    /// <Output>.
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Declare what each field of a problem has of its own: <Initial conditions> and
     * <Body force>, in the current subsection (the top level, or a physics' own, e.g.
     * <Heat>).
     */
    static void
    declare_field_parameters(dealii::ParameterHandler &prm);

    /// @brief Read the entries of declare_field_parameters() in the current subsection.
    void
    parse_field_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read and check the entries of declare_parameters(). The expressions of the
     * initial conditions and the body force are kept as text: their number of components is
     * the field's (FieldLayout), which the driver knows once the regions are read.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief The accuracy of a quasi-static solution relative to its largest force: round-off
     * (1e-10) for a direct static solve; else 100 <Solver/Tolerance>, the residual an iterative
     * solve or a relaxation leaves (its tolerance times its force scale, a norm over every
     * unknown, which exceeds the largest load or reaction by up to the square root of the
     * number of loaded unknowns). Printed summaries show forces and relative energy errors
     * to this accuracy, so that they read the same on every machine: where a relaxation stops
     * depends on the summation order, i.e. on the SIMD width of the force kernels.
     */
    double
    solution_accuracy() const;

    /// The entries of subsection <Solver>: type, load steps, tolerance, iterations, density
    /// safety factor of adaptive dynamic relaxation, linear solver.
    ///@{
    SolverType       solver_type           = SolverType::explicit_dynamics;
    unsigned int     load_steps            = 1;
    double           tolerance             = 1e-8;
    unsigned int     max_iterations        = 100000;
    double           density_safety_factor = 1.;
    LinearSolverType linear_solver         = LinearSolverType::cg_amg;
    ///@}

    /// The entries of subsection <Time stepping>: end time and time step [s], safety factor of
    /// the stable step, mass-proportional damping [1/s].
    ///@{
    double end_time = 0., time_step = 0., safety_factor = 0.8, damping = 0.;
    ///@}

    /// <Time stepping/Theta>: the weight of the new state in the implicit theta scheme, in
    /// [1/2, 1] (1: backward Euler, 1/2: Crank-Nicolson).
    double theta = 1.;

    /// <Initial conditions>: one expression per component, or "0".
    ///@{
    std::string initial_displacement = "0", initial_velocity = "0";
    ///@}

    /// <Body force/Function>: one expression per component, or "0".
    std::string body_force = "0";

    /// The entries of subsection <Output>: directory, base name, intervals of field output,
    /// statistics and checkpoints (in steps), formats, progress report.
    ///@{
    std::string output_directory = "output", base_name = "particles";
    /// The base name of the FE field output (not an entry): "solution", and
    /// "solution_<name>" for a physics of <Physics/List>, whose particle output is
    /// <Base name>_<name>.
    std::string  solution_name   = "solution";
    unsigned int output_interval = 0, statistics_interval = 10, checkpoint_interval = 0;
    ///@}
    /// <Checkpoint time interval>: simulated time [s] (explicit) or load factor (quasi-static).
    double checkpoint_time_interval = 0.;
    /// <Write HDF5>, <Write VTU>, <Progress>.
    ///@{
    bool write_hdf5 = true, write_vtu = false, show_progress = true;
    ///@}
    /// <Probe points>: the points whose displacements the statistics list [m].
    std::vector<dealii::Point<dim>> probe_points;
  };
} // namespace perideal

#endif
