// ---------------------------------------------------------------------
// PeriDeal: the constants of the Timoshenko-bond model (seed 003): calibration, failure limits.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>
#include <deal.II/base/symmetric_tensor.h>

#include <perideal/pd/timoshenko_bond_based.h>

#include <cmath>
#include <limits>
#include <string>

namespace perideal
{
  using namespace dealii;

  namespace Timoshenko
  {
    double
    poisson_limit(const PlanarAssumption planar)
    {
      return planar == PlanarAssumption::plane_stress ? 1. / 3. : 0.25;
    }

    std::array<double, 2>
    target_moduli(const double E, const double nu, const PlanarAssumption planar)
    {
      if (planar == PlanarAssumption::plane_stress)
        return {{E / (1. - nu * nu), nu * E / (1. - nu * nu)}};
      const double scale = E / ((1. + nu) * (1. - 2. * nu));
      return {{scale * (1. - nu), scale * nu}};
    }

    Stiffness
    continuum_stiffness(const std::array<double, 2> &D,
                        const int                    dim,
                        const double                 horizon,
                        const double                 thickness)
    {
      const double pi = numbers::PI, delta = horizon;
      Stiffness    k;
      if (dim == 3)
        {
          k.normal = 6. * (D[0] + 2. * D[1]) / (pi * std::pow(delta, 4));
          k.shear  = (D[0] - 3. * D[1]) / (4. * pi * delta * delta);
        }
      else
        {
          k.normal = 6. * (D[0] + D[1]) / (pi * thickness * std::pow(delta, 3));
          k.shear  = (D[0] - 3. * D[1]) / (6. * pi * thickness * delta);
        }
      return k;
    }

    template <int dim>
    std::array<double, 4>
    lattice_sums(const std::vector<Tensor<1, dim>> &xi, const std::vector<double> &weight)
    {
      // D_11 = sum V [C_N |xi| n_1^4 / 2 + 6 C_theta (n_1^2 - n_1^4) / |xi|],
      // D_12 = sum V [C_N |xi| n_1^2 n_2^2 / 2 - 6 C_theta n_1^2 n_2^2 / |xi|].
      std::array<double, 4> sums{};
      for (std::size_t b = 0; b < xi.size(); ++b)
        {
          const double r = xi[b].norm(), n1 = xi[b][0] / r, n2 = xi[b][1] / r, V = weight[b];
          sums[0] += V * 0.5 * r * std::pow(n1, 4);
          sums[1] += V * 6. * (n1 * n1 - std::pow(n1, 4)) / r;
          sums[2] += V * 0.5 * r * n1 * n1 * n2 * n2;
          sums[3] -= V * 6. * n1 * n1 * n2 * n2 / r;
        }
      return sums;
    }

    Stiffness
    lattice_stiffness(const std::array<double, 2> &D, const std::array<double, 4> &a)
    {
      const double det = a[0] * a[3] - a[1] * a[2];
      Stiffness    k;
      k.normal = (D[0] * a[3] - a[1] * D[1]) / det;
      k.shear  = (a[0] * D[1] - a[2] * D[0]) / det;
      return k;
    }

    template <int dim>
    std::array<double, 3>
    lattice_moduli(const Stiffness                   &stiffness,
                   const std::vector<Tensor<1, dim>> &xi,
                   const std::vector<double>         &weight)
    {
      // W = 1/2 sum V w_b for the symmetric strain eps (theta = omega = 0).
      const auto energy = [&](const SymmetricTensor<2, dim> &eps) {
        double W = 0.;
        for (std::size_t b = 0; b < xi.size(); ++b)
          {
            const double         r = xi[b].norm();
            const Tensor<1, dim> n = xi[b] / r, en = eps * n;
            const double         s  = n * en;
            const double         g2 = en * en - s * s;
            W += 0.5 * weight[b] *
                 (0.5 * stiffness.normal * r * s * s + 6. * stiffness.shear * g2 / r);
          }
        return W;
      };
      SymmetricTensor<2, dim> e11, e12, both;
      e11[0][0]  = 1.;
      e12[0][1]  = 0.5; // engineering shear 1
      both[0][0] = both[1][1] = 1.;
      const double D11        = 2. * energy(e11);
      // W(e11 + e22) = D11 + D12 (with D22 = D11 on the square/cubic lattice).
      const double D12 = energy(both) - D11;
      return {{D11, D12, 2. * energy(e12)}};
    }

    std::array<double, 2>
    limit_ratios(const Stiffness &k, const int dim, const double horizon)
    {
      const double inf = std::numeric_limits<double>::infinity(), d2 = horizon * horizon;
      const double g2 = (dim == 2 ? 24. : 20.), b2 = (dim == 2 ? 2. : 5. / 3.);
      return {{k.shear > 0. ? std::sqrt(k.normal * d2 / (g2 * k.shear)) : inf,
               k.bending > 0. ? std::sqrt(k.normal * d2 / (b2 * k.bending)) : inf}};
    }

    double
    brittle_stretch(const Stiffness &k,
                    const int        dim,
                    const double     horizon,
                    const double     thickness,
                    const double     G0)
    {
      if (dim == 2)
        return std::sqrt(4. * G0 / (std::pow(horizon, 4) * thickness * k.normal));
      return std::sqrt(10. * G0 / (numbers::PI * k.normal * std::pow(horizon, 5)));
    }

    double
    softening_for_limit_ratio(const double ratio)
    {
      AssertThrow(ratio > 0. && ratio < 1.,
                  ExcMessage("The limit ratio " + std::to_string(ratio) +
                             " is not in (0, 1): no softening law dissipates the brittle work."));
      return 2. * ratio * ratio / (1. - ratio * ratio);
    }

    template std::array<double, 4>
    lattice_sums<2>(const std::vector<Tensor<1, 2>> &, const std::vector<double> &);
    template std::array<double, 4>
    lattice_sums<3>(const std::vector<Tensor<1, 3>> &, const std::vector<double> &);
    template std::array<double, 3>
    lattice_moduli<2>(const Stiffness &,
                      const std::vector<Tensor<1, 2>> &,
                      const std::vector<double> &);
    template std::array<double, 3>
    lattice_moduli<3>(const Stiffness &,
                      const std::vector<Tensor<1, 3>> &,
                      const std::vector<double> &);
  } // namespace Timoshenko
} // namespace perideal
