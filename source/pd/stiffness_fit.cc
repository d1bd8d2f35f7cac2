// ---------------------------------------------------------------------
// PeriDeal: the stiffness fit, a surface correction that restores each particle's whole
// elasticity tensor.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <perideal/pd/stiffness_fit.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>


namespace perideal
{
  using namespace dealii;

  std::string
  StiffnessFitReport::summary() const
  {
    std::ostringstream out;
    out << "stiffness fit: deviation of the particles' tensors from the interior's, largest "
        << largest_before << " -> " << largest_after << ", rms " << rms_before << " -> "
        << rms_after << "; bond factors " << smallest_factor << " ... " << largest_factor << " ("
        << held << " bonds at a bound), times " << interior_scale
        << " (the target's C_1111 over the lattice's)";
    return out.str();
  }

  namespace
  {
    /// The bounds of the factors: every bond keeps a positive, bounded stiffness.
    constexpr double smallest_factor = 0.2, largest_factor = 5.;
    /// rho relative to the mean diagonal of the normal equations.
    constexpr double relative_regularization = 1e-2;

    /// Voigt notation: the strain (e_11, e_22, 2 e_12) in 2D, (e_11, e_22, e_33, 2 e_23,
    /// 2 e_13, 2 e_12) in 3D; a symmetric Voigt matrix stored by its upper triangle.
    template <int dim>
    struct Voigt
    {
      static constexpr unsigned int n      = dim == 2 ? 3 : 6;
      static constexpr unsigned int unique = n * (n + 1) / 2;
      using Entries                        = std::array<double, unique>;

      /// The upper triangle of H = axial a a^T + shear sum_k r_k^T r_k for the direction
      /// @p v: a.e = n.e.n and r_k.e = (e.n)_k.
      static Entries
      bond_tensor(const Tensor<1, dim> &v, const double axial, const double shear)
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
    };

    /**
     * @brief The normal equations of the fit, (K + rho I) lambda with K lambda = sum over the
     * free bonds of h_b (h_b . (lambda_i + lambda_j)); Voigt<dim>::unique multipliers per owned
     * particle.
     */
    template <int dim>
    class NormalEquations
    {
    public:
      static constexpr unsigned int m = Voigt<dim>::unique;

      explicit NormalEquations(const ParticleSystem<dim> &particles)
        : particles(particles)
        , free(particles.bonds().size(), 1)
        , fixed(particles.bonds().size(), 1.)
      {}

      /// h_b . (lambda_i + lambda_j) in four partial sums: independent chains of additions that
      /// the compiler vectorizes (one sum is a chain of m dependent additions, the bottleneck
      /// of the fit's operator).
      static double
      change_of(const double *h_b, const double *lambda_i, const double *lambda_j)
      {
        double       s[4] = {0., 0., 0., 0.};
        unsigned int k    = 0;
        for (; k + 4 <= m; k += 4)
          for (unsigned int l = 0; l < 4; ++l)
            s[l] += h_b[k + l] * (lambda_i[k + l] + lambda_j[k + l]);
        for (; k < m; ++k)
          s[0] += h_b[k] * (lambda_i[k] + lambda_j[k]);
        return (s[0] + s[1]) + (s[2] + s[3]);
      }

      /// G_b - 1 of bond @p b in row @p i (0 for a bond held at a bound); ghost values of
      /// @p lambda current.
      double
      change(const unsigned int i, const std::size_t b, const ParticleVector &lambda) const
      {
        if (!free[b])
          return 0.;
        const std::size_t j = particles.bonds().neighbor[b];
        return scale(b) * change_of(h(b), lambda.begin() + i * m, lambda.begin() + j * m);
      }

      /// What a bond adds to the sums of its ends.
      enum class Sum
      {
        /// c_b h_b with c_b = G_b - 1 of the multipliers (K lambda).
        change,
        /// G_b h_b without multipliers (1, or the bound of a held bond): the particles' D V.
        tensor,
        /// The squares of the entries of h_b of the free bonds (K's diagonal).
        squares
      };

      void
      add_bond_sums(ParticleVector &dst, const Sum sum, const ParticleVector *lambda) const
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

