// ---------------------------------------------------------------------
// PeriDeal: the micromodulus tensor of anisotropic linearized bond-based PD (seed 004).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <perideal/pd/anisotropic_micromodulus.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace perideal
{
  namespace anisotropic_micromodulus
  {
    using namespace dealii;

    namespace
    {
      const std::array<std::array<unsigned int, 3>, 15> exponent_table = {{{{4, 0, 0}},
                                                                           {{0, 4, 0}},
                                                                           {{0, 0, 4}},
                                                                           {{2, 2, 0}},
                                                                           {{2, 0, 2}},
                                                                           {{0, 2, 2}},
                                                                           {{3, 1, 0}},
                                                                           {{1, 3, 0}},
                                                                           {{1, 1, 2}},
                                                                           {{3, 0, 1}},
                                                                           {{1, 0, 3}},
                                                                           {{1, 2, 1}},
                                                                           {{0, 3, 1}},
                                                                           {{0, 1, 3}},
                                                                           {{2, 1, 1}}}};

      // The number of orderings of the index multiset of component k, 4!/(a! b! c!).
      double
      multiplicity(const unsigned int k)
      {
        const auto   e           = exponent_table[k];
        const double factorial[] = {1., 1., 2., 6., 24.};
        return 24. / (factorial[e[0]] * factorial[e[1]] * factorial[e[2]]);
      }

      // The component of the index multiset of (i, j, k, l).
      unsigned int
      component_of(const std::array<unsigned int, 4> &indices)
      {
        std::array<unsigned int, 3> e = {{0, 0, 0}};
        for (const unsigned int i : indices)
          ++e[i];
        return std::find(exponent_table.begin(), exponent_table.end(), e) - exponent_table.begin();
      }

      // The monomials n^e of a unit vector, powers 0 ... 8 per axis.
      std::array<std::array<double, 9>, 3>
      powers(const Tensor<1, 3> &n)
      {
        std::array<std::array<double, 9>, 3> p;
        for (unsigned int d = 0; d < 3; ++d)
          {
            p[d][0] = 1.;
            for (unsigned int q = 1; q < 9; ++q)
              p[d][q] = p[d][q - 1] * n[d];
          }
        return p;
      }

      // int_S n1^p n2^q n3^r dS: 2 Gamma((p+1)/2) Gamma((q+1)/2) Gamma((r+1)/2) /
      // Gamma((p+q+r+3)/2) if p, q, r are even, else 0.
      double
      sphere_moment(const unsigned int p, const unsigned int q, const unsigned int r)
      {
        if (p % 2 != 0 || q % 2 != 0 || r % 2 != 0)
          return 0.;
        return 2. * std::tgamma(0.5 * (p + 1)) * std::tgamma(0.5 * (q + 1)) *
               std::tgamma(0.5 * (r + 1)) / std::tgamma(0.5 * (p + q + r + 3));
      }
    } // namespace

    std::array<unsigned int, 3>
    component_exponents(const unsigned int k)
    {
      return exponent_table[k];
    }

    std::string
    component_name(const unsigned int k)
    {
      std::string name;
      for (unsigned int d = 0; d < 3; ++d)
        name += std::string(exponent_table[k][d], char('1' + d));
      return name;
    }

    Components
    completely_symmetric_part(const SymmetricTensor<4, 3> &C)
    {
      Components sum{}, count{};
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              {
                const unsigned int c = component_of({{i, j, k, l}});
                sum[c] += C[i][j][k][l];
                count[c] += 1.;
              }
      for (unsigned int c = 0; c < 15; ++c)
        sum[c] /= count[c];
      return sum;
    }

    SymmetricTensor<4, 3>
    to_tensor(const Components &values)
    {
      SymmetricTensor<4, 3> C;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = k; l < 3; ++l)
              C[i][j][k][l] = values[component_of({{i, j, k, l}})];
      return C;
    }

    std::vector<CauchyRelation>
    cauchy_relations(const SymmetricTensor<4, 3> &C)
    {
      return {{"C66 = C12", C[0][1][0][1] - C[0][0][1][1]},
              {"C44 = C23", C[1][2][1][2] - C[1][1][2][2]},
              {"C55 = C13", C[0][2][0][2] - C[0][0][2][2]},
              {"C56 = C14", C[0][2][0][1] - C[0][0][1][2]},
              {"C46 = C25", C[1][2][0][1] - C[1][1][0][2]},
              {"C45 = C36", C[1][2][0][2] - C[2][2][0][1]}};
    }

    double
    directional_modulus(const Components &Lambda, const Tensor<1, 3> &n)
    {
      const auto p   = powers(n);
      double     sum = 0.;
      for (unsigned int k = 0; k < 15; ++k)
        {
          const auto e = exponent_table[k];
          sum += multiplicity(k) * Lambda[k] * p[0][e[0]] * p[1][e[1]] * p[2][e[2]];
        }
      return sum;
    }

    double
    mean_directional_modulus(const Components &Lambda)
    {
      return (Lambda[0] + Lambda[1] + Lambda[2] + 2. * (Lambda[3] + Lambda[4] + Lambda[5])) / 5.;
    }

    LatticeFamily
    interior_family(const ParticleSystem<3> &particles)
    {
      const MPI_Comm     comm    = particles.get_communicator();
      const BondList    &bonds   = particles.bonds();
      const unsigned int n_owned = particles.n_owned();
      // The bond list holds an owned-owned bond once, in one of the two rows: a particle's
      // family is its row and the bonds of other rows that name it.
      std::vector<unsigned int> n_bonds(n_owned, 0);
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            ++n_bonds[i];
            if (bonds.neighbor[b] < n_owned)
              ++n_bonds[bonds.neighbor[b]];
          }
      const auto         best = std::max_element(n_bonds.begin(), n_bonds.end()) - n_bonds.begin();
      const unsigned int n_best = n_owned > 0 ? n_bonds[best] : 0;
      const unsigned int n_max  = Utilities::MPI::max(n_best, comm);
      const unsigned int rank   = Utilities::MPI::this_mpi_process(comm);
      const unsigned int root =
        Utilities::MPI::min(n_best == n_max ? rank : std::numeric_limits<unsigned int>::max(),
                            comm);
      std::vector<double> flat;
      const auto add = [&](const unsigned int from, const unsigned int to, const std::size_t b) {
        const auto xi = particles.positions()[to] - particles.positions()[from];
        flat.insert(flat.end(),
                    {xi[0], xi[1], xi[2], bonds.volume_factor[b] * particles.volumes()[to]});
      };
      if (rank == root)
        {
          for (unsigned int i = 0; i < n_owned; ++i)
            for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
              {
                if (i == best)
                  add(i, bonds.neighbor[b], b);
                else if (bonds.neighbor[b] == best)
                  add(best, i, b);
              }
        }
      flat = Utilities::MPI::broadcast(comm, flat, root);
      LatticeFamily family;
      for (std::size_t b = 0; b < flat.size(); b += 4)
        {
          family.xi.emplace_back();
          for (unsigned int d = 0; d < 3; ++d)
            family.xi.back()[d] = flat[b + d];
          family.weight.push_back(flat[b + 3]);
        }
      return family;
    }

    FullMatrix<double>
    lattice_moment_matrix(const LatticeFamily &family)
    {
      FullMatrix<double> M(15, 15);
      for (std::size_t b = 0; b < family.xi.size(); ++b)
        {
          const double r = family.xi[b].norm();
          const auto   p = powers(family.xi[b] / r);
          for (unsigned int alpha = 0; alpha < 15; ++alpha)
            for (unsigned int beta = 0; beta < 15; ++beta)
              {
                const auto a = exponent_table[alpha], e = exponent_table[beta];
                M(alpha, beta) += 0.5 * family.weight[b] * r * multiplicity(beta) *
                                  p[0][a[0] + e[0]] * p[1][a[1] + e[1]] * p[2][a[2] + e[2]];
              }
        }
      return M;
    }

    FullMatrix<double>
    continuum_moment_matrix(const double horizon)
    {
      FullMatrix<double> M(15, 15);
      const double       scale = std::pow(horizon, 4) / 8.;
      for (unsigned int alpha = 0; alpha < 15; ++alpha)
        for (unsigned int beta = 0; beta < 15; ++beta)
          {
            const auto a = exponent_table[alpha], e = exponent_table[beta];
            M(alpha, beta) =
              scale * multiplicity(beta) * sphere_moment(a[0] + e[0], a[1] + e[1], a[2] + e[2]);
          }
      return M;
    }

    Components
    solve(const FullMatrix<double> &M, const Components &C)
    {
      FullMatrix<double> inverse(15, 15);
      inverse.invert(M);
      return multiply(inverse, C);
    }

    Components
    multiply(const FullMatrix<double> &M, const Components &Lambda)
    {
      Components result{};
      for (unsigned int alpha = 0; alpha < 15; ++alpha)
        for (unsigned int beta = 0; beta < 15; ++beta)
          result[alpha] += M(alpha, beta) * Lambda[beta];
      return result;
    }

    double
    norm(const Components &values)
    {
      double sum = 0.;
      for (unsigned int k = 0; k < 15; ++k)
        sum += multiplicity(k) * values[k] * values[k];
      return std::sqrt(sum);
    }

    DirectionScan
    scan_directions(const Components &Lambda)
    {
      DirectionScan scan;
      scan.minimum = std::numeric_limits<double>::infinity();
      double area = 0., negative = 0.;
      for (unsigned int t = 0; t < 180; ++t)
        for (unsigned int f = 0; f < 360; ++f)
          {
            const double theta   = (t + 0.5) * numbers::PI / 180.,
                         phi     = (f + 0.5) * numbers::PI / 180.;
            const Tensor<1, 3> n = Point<3>(std::sin(theta) * std::cos(phi),
                                            std::sin(theta) * std::sin(phi),
                                            std::cos(theta));
            const double       c = directional_modulus(Lambda, n);
            area += std::sin(theta);
            if (c < 0.)
              negative += std::sin(theta);
            if (c < scan.minimum)
              {
                scan.minimum           = c;
                scan.minimum_direction = n;
              }
          }
      scan.negative_fraction = negative / area;
      return scan;
    }

    SymbolScan
    scan_symbol(const Components    &Lambda,
                const LatticeFamily &family,
                const double         spacing,
                const unsigned int   n_k)
    {
      const std::size_t                  n_bonds = family.xi.size();
      std::vector<SymmetricTensor<2, 3>> nn(n_bonds);
      for (std::size_t b = 0; b < n_bonds; ++b)
        {
          const double       r = family.xi[b].norm();
          const Tensor<1, 3> n = family.xi[b] / r;
          nn[b] =
            directional_modulus(Lambda, n) * family.weight[b] / r * symmetrize(outer_product(n, n));
        }
      SymbolScan   scan;
      double       smallest = std::numeric_limits<double>::infinity(), largest = 0.;
      const double dk = 2. * numbers::PI / (spacing * n_k);
      for (unsigned int q = 1; q < n_k * n_k * n_k; ++q)
        {
          const Tensor<1, 3> k =
            Point<3>(dk * (q % n_k), dk * ((q / n_k) % n_k), dk * (q / (n_k * n_k)));
          SymmetricTensor<2, 3> K;
          for (std::size_t b = 0; b < n_bonds; ++b)
            K += (1. - std::cos(k * family.xi[b])) * nn[b];
          const auto values = eigenvalues(K);
          largest           = std::max(largest, values[0]);
          if (values[2] < smallest)
            {
              smallest         = values[2];
              scan.wave_vector = k;
            }
        }
      scan.relative_minimum = smallest / largest;
      return scan;
    }
  } // namespace anisotropic_micromodulus
} // namespace perideal
