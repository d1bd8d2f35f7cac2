// ---------------------------------------------------------------------
// PeriDeal: the static linear solve of an FE-PD coupling (blended, Schwarz, FE only).
// ---------------------------------------------------------------------
#ifndef perideal_coupling_coupled_static_solver_h
#define perideal_coupling_coupled_static_solver_h

#include <deal.II/base/tensor.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/coupling/transfer_operator.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/adaptive_dynamic_relaxation.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>
#include <perideal/pd/static_solver.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace perideal
{
  /**
   * @brief The static equilibrium of an FE region and a particle region joined by a
   * TransferOperator, linearized about the reference configuration: one symmetric positive
   * definite Trilinos system for the FE dofs and the free particles, solved by CG + AMG or a
   * direct solver (Amesos KLU). The blended coupling solves both regions in one system; the
   * overlapping Schwarz method solves each region alone (the other one empty), as do FE-only
   * runs (no particles).
   *
   * Unknowns z = (U, u_free): the FE dofs and the components of the particles in FE_Nothing
   * cells. The particle displacements are u = T z with T = [P for the particles that
   * are slaved to the FE field; identity for the free ones] (P from TransferOperator). The energy
   * of the coupling (the blended energy of doc/theory/coupling.md; for a region alone, that
   * region's own energy), linearized,
   *
   *   E(z) = 1/2 U^T K_FE U + 1/2 (G T z - o)^T diag(w) (G T z - o) - F^T z,
   *
   * with K_FE the FE stiffness weighted by 1 - beta (FERegion) and G, w, o the extension matrix,
   * row weights and row offsets (a thermal strain, taken at assemble()) of the PD model's
   * linearization (StaticSolver::extension_matrix(); the bond energies are already weighted by
   * beta_b), has the stationarity condition K z = F with
   *
   *   K = E^T K_FE E + (G T)^T diag(w) (G T),
   *   F = E^T f_FE + T^T (V f_PD) + (G T)^T diag(w) o,
   *
   * where E takes z to the FE dofs and V f_PD are the particle loads [N]. E^T K_FE E and G T
   * are Trilinos matrix products (TrilinosWrappers::SparseMatrix::mmult, Tmmult); (G T)^T diag(w)
   * (G T) is summed row by row of G T (Trilinos' transposed products corrupt the heap on two
   * ranks for some partitions). Prescribed components (FE displacement conditions; PD displacement
   * conditions on free particles) are eliminated symmetrically as in StaticSolver: their columns
   * are dropped (E and T are multiplied by a 0/1 diagonal mask), the known values move to the
   * right-hand side (F_f - K_fc g), and their rows read s z_c = s g_c with s the mean diagonal
   * entry of the free rows.
   *
   * Numbering of z: contiguous per rank, the rank's owned FE dofs (in their order), then the
   * components of its owned free particles.
   */
  template <int dim>
  class CoupledStaticSolver
  {
  public:
    /// The linear solver, as the PD static solver's.
    using Settings = typename StaticSolver<dim>::Settings;

    /**
     * @brief A solver with the settings of <Solver> (linear solver, tolerance, iterations).
     */
    explicit CoupledStaticSolver(const Settings &settings);

    /**
     * @brief Stop with a message naming <Solver/Type> if the mesh of @p fe has hanging nodes,
     * which T = [P; I] on the raw FE dofs cannot carry. The quasi-static solvers' check() calls
     * it, so --validate finds it; reinit() too.
     */
    static void
    check_mesh(const FERegion<dim> &fe);

    /**
     * @brief Number the unknowns, build T and the FE part of K for the FE region @p fe and the
     * @p particles joined by @p transfer. The prescribed FE dofs are FERegion::prescribed_mask();
     * @p particle_prescribed holds 1 on the prescribed components of owned free particles
     * (owned entries; particles slaved to the FE field cannot be prescribed).
     */
    void
    reinit(const FERegion<dim>         &fe,
           const ParticleSystem<dim>   &particles,
           const TransferOperator<dim> &transfer,
           const ParticleVector        &particle_prescribed);

    /**
     * @brief A diagonal D added to K by the following assemble() calls, so that solve() solves
     * (D + K) z = F: the lumped capacities over theta dt of an implicit time step (ThetaScheme),
     * from @p fe_diagonal on the FE dofs and @p particle_diagonal [N per unit of the field] on
     * the components of the free particles (owned entries). After reinit(); D is 0 until set.
     * forces() keeps K alone.
     */
    void
    set_diagonal(const FEVector &fe_diagonal, const ParticleVector &particle_diagonal);

    /**
     * @brief Linearize @p material about the reference state (bonds broken since the last call
     * drop out) and build K with the prescribed rows eliminated. @p conditions names the
     * boundary conditions for the error message of a singular system.
     */
    void
    assemble(const MaterialModel<dim> &material, const std::string &conditions);

    /**
     * @brief assemble(), then solve K z = F. On entry @p U and @p u hold the prescribed values
     * (owned entries; others are ignored); on exit the solution with ghost values, u = P U of the
     * particles slaved to the FE field included. @p f_fe is the FE load
     * (FERegion::assemble_load()), @p f_pd the particle force density [N/m^3] (owned entries).
     * Returns the number of CG iterations (0 for the direct solver).
     */
    unsigned int
    solve(const MaterialModel<dim> &material,
          const FEVector           &f_fe,
          const ParticleVector     &f_pd,
          FEVector                 &U,
          ParticleVector           &u,
          const std::string        &conditions);

    /**
     * @brief solve() with the K of the last assemble(): for repeated solves of one stiffness
     * with other loads and prescribed values (the alternating solves of SchwarzCoupling).
     */
    unsigned int
    solve_assembled(const MaterialModel<dim> &material,
                    const FEVector           &f_fe,
                    const ParticleVector     &f_pd,
                    FEVector                 &U,
                    ParticleVector           &u,
                    const std::string        &conditions);

    /**
     * @brief The forces of the state (@p U, @p u) with the linearization of the last solve:
     * @p fe_residual = (K z - F) restricted to the FE dofs (on prescribed dofs the force the
     * supports exert, as FERegion::reactions() expects), @p pd_force the particles' internal force
     * density -(G^T diag(w) (G u - o))_i / V_i (owned entries; o the row offsets). Returns the
     * particles' strain energy 1/2 (G u - o)^T diag(w) (G u - o) [J].
     */
    double
    forces(const FEVector       &U,
           const ParticleVector &u,
           const FEVector       &f_fe,
           const ParticleVector &f_pd,
           FEVector             &fe_residual,
           ParticleVector       &pd_force) const;

    /**
     * @brief The particles' strain energies 1/2 (G u - o)^T diag(w) (G u - o) [J] of @p u_0 and
     * @p u_1 in the linearization of @p material now (its temperature change and its bonds; the
     * last solve's is not changed): CouplingMethod::equilibrium_particle_energies().
     */
    std::array<double, 2>
    particle_energies(const MaterialModel<dim> &material,
                      const ParticleVector     &u_0,
                      const ParticleVector     &u_1) const;

    /**
     * @brief @p fe_residual = K_FE @p U - @p f_fe - P^T @p nodal_force: the FE part of the
     * forces of forces(), for the particles' unbalanced forces @p nodal_force [N] (internal plus
     * applied; only the rows of P^T of the particles slaved to the FE field contribute).
     */
    void
    fe_forces(const FEVector       &U,
              const FEVector       &f_fe,
              const ParticleVector &nodal_force,
              FEVector             &fe_residual) const;

    /// Size @p z as the unknowns z (owned entries, no ghosts).
    void
    reinit_unknowns(ParticleVector &z) const;

    /// The unknowns z of the FE dofs @p U and the free particles' components of @p u.
    void
    to_unknowns(const FEVector &U, const ParticleVector &u, ParticleVector &z) const;

    /**
     * @brief The FE dofs @p U and the particle displacements @p u (free ones from @p z, those
     * slaved to the FE field u = P U) of the unknowns @p z, with ghost values.
     */
    void
    from_unknowns(const ParticleVector &z, FEVector &U, ParticleVector &u) const;

    /// Whether the owned unknown with local index @p k is prescribed.
    bool
    is_prescribed(const std::size_t k) const;

    /// Set the prescribed owned components of @p v (laid out like z) to zero.
    void
    clear_prescribed(ParticleVector &v) const;

    /**
     * @brief Adaptive dynamic relaxation of the unknowns z with the force @p residual(z, force)
     * computes (its prescribed components cleared here), the prescribed components of z held at
     * those of @p prescribed_values (which must outlive the relaxation), and the fictitious
     * density from the Gershgorin bounds sum_j |K_ij| of the assembled K times @p safety.
     */
    std::unique_ptr<AdaptiveDynamicRelaxation>
    relaxation(const std::function<void(ParticleVector &, ParticleVector &)> &residual,
               const ParticleVector                                          &prescribed_values,
               const AdaptiveDynamicRelaxation::Settings                     &settings,
               const double                                                   safety) const;

    /// Number of unknowns z (all ranks).
    dealii::types::global_dof_index
    n_unknowns() const;

    /// The system matrix of the last solve (prescribed rows eliminated).
    const SparseMatrix &
    matrix() const;

  private:
    /// The index in z of the FE dof @p dof (owned by any rank).
    dealii::types::global_dof_index
    fe_to_z(const dealii::types::global_dof_index dof) const;
    /**
     * @brief Find the free particles whose intact bonds leave directions without stiffness (a
     * particle hanging on one bond, or on collinear or, in 3D, coplanar ones) in the assembled K
     * (its diagonal block of the particle is singular there): the projectors onto those
     * directions, for follow_neighbours_in_mechanisms(). Only for a field of translations; called
     * by assemble(), as K changes only there.
     */
    void
    find_mechanisms(const MaterialModel<dim> &material);
    /**
     * @brief Give each particle find_mechanisms() found the mean displacement of its bonded
     * neighbours in its directions without stiffness, and renew the ghost values of @p u. Such a
     * direction is a null vector of the positive semi-definite K, so the solution of K z = F
     * leaves it to the solver's round-off and the preconditioner, which moved one particle of the
     * alumina quench by 2.3 bond lengths; the bond's nonlinear stretch then broke it and released
     * a spurious energy (doc/architecture/08_solvers.md). Moving the particle along the null
     * vector changes neither K z nor any bond's linearized stretch. A particle without intact
     * bonds keeps its value (nothing depends on it).
     */
    void
    follow_neighbours_in_mechanisms(ParticleVector &u) const;
    /// The particle displacements of owned particles as a Trilinos vector.
    void
    gather_particles(const ParticleVector &u, SolverVector &result) const;

    Settings                     settings;
    MPI_Comm                     comm      = MPI_COMM_SELF;
    const FERegion<dim>         *fe        = nullptr;
    const ParticleSystem<dim>   *particles = nullptr;
    const TransferOperator<dim> *transfer  = nullptr;
    /// Unknowns per point (the field layout of both regions).
    unsigned int                    n_components = 0;
    dealii::IndexSet                z_owned, fe_owned, particle_rows;
    dealii::types::global_dof_index z_first = 0;
    /// First FE dof, number of FE dofs and first z index of every rank (FE dofs are contiguous).
    std::vector<dealii::types::global_dof_index> rank_fe_first, rank_fe_count, rank_z_first;
    /// Per owned particle component: its index in z (free particles) or invalid (it follows the FE
    /// field).
    std::vector<dealii::types::global_dof_index> particle_z;
    /// Per locally owned z entry: prescribed or not.
    std::vector<bool> prescribed;
    /// Per locally owned z entry: the diagonal of set_diagonal() (empty: none).
    std::vector<double> added_diagonal;
    /// The diagonal entry of the prescribed rows: the mean diagonal entry of the free rows.
    double       prescribed_scale = 1.;
    SparseMatrix T, T_free, fe_part, G, system_matrix;
    SolverVector weights, offsets;
    /// Per owned particle of find_mechanisms(): its index and the projector onto its directions
    /// without stiffness in system_matrix.
    std::vector<std::pair<unsigned int, dealii::Tensor<2, dim>>> mechanisms;
    /// Whether any rank has such a particle.
    bool any_mechanism = false;
    /// The factorization or preconditioner of system_matrix, built by the first solve after
    /// assemble().
    typename StaticSolver<dim>::LinearSystem linear_system;
  };
} // namespace perideal

#endif
