// ---------------------------------------------------------------------
// PeriDeal: energy blending of the FE region and the particles in the overlap.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_blended_coupling_h
#define perideal_coupling_blended_coupling_h

#include <perideal/coupling/coupled_static_solver.h>
#include <perideal/coupling/coupling_method.h>

#include <memory>

namespace perideal
{
  /**
   * @brief <Coupling/Method> = blended: the energies are blended in the overlap, E = int (1 -
   * beta) W_FE dx + sum_i beta_i W_i V_i, the masses likewise, and the particles inside cells
   * with FE unknowns are slaved to the FE field (u = P U, forces back with P^T, P the
   * TransferOperator that initialize() builds; the others are free).
   *
   * Quasi-static load steps reach equilibrium either by one symmetric positive definite
   * Trilinos system for the FE dofs and the free particles, linearized about the reference
   * configuration (<Solver/Type> = static, CoupledStaticSolver), or by adaptive dynamic
   * relaxation of the same unknowns with the model's own forces (<Solver/Type> = adaptive
   * dynamic relaxation), whose fictitious density is the Gershgorin bound of the static K. See
   * doc/theory/coupling.md.
   */
  template <int dim>
  class BlendedCoupling : public CouplingMethod<dim>
  {
  public:
    /// No parameters of its own (the overlap is <Coupling/Blending function>).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

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
    void
    add_particle_forces(const ParticleVector &f, FEVector &F) const override;
    /// The sum of the weighted energies: U^T K_FE U / 2 (K_FE weighted by 1 - beta) and the
    /// particles' (weighted by beta).
    CoupledEnergy
    strain_energy(const FEVector &U, const double particle_energy) const override;
    void
    lumped_masses(FEVector &fe_mass, std::vector<double> &particle_mass) const override;
    void
    initialize_equilibrium(const ParticleVector           &particle_prescribed,
                           const EquilibriumSettings<dim> &settings,
                           const std::string              &conditions) override;
    dealii::types::global_dof_index
    n_unknowns() const override;
    void
    set_equilibrium_diagonal(const FEVector       &fe_diagonal,
                             const ParticleVector &particle_diagonal) override;
    std::vector<ExchangeVolume>
    transfer_exchanges() const override;
    unsigned int
    solve_equilibrium(const FEVector       &f_fe,
                      const ParticleVector &f_pd,
                      FEVector             &U,
                      ParticleVector       &u) override;
    std::array<double, 2>
    equilibrium_particle_energies(const ParticleVector &u_0, const ParticleVector &u_1) override;
    double
    equilibrium_forces(const FEVector       &U,
                       const ParticleVector &u,
                       const FEVector       &f_fe,
                       const ParticleVector &f_pd,
                       FEVector             &fe_residual,
                       ParticleVector       &pd_force) override;

  private:
    /**
     * @brief Stop, naming the blending function, if a bond joins a particle with beta = 1 to one
     * with beta = 0 (a transition narrower than the horizon).
     */
    void
    check_overlap_width() const;

    /**
     * @brief The forces of (@p U, @p u) with the model's own forces (no bond breaks here): @p
     * fe_residual as in equilibrium_forces(), @p pd_force the internal force density, and in
     * nodal_force the particles' unbalanced force V (f_int + f_pd) [N]. Returns the particles'
     * strain energy if @p with_energy (0 otherwise).
     */
    double
    model_forces(const FEVector       &U,
                 const ParticleVector &u,
                 const FEVector       &f_fe,
                 const ParticleVector &f_pd,
                 FEVector             &fe_residual,
                 ParticleVector       &pd_force,
                 const bool            with_energy);

    CoupledRegions<dim>                        regions;
    TransferOperator<dim>                      transfer;
    std::string                                conditions;
    std::unique_ptr<CoupledStaticSolver<dim>>  static_solver;
    std::unique_ptr<AdaptiveDynamicRelaxation> relaxation;
    // Adaptive dynamic relaxation: the unknowns, the prescribed values, a force in z, the loads
    // of the current solve, the state the unknowns stand for and work space.
    ParticleVector        z, z_prescribed, z_force, nodal_force, pd_work, particle_state;
    FEVector              fe_work, fe_state;
    const FEVector       *current_fe_load = nullptr;
    const ParticleVector *current_pd_load = nullptr;
    std::vector<double>   energy_density;
  };
} // namespace perideal

#endif
