// ---------------------------------------------------------------------
// PeriDeal: the normal equations of the stiffness fit and their block-Jacobi preconditioner
// (used by stiffness_fit.cc only).
// ---------------------------------------------------------------------
#ifndef perideal_pd_stiffness_fit_equations_h
#define perideal_pd_stiffness_fit_equations_h

#include <deal.II/base/tensor.h>

#include <perideal/pd/particle_system.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

/**
 * @brief The parts of the stiffness fit (apply_stiffness_fit()): the Voigt entries of a bond,
 * the normal equations of the fit's multipliers and their preconditioner.
 */
namespace perideal::stiffness_fit
{
  using dealii::Tensor;

  /// Voigt notation: the strain (e_11, e_22, 2 e_12) in 2D, (e_11, e_22, e_33, 2 e_23,
  /// 2 e_13, 2 e_12) in 3D; a symmetric Voigt matrix stored by its upper triangle.
  template <int dim>
  struct Voigt
  {
    /// Strain components.
    static constexpr unsigned int n = dim == 2 ? 3 : 6;
    /// Entries of a symmetric Voigt matrix.
    static constexpr unsigned int unique = n * (n + 1) / 2;
    /// A symmetric Voigt matrix by its upper triangle.
    using Entries = std::array<double, unique>;

    /// The upper triangle of H = axial a a^T + shear sum_k r_k^T r_k for the direction
    /// @p v: a.e = n.e.n and r_k.e = (e.n)_k.
    static Entries
    bond_tensor(const Tensor<1, dim> &v, const double axial, const double shear);
  };

  /**
   * @brief The normal equations of the fit, (K + rho I) lambda with K lambda = sum over the
   * free bonds of h_b (h_b . (lambda_i + lambda_j)); Voigt::unique multipliers per owned
   * particle.
   */
  template <int dim>
  class NormalEquations
  {
  public:
    /// Multipliers per particle.
    static constexpr unsigned int m = Voigt<dim>::unique;

    /// The equations of the bonds of @p particles, every bond free (no entries yet).
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

    /// Add to @p dst (owned entries) what every bond adds to its ends: @p sum says what;
    /// @p lambda, with current ghost values, the multipliers of Sum::change.
    void
    add_bond_sums(ParticleVector &dst, const Sum sum, const ParticleVector *lambda) const;

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
    vmult_by_class(ParticleVector &dst, const ParticleVector &src) const;

    /// (K + rho I) src by bond: per row, the particle's multipliers and sums kept in local
    /// arrays.
    void
    vmult_by_bond(ParticleVector &dst, const ParticleVector &src) const;

    /// The particles and their bonds.
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
      /// The slot() of the bond's row.
      unsigned int i;
      /// The slot() of the bond's other end.
      unsigned int j;
      /// s_b^2.
      double scale2;
    };
    /// The free bonds by class (those of class c from class_start[c]), in the bond order.
    std::vector<ClassBond> class_bonds;
    /// Where each class's bonds begin in class_bonds (n_classes + 1 entries).
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
    sort_free_bonds();

    /// Group the lattice vectors' entries of the table into classes of equal H (a vector and
    /// its opposite), for vmult_by_class().
    void
    set_classes();

    /// rho.
    double regularization = 0.;
    /// Whether a bond's factor is fitted (1) or held at a bound (0; the bound in fixed).
    std::vector<std::uint8_t> free;
    /// The bound of a held bond.
    std::vector<double> fixed;
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
    /// Multipliers per particle.
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
    vmult(ParticleVector &dst, const ParticleVector &src) const;

  private:
    /// The inverses (m^2 doubles each) and the one of each owned particle.
    std::vector<double>       inverses;
    std::vector<unsigned int> block_of;
    /// By class: the inverses' weights w_ic, as bytes, and their inverse's number.
    std::unordered_map<std::string, unsigned int> known;

    /// Overwrite @p block, the lower triangle of a block less rho I (entry (p, q), q <= p,
    /// at p m + q), by its inverse, all of it.
    static void
    invert(double *block, const double regularization);

    /// The blocks by class: every particle's weights, a new inverse for weights not met
    /// before (the inverses of earlier rounds are kept: a particle whose held bonds changed
    /// may find its new weights among them).
    void
    reinit_by_class(const NormalEquations<dim> &equations);

    /// The blocks of every owned particle (or of those marked in @p changed) from their
    /// bonds' h_b.
    void
    reinit_by_bond(const NormalEquations<dim> &equations, const std::vector<std::uint8_t> *changed);
  };
} // namespace perideal::stiffness_fit

#endif
