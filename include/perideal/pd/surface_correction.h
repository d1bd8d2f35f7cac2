// ---------------------------------------------------------------------
// PeriDeal: the surface correction of the PD models: the energy method, and the one dispatch
// between it and the stiffness fit from the law a model supplies.
// ---------------------------------------------------------------------
#ifndef perideal_pd_surface_correction_h
#define perideal_pd_surface_correction_h

#include <deal.II/base/symmetric_tensor.h>

#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>
#include <perideal/pd/stiffness_fit.h>

#include <array>
#include <functional>
#include <vector>

namespace perideal
{
  /// The surface-correction factor G of bond b of row i of the bond list, as a function (i, b).
  using SurfaceFactors = std::function<double(const unsigned int, const std::size_t)>;

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

  /**
   * @brief The surface correction of @p model, the one place that chooses the method: nothing
   * unless @p context asks for a correction and the model supplies a law
   * (MaterialModel::surface_correction_law()); then the stiffness fit (apply_stiffness_fit(),
   * if @p context says so: the parameters checked that the law has one) or the energy method
   * (apply_energy_surface_correction(), with the model's coefficients set uncorrected first).
   * It sets BondList::surface_factor; the model then sets its coefficients with the factors.
   * Called by the model's initialize() once its constants are set. Returns the fit's report
   * (the default one without a fit).
   *
   * With @p use, the correction hands the factors to @p use instead, once, as a function of
   * the bond (SurfaceFactors: 1 without a correction, BondList::surface_factor after the fit);
   * the energy method then computes each bond's factor from the particles' directional factors
   * when asked and stores none per bond (a model that puts them straight into its own
   * coefficients: PMB, which does not keep BondList::surface_factor).
   */
  template <int dim>
  StiffnessFitReport
  apply_surface_correction(MaterialModel<dim>                                &model,
                           ParticleSystem<dim>                               &particles,
                           const ModelContext                                &context,
                           const std::function<void(const SurfaceFactors &)> &use = {});

  /**
   * @brief The energy density of the energy method by @p model's own force evaluation
   * (MaterialModel::compute_forces() with no bond breaking, a force vector of its own): the
   * SurfaceCorrectionLaw::energy_density of a model whose forces give its whole energy.
   */
  template <int dim>
  std::function<void(const ParticleVector &, std::vector<double> &)>
  model_energy_density(MaterialModel<dim> &model, ParticleSystem<dim> &particles);

  /**
   * @brief The law of an elastic displacement model: its own energy
   * (model_energy_density()), the moduli C_aaaa of its elasticity_tensor() along the axes (and
   * C_1111 as the stiffness fit's target) and @p uncorrected_coefficients; the model adds its
   * bond stiffness law if it has a stiffness fit.
   */
  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  elastic_surface_correction_law(MaterialModel<dim>          &model,
                                 ParticleSystem<dim>         &particles,
                                 const std::function<void()> &uncorrected_coefficients);
} // namespace perideal

#endif
