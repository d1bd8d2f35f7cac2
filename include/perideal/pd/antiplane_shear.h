// ---------------------------------------------------------------------
// PeriDeal: what the antiplane shear models (one scalar w per particle) share.
// ---------------------------------------------------------------------
#ifndef perideal_pd_antiplane_shear_h
#define perideal_pd_antiplane_shear_h

#include <deal.II/base/parameter_handler.h>

#include <perideal/base/torsion.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/region_moduli.h>

#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief The constants that the antiplane models (`antiplane bond based`, `antiplane state
   * based`; Oterkus & Madenci 2015, seed 000) share: the micromodulus of the bond-based energy
   * and the critical slope of a fracture energy (derivations in doc/theory/models.md).
   */
  namespace AntiplaneShear
  {
    /**
     * @brief The micromodulus c [N/m^6] of the bond-based energy W_i = 1/4 sum_j c r^2 |xi| V_j
     * that matches W = mu |grad w|^2 / 2 (seed eq. 40): 6 mu / (pi h delta^3) for @p dim = 2
     * (a cross-section of thickness @p thickness), 6 mu / (pi delta^4) for @p dim = 3.
     */
    double
    micromodulus(const unsigned int dim,
                 const double       shear_modulus,
                 const double       horizon,
                 const double       thickness);

    /**
     * @brief The critical bond slope r_c of the fracture energy @p fracture_energy (G_IIIc
     * [J/m^2]) for the bond-based energy: sqrt(2 pi G / (3 mu delta)) for @p dim = 2 (seed
     * eq. 78), sqrt(5 G / (3 mu delta)) for @p dim = 3.
     */
    double
    critical_slope(const unsigned int dim,
                   const double       fracture_energy,
                   const double       shear_modulus,
                   const double       horizon);
  } // namespace AntiplaneShear

  /**
   * @brief The base of the antiplane models: the one unknown w per particle (the out-of-plane
   * displacement, or the warping under torsion), the shear modulus mu and its values by
   * region (<Shear moduli by region>, RegionModuli: dissimilar materials), Saint-Venant torsion
   * (<Twist per unit length> psi and <Twist axis> in the model's subsection, see Torsion:
   * the models add the twist to the bond slope, TwistedSlopePairLaw), the critical slope of
   * a fracture energy, and the outputs: the shear stresses tau = mu (grad w + psi (-(y - y0),
   * x - x0)) at the particles (AntiplaneTorsion::shear_stresses()) and, under torsion, the
   * torque and the strain energy per unit length (AntiplaneTorsion::section_integrals()).
   */
  template <int dim>
  class AntiplaneModel : public MaterialModel<dim>
  {
  public:
    /**
     * @brief The scalar "w".
     */
    FieldLayout
    field_layout() const override;

    /**
     * @brief The critical slope r_c of the fracture energy @p fracture_energy (G_IIIc), that of
     * the bond-based energy for both models (seed eqs. 68-78).
     */
    double
    critical_stretch(const double fracture_energy) const override;

    /**
     * @brief Whether a twist is given (the static linear solve does not carry it).
     */
    bool
    has_prestrain() const override;

    /**
     * @brief The twist (<Twist per unit length>, <Twist axis>) if one is given, else nullptr.
     */
    const Torsion *
    torsion() const override;

    /**
     * @brief "torque", "torsion_energy" with a twist.
     */
    std::vector<std::string>
    integral_names() const override;

    /**
     * @brief With a twist, the torque and strain energy per unit length.
     */
    std::vector<double>
    section_integrals(const ParticleSystem<dim> &particles,
                      const ParticleVector      &u,
                      const double               strain_energy) const override;

    /**
     * @brief "shear_stress": the dim components of tau at the particles.
     */
    std::vector<DerivedParticleField>
    derived_fields(const ParticleSystem<dim> &particles, const ParticleVector &u) const override;

    /**
     * @brief The lattice calibration of the critical slope (ModelCapabilities::lattice_fracture;
     * each model sets fracture_factor in its initialize()).
     */
    ModelCapabilities
    capabilities() const override;

    /**
     * @brief The shear modulus mu [Pa] (of the particles outside the regions of <Shear moduli
     * by region>).
     */
    double
    shear_modulus() const;

    /**
     * @brief Look up the regions of <Shear moduli by region>.
     */
    void
    resolve_regions(const RegionCollection<dim> &regions) override;

  protected:
    /**
     * @brief Declare "Shear modulus", "Shear moduli by region", "Twist per unit length" and
     * "Twist axis" in the model's subsection.
     */
    static void
    declare_antiplane_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read them; messages name <Material/@p model_name/...>. Throws unless mu > 0, and
     * for region moduli together with a twist (torsion takes one shear modulus).
     */
    void
    parse_antiplane_parameters(dealii::ParameterHandler &prm, const std::string &model_name);

    /**
     * @brief "; by region: ..." with region moduli, "; torsion: twist psi rad/m about (x0 y0)"
     * with a twist, else empty.
     */
    std::string
    antiplane_summary() const;

    /**
     * @brief Check, under torsion, that the section holds the horizon
     * (AntiplaneTorsion::check_section()), and return the twist fields p = psi (x - x0),
     * q = psi (y - y0) per local particle (empty without a twist).
     */
    std::vector<double>
    twist_fields(const ParticleSystem<dim> &particles) const;

    /// <Shear modulus> [Pa], <Shear moduli by region>, the twist entries of Saint-Venant
    /// torsion and what initialize() was given.
    ///@{
    double            mu = 0.;
    RegionModuli<dim> region_moduli;
    Torsion           twist;
    ModelContext      context;
    ///@}
    /// The factor of the lattice calibration on the continuum's critical slope (1 without it,
    /// ModelContext::lattice_fracture), set by initialize().
    double fracture_factor = 1.;
  };
} // namespace perideal

#endif
