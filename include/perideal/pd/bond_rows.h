// ---------------------------------------------------------------------
// PeriDeal: row buffers and SIMD blocks for the vectorized bond loops of the force kernels.
// ---------------------------------------------------------------------
#ifndef perideal_pd_bond_rows_h
#define perideal_pd_bond_rows_h

#include <perideal/pd/particle_system.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include <experimental/simd>

namespace perideal
{
  /**
   * @brief SIMD building blocks of the bond loops (std::experimental::simd of the width the
   * kernels are compiled for: 8 doubles with AVX-512, 4 with AVX2, 2 with SSE2).
   *
   * A force kernel treats one row of the BondList (the bonds of one owned particle i) at a
   * time in three steps:
   *  1. BondRows::gather() forms the bond vectors (x_j - x_i) + (u_j - u_i) with scalar loads
   *     (on Zen 4 the hardware gathers that the auto-vectorizer emits are slower than scalar
   *     loads, which is why the kernels are compiled with -fno-tree-vectorize);
   *  2. the model computes the bond forces in blocks of bond_simd::width bonds with contiguous
   *     loads of the per-bond arrays (load() masks the last, partial block of a row);
   *  3. BondRows::scatter() subtracts the bond forces from the owned neighbours j.
   */
  namespace bond_simd
  {
    namespace stdx = std::experimental;

    /// A SIMD vector of doubles.
    using Vector = stdx::native_simd<double>;
    /// A lane mask.
    using Mask = Vector::mask_type;
    /// Number of lanes.
    constexpr unsigned int width = Vector::size();

    /**
     * @brief The lanes l < @p n_valid.
     */
    inline Mask
    valid_lanes(const unsigned int n_valid)
    {
      return Vector([](const auto l) { return double(l); }) < double(n_valid);
    }

    /**
     * @brief The block at @p p; lanes from @p n_valid on are not read and hold @p fill.
     */
    inline Vector
    load(const double *p, const unsigned int n_valid, const double fill)
    {
      Vector v;
      if (n_valid >= width)
        v.copy_from(p, stdx::element_aligned);
      else
        {
          v = fill;
          stdx::where(valid_lanes(n_valid), v).copy_from(p, stdx::element_aligned);
        }
      return v;
    }

    /**
     * @brief The lanes of intact bonds (BondList::intact != 0) among the first @p n_valid.
     */
    inline Mask
    intact_lanes(const std::uint8_t *state, const unsigned int n_valid)
    {
      stdx::fixed_size_simd<std::uint8_t, width> bytes;
      if (n_valid >= width)
        bytes.copy_from(state, stdx::element_aligned);
      else
        {
          bytes = 0;
          for (unsigned int l = 0; l < n_valid; ++l)
            bytes[l] = state[l];
        }
      return stdx::static_simd_cast<Vector>(bytes) != 0.;
    }

    /**
     * @brief Break the bonds of a block whose lanes in @p overstretched are breakable (state 1);
     * returns the lanes broken now. Bonds that never break (state 2) are left alone.
     */
    inline Mask
    break_bonds(const Mask &overstretched, std::uint8_t *state)
    {
      Mask broken(false);
      for (unsigned int l = 0; l < width; ++l)
        if (overstretched[l] && state[l] == 1)
          {
            state[l]  = 0;
            broken[l] = true;
          }
      return broken;
    }
  } // namespace bond_simd

  /**
   * @brief Per-row work arrays of a force kernel: the bond vectors of one row by component and
   * @p n_scalars further per-bond values, padded to whole SIMD blocks. Sized once for the
   * longest row (reinit()), so the time loop does not allocate.
   */
  template <int dim>
  class BondRows
  {
  public:
    /**
     * @brief Size for the longest row of @p bonds, with @p n_scalars per-bond scalars.
     */
    void
    reinit(const BondList &bonds, const unsigned int n_scalars)
    {
      unsigned int longest = 0;
      for (std::size_t i = 0; i + 1 < bonds.row_start.size(); ++i)
        longest = std::max(longest, bonds.row_start[i + 1] - bonds.row_start[i]);
      stride = (longest + bond_simd::width - 1) / bond_simd::width * bond_simd::width;
      data.assign(std::size_t(stride) * (dim + n_scalars), 0.);
    }

