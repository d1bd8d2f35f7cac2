// ---------------------------------------------------------------------
// PeriDeal: velocity-Verlet time stepping.
// ---------------------------------------------------------------------
#include <perideal/pd/explicit_solver.h>

namespace perideal
{
  VelocityVerlet::VelocityVerlet(const Operations &operations,
                                 const double      dt,
                                 const double      damping)
    : operations(operations)
    , dt(dt)
    , damping(damping)
  {}

  void
  VelocityVerlet::initialize(const double time, ParticleVector &u, ParticleVector &a)
  {
    operations.prescribe_displacement(time, u);
    operations.acceleration(time, u, a);
  }

  void
  VelocityVerlet::step(const double time, ParticleVector &u, ParticleVector &v, ParticleVector &a)
  {
    v.add(0.5 * dt, a);
    operations.prescribe_step_velocity(time, dt, v);
    u.add(dt, v);
    operations.prescribe_displacement(time + dt, u);
    operations.acceleration(time + dt, u, a);
    if (damping > 0.)
      a.add(-damping, v);
    v.add(0.5 * dt, a);
    operations.prescribe_step_velocity(time, dt, v);
  }
} // namespace perideal
