// ---------------------------------------------------------------------
// PeriDeal: the failure law of a bond beyond its elastic limit (brittle, or linear softening
// in saw-tooth form for the sequentially linear control).
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/pd/bond_softening.h>

#include <cmath>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  BondSoftening::BondSoftening(const double ratio, const unsigned int teeth)
    : failure(BondFailure::linear_softening)
    , n(ratio)
    , n_teeth(teeth)
  {
    AssertThrow(ratio > 1. && std::isfinite(ratio),
                ExcMessage(
                  "<Material/critical stretch/Softening ratio> = " + std::to_string(ratio) +
                  ": the final stretch over the elastic limit must be > 1."));
    AssertThrow(teeth >= 1 && teeth <= 255,
                ExcMessage("<Material/critical stretch/Softening teeth> = " +
                           std::to_string(teeth) + ": accepted 1 ... 255."));
  }

  BondFailure
  BondSoftening::law() const
  {
    return failure;
  }

  double
  BondSoftening::ratio() const
  {
    return n;
  }

  unsigned int
  BondSoftening::teeth() const
  {
    return n_teeth;
  }

  double
  BondSoftening::elastic_limit(const double s_G) const
  {
    return s_G / std::sqrt(n);
  }

  double
  BondSoftening::envelope(const double x) const
  {
    if (failure == BondFailure::brittle)
      return x <= 1. ? x : 0.;
    return x <= 1. ? x : (x < n ? (n - x) / (n - 1.) : 0.);
  }

  double
  BondSoftening::secant_factor(const unsigned int i) const
  {
    Assert(i <= n_teeth, ExcIndexRange(i, 0, n_teeth + 1));
    if (i == n_teeth)
      return 0.;
    if (failure == BondFailure::brittle)
      return 1.;
    const double x = std::pow(n, double(i) / n_teeth);
    return (n / x - 1.) / (n - 1.);
  }

  double
  BondSoftening::drop_stretch(const unsigned int i) const
  {
    Assert(i < n_teeth, ExcIndexRange(i, 0, n_teeth));
    return failure == BondFailure::brittle ? 1. : std::pow(n, (i + 0.5) / n_teeth);
  }

  double
  BondSoftening::drop_over_brittle(const unsigned int i) const
  {
    return drop_stretch(i) / std::sqrt(n);
  }

  double
  BondSoftening::tooth_dissipation(const unsigned int i) const
  {
    const double x = drop_stretch(i);
    return (secant_factor(i) - secant_factor(i + 1)) * x * x;
  }

  std::string
  BondSoftening::summary() const
  {
    if (failure == BondFailure::brittle)
      return "brittle";
    std::ostringstream out;
    out << "linear softening from s0 = " << 1. / std::sqrt(n) << " s_G to s1 = " << std::sqrt(n)
        << " s_G (ratio " << n << "), " << n_teeth << " saw teeth";
    return out.str();
  }
} // namespace perideal
