// ---------------------------------------------------------------------
// PeriDeal: the data of the anisotropic plane-stress model's force kernel (AnisotropicPlaneStress),
// shared by its source files. A kernel header (source/pd/CMakeLists.txt): included only by the
// anisotropic_plane_stress*.cc files compiled with the kernel options.
// ---------------------------------------------------------------------
#ifndef perideal_pd_anisotropic_plane_stress_kernel_h
#define perideal_pd_anisotropic_plane_stress_kernel_h

#include <perideal/pd/anisotropic_plane_stress.h>
#include <perideal/pd/bond_loop.h>

#include <array>

namespace perideal
{
  /**
   * @brief The force kernel of AnisotropicPlaneStress: its bond blocks, the per-lane
   * coefficients k and g, and the fields in kernel order that the two passes read and write.
   */
  struct AnisotropicPlaneStress::Kernel
  {
    /// The bonds in SIMD blocks.
    BondBlocks<2> blocks;
    /// Per lane the pair coefficients k and g.
    ///@{
    BondBlocks<2>::Array lane_k, lane_g;
    ///@}
    /// Kernel-order work fields: displacement, force, energy density, pass-1 sums, beta A,
    /// temperature change.
    ///@{
    BondBlocks<2>::Array u_field, f_field, w_field, a_field, beta_A_field, delta_T_field;
    ///@}

    /// The kernel-order unknowns of the laws: the displacement and, if @p thermal, the
    /// temperature change.
    template <bool thermal>
    std::array<const double *, 2 + thermal>
    unknowns()
    {
      std::array<const double *, 2 + thermal> u;
      for (unsigned int d = 0; d < 2; ++d)
        u[d] = blocks.component(u_field, d);
      if constexpr (thermal)
        u[2] = blocks.component(delta_T_field, 0);
      return u;
    }

    /// Pass 1 (the dilatation law: breaks bonds, sums g_b n . eta into a_field) with the in-plane
    /// expansion @p expansion if @p thermal.
    template <bool thermal>
    void
    dilatation_loop(BondList                    &bonds,
                    const double                 critical_stretch,
                    const std::array<double, 3> &expansion);

    /// Pass 2 (the force law into f_field), with the energy density into w_field if
    /// @p with_energy.
    template <bool with_energy, bool thermal>
    void
    force_loop(BondList &bonds, const std::array<double, 3> &expansion);
  };
} // namespace perideal

#endif
