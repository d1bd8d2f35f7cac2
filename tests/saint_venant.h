// The Saint-Venant series of the torsion of a rectangular bar (Timoshenko & Goodier, Theory of
// Elasticity, 3rd ed., 1970, sect. 109; seed note 000, sec. 5.4): the section |x| <= a,
// |y| <= b, twist axis at the centroid, mu = psi = 1 (the values scale with mu psi).
#ifndef perideal_tests_saint_venant_h
#define perideal_tests_saint_venant_h

#include <deal.II/base/function.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <cmath>

namespace saint_venant
{
  /// sinh(k y) / cosh(k b) for |y| <= b without overflow.
  inline double
  sinh_ratio(const double k, const double y, const double b)
  {
    const double s = y < 0. ? -1. : 1.;
    return s * std::exp(k * (std::abs(y) - b)) * (1. - std::exp(-2. * k * std::abs(y))) /
           (1. + std::exp(-2. * k * b));
  }

  /// cosh(k y) / cosh(k b) for |y| <= b without overflow.
  inline double
  cosh_ratio(const double k, const double y, const double b)
  {
    return std::exp(k * (std::abs(y) - b)) * (1. + std::exp(-2. * k * std::abs(y))) /
           (1. + std::exp(-2. * k * b));
  }

  /// The torque T/(mu psi) = (2a)^3 (2b)/3 [1 - 192 a / (pi^5 b) sum_odd tanh(n pi b/2a)/n^5].
  inline double
  torque(const double a, const double b)
  {
    const double pi  = dealii::numbers::PI;
    double       sum = 0.;
    for (unsigned int n = 1; n < 400; n += 2)
      sum += std::tanh(n * pi * b / (2. * a)) / std::pow(n, 5);
    return std::pow(2. * a, 3) * (2. * b) / 3. * (1. - 192. / std::pow(pi, 5) * a / b * sum);
  }

  /// The stresses (tau_xz, tau_yz)/(mu psi) at @p p.
  inline dealii::Tensor<1, 2>
  stress(const dealii::Point<2> &p, const double a, const double b)
  {
    const double         pi = dealii::numbers::PI;
    dealii::Tensor<1, 2> tau;
    tau[1] = 2. * p[0];
    for (unsigned int n = 0; n < 200; ++n)
      {
        const double k = (2. * n + 1.) * pi / (2. * a), sign = (n % 2 == 0 ? 1. : -1.);
        const double c = 16. * a / (pi * pi) * sign / std::pow(2. * n + 1., 2);
        tau[0] -= c * std::cos(k * p[0]) * sinh_ratio(k, p[1], b);
        tau[1] -= c * std::sin(k * p[0]) * cosh_ratio(k, p[1], b);
      }
    return tau;
  }

  /// The warping w/psi, zero at the centroid.
  class Warping : public dealii::Function<2>
  {
  public:
    Warping(const double a, const double b)
      : a(a)
      , b(b)
    {}

    double
    value(const dealii::Point<2> &p, const unsigned int = 0) const override
    {
      const double pi = dealii::numbers::PI;
      double       w  = p[0] * p[1];
      for (unsigned int n = 0; n < 200; ++n)
        {
          const double k = (2. * n + 1.) * pi / (2. * a), sign = (n % 2 == 0 ? 1. : -1.);
          w -= 32. * a * a / std::pow(pi, 3) * sign / std::pow(2. * n + 1., 3) *
               std::sin(k * p[0]) * sinh_ratio(k, p[1], b);
        }
      return w;
    }

  private:
    const double a, b;
  };
} // namespace saint_venant

#endif
