// ---------------------------------------------------------------------
// PeriDeal: influence functions omega(|xi|) of state-based models.
// ---------------------------------------------------------------------
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
