// ---------------------------------------------------------------------
// PeriDeal: a problem with an FE region and particles joined through an overlap zone.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_coupled_problem_h
#define perideal_coupling_coupled_problem_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/energy_balance.h>
#include <perideal/base/statistics_file.h>
#include <perideal/coupling/coupling_method.h>
#include <perideal/coupling/transfer_operator.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/pd_problem.h>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief FE far field and PD particles solving one problem, blended in an overlap zone.
   *
   * The blending function beta(x) in [0, 1] (<Coupling/Blending function>: 1 where only PD
   * acts, 0 where only FE acts) weights the energies: E = int (1 - beta) W_FE dx +
   * sum_bonds beta_b w_b with beta_b = (beta_i + beta_j) / 2, and the masses likewise.
   * Particles fill the body (<Discretization/Body>) where beta > 0 and within a horizon of it;
   * FE cells where 1 - beta vanishes carry FE_Nothing. Particles inside FE-carrying cells are
   * slaved to the FE field through the TransferOperator P (u = P U, forces back with P^T), the
   * others are free. <Solver/Type> = explicit: velocity Verlet on (FE dofs, free particles) with
   * the lumped FE mass plus P^T of the slaved particles' masses, and the mass-proportional
   * damping of <Time stepping/Damping> on both. <Solver/Type> = static: the
   * equilibrium of the energy linearized about the reference configuration (CoupledStaticSolver)
   * in <Solver/Load steps> load steps, re-solved while bonds break; it prints the reactions of
   * the FE and PD displacement conditions against the applied loads (force balance), the strain
   * energy against the work of the loads and, if <Coupling/Exact displacement> is given, the
   * largest displacement error at the FE nodes and the particles. <Solver/Type> = adaptive
   * dynamic relaxation: the same load steps, the unknowns of the static solve relaxed with the
   * model's own forces (model_forces()), fictitious density from the Gershgorin bound of the
   * static K (CoupledStaticSolver::row_bounds()).
   *
   * Checked before any heavy work: beta in [0, 1]; the transition 0 < beta < 1 at least a
   * horizon wide (no bond joins a particle with beta = 1 to one with beta = 0); every particle
   * inside the mesh; PD boundary conditions only on free particles. Any material model: the
   * PD energy is sum_i beta_i W_i V_i (ParticleSystem::energy_weights()), which for the
   * bond-based model weights each bond by (beta_i + beta_j) / 2.
   *
   * Either region may be empty: beta = 1 on the whole mesh leaves no FE unknowns (every
   * particle free), beta = 0 on the whole body leaves no particles. The run is then the other
   * region's problem alone through this code path, with the same numbers as PDProblem and
   * FEProblem (tests/coupling/empty_region_01).
   */
  template <int dim>
  class CoupledProblem
  {
  public:
    CoupledProblem(const MPI_Comm comm, std::ostream &log);

    static void
    declare_parameters(dealii::ParameterHandler       &prm,
                       const std::vector<std::string> &region_names,
                       const std::vector<std::string> &condition_names,
                       const std::vector<std::string> &fe_condition_names);
    void
    parse_parameters(dealii::ParameterHandler &prm);
    void
    setup();
    void
    run();

    /// The particles (after setup()).
    const ParticleSystem<dim> &
    particles() const;

    /// The particles' displacement after run() (owned entries).
    const ParticleVector &
    particle_displacement() const;

    /// The FE displacement after run() (owned entries).
    const dealii::LinearAlgebra::distributed::Vector<double> &
    fe_displacement() const;

    /// The FE region (its mesh and dofs after setup()).
    const FERegion<dim> &
    fe_region() const;

    /// The explicit time step (after setup() of an explicit run) [s].
    double
    time_step() const;

    /// beta at @p x (values within 1e-10 of 0 or 1 snapped to them).
    double
    blending(const dealii::Point<dim> &x) const;

  private:
    using FEVector = dealii::LinearAlgebra::distributed::Vector<double>;

    void
    check_blending() const;
    void
    run_explicit();
    void
    run_static();
    /**
     * @brief One statistics row of a static run (and the summary after the last load step):
     * energies, reactions, force balance, and the error against the exact displacement.
     */
    void
    write_static_statistics(const unsigned int step,
                            const double       factor,
                            const unsigned int iterations,
                            const double       pd_energy,
                            const bool         final_row);
    /**
     * @brief Forces and accelerations of both regions at @p time (P U into the slaved
     * particles first); the particles' energy density only if @p with_energy.
     */
    void
    compute_acceleration(const double time, const bool with_energy);
    /**
     * @brief Start the work of the loads at 0 from the current state.
     */
    void
    start_work(const ParticleVector &applied);
    /**
     * @brief Add the work of the loads from the previous state to the current one (trapezoidal
     * rule in the loads) and make the current state the previous one; @p applied is the
     * applied force density on the particles.
     */
    void
    accumulate_work(const ParticleVector &applied);
    /// Whether the problem has both regions (particles and an FE mesh).
    bool
    is_coupled() const;
    /**
     * @brief The mass-proportional damping of <Time stepping/Damping>: A -= c V on the free FE
     * dofs, a -= c v on the free components of free particles.
     */
    void
    add_damping();
    /**
     * @brief Print the largest unbalanced force at t = 0 relative to the FE internal-force
     * scale: the ghost force when the initial state is one the model reproduces exactly.
     */
    void
    report_initial_residual();
    /**
     * @brief Print "@p what: R N ..., relative to the FE internal-force scale: R / S" with R, S
     * the largest of @p local_largest and @p local_scale over the ranks (root only; R below
     * 1e-12 S is round-off and printed as 0; without FE unknowns only R).
     */
    void
    log_residual(const std::string &what,
                 const double       local_largest,
                 const double       local_scale) const;
    void
    write_statistics(const unsigned int step, const double time, const bool final_row);
    void
    write_output(const unsigned int step, const double time);
    /**
     * @brief Print the broken bonds and the largest particle displacement (if there are
     * particles) and the largest FE nodal displacement component (if there are FE unknowns);
     * root only.
     */
    void
    log_displacements(const std::uint64_t broken,
                      const double        max_particle,
                      const double        max_fe) const;
    /**
     * @brief Print the reactions of the PD and FE displacement conditions (root only).
     */
    void
    log_reactions(const std::vector<dealii::Tensor<1, dim>> &pd_reactions,
                  const std::vector<dealii::Tensor<1, dim>> &fe_reactions) const;

    MPI_Comm      comm;
    std::ostream &log;
    bool          is_root;

    PDProblem<dim>                               pd;
    FERegion<dim>                                fe;
    TransferOperator<dim>                        transfer;
    std::string                                  method_name;
    std::unique_ptr<CouplingMethod<dim>>         method;
    std::string                                  blending_expression;
    std::unique_ptr<dealii::FunctionParser<dim>> beta;
    std::unique_ptr<dealii::FunctionParser<dim>> exact_displacement;
    double                                       exact_tolerance = 0.;

    double              dt = 0., stable_dt = 0.;
    FEVector            U, V, A, mass, f_ext, residual, fe_load, previous_fe_load, previous_U;
    std::vector<double> particle_volume_weight;
    /// How each owned particle component moves: with the FE field (slaved particles), by its
    /// acceleration (free), or by a PD displacement or velocity condition (free, prescribed).
    enum class Motion : unsigned char
    {
      follows_fe,
      moves,
      prescribed
    };
    std::vector<Motion> motion;
    std::vector<double> particle_mass;
    // Per owned particle component: force density to acceleration (explicit runs), and the
    // internal and applied force density to the load that does work (accumulate_work()).
    std::vector<double> acceleration_factor, internal_work_factor, applied_work_factor;
    ParticleVector      nodal_force;
    // Static runs: the applied loads at the current load factor and the FE residual K z - F.
    FEVector                        static_fe_load;
    ParticleVector                  static_pd_load;
    std::vector<unsigned int>       fe_dof_component;
    double                          local_work = 0.;
    EnergyBalance                   energy_balance;
    std::unique_ptr<StatisticsFile> statistics;
  };
} // namespace perideal

#endif
