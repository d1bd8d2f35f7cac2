// ---------------------------------------------------------------------
// PeriDeal: interface of peridynamic material models.
// ---------------------------------------------------------------------
#include <perideal/pd/material_model.h>

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
  void
  MaterialModel<dim>::stiffness_bound(const ParticleSystem<dim> &, std::vector<double> &) const
  {
    AssertThrow(false,
                dealii::ExcMessage("This material model provides no stiffness bound; the "
                                   "quasi-static solvers (<Solver/Type> = adaptive dynamic "
                                   "relaxation or static) cannot use it. Choose <Solver/Type> = "
                                   "explicit."));
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