      /// (K + rho I) src.
      void
      vmult(ParticleVector &dst, const ParticleVector &src) const
      {
        if (n_classes > 0)
          vmult_by_class(dst, src);
        else
          vmult_by_bond(dst, src);
      }

      /**
       * (K + rho I) src on an unperturbed lattice, by classes of bonds (a lattice vector and its
       * opposite share a class and H): the projections p_ci = H_c . lambda_i of every particle
       * on every class (dense products over blocks of particles), c_b = s_b^2 (p_ci + p_cj) per
       * free bond summed into t_ci and t_cj class by class (one class's p and t stay in the
       * cache), and the sums t_ci H_c per particle: 2 m n_classes multiply-adds per particle
       * and 4 per bond instead of 3 m per bond.
       */
      void
      vmult_by_class(ParticleVector &dst, const ParticleVector &src) const
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
        std::array<double, m * block> transposed;
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

      /// (K + rho I) src by bond: per row, the particle's multipliers and sums kept in local
      /// arrays.
      void
      vmult_by_bond(ParticleVector &dst, const ParticleVector &src) const
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

      const ParticleSystem<dim> &particles;
      /**
       * The entries h_b = s_b H of each bond (stored: forming them from the bond's direction in
       * each product with the operator took 1.5 times as long). On a lattice without
       * perturbation, H is that of the bond's lattice vector, one table entry per vector
       * (by_vector), and s_b the bond's own factor (scales): 10 B per bond instead of 168, and
       * the table stays in the cache. Otherwise every bond has its own H = h_b (s_b = 1).
       */
      ///@{
      bool                       by_vector = false;
      std::vector<double>        table;
      std::vector<std::uint16_t> vector_of;
      std::vector<double>        scales;
      ///@}

      /// H of bond @p b (m entries).
      const double *
      h(const std::size_t b) const
      {
        return table.data() + (by_vector ? std::size_t(vector_of[b]) : b) * m;
      }
      /// s_b of bond @p b.
      double
      scale(const std::size_t b) const
      {
        return by_vector ? scales[b] : 1.;
      }
      /**
       * The classes of vmult_by_class() (n_classes = 0: not used): H of class c at
       * class_table[c m], its transpose (entry k of class c at class_table_t[k n_classes + c]),
       * the class of each bond, and the work arrays of the products (projections of the local
       * particles, totals of the owned ones).
       */
      ///@{
      unsigned int                n_classes = 0;
      std::vector<double>         class_table;
      std::vector<std::uint16_t>  class_of_bond;
      mutable std::vector<double> projections, totals;
      ///@}

      /// A free bond of vmult_by_class(): its ends and s_b^2.
      struct ClassBond
      {
        unsigned int i, j;
        double       scale2;
      };
      /// The free bonds by class (those of class c from class_start[c]), in the bond order.
      std::vector<ClassBond>   class_bonds;
      std::vector<std::size_t> class_start;

      /// The particles of vmult_by_class()'s work arrays in tiles of this many, a tile's values
      /// class by class.
      static constexpr unsigned int tile = 64;
      /// The place of particle @p i in a class's values of vmult_by_class()'s work arrays.
      unsigned int
      slot(const unsigned int i) const
      {
        return (i / tile) * n_classes * tile + i % tile;
      }

      /// Sort the free bonds into their classes (after free changed).
      void
      sort_free_bonds()
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

      /// Group the lattice vectors' entries of the table into classes of equal H (a vector and
      /// its opposite), for vmult_by_class().
      void
      set_classes()
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
        class_of_bond.resize(vector_of.size());
        for (std::size_t b = 0; b < vector_of.size(); ++b)
          class_of_bond[b] = class_of_vector[vector_of[b]];
      }

      double regularization = 0.;
      /// Whether a bond's factor is fitted (1) or held at a bound (0; the bound in fixed).
      std::vector<std::uint8_t> free;
      std::vector<double>       fixed;
    };