    /**
     * @brief Component @p d of the bond vectors of the current row (block-aligned). After the
     * model has computed the forces it holds the force components for scatter().
     */
    double *
    component(const unsigned int d)
    {
      return data.data() + std::size_t(stride) * d;
    }

    /**
     * @brief Per-bond scalar @p k of the current row.
     */
    double *
    scalar(const unsigned int k)
    {
      return component(dim + k);
    }

    /**
     * @brief The bond vectors (x_j - x_i) + (u_j - u_i) of the @p n bonds to @p neighbor of
     * particle @p i (x and u flat, dim values per particle); lanes up to the end of the last
     * block are set to the unit vector e_0 so that their (discarded) arithmetic stays finite.
     */
    void
    gather(const double       *x,
           const double       *u,
           const unsigned int  i,
           const unsigned int *neighbor,
           const unsigned int  n)
    {
      std::array<double, dim> xi, ui;
      for (unsigned int d = 0; d < dim; ++d)
        {
          xi[d] = x[std::size_t(i) * dim + d];
          ui[d] = u[std::size_t(i) * dim + d];
        }
      std::array<double *, dim> r;
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = component(d);
      for (unsigned int l = 0; l < n; ++l)
        {
          const std::size_t j = std::size_t(neighbor[l]) * dim;
          for (unsigned int d = 0; d < dim; ++d)
            r[d][l] = (x[j + d] - xi[d]) + (u[j + d] - ui[d]);
        }
      const unsigned int padded = (n + bond_simd::width - 1) / bond_simd::width * bond_simd::width;
      for (unsigned int l = n; l < padded; ++l)
        for (unsigned int d = 0; d < dim; ++d)
          r[d][l] = (d == 0 ? 1. : 0.);
    }

    /**
     * @brief Subtract the force components of the current row from the owned neighbours:
     * f[j * dim + d] -= component(d)[l] for the @p n bonds to @p neighbor with j < @p n_owned.
     */
    void
    scatter(double             *f,
            const unsigned int *neighbor,
            const unsigned int  n,
            const unsigned int  n_owned)
    {
      std::array<const double *, dim> g;
      for (unsigned int d = 0; d < dim; ++d)
        g[d] = component(d);
      for (unsigned int l = 0; l < n; ++l)
        {
          const unsigned int j = neighbor[l];
          if (j < n_owned)
            for (unsigned int d = 0; d < dim; ++d)
              f[std::size_t(j) * dim + d] -= g[d][l];
        }
    }

    /**
     * @brief Per-bond scalar @p k of the current row from a per-particle array:
     * scalar(k)[l] = @p values[neighbor[l]] for the @p n bonds; lanes up to the end of the last
     * block are set to zero.
     */
    void
    gather_scalar(const unsigned int  k,
                  const double       *values,
                  const unsigned int *neighbor,
                  const unsigned int  n)
    {
      double *a = scalar(k);
      for (unsigned int l = 0; l < n; ++l)
        a[l] = values[neighbor[l]];
      const unsigned int padded = (n + bond_simd::width - 1) / bond_simd::width * bond_simd::width;
      std::fill(a + n, a + padded, 0.);
    }

    /**
     * @brief Add the per-bond scalar @p k of the current row to the owned neighbours:
     * target[j] += scalar(k)[l] for the @p n bonds to @p neighbor with j < @p n_owned.
     */
    void
    scatter_scalar(const unsigned int  k,
                   double             *target,
                   const unsigned int *neighbor,
                   const unsigned int  n,
                   const unsigned int  n_owned)
    {
      const double *a = scalar(k);
      for (unsigned int l = 0; l < n; ++l)
        if (neighbor[l] < n_owned)
          target[neighbor[l]] += a[l];
    }

  private:
    unsigned int        stride = 0;
    std::vector<double> data;
  };
} // namespace perideal

#endif
