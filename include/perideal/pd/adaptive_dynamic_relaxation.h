// ---------------------------------------------------------------------
// PeriDeal: adaptive dynamic relaxation for quasi-static peridynamics.
// ---------------------------------------------------------------------
#ifndef perideal_pd_adaptive_dynamic_relaxation_h
#define perideal_pd_adaptive_dynamic_relaxation_h

#include <deal.II/base/mpi.h>

#include <perideal/base/linear_algebra.h>

#include <functional>
#include <vector>

namespace perideal
{
  /**
   * @brief Adaptive dynamic relaxation (Kilic & Madenci 2010, Theor. Appl. Fract. Mech. 53,
   * eqs. 8–18; seed note 002, sec. 5.4): the static equilibrium F(u) = 0 as the steady state of
   * the damped fictitious dynamics Lambda u'' + c Lambda u' = F(u) with time step 1.
   *
   * - Fictitious diagonal density lambda_ii = 1/4 dt^2 sum_j |K_ij| (dt = 1), from the model's
   *   Gershgorin bound (MaterialModel::stiffness_bound(), per particle component, or the row
   *   sums of an assembled matrix), times a safety factor (1 by default; the bound is already
   * rigorous).
   * - Damping from the local Rayleigh quotient c^n = 2 sqrt(u^T K^n u / u^T u), with the
   *   diagonal estimate K_ii^n = -(F_i^n - F_i^{n-1}) / (lambda_ii v_i^{n-1/2}) (entries with
   *   v = 0 skipped, in both sums: prescribed components do not move); c = 0 if the quotient is not
   * positive, c = 1.9 if it exceeds 2.
   * - Update v^{n+1/2} = ((2 - c) v^{n-1/2} + 2 F^n / lambda) / (2 + c), u^{n+1} = u^n + v^{n+1/2},
   *   starting from v^{1/2} = F^0 / (2 lambda).
   * - Convergence when ||F||_2 < tolerance * max(||F_ext||_2, ||F^0||_2), with F the residual
   *   force density on the free components (prescribed components carry reactions); nothing to
   *   do when both norms are round-off (Settings::length_scale).
   *
   * It works on any ParticleVector through callbacks, like VelocityVerlet.
   */
  class AdaptiveDynamicRelaxation
  {
  public:
    /// What the solver asks of the problem: its residual and its prescribed components.
    struct Operations
    {
      /// F = internal + external force density for u, zero on prescribed components; must import
      /// the ghost values of u itself.
      std::function<void(ParticleVector &u, ParticleVector &force)> residual;
      /// Overwrite the prescribed components of u.
      std::function<void(ParticleVector &u)> prescribe_displacement;
      /// Set the prescribed components of a velocity-like vector to zero.
      std::function<void(ParticleVector &v)> clear_prescribed;
    };

    /// How a solve stops.
    struct Settings
    {
      /// Relative residual at which the iteration stops.
      double tolerance = 1e-8;
      /// Largest number of iterations of one solve.
      unsigned int max_iterations = 100000;
      /**
       * A length of the problem (the horizon) [m]: forces below 1e-12 * length_scale *
       * ||lambda||_2, those of a strain of 1e-12, are round-off of the force evaluation (a
       * stretch is computed to about 1e-16). A solve whose external and initial forces are
       * both below it (no load, nothing prescribed) returns at once instead of relaxing
       * round-off. 0: no floor.
       */
      double length_scale = 0.;
    };

    /// What a solve did.
    struct Result
    {
      /// The iterations it took.
      unsigned int iterations = 0;
      /// ||F||_2 / scale at the end.
      double relative_residual = 0.;
    };

    /**
     * @brief Relaxation with @p operations, per-component fictitious density @p density
     * (a vector laid out like u) and @p settings; norms are summed over @p comm.
     */
    AdaptiveDynamicRelaxation(const Operations     &operations,
                              const ParticleVector &density,
                              const Settings       &settings,
                              const MPI_Comm        comm);

    /**
     * @brief Relax @p u (initial guess on entry) to equilibrium. @p external_norm is
     * ||F_ext||_2 of the applied force density (0 for pure displacement control). Throws with
     * the residual history if it does not converge within the allowed iterations.
     */
    Result
    solve(ParticleVector &u, const double external_norm);

    /**
     * @brief The fictitious density lambda_ii = safety / 4 * bound_i of each owned unknown i
     * (@p bound from MaterialModel::stiffness_bound(), one value per particle component, or the
     * absolute row sums of a matrix), into @p density (already sized).
     */
    static void
    fictitious_density(const std::vector<double> &bound,
                       const double               safety,
                       ParticleVector            &density);

  private:
    Operations     operations;
    ParticleVector lambda;
    Settings       settings;
    /// Forces below this are round-off (Settings::length_scale).
    double   round_off_force = 0.;
    MPI_Comm communicator;
  };
} // namespace perideal

#endif
