// ---------------------------------------------------------------------
// PeriDeal: the energy method of surface correction for bond-based models.
// ---------------------------------------------------------------------
#ifndef perideal_pd_surface_correction_h
#define perideal_pd_surface_correction_h

#include <deal.II/base/symmetric_tensor.h>

#include <perideal/base/linear_algebra.h>
#include <perideal/pd/particle_system.h>

#include <functional>
#include <vector>

namespace perideal
{
  /**
   * @brief Set BondList::surface_factor by the energy method (Madenci & Oterkus 2014, sec. 4.2;
   * seed note 002, sec. 3.2).
   *
   * For each direction a, the uniaxial test field u = s* x_a e_a is applied and the model's
   * strain-energy density W_i compared with the classical value W = C_aaaa s*^2 / 2 of the
   * target tensor @p elasticity: g_a(i) = W / W_i. A bond takes
   * G = [sum_a (n_a / G_a)^2]^(-1/2) with G_a = (g_a(i) + g_a(j)) / 2 and n = xi/|xi|.
   * @p energy_density evaluates W_i of the owned particles for a displacement with current
   * ghost values; it is called with all surface factors equal to one.
   */
  template <int dim>
  void
  apply_energy_surface_correction(
    ParticleSystem<dim>                                                      &particles,
    const dealii::SymmetricTensor<4, dim>                                    &elasticity,
    const std::function<void(const ParticleVector &, std::vector<double> &)> &energy_density);
} // namespace perideal

#endif
