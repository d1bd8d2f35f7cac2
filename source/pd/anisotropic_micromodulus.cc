// ---------------------------------------------------------------------
// PeriDeal: the micromodulus tensor of anisotropic linearized bond-based PD (seed 004).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/anisotropic_micromodulus.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  namespace anisotropic_micromodulus
  {
    using namespace dealii;

    namespace
    {
      const std::array<std::array<unsigned int, 3>, 15> exponent_table_3d = {{{{4, 0, 0}},
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
      // The 3D order without the components that hold a 3.
      const std::array<std::array<unsigned int, 3>, 5> exponent_table_2d = {
        {{{4, 0, 0}}, {{0, 4, 0}}, {{2, 2, 0}}, {{3, 1, 0}}, {{1, 3, 0}}}};

      template <int dim>
      const std::array<unsigned int, 3> &
      exponents(const unsigned int k)
      {
        if constexpr (dim == 2)
          return exponent_table_2d[k];
        else
          return exponent_table_3d[k];
      }

      // The number of orderings of the index multiset of component k, 4!/(a! b! c!).
      template <int dim>
      double
      multiplicity(const unsigned int k)
      {
        const auto   e           = exponents<dim>(k);
        const double factorial[] = {1., 1., 2., 6., 24.};
        return 24. / (factorial[e[0]] * factorial[e[1]] * factorial[e[2]]);
      }

      // The component of the index multiset of (i, j, k, l).
      template <int dim>
      unsigned int
      component_of(const std::array<unsigned int, 4> &indices)
      {
        std::array<unsigned int, 3> e = {{0, 0, 0}};
        for (const unsigned int i : indices)
          ++e[i];
        for (unsigned int k = 0; k < n_components<dim>; ++k)
          if (exponents<dim>(k) == e)
            return k;
        return numbers::invalid_unsigned_int;
      }

      // The monomials n^e of a unit vector, powers 0 ... 8 per axis (axis 3 is 1 in 2D).
      template <int dim>
      std::array<std::array<double, 9>, 3>
      powers(const Tensor<1, dim> &n)
      {
        std::array<std::array<double, 9>, 3> p;
        for (unsigned int d = 0; d < 3; ++d)
          {
            p[d][0] = 1.;
            for (unsigned int q = 1; q < 9; ++q)
              p[d][q] = p[d][q - 1] * (d < dim ? n[d] : 0.);
          }
        return p;
      }

      // The monomial n^(e + f) of the powers p.
      inline double
      monomial(const std::array<std::array<double, 9>, 3> &p,
               const std::array<unsigned int, 3>          &e,
               const std::array<unsigned int, 3>          &f)
      {
        return p[0][e[0] + f[0]] * p[1][e[1] + f[1]] * p[2][e[2] + f[2]];
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

      // int_0^(2 pi) cos^p sin^q d theta: 2 Gamma((p+1)/2) Gamma((q+1)/2) / Gamma((p+q+2)/2) if p
      // and q are even, else 0.
      double
      circle_moment(const unsigned int p, const unsigned int q)
      {
        if (p % 2 != 0 || q % 2 != 0)
          return 0.;
        return 2. * std::tgamma(0.5 * (p + 1)) * std::tgamma(0.5 * (q + 1)) /
               std::tgamma(0.5 * (p + q + 2));
      }

      template <std::size_t N>
      constexpr int
      dimension_of()
      {
        return N == 5 ? 2 : 3;
      }
    } // namespace

    template <int dim>
    std::array<unsigned int, 3>
    component_exponents(const unsigned int k)
    {
      return exponents<dim>(k);
    }

    template <int dim>
    std::string
    component_name(const unsigned int k)
    {
      std::string name;
      for (unsigned int d = 0; d < 3; ++d)
        name += std::string(exponents<dim>(k)[d], char('1' + d));
      return name;
    }

    template <int dim>
    ComponentsOf<dim>
    completely_symmetric_part(const SymmetricTensor<4, dim> &C)
    {
      ComponentsOf<dim> sum{}, count{};
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              {
                const unsigned int c = component_of<dim>({{i, j, k, l}});
                sum[c] += C[i][j][k][l];
                count[c] += 1.;
              }
      for (unsigned int c = 0; c < n_components<dim>; ++c)
        sum[c] /= count[c];
      return sum;
    }

    template <int dim>
    SymmetricTensor<4, dim>
    to_tensor(const ComponentsOf<dim> &values)
    {
      SymmetricTensor<4, dim> C;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              C[i][j][k][l] = values[component_of<dim>({{i, j, k, l}})];
      return C;
    }

    template <int dim>
    std::vector<CauchyRelation>
    cauchy_relations(const SymmetricTensor<4, dim> &C)
    {
      if constexpr (dim == 2)
        return {{"C66 = C12", C[0][1][0][1] - C[0][0][1][1]}};
      else
        return {{"C66 = C12", C[0][1][0][1] - C[0][0][1][1]},
                {"C44 = C23", C[1][2][1][2] - C[1][1][2][2]},
                {"C55 = C13", C[0][2][0][2] - C[0][0][2][2]},
                {"C56 = C14", C[0][2][0][1] - C[0][0][1][2]},
                {"C46 = C25", C[1][2][0][1] - C[1][1][0][2]},
                {"C45 = C36", C[1][2][0][2] - C[2][2][0][1]}};
    }

    template <int dim>
    double
    largest_component(const SymmetricTensor<4, dim> &C)
    {
      double largest = 0.;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = 0; l < dim; ++l)
              largest = std::max(largest, std::abs(C[i][j][k][l]));
      return largest;
    }

    template <int dim>
    std::string
    cauchy_violations(const SymmetricTensor<4, dim> &C)
    {
      const double       scale = largest_component(C);
      std::ostringstream violated;
      for (const auto &relation : cauchy_relations(C))
        if (std::abs(relation.difference) > 1e-8 * scale)
          violated << " " << relation.relation << " is off by "
                   << ParameterUtilities::format_number(relation.difference) << " Pa ("
                   << ParameterUtilities::format_number(relation.difference / scale)
                   << " of the largest constant);";
      return violated.str();
    }

    template <int dim>
    double
    directional_modulus(const ComponentsOf<dim> &Lambda, const Tensor<1, dim> &n)
    {
      const auto                        p    = powers<dim>(n);
      const std::array<unsigned int, 3> zero = {{0, 0, 0}};
      double                            sum  = 0.;
      for (unsigned int k = 0; k < n_components<dim>; ++k)
        sum += multiplicity<dim>(k) * Lambda[k] * monomial(p, exponents<dim>(k), zero);
      return sum;
    }

    template <int dim>
    double
    mean_directional_modulus(const ComponentsOf<dim> &Lambda)
    {
      if constexpr (dim == 2)
        return 3. * (Lambda[0] + Lambda[1] + 2. * Lambda[2]) / 8.;
      else
        return (Lambda[0] + Lambda[1] + Lambda[2] + 2. * (Lambda[3] + Lambda[4] + Lambda[5])) / 5.;
    }

    template <int dim>
    Family<dim>
    interior_family(const ParticleSystem<dim> &particles)
    {
      Family<dim> family;
      particles.lattice_family(family.xi, family.weight);
      return family;
    }

    template <int dim>
    FullMatrix<double>
    lattice_moment_matrix(const Family<dim> &family)
    {
      constexpr unsigned int n = n_components<dim>;
      FullMatrix<double>     M(n, n);
      for (std::size_t b = 0; b < family.xi.size(); ++b)
        {
          const double r = family.xi[b].norm();
          const auto   p = powers<dim>(family.xi[b] / r);
          for (unsigned int alpha = 0; alpha < n; ++alpha)
            for (unsigned int beta = 0; beta < n; ++beta)
              M(alpha, beta) += 0.5 * family.weight[b] * r * multiplicity<dim>(beta) *
                                monomial(p, exponents<dim>(alpha), exponents<dim>(beta));
        }
      return M;
    }

    template <int dim>
    FullMatrix<double>
    continuum_moment_matrix(const double horizon, const double thickness)
    {
      constexpr unsigned int n = n_components<dim>;
      FullMatrix<double>     M(n, n);
      // 1/2 int_0^delta r^-3 r^4 r^(dim - 1) dr: delta^4/8 (3D), delta^3/6 (2D, times h).
      const double scale =
        dim == 2 ? thickness * std::pow(horizon, 3) / 6. : std::pow(horizon, 4) / 8.;
      for (unsigned int alpha = 0; alpha < n; ++alpha)
        for (unsigned int beta = 0; beta < n; ++beta)
          {
            const auto a = exponents<dim>(alpha), e = exponents<dim>(beta);
            M(alpha, beta) = scale * multiplicity<dim>(beta) *
                             (dim == 2 ? circle_moment(a[0] + e[0], a[1] + e[1]) :
                                         sphere_moment(a[0] + e[0], a[1] + e[1], a[2] + e[2]));
          }
      return M;
    }

    template <std::size_t N>
    std::array<double, N>
    solve(const FullMatrix<double> &M, const std::array<double, N> &C)
    {
      FullMatrix<double> inverse(N, N);
      inverse.invert(M);
      return multiply(inverse, C);
    }

    template <std::size_t N>
    std::array<double, N>
    multiply(const FullMatrix<double> &M, const std::array<double, N> &Lambda)
    {
      std::array<double, N> result{};
      for (unsigned int alpha = 0; alpha < N; ++alpha)
        for (unsigned int beta = 0; beta < N; ++beta)
          result[alpha] += M(alpha, beta) * Lambda[beta];
      return result;
    }

    template <std::size_t N>
    double
    norm(const std::array<double, N> &values)
    {
      double sum = 0.;
      for (unsigned int k = 0; k < N; ++k)
        sum += multiplicity<dimension_of<N>()>(k) * values[k] * values[k];
      return std::sqrt(sum);
    }

    template <int dim>
    DirectionScanOf<dim>
    scan_directions(const ComponentsOf<dim> &Lambda)
    {
      DirectionScanOf<dim> scan;
      scan.minimum    = std::numeric_limits<double>::infinity();
      double     area = 0., negative = 0.;
      const auto visit = [&](const Tensor<1, dim> &n, const double weight) {
        const double c = directional_modulus<dim>(Lambda, n);
        area += weight;
        if (c < 0.)
          negative += weight;
        if (c < scan.minimum)
          {
            scan.minimum           = c;
            scan.minimum_direction = n;
          }
      };
      if constexpr (dim == 2)
        for (unsigned int f = 0; f < 3600; ++f)
          {
            const double phi = (f + 0.5) * numbers::PI / 1800.;
            visit(Point<2>(std::cos(phi), std::sin(phi)), 1.);
          }
      else
        for (unsigned int t = 0; t < 180; ++t)
          for (unsigned int f = 0; f < 360; ++f)
            {
              const double theta = (t + 0.5) * numbers::PI / 180.,
                           phi   = (f + 0.5) * numbers::PI / 180.;
              visit(Point<3>(std::sin(theta) * std::cos(phi),
                             std::sin(theta) * std::sin(phi),
                             std::cos(theta)),
                    std::sin(theta));
            }
      scan.negative_fraction = negative / area;
      return scan;
    }

    template <int dim>
    SymbolScanOf<dim>
    scan_symbol(const ComponentsOf<dim> &Lambda,
                const Family<dim>       &family,
                const double             spacing,
                const unsigned int       n_k,
                const SymbolTerm<dim>   &extra_term)
    {
      const std::size_t                    n_bonds = family.xi.size();
      std::vector<SymmetricTensor<2, dim>> nn(n_bonds);
      for (std::size_t b = 0; b < n_bonds; ++b)
        {
          const double         r = family.xi[b].norm();
          const Tensor<1, dim> n = family.xi[b] / r;
          nn[b]                  = directional_modulus<dim>(Lambda, n) * family.weight[b] / r *
                  symmetrize(outer_product(n, n));
        }
      SymbolScanOf<dim>  scan;
      double             smallest = std::numeric_limits<double>::infinity(), largest = 0.;
      const double       dk  = 2. * numbers::PI / (spacing * n_k);
      const unsigned int n_q = dim == 2 ? n_k * n_k : n_k * n_k * n_k;
      for (unsigned int q = 1; q < n_q; ++q)
        {
          Tensor<1, dim> k;
          k[0] = dk * (q % n_k);
          k[1] = dk * ((q / n_k) % n_k);
          if constexpr (dim == 3)
            k[2] = dk * (q / (n_k * n_k));
          SymmetricTensor<2, dim> K;
          for (std::size_t b = 0; b < n_bonds; ++b)
            K += (1. - std::cos(k * family.xi[b])) * nn[b];
          if (extra_term)
            extra_term(k, K);
          const auto values = eigenvalues(K);
          largest           = std::max(largest, values[0]);
          if (values[dim - 1] < smallest)
            {
              smallest         = values[dim - 1];
              scan.wave_vector = k;
            }
        }
      scan.relative_minimum = smallest / largest;
      return scan;
    }

#define PERIDEAL_INSTANTIATE(dim)                                                                   \
  template std::array<unsigned int, 3> component_exponents<dim>(const unsigned int);                \
  template std::string                 component_name<dim>(const unsigned int);                     \
  template ComponentsOf<dim>       completely_symmetric_part<dim>(const SymmetricTensor<4, dim> &); \
  template SymmetricTensor<4, dim> to_tensor<dim>(const ComponentsOf<dim> &);                       \
  template std::vector<CauchyRelation> cauchy_relations<dim>(const SymmetricTensor<4, dim> &);      \
  template double                      largest_component<dim>(const SymmetricTensor<4, dim> &);     \
  template std::string                 cauchy_violations<dim>(const SymmetricTensor<4, dim> &);     \
  template double      directional_modulus<dim>(const ComponentsOf<dim> &, const Tensor<1, dim> &); \
  template double      mean_directional_modulus<dim>(const ComponentsOf<dim> &);                    \
  template Family<dim> interior_family<dim>(const ParticleSystem<dim> &);                           \
  template FullMatrix<double> lattice_moment_matrix<dim>(const Family<dim> &);                      \
  template FullMatrix<double> continuum_moment_matrix<dim>(const double, const double);             \
  template std::array<double, n_components<dim>> solve(                                             \
    const FullMatrix<double> &,                                                                     \
    const std::array<double, n_components<dim>> &);                                                 \
  template std::array<double, n_components<dim>> multiply(                                          \
    const FullMatrix<double> &,                                                                     \
    const std::array<double, n_components<dim>> &);                                                 \
  template double               norm(const std::array<double, n_components<dim>> &);                \
  template DirectionScanOf<dim> scan_directions<dim>(const ComponentsOf<dim> &);                    \
  template SymbolScanOf<dim>    scan_symbol<dim>(const ComponentsOf<dim> &,                         \
                                              const Family<dim> &,                               \
                                              const double,                                      \
                                              const unsigned int,                                \
                                              const SymbolTerm<dim> &);

    PERIDEAL_INSTANTIATE(2)
    PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
  } // namespace anisotropic_micromodulus
} // namespace perideal
