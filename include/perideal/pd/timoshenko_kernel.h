// ---------------------------------------------------------------------
// PeriDeal: the data of the Timoshenko bond model's force kernel (TimoshenkoBondBased), shared by
// its source files. A kernel header (source/pd/CMakeLists.txt): included only by the
// timoshenko_bond_based*.cc files, which are compiled with the kernel options.
// ---------------------------------------------------------------------
#ifndef perideal_pd_timoshenko_kernel_h
#define perideal_pd_timoshenko_kernel_h

#include <perideal/pd/bond_loop.h>
#include <perideal/pd/timoshenko_bond_based.h>

#include <array>

namespace perideal
{
  /**
   * @brief The force kernel of TimoshenkoBondBased: its bond blocks, the per-lane coefficients
   * and softening histories, and the fields in kernel order that one force_loop() reads and writes.
   */
  template <int dim>
  struct TimoshenkoBondBased<dim>::Kernel
  {
    /// Translations and rotations (one rotation in 2D, three in 3D).
    static constexpr unsigned int n_components = dim + (dim == 2 ? 1 : 3);
    /// The bonds in lanes of the kernel's order.
    BondBlocks<dim> blocks;
    /// Per lane the pair coefficient k = G chi V_i V_j.
    typename BondBlocks<dim>::Array lane_coefficient;
    /// The unknowns, the forces and moments, the pair energies, and the temperature change
    /// (sized on its first use), in kernel order.
    ///@{
    typename BondBlocks<dim>::Array u_field, f_field, w_field, t_field;
    ///@}
    /// Softening: per lane the histories and factors of the three modes, and the dissipated
    /// energy (lanes of bonds to ghosts count on both ranks).
    ///@{
    typename BondBlocks<dim>::Array history[3], factor[3], dissipated;
    ///@}
    /// The dissipated energy reported so far, and the largest growth of a history in the last
    /// committed pass.
    ///@{
    double dissipated_reported = 0., largest_growth = 0.;
    ///@}

    /**
     * @brief One pass of the pair law @p law (the TimoshenkoPairLaw of
     * source/pd/timoshenko_bond_based.cc) over the bond blocks: forces and moments into
     * f_field and, if the law has an energy output, the pair energies into w_field; a thermal
     * law (an input more than the unknowns) reads the kernel-order temperature change
     * @p delta_T.
     */
    template <typename Law>
    void
    force_loop(Law law, BondList &bonds, const double threshold, const double *delta_T)
    {
      std::array<const double *, Law::n_inputs> u;
      std::array<double *, Law::n_outputs>      out;
      for (unsigned int c = 0; c < n_components; ++c)
        {
          u[c]   = blocks.component(u_field, c);
          out[c] = blocks.component(f_field, c);
        }
      if constexpr (Law::n_inputs > n_components)
        u[n_components] = delta_T;
      if constexpr (Law::n_outputs > n_components)
        out[n_components] = blocks.component(w_field, 0);
      law.p.coefficient = lane_coefficient.data();
      law.p.state       = blocks.state();
      if constexpr (Law::softens)
        {
          for (unsigned int m = 0; m < 3; ++m)
            {
              law.p.history[m] = history[m].data();
              law.p.factor[m]  = factor[m].data();
            }
          law.p.dissipated     = dissipated.data();
          law.p.largest_growth = &largest_growth;
        }
      for_each_bond_block<Law::n_inputs>(blocks, u, out, law, bonds, threshold);
    }
  };
} // namespace perideal

#endif