    /**
     * @brief The block-Jacobi preconditioner of the normal equations: per owned particle the
     * inverse of its diagonal block rho I + sum over its free bonds of h_b h_b^T (from the
     * block's Cholesky factor). The multipliers of a particle are strongly coupled (every h_b
     * touches all of them): the point-Jacobi preconditioner needed four times the iterations.
     * The inverse is applied as a dense product, column by column (the triangular solves of the
     * factor are chains of dependent operations, 3 times slower).
     *
     * On an unperturbed lattice (NormalEquations::n_classes > 0) a block is sum_c w_ic H_c H_c^T
     * with w_ic the sum of s_b^2 over the particle's free bonds of class c: particles with the
     * same weights bit for bit (the interior, and the particles of a face at the same depth)
     * share one inverse, found by their weights. Otherwise every particle has its own, m^2
     * doubles.
     */
    template <int dim>
    class BlockJacobi
    {
    public:
      static constexpr unsigned int m = Voigt<dim>::unique;

      /// The inverses of the blocks of the free bonds of @p equations: of every owned particle,
      /// or (@p changed, by bond only) of those marked, whose bonds changed since the last call.
      void
      reinit(const NormalEquations<dim> &equations, const std::vector<std::uint8_t> *changed)
      {
        if (equations.n_classes > 0)
          reinit_by_class(equations);
        else
          reinit_by_bond(equations, changed);
      }

      /// dst = the blocks' inverses times src (owned entries).
      void
      vmult(ParticleVector &dst, const ParticleVector &src) const
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

    private:
      /// The inverses (m^2 doubles each) and the one of each owned particle.
      std::vector<double>       inverses;
      std::vector<unsigned int> block_of;
      /// By class: the inverses' weights w_ic, as bytes, and their inverse's number.
      std::unordered_map<std::string, unsigned int> known;

      /// Overwrite @p block, the lower triangle of a block less rho I (entry (p, q), q <= p,
      /// at p m + q), by its inverse, all of it.
      static void
      invert(double *block, const double regularization)
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

      /// The blocks by class: every particle's weights, a new inverse for weights not met
      /// before (the inverses of earlier rounds are kept: a particle whose held bonds changed
      /// may find its new weights among them).
      void
      reinit_by_class(const NormalEquations<dim> &equations)
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
              w = std::ldexp(std::round(std::ldexp(fraction, 36)), exponent - 36);
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

      /// The blocks of every owned particle (or of those marked in @p changed) from their
      /// bonds' h_b.
      void
      reinit_by_bond(const NormalEquations<dim>      &equations,
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
    };
  } // namespace

