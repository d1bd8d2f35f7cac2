// ---------------------------------------------------------------------
// PeriDeal: the normal equations of the stiffness fit: the bond entries, the operator.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/pd/stiffness_fit_equations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace perideal::stiffness_fit
{
  template <int dim>
  typename Voigt<dim>::Entries
  Voigt<dim>::bond_tensor(const Tensor<1, dim> &v, const double axial, const double shear)
  {
    std::array<double, n> a{}, r[dim]{};
    if constexpr (dim == 2)
      {
        a    = {{v[0] * v[0], v[1] * v[1], v[0] * v[1]}};
        r[0] = {{v[0], 0., 0.5 * v[1]}};
        r[1] = {{0., v[1], 0.5 * v[0]}};
      }
    else
      {
        a    = {{v[0] * v[0], v[1] * v[1], v[2] * v[2], v[1] * v[2], v[0] * v[2], v[0] * v[1]}};
        r[0] = {{v[0], 0., 0., 0., 0.5 * v[2], 0.5 * v[1]}};
        r[1] = {{0., v[1], 0., 0.5 * v[2], 0., 0.5 * v[0]}};
        r[2] = {{0., 0., v[2], 0.5 * v[1], 0.5 * v[0], 0.}};
      }
    Entries      h;
    unsigned int k = 0;
    for (unsigned int p = 0; p < n; ++p)
      for (unsigned int q = p; q < n; ++q, ++k)
        {
          h[k] = axial * a[p] * a[q];
          for (unsigned int d = 0; d < dim; ++d)
            h[k] += shear * r[d][p] * r[d][q];
        }
    return h;
  }

  template <int dim>
  void
  NormalEquations<dim>::add_bond_sums(ParticleVector       &dst,
                                      const Sum             sum,
                                      const ParticleVector *lambda) const
  {
    const BondList    &bonds   = particles.bonds();
    const unsigned int n_owned = particles.n_owned();
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          if (sum == Sum::squares && !free[b])
            continue;
          const unsigned int j   = bonds.neighbor[b];
          const double      *h_b = h(b);
          const double       s_b = scale(b);
          const double       c   = sum == Sum::change ? change(i, b, *lambda) :
                                   sum == Sum::tensor ? (free[b] ? 1. : fixed[b]) :
                                                        1.;
          for (unsigned int k = 0; k < m; ++k)
            {
              const double v =
                sum == Sum::squares ? (s_b * h_b[k]) * (s_b * h_b[k]) : c * (s_b * h_b[k]);
              dst.local_element(i * m + k) += v;
              if (j < n_owned)
                dst.local_element(j * m + k) += v;
            }
        }
  }

  template <int dim>
  void
  NormalEquations<dim>::vmult_by_class(ParticleVector &dst, const ParticleVector &src) const
  {
    src.update_ghost_values();
    const unsigned int     n_owned = particles.n_owned();
    const std::size_t      n_local = particles.n_local();
    const unsigned int     k_c     = n_classes;
    const double          *lambda  = src.begin();
    double                *sums    = dst.begin();
    constexpr unsigned int block   = tile;
    constexpr unsigned int lanes   = 8;
    const std::size_t      n_tiles = (n_local + block - 1) / block;
    projections.resize(n_tiles * k_c * block);
    totals.assign(n_tiles * k_c * block, 0.);
    std::array<double, m * block> transposed{};
    for (std::size_t first = 0; first < n_local; first += block)
      {
        const unsigned int size = std::min<std::size_t>(block, n_local - first);
        for (unsigned int i = 0; i < size; ++i)
          for (unsigned int k = 0; k < m; ++k)
            transposed[k * block + i] = lambda[(first + i) * m + k];
        for (unsigned int c = 0; c < k_c; ++c)
          {
            const double *h_c = class_table.data() + std::size_t(c) * m;
            double       *p_c = projections.data() + first * k_c + c * block;
            for (unsigned int i0 = 0; i0 < size; i0 += lanes)
              {
                double p[lanes] = {};
                for (unsigned int k = 0; k < m; ++k)
                  {
                    const double  h = h_c[k];
                    const double *l = transposed.data() + k * block + i0;
                    for (unsigned int u = 0; u < lanes; ++u)
                      p[u] += h * l[u];
                  }
                std::copy_n(p, std::min(lanes, size - i0), p_c + i0);
              }
          }
      }
    for (unsigned int c = 0; c < k_c; ++c)
      {
        const double *p_c = projections.data() + c * block;
        double       *t_c = totals.data() + c * block;
        for (std::size_t e = class_start[c]; e < class_start[c + 1]; ++e)
          {
            const ClassBond &bond = class_bonds[e];
            const double     t    = bond.scale2 * (p_c[bond.i] + p_c[bond.j]);
            t_c[bond.i] += t;
            t_c[bond.j] += t;
          }
      }
    for (std::size_t first = 0; first < n_owned; first += block)
      {
        const unsigned int size = std::min<std::size_t>(block, n_owned - first);
        for (unsigned int i0 = 0; i0 < size; i0 += lanes)
          for (unsigned int k = 0; k < m; ++k)
            {
              double s[lanes];
              for (unsigned int u = 0; u < lanes; ++u)
                s[u] = regularization * lambda[(first + std::min(i0 + u, size - 1)) * m + k];
              for (unsigned int c = 0; c < k_c; ++c)
                {
                  const double  h = class_table[std::size_t(c) * m + k];
                  const double *t = totals.data() + first * k_c + c * block + i0;
                  for (unsigned int u = 0; u < lanes; ++u)
                    s[u] += h * t[u];
                }
              std::copy_n(s, lanes, transposed.data() + k * block + i0);
            }
        for (unsigned int i = 0; i < size; ++i)
          for (unsigned int k = 0; k < m; ++k)
            sums[(first + i) * m + k] = transposed[k * block + i];
      }
    src.zero_out_ghost_values();
  }

  template <int dim>
  void
  NormalEquations<dim>::vmult_by_bond(ParticleVector &dst, const ParticleVector &src) const
  {
    src.update_ghost_values();
    const BondList    &bonds   = particles.bonds();
    const unsigned int n_owned = particles.n_owned();
    const double      *lambda  = src.begin();
    double            *sums    = dst.begin();
    for (unsigned int c = 0; c < n_owned * m; ++c)
      sums[c] = regularization * lambda[c];
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        std::array<double, m> lambda_i, sum_i{};
        std::copy_n(lambda + i * m, m, lambda_i.begin());
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            if (!free[b])
              continue;
            const unsigned int j        = bonds.neighbor[b];
            const double      *h_b      = h(b);
            const double       s_b      = scale(b);
            const double      *lambda_j = lambda + std::size_t(j) * m;
            // c h_b of the stored entries: s_b^2 (H . (lambda_i + lambda_j)) H.
            const double c = s_b * s_b * change_of(h_b, lambda_i.data(), lambda_j);
            for (unsigned int k = 0; k < m; ++k)
              sum_i[k] += c * h_b[k];
            if (j < n_owned)
              for (unsigned int k = 0; k < m; ++k)
                sums[std::size_t(j) * m + k] += c * h_b[k];
          }
        for (unsigned int k = 0; k < m; ++k)
          sums[i * m + k] += sum_i[k];
      }
    src.zero_out_ghost_values();
  }

  template <int dim>
  void
  NormalEquations<dim>::sort_free_bonds()
  {
    if (n_classes == 0)
      return;
    const BondList    &bonds   = particles.bonds();
    const unsigned int n_owned = particles.n_owned();
    class_start.assign(n_classes + 1, 0);
    for (std::size_t b = 0; b < class_of_bond.size(); ++b)
      if (free[b])
        ++class_start[class_of_bond[b] + 1];
    for (unsigned int c = 0; c < n_classes; ++c)
      class_start[c + 1] += class_start[c];
    class_bonds.resize(class_start[n_classes]);
    std::vector<std::size_t> next(class_start.begin(), class_start.end() - 1);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (free[b])
          {
            const unsigned int j = bonds.neighbor[b];
            // A ghost end gets its sum in a slot that is not read.
            class_bonds[next[class_of_bond[b]]++] = {slot(i), slot(j), scales[b] * scales[b]};
          }
  }

  template <int dim>
  void
  NormalEquations<dim>::set_classes()
  {
    const unsigned int         n_vectors = table.size() / m;
    std::vector<std::uint16_t> class_of_vector(n_vectors);
    for (unsigned int v = 0; v < n_vectors; ++v)
      {
        unsigned int c = 0;
        for (; c < n_classes; ++c)
          if (std::equal(table.begin() + v * m,
                         table.begin() + (v + 1) * m,
                         class_table.begin() + c * m))
            break;
        if (c == n_classes)
          {
            class_table.insert(class_table.end(),
                               table.begin() + v * m,
                               table.begin() + (v + 1) * m);
            ++n_classes;
          }
        class_of_vector[v] = c;
      }
    // The places of slot() are unsigned int: more than 2^32 / n_classes local particles on a
    // rank (7 * 10^7 in 3D) keep the products by bond, on every rank alike.
    const bool too_many = std::uint64_t(particles.n_local() + tile) * n_classes >=
                          std::numeric_limits<unsigned int>::max();
    if (dealii::Utilities::MPI::max(too_many ? 1 : 0, particles.get_communicator()) == 1)
      {
        n_classes = 0;
        class_table.clear();
        return;
      }
    class_of_bond.resize(vector_of.size());
    for (std::size_t b = 0; b < vector_of.size(); ++b)
      class_of_bond[b] = class_of_vector[vector_of[b]];
  }

  template struct Voigt<2>;
  template struct Voigt<3>;
  template class NormalEquations<2>;
  template class NormalEquations<3>;
} // namespace perideal::stiffness_fit
