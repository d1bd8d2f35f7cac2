// ---------------------------------------------------------------------
// PeriDeal: overlapping (alternating) Schwarz coupling of the FE region and the particles.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_schwarz_coupling_h
#define perideal_coupling_schwarz_coupling_h

#include <perideal/coupling/coupled_static_solver.h>
#include <perideal/coupling/coupling_method.h>
#include <perideal/coupling/interface_fit.h>
#include <perideal/coupling/transfer_operator.h>
#include <perideal/pd/adaptive_dynamic_relaxation.h>

#include <memory>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief <Coupling/Method> = overlapping schwarz: the FE part {beta < 1} and the PD part
   * {beta > 0} are solved alternately (multiplicative Schwarz), each with the full, unweighted
   * model of its part, and exchange Dirichlet data in the overlap 0 < beta < 1. No ghost
   * forces: a field both models reproduce (rigid motions, uniform strain) is a fixed point.
   *
   * - PD subproblem: the particles with beta > 0 and no bond to a particle with beta = 0 are
   *   free; the others (a layer of one horizon inside beta > 0, and the particles beyond it
   *   that the driver generates within a horizon) are the nonlocal volume constraint, u = P U
   *   (TransferOperator, the FE field at the particles). Energy weight 1 wherever beta > 0.
   * - FE subproblem: the FE energy weight is 1 where beta < 1 (0 where beta = 1, so cells
   *   entirely in the PD-only zone carry no unknowns); every dof of a cell with a vertex at
   *   beta = 1 (not held by an FE condition) is prescribed (FERegion::set_interior_values()), so
   *   the free dofs see the unweighted FE operator only. Its value is a quadratic
   *   least-squares fit of the particle values of the particle nearest to its support point
   *   and that particle's family (exact for quadratic fields).
   * - Iteration on the interface values x (the prescribed FE dofs): FE solve with x, the
   *   constraint layer from the FE field, PD solve, G(x) the fit of the PD field; r = G(x) - x,
   *   x <- x + omega r with omega = 1, a fixed factor, or Aitken's dynamic factor; converged when
   *   |r| <= <Tolerance> |G(x)|. Both solves are the library's static solve
   *   (CoupledStaticSolver) of one region alone, the PD stiffness assembled (and factorized)
   *   once per load step. With <Solver/Type> = adaptive dynamic relaxation the PD part is
   *   relaxed with the model's own forces instead (warm-started from the last iteration), the
   *   FE part, linear, keeps its static solve.
   *
   * The strain energy counts the FE part on {beta < 1} (1/2 U^T K U with the FE weight) and the
   * particles with beta = 1 (sum_i W_i V_i), so every point of the body once. Solver/Type =
   * static or adaptive dynamic relaxation. See doc/theory/coupling.md, "Overlapping Schwarz".
   */
  template <int dim>
  class SchwarzCoupling : public CouplingMethod<dim>
  {
  public:
    /// How the interface values are updated.
    enum class Relaxation
    {
      none,
      fixed,
      aitken
    };

    /// <Tolerance>, <Maximum iterations>, <Relaxation>, <Relaxation factor>.
    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm) override;
    /// Static and adaptive dynamic relaxation: explicit dynamics is refused.
    void
    check_solver(const SolverType type) const override;
    double
    fe_weight(const double beta) const override;
    double
    particle_weight(const double beta) const override;
    void
    initialize(const CoupledRegions<dim> &regions) override;
    std::string
    summary() const override;
    const std::vector<bool> &
    slaved_particles() const override;
    void
    interpolate_to_particles(const FEVector &U, ParticleVector &u) const override;
    /// Explicit dynamics only, which check_solver() refuses.
    void
    add_particle_forces(const ParticleVector &f, FEVector &F) const override;
    /// 1/2 U^T K U of the FE part {beta < 1} and @p particle_energy, the particles' with beta = 1
    /// (equilibrium_forces()).
    CoupledEnergy
    strain_energy(const FEVector &U, const double particle_energy) const override;
    /// Explicit dynamics only, which check_solver() refuses.
    void
    lumped_masses(FEVector &fe_mass, std::vector<double> &particle_mass) const override;
    void
    initialize_equilibrium(const ParticleVector           &particle_prescribed,
                           const EquilibriumSettings<dim> &settings,
                           const std::string              &conditions) override;
    dealii::types::global_dof_index
    n_unknowns() const override;
    /// 100 <Tolerance> (as ProblemSettings::solution_accuracy() for an iterative solve).
    double
    solution_accuracy() const override;
    /// The Schwarz iteration of one load step; returns the number of Schwarz iterations.
    unsigned int
    solve_equilibrium(const FEVector       &f_fe,
                      const ParticleVector &f_pd,
                      FEVector             &U,
                      ParticleVector       &u) override;
    std::array<double, 2>
    equilibrium_particle_energies(const ParticleVector &u_0, const ParticleVector &u_1) override;
    /// The FE residual K U - f (0 on the interface dofs, which are no supports), the particles'
    /// linearized internal force; returns sum_i W_i V_i over the particles with beta = 1.
    double
    equilibrium_forces(const FEVector       &U,
                       const ParticleVector &u,
                       const FEVector       &f_fe,
                       const ParticleVector &f_pd,
                       FEVector             &fe_residual,
                       ParticleVector       &pd_force) override;

  private:
    /// Classify the particles (free or volume constraint), checking the overlap width.
    void
    classify_particles();
    /// Find the interface dofs, prescribe them in the FE region and build their fit.
    void
    setup_interface();
    /// The PD subproblem for the volume constraint in @p u: the static solve of the assembled
    /// stiffness, or the relaxation.
    void
    solve_pd_part(const ParticleVector &f_pd, ParticleVector &u);
    /// The model's force density of @p u into force, (force + @p f_pd) V into nodal_force;
    /// with @p energy (the energy densities), returns sum_i W_i V_i over the particles with
    /// beta = 1.
    double
    particle_nodal_forces(const ParticleVector &u,
                          const ParticleVector &f_pd,
                          std::vector<double>  *energy);

    double       tolerance         = 1e-10;
    unsigned int max_iterations    = 100;
    Relaxation   relaxation        = Relaxation::aitken;
    double       relaxation_factor = 0.5;
    std::string  relaxation_name   = "aitken";

    CoupledRegions<dim>   regions;
    TransferOperator<dim> transfer;
    std::string           conditions;
    /// Per owned particle: part of the volume constraint (true) or free.
    std::vector<bool> constrained;
    /// Per owned particle: beta = 1 (its energy is the PD part's).
    std::vector<bool>               pd_only;
    dealii::types::global_dof_index n_constrained = 0;
    /// The owned interface dofs (local indices) and their current values x.
    std::vector<unsigned int> interface_dofs;
    std::vector<double>       interface_values;
    /// The fit of the interface values from the particle field.
    InterfaceFit<dim> interface_fit;

    // The empty counterparts of the two regions and the one-region static solves.
    std::unique_ptr<FERegion<dim>>            no_fe;
    std::unique_ptr<ParticleSystem<dim>>      no_particles;
    TransferOperator<dim>                     fe_transfer, pd_transfer;
    std::unique_ptr<CoupledStaticSolver<dim>> fe_solver, pd_solver;
    FEVector                                  no_U, no_fe_load, no_fe_residual;
    ParticleVector                            no_u, no_particle_load, no_particle_force, force;
    /// P U at every particle of an FE cell (work space of interpolate_to_particles()).
    mutable ParticleVector layer_values;
    std::vector<double>    residual, previous_residual, fitted_values, energy_density;
    /// Adaptive dynamic relaxation of the PD part (<Solver/Type> = adaptive dynamic
    /// relaxation) on the unknowns z of pd_solver, and its work space.
    std::unique_ptr<AdaptiveDynamicRelaxation> pd_relaxation;
    /// The unbalanced force on the PD part's unknowns (prescribed components not cleared).
    std::function<void(ParticleVector &, ParticleVector &)> pd_residual;
    ParticleVector        z, z_prescribed, z_force, z_work, nodal_force, particle_state;
    const ParticleVector *current_pd_load = nullptr;
    /// ||F|| the relaxations of one load step are measured against (solve_pd_part()).
    double pd_force_scale = 0.;
  };
} // namespace perideal

#endif
