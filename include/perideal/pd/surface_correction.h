// ---------------------------------------------------------------------
// PeriDeal: the energy method of surface correction for bond-based models.
// ---------------------------------------------------------------------
#ifndef perideal_pd_surface_correction_h
#define perideal_pd_surface_correction_h

#include <deal.II/base/symmetric_tensor.h>

#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/pd/particle_system.h>

#include <array>
#include <functional>
#include <vector>

namespace perideal
{
  /**
   * @brief Set BondList::surface_factor by the energy method (Madenci & Oterkus 2014, sec. 4.2;
   * seed note 002, sec. 3.2; for the scalar antiplane field, seed 000, sec. 5.1).
   *
   * For each direction a, the test field of slope s* along x_a is applied: u = s* x_a e_a on
   * the translation of axis a for a displacement @p layout, w = s* x_a on the component of a
   * scalar @p layout. The model's strain-energy density W_i is compared with the classical
   * value W = M_a s*^2 / 2 of the modulus @p modulus[a] of that field (C_aaaa of the target
   * elasticity tensor; the shear modulus of antiplane shear): g_a(i) = W / W_i. A bond takes
   * G = [sum_a (n_a / G_a)^2]^(-1/2) with G_a = (g_a(i) + g_a(j)) / 2 and n = xi/|xi| (the
   * ellipse rule). @p energy_density evaluates W_i of the owned particles for a field of
   * @p layout with current ghost values; it is called with all surface factors equal to one and
   * every bond intact (pre-cracked ones too: the correction describes the uncracked geometry;
   * BondList::intact is restored afterwards).
   */
  template <int dim>
  void
  apply_energy_surface_correction(
    ParticleSystem<dim>                                                      &particles,
    const FieldLayout                                                        &layout,
    const std::array<double, dim>                                            &modulus,
    const std::function<void(const ParticleVector &, std::vector<double> &)> &energy_density);
} // namespace perideal

#endif
