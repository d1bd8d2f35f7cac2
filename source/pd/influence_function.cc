// ---------------------------------------------------------------------
// PeriDeal: influence functions omega(|xi|) of state-based models.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <perideal/pd/influence_function.h>

#include <cmath>

namespace perideal
{
  double
  ConstantInfluence::value(const double, const double) const
  {
    return 1.;
  }

  double
  InverseDistanceInfluence::value(const double r, const double delta) const
  {
    return delta / r;
  }

  double
  GaussianInfluence::value(const double r, const double delta) const
  {
    return std::exp(-r * r / (delta * delta));
  }

  template <int dim>
  double
  continuum_weighted_volume(const InfluenceFunction &omega,
                            const double             delta,
                            const double             thickness)
  {
    const dealii::QGauss<1> gauss(12);
    const unsigned int      n_intervals = 64;
    double                  m           = 0.;
    for (unsigned int k = 0; k < n_intervals; ++k)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        {
          const double r     = delta * (k + gauss.point(q)[0]) / n_intervals;
          const double w     = gauss.weight(q) * delta / n_intervals;
          const double shell = (dim == 3 ? 4. * dealii::numbers::PI * r * r :
                                           2. * dealii::numbers::PI * r * thickness);
          m += w * omega.value(r, delta) * r * r * shell;
        }
    return m;
  }

  template double
  continuum_weighted_volume<2>(const InfluenceFunction &, const double, const double);
  template double
  continuum_weighted_volume<3>(const InfluenceFunction &, const double, const double);
} // namespace perideal

PERIDEAL_REGISTER_PLUGIN(perideal::InfluenceFunction,
                         perideal::ConstantInfluence,
                         "constant",
                         "omega = 1.")
PERIDEAL_REGISTER_PLUGIN(perideal::InfluenceFunction,
                         perideal::InverseDistanceInfluence,
                         "inverse distance",
                         "omega = delta/|xi| (Madenci & Oterkus).")
PERIDEAL_REGISTER_PLUGIN(perideal::InfluenceFunction,
                         perideal::GaussianInfluence,
                         "gaussian",
                         "omega = exp(-|xi|^2/delta^2).")
