// ---------------------------------------------------------------------
// PeriDeal: static linear solve of the linearized peridynamic equations.
// ---------------------------------------------------------------------
#ifndef perideal_pd_static_solver_h
#define perideal_pd_static_solver_h

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/base/problem_settings.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>

#include <functional>
#include <memory>
#include <string>

namespace perideal
{
  /**
   * @brief The static equilibrium of the model linearized about the reference configuration,
   * K u = F_ext, assembled into a distributed Trilinos matrix and solved by CG + AMG or a direct
   * solver (Amesos KLU).
   *
   * Linearization (MaterialModel::linearize()): E = 1/2 sum_r w_r (G_r u)^2 with the rows G_r
   * of the model's strain operator (LinearizedModel: bond extensions and dilatations for PMB
   * and LPS, whatever strains another model emits). Collected into a rectangular matrix G
   * (the owned rows of every rank), the stiffness is K = G^T diag(w) G (Trilinos' A^T diag(V) B
   * product); rows that couple the neighbours of neighbours (the LPS dilatation) get that
   * sparsity from the product without a search. The unknowns are the particles' components
   * of the model's field_layout() (global index = particle index * n_components + component,
   * the partitioner of ParticleSystem::partitioner(n_components)); the solver knows nothing of
   * what a row means.
   *
   * Prescribed components are eliminated symmetrically: their columns are left out of G (so
   * K_ff only), the known values move to the right-hand side (F_f - K_fc g), and the row gets
   * s u_c = s g_c with s the particle's stiffness scale (LinearizedModel::stiffness_scale(),
   * for PMB and LPS the sum of the particle's bond weights), which keeps the condition number
   * of the free block.
   */
  template <int dim>
  class StaticSolver
  {
  public:
    /// The linear solver (Patterns::Selection "cg amg|direct" of <Solver/Linear solver>).

    struct Settings
    {
      /// <Solver/Linear solver>.
      LinearSolverType linear_solver = LinearSolverType::cg_amg;
      /// Relative residual ||K u - F|| / ||F|| of CG.
      double tolerance = 1e-10;
      /// Largest number of CG iterations.
      unsigned int max_iterations = 10000;
    };

    /**
     * @brief A solver with @p settings.
     */
    explicit StaticSolver(const Settings &settings);

    /**
     * @brief Solve for @p u. @p prescribed holds 1 on prescribed components (owned entries),
     * @p u their values on entry (other entries are ignored) and the solution on exit, with
     * ghost values; @p external_force is the applied force density [N/m^3] (owned entries).
     * @p conditions names the boundary conditions for the error messages. Throws if no
     * component is prescribed (rigid-body modes) or the solver fails. Returns the number of
     * CG iterations (0 for the direct solver).
     */
    unsigned int
    solve(const ParticleSystem<dim> &particles,
          const MaterialModel<dim>  &material,
          const ParticleVector      &prescribed,
          const ParticleVector      &external_force,
          ParticleVector            &u,
          const std::string         &conditions);

    /**
     * @brief The unconstrained strain matrix G of @p linearized (rows: the model's rows, e.g.
     * the bonds with a stiffness and, for state-based models, the dilatations; columns: the
     * particle dofs, linearized.n_components() per particle) and its row weights, so that G^T
     * diag(@p weights) G is the stiffness without boundary conditions, and its row offsets
     * @p offsets (LinearizedModel::offset(): G^T diag(w) o is the load of a thermal strain). For
     * solves that map the particle dofs to other unknowns (the coupled static solve: G T).
     */
    static void
    extension_matrix(const ParticleSystem<dim> &particles,
                     const LinearizedModel     &linearized,
                     SparseMatrix              &G,
                     SolverVector              &weights,
                     SolverVector              &offsets);

    /**
     * @brief The solves of one symmetric positive definite system K x = b of a static solve for
     * any number of right-hand sides, as the <Solver> settings say: KLU, or CG preconditioned by
     * ML AMG. The factorization or the AMG hierarchy is built by the first solve() and kept for
     * the next ones until clear() (the alternating solves of overlapping Schwarz, one stiffness
     * per load step).
     */
    class LinearSystem
    {
    public:
      /// Forget the factorization or preconditioner: the next solve() builds it for its K.
      void
      clear();

      /**
       * @brief Solve @p K x = @p b (@p K the matrix of every solve since clear()) with
       * @p amg_data() the AMG set-up (the near-null space of the unknowns). @p what names the
       * solve in the messages and @p advice ends them. Throws, naming the <Solver> entries, if
       * CG does not converge, the solver fails, or the solution is not finite or leaves a
       * residual above 1e3 times the tolerance (a singular system). For b = 0, x is left as it
       * is. Returns the number of CG iterations (0 for the direct solver).
       */
      unsigned int
      solve(
        const SparseMatrix                                                               &K,
        const SolverVector                                                               &b,
        SolverVector                                                                     &x,
        const Settings                                                                   &settings,
        const std::function<dealii::TrilinosWrappers::PreconditionAMG::AdditionalData()> &amg_data,
        const std::string                                                                &what,
        const std::string                                                                &advice);

    private:
      /// The direct solver keeps a reference to its control.
      dealii::SolverControl                                      direct_control;
      std::unique_ptr<dealii::TrilinosWrappers::SolverDirect>    direct;
      std::unique_ptr<dealii::TrilinosWrappers::PreconditionAMG> amg;
    };

    /**
     * @brief The matrix of the last solve (prescribed rows eliminated).
     */
    const SparseMatrix &
    matrix() const;

  private:
    Settings     settings;
    SparseMatrix system_matrix;
  };
} // namespace perideal

#endif
