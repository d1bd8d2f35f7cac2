// ---------------------------------------------------------------------
// PeriDeal: interface of peridynamic material models.
// ---------------------------------------------------------------------
#include <perideal/pd/material_model.h>

#include <cmath>
#include <limits>

namespace perideal
{
  template <int dim>
  dealii::SymmetricTensor<4, dim>
  isotropic_elasticity_tensor(const double           youngs_modulus,
                              const double           poisson_ratio,
                              const PlanarAssumption planar)
  {
    const double mu = youngs_modulus / (2. * (1. + poisson_ratio));
    double       lambda =
      youngs_modulus * poisson_ratio / ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    if (planar == PlanarAssumption::plane_stress)
      lambda = 2. * lambda * mu / (lambda + 2. * mu);
    const auto identity = dealii::unit_symmetric_tensor<dim>();
    return lambda * dealii::outer_product(identity, identity) +
           2. * mu * dealii::identity_tensor<dim>();
  }

  template dealii::SymmetricTensor<4, 2>
  isotropic_elasticity_tensor<2>(const double, const double, const PlanarAssumption);
  template dealii::SymmetricTensor<4, 3>
  isotropic_elasticity_tensor<3>(const double, const double, const PlanarAssumption);

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