  namespace
  {
    /**
     * @brief The entries h_b of the bonds of @p particles (NormalEquations::table): by lattice
     * vector if the particles sit on an unperturbed lattice, else per bond.
     */
    template <int dim>
    void
    set_bond_tensors(const ParticleSystem<dim>   &particles,
                     const BondStiffnessLaw<dim> &law,
                     const double                 unit,
                     NormalEquations<dim>        &equations)
    {
      using V                        = Voigt<dim>;
      constexpr unsigned int m       = V::unique;
      const BondList        &bonds   = particles.bonds();
      const auto            &x       = particles.positions();
      const auto            &volume  = particles.volumes();
      const unsigned int     n_owned = particles.n_owned();
      const double           dx      = particles.lattice().spacing();
      // The lattice vectors of the bonds, numbered in a box of (2 reach + 1)^dim vectors.
      const long       reach = static_cast<long>(std::ceil(particles.search_radius() / dx)) + 1;
      const long       width = 2 * reach + 1;
      std::vector<int> number;
      bool             by_vector = particles.lattice().offset_bound() == 0. && dx > 0.;
      if (by_vector)
        {
          std::size_t size = 1;
          for (unsigned int d = 0; d < dim; ++d)
            size *= width;
          number.assign(size, -1);
          equations.vector_of.resize(bonds.size());
          equations.scales.resize(bonds.size());
        }
      for (unsigned int i = 0; i < n_owned && by_vector; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int j  = bonds.neighbor[b];
            const auto         xi = x[j] - x[i];
            // The bond's lattice vector n (xi = n dx up to round-off).
            std::size_t    slot = 0, stride = 1;
            Tensor<1, dim> lattice_vector;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const long n = std::lround(xi[d] / dx);
                if (std::abs(xi[d] - n * dx) > 1e-6 * dx || std::abs(n) > reach)
                  by_vector = false;
                slot += (n + reach) * stride;
                stride *= width;
                lattice_vector[d] = n * dx;
              }
            if (!by_vector)
              break;
            if (number[slot] < 0)
              {
                if (equations.table.size() / m > std::numeric_limits<std::uint16_t>::max())
                  {
                    by_vector = false;
                    break;
                  }
                double axial, shear;
                law(lattice_vector, axial, shear);
                number[slot] = equations.table.size() / m;
                const auto h = V::bond_tensor(lattice_vector / lattice_vector.norm(), axial, shear);
                equations.table.insert(equations.table.end(), h.begin(), h.end());
              }
            equations.vector_of[b] = number[slot];
            equations.scales[b]    = bonds.volume_factor(b) * volume[i] * volume[j] / unit;
          }
      // The same choice on every rank (the same round-off whatever the rank count).
      by_vector = Utilities::MPI::min(by_vector ? 1 : 0, particles.get_communicator()) == 1;
      equations.by_vector = by_vector;
      if (by_vector)
        {
          equations.set_classes();
          return;
        }
      equations.vector_of.clear();
      equations.scales.clear();
      equations.table.assign(bonds.size() * m, 0.);
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            double               axial, shear;
            const Tensor<1, dim> xi = x[bonds.neighbor[b]] - x[i];
            law(xi, axial, shear);
            const double k = bonds.volume_factor(b) * volume[i] * volume[bonds.neighbor[b]] / unit;
            const auto   h = V::bond_tensor(xi / bonds.length[b], k * axial, k * shear);
            std::copy(h.begin(), h.end(), equations.table.begin() + std::size_t(b) * m);
          }
    }
  } // namespace

  template <int dim>
  StiffnessFitReport
  apply_stiffness_fit(ParticleSystem<dim>         &particles,
                      const BondStiffnessLaw<dim> &law,
                      const double                 modulus)
  {
    using V                        = Voigt<dim>;
    constexpr unsigned int m       = V::unique;
    BondList              &bonds   = particles.bonds();
    const auto            &volume  = particles.volumes();
    const unsigned int     n_owned = particles.n_owned();
    const MPI_Comm         comm    = particles.get_communicator();
    StiffnessFitReport     report;
    // A coupled problem may leave the region without particles.
    if (particles.n_global() == 0)
      return report;

    // The interior's tensor per unit volume of the particle, from the lattice family.
    std::vector<Tensor<1, dim>> family;
    std::vector<double>         family_weight;
    particles.lattice_family(family, family_weight);
    typename V::Entries interior{};
    for (unsigned int f = 0; f < family.size(); ++f)
      {
        const double length = family[f].norm();
        double       axial, shear;
        law(family[f], axial, shear);
        const auto h =
          V::bond_tensor(family[f] / length, family_weight[f] * axial, family_weight[f] * shear);
        for (unsigned int k = 0; k < m; ++k)
          interior[k] += h[k];
      }
    // Scale: the interior's largest entry times the largest volume, so that the multipliers
    // are of the order of the relative deviations.
    double largest_volume = 0.;
    for (unsigned int i = 0; i < n_owned; ++i)
      largest_volume = std::max(largest_volume, volume[i]);
    largest_volume       = Utilities::MPI::max(largest_volume, comm);
    double largest_entry = 0.;
    for (const double d : interior)
      largest_entry = std::max(largest_entry, std::abs(d));
    const double unit = largest_entry * largest_volume;
    AssertThrow(interior[0] > 0., ExcInternalError());

    NormalEquations<dim> equations(particles);
    set_bond_tensors(particles, law, unit, equations);

    // The right-hand side, the interior's D V_i minus the particles' with the factors without
    // multipliers; with @p lambda, the particles' deviation after the fit. Returns the largest
    // and the root-mean-square deviation relative to the interior's largest entry.
    ParticleVector rhs, lambda, sums;
    particles.reinit_vector(rhs, m);
    particles.reinit_vector(lambda, m);
    particles.reinit_vector(sums, m);
    const auto deviation = [&](const ParticleVector *multipliers) {
      sums = 0.;
      equations.add_bond_sums(sums, NormalEquations<dim>::Sum::tensor, nullptr);
      if (multipliers)
        equations.add_bond_sums(sums, NormalEquations<dim>::Sum::change, multipliers);
      double largest = 0., squares = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int k = 0; k < m; ++k)
          {
            const double d = interior[k] * volume[i] / unit - sums.local_element(i * m + k);
            rhs.local_element(i * m + k) = d;
            const double relative        = d * largest_volume / volume[i];
            largest                      = std::max(largest, std::abs(relative));
            squares += relative * relative;
          }
      const double n = static_cast<double>(particles.n_global()) * m;
      return std::make_pair(Utilities::MPI::max(largest, comm),
                            std::sqrt(Utilities::MPI::sum(squares, comm) / n));
    };
    report.interior_scale                              = modulus / interior[0];
    std::tie(report.largest_before, report.rms_before) = deviation(nullptr);

    // Rounds: CG on the normal equations of the free bonds (block-Jacobi preconditioner); a
    // free bond whose factor leaves the bounds is held at the bound it crossed, and the others
    // are fitted again, until every factor is within the bounds. A round solves to 1e-6 of the
    // right-hand side first, enough to find the bonds that leave the bounds; only a round that
    // finds none goes on to the final 1e-10 (and checks the bounds again).
    {
      ParticleVector diagonal;
      particles.reinit_vector(diagonal, m);
      equations.add_bond_sums(diagonal, NormalEquations<dim>::Sum::squares, nullptr);
      equations.regularization = relative_regularization * diagonal.mean_value();
    }
    BlockJacobi<dim>          preconditioner;
    std::vector<std::uint8_t> changed;
    bool                      final_accuracy = false;
    for (unsigned int round = 0;; ++round)
      {
        AssertThrow(round < 100, ExcMessage("The stiffness fit did not settle in 100 rounds."));
        if (round == 0 || !final_accuracy)
          {
            if (round > 0)
              deviation(nullptr);
            preconditioner.reinit(equations, round == 0 ? nullptr : &changed);
            equations.sort_free_bonds();
          }
        // Warm start: each round begins from the last round's multipliers.
        const double             target = 1e-10 * rhs.l2_norm();
        SolverControl            control(10000, final_accuracy ? target : 1e4 * target);
        SolverCG<ParticleVector> cg(control);
        cg.solve(equations, lambda, rhs, preconditioner);

        lambda.update_ghost_values();
        changed.assign(n_owned, 0);
        unsigned int n_held = 0;
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            if (equations.free[b])
              {
                const double g = 1. + equations.change(i, b, lambda);
                if (g < smallest_factor || g > largest_factor)
                  {
                    equations.free[b]  = 0;
                    equations.fixed[b] = g < smallest_factor ? smallest_factor : largest_factor;
                    changed[i]         = 1;
                    if (bonds.neighbor[b] < n_owned)
                      changed[bonds.neighbor[b]] = 1;
                    ++n_held;
                  }
              }
        lambda.zero_out_ghost_values();
        if (Utilities::MPI::sum(n_held, comm) > 0)
          final_accuracy = false;
        else if (final_accuracy)
          break;
        else
          final_accuracy = true;
      }
    lambda.update_ghost_values();

    report.smallest_factor = std::numeric_limits<double>::max();
    report.largest_factor  = -std::numeric_limits<double>::max();
    unsigned long held     = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          bonds.surface_factor[b] =
            equations.free[b] ? 1. + equations.change(i, b, lambda) : equations.fixed[b];
          report.smallest_factor = std::min(report.smallest_factor, bonds.surface_factor[b]);
          report.largest_factor  = std::max(report.largest_factor, bonds.surface_factor[b]);
          // Twice, so that a bond to a ghost (a row on both ranks) counts once in the sum.
          if (!equations.free[b])
            held += particles.neighbor_is_owned(b) ? 2 : 1;
        }
    report.held            = Utilities::MPI::sum(held, comm) / 2;
    report.smallest_factor = Utilities::MPI::min(report.smallest_factor, comm);
    report.largest_factor  = Utilities::MPI::max(report.largest_factor, comm);
    std::tie(report.largest_after, report.rms_after) = deviation(&lambda);
    lambda.zero_out_ghost_values();
    for (double &g : bonds.surface_factor)
      g *= report.interior_scale;
    return report;
  }

  template StiffnessFitReport
  apply_stiffness_fit<2>(ParticleSystem<2> &, const BondStiffnessLaw<2> &, double);
  template StiffnessFitReport
  apply_stiffness_fit<3>(ParticleSystem<3> &, const BondStiffnessLaw<3> &, double);
} // namespace perideal
