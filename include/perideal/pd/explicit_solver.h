// ---------------------------------------------------------------------
// PeriDeal: velocity-Verlet time stepping.
// ---------------------------------------------------------------------
#ifndef perideal_pd_explicit_solver_h
#define perideal_pd_explicit_solver_h

#include <perideal/base/linear_algebra.h>

#include <functional>

namespace perideal
{
  /**
   * @brief Velocity Verlet (Störmer–Verlet) for M a = F(u) - c M v, with prescribed components.
   *
   * One step from t to t + dt:
   *   v <- v + dt/2 a;  prescribed velocities over the step;  u <- u + dt v;
   *   prescribed displacements at t + dt;  a <- acceleration(u);  v <- v + dt/2 a;
   *   prescribed velocities again.
   * Without damping the scheme is symplectic and second-order; the energy error stays bounded
   * for dt below the stability limit. The seed thesis (002, eqs. 6.7–6.8) uses symplectic Euler,
   * which gives the same displacements up to the first half step.
   * The damping c [1/s] (mass proportional, 0 by default) uses the half-step velocity, which
   * keeps the scheme explicit; it serves to reach a steady state.
   */
  class VelocityVerlet
  {
  public:
    struct Operations
    {
      /// a = acceleration(t, u); must import the ghost values of u itself.
      std::function<void(double, ParticleVector &, ParticleVector &)> acceleration;
      /// Overwrite prescribed components of v for the step from t to t + dt.
      std::function<void(double, double, ParticleVector &)> prescribe_step_velocity;
      /// Overwrite prescribed components of u at time t.
      std::function<void(double, ParticleVector &)> prescribe_displacement;
    };

    /**
     * @brief Stepper with @p operations, time step @p dt [s] and damping @p damping [1/s].
     */
    VelocityVerlet(const Operations &operations, const double dt, const double damping);

    /**
     * @brief Compute the initial acceleration (call once before the first step).
     */
    void
    initialize(const double time, ParticleVector &u, ParticleVector &a);

    /**
     * @brief Advance from @p time to time + dt.
     */
    void
    step(const double time, ParticleVector &u, ParticleVector &v, ParticleVector &a);

  private:
    Operations operations;
    double     dt;
    double     damping;
  };
} // namespace perideal

#endif
