// ---------------------------------------------------------------------
// PeriDeal: the block-Jacobi preconditioner of the stiffness fit.
// ---------------------------------------------------------------------
#include <perideal/pd/stiffness_fit_equations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace perideal::stiffness_fit
{
  template <int dim>
  void
  BlockJacobi<dim>::vmult(ParticleVector &dst, const ParticleVector &src) const
  {
    const unsigned int n = block_of.size();
    for (unsigned int i = 0; i < n; ++i)
      {
        const double         *inverse = inverses.data() + std::size_t(block_of[i]) * m * m;
        const double         *x       = src.begin() + std::size_t(i) * m;
        double               *y       = dst.begin() + std::size_t(i) * m;
        std::array<double, m> sum{};
        for (unsigned int c = 0; c < m; ++c)
          for (unsigned int p = 0; p < m; ++p)
            sum[p] += inverse[c * m + p] * x[c];
        std::copy(sum.begin(), sum.end(), y);
      }
  }

  template <int dim>
  void
  BlockJacobi<dim>::invert(double *block, const double regularization)
  {
    // Cholesky L L^T of the block, then its inverse column by column.
    std::array<double, m * m> l{};
    for (unsigned int p = 0; p < m; ++p)
      for (unsigned int q = 0; q <= p; ++q)
        {
          double s = block[p * m + q] + (p == q ? regularization : 0.);
          for (unsigned int r = 0; r < q; ++r)
            s -= l[p * m + r] * l[q * m + r];
          l[p * m + q] = p == q ? std::sqrt(s) : s / l[q * m + q];
        }
    for (unsigned int c = 0; c < m; ++c)
      {
        std::array<double, m> y;
        for (unsigned int p = 0; p < m; ++p)
          {
            double s = p == c ? 1. : 0.;
            for (unsigned int r = 0; r < p; ++r)
              s -= l[p * m + r] * y[r];
            y[p] = s / l[p * m + p];
          }
        for (unsigned int p = m; p-- > 0;)
          {
            double s = y[p];
            for (unsigned int r = p + 1; r < m; ++r)
              s -= l[r * m + p] * y[r];
            y[p] = s / l[p * m + p];
          }
        for (unsigned int p = 0; p < m; ++p)
          block[c * m + p] = y[p];
      }
  }

  template <int dim>
  void
  BlockJacobi<dim>::reinit_by_class(const NormalEquations<dim> &equations)
  {
    const BondList     &bonds   = equations.particles.bonds();
    const unsigned int  n_owned = equations.particles.n_owned();
    const unsigned int  k_c     = equations.n_classes;
    std::vector<double> weights(std::size_t(n_owned) * k_c, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (equations.free[b])
          {
            const unsigned int j  = bonds.neighbor[b];
            const unsigned int c  = equations.class_of_bond[b];
            const double       s2 = equations.scales[b] * equations.scales[b];
            weights[std::size_t(i) * k_c + c] += s2;
            if (j < n_owned)
              weights[std::size_t(j) * k_c + c] += s2;
          }
    // The weights to 36 bits (a relative change below 1e-11 of the blocks, nothing to the
    // preconditioner): s_b is formed from the bond's length, whose last bits depend on
    // where the bond lies, and exact weights would make most particles' blocks differ.
    for (double &w : weights)
      if (w != 0.)
        {
          int          exponent;
          const double fraction = std::frexp(w, &exponent);
          w                     = std::ldexp(std::round(std::ldexp(fraction, 36)), exponent - 36);
        }
    block_of.resize(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double *w = weights.data() + std::size_t(i) * k_c;
        const auto    found =
          known.emplace(std::string(reinterpret_cast<const char *>(w), k_c * sizeof(double)),
                        inverses.size() / (m * m));
        block_of[i] = found.first->second;
        if (!found.second)
          continue;
        inverses.resize(inverses.size() + m * m, 0.);
        double *block = inverses.data() + inverses.size() - m * m;
        for (unsigned int c = 0; c < k_c; ++c)
          if (w[c] != 0.)
            {
              const double *h = equations.class_table.data() + std::size_t(c) * m;
              for (unsigned int p = 0; p < m; ++p)
                for (unsigned int q = 0; q <= p; ++q)
                  block[p * m + q] += w[c] * (h[p] * h[q]);
            }
        invert(block, equations.regularization);
      }
  }

  template <int dim>
  void
  BlockJacobi<dim>::reinit_by_bond(const NormalEquations<dim>      &equations,
                                   const std::vector<std::uint8_t> *changed)
  {
    const ParticleSystem<dim> &particles = equations.particles;
    const BondList            &bonds     = particles.bonds();
    const unsigned int         n_owned   = particles.n_owned();
    const auto redo = [&](const unsigned int i) { return !changed || (*changed)[i]; };
    block_of.resize(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      block_of[i] = i;
    inverses.resize(std::size_t(n_owned) * m * m);
    for (unsigned int i = 0; i < n_owned; ++i)
      if (redo(i))
        std::fill_n(inverses.begin() + std::size_t(i) * m * m, m * m, 0.);
    const auto add = [&](const unsigned int i, const double *h_b, const double s_b) {
      double *block = inverses.data() + std::size_t(i) * m * m;
      for (unsigned int p = 0; p < m; ++p)
        for (unsigned int q = 0; q <= p; ++q)
          block[p * m + q] += (s_b * h_b[p]) * (s_b * h_b[q]);
    };
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (equations.free[b])
          {
            const unsigned int j = bonds.neighbor[b];
            if (redo(i))
              add(i, equations.h(b), equations.scale(b));
            if (j < n_owned && redo(j))
              add(j, equations.h(b), equations.scale(b));
          }
    for (unsigned int i = 0; i < n_owned; ++i)
      if (redo(i))
        invert(inverses.data() + std::size_t(i) * m * m, equations.regularization);
  }

  template class BlockJacobi<2>;
  template class BlockJacobi<3>;
} // namespace perideal::stiffness_fit
