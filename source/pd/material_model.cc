// ---------------------------------------------------------------------
// PeriDeal: interface of peridynamic material models.
// ---------------------------------------------------------------------
#include <perideal/pd/material_model.h>

#include <cmath>
#include <limits>

namespace perideal
{
  template <int dim>
  double
  MaterialModel<dim>::stable_time_step(const ParticleSystem<dim> &particles,
                                       const double               density) const
  {
    std::vector<double> bound;
    stiffness_bound(particles, bound);
    double dt = std::numeric_limits<double>::max();
    for (const double k : bound)
      if (k > 0.)
        dt = std::min(dt, std::sqrt(4. * density / k));
    return dealii::Utilities::MPI::min(dt, particles.get_communicator());
  }

  template <int dim>
  void
  MaterialModel<dim>::linearize(const ParticleSystem<dim> &, LinearizedModel &) const
  {
    AssertThrow(false,
                dealii::ExcMessage("This material model provides no linearization; the static "
                                   "solver (<Solver/Type> = static) cannot use it. Choose "
                                   "<Solver/Type> = adaptive dynamic relaxation or explicit."));
  }

  template class MaterialModel<2>;
  template class MaterialModel<3>;
} // namespace perideal
