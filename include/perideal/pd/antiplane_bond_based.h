// ---------------------------------------------------------------------
// PeriDeal: the bond-based peridynamic model of antiplane shear (one scalar per particle).
// ---------------------------------------------------------------------
#ifndef perideal_pd_antiplane_bond_based_h
#define perideal_pd_antiplane_bond_based_h

#include <perideal/pd/antiplane_shear.h>

#include <memory>

namespace perideal
{
  /**
   * @brief Bond-based peridynamics of antiplane shear (Oterkus & Madenci 2015, seed 000,
   * sec. 4; seed note 000, sec. 1.3): one unknown per particle, the out-of-plane displacement
   * w (field layout: the scalar "w").
   *
   * Bond slope r = (w_j - w_i)/|xi|; pair force c G r on i (its negative on j), with G the
   * surface-correction factor; the force density on i is sum_j c G r chi V_j (chi the
   * partial-volume factor), W_i = 1/4 sum_j c G r^2 |xi| chi V_j. The micromodulus follows
   * from the shear modulus mu by energy matching with W = mu |grad w|^2 / 2 (seed eq. 40):
   *  - 2D (the cross-section of a prismatic body of thickness h): c = 6 mu / (pi h delta^3);
   *  - 3D (the same Laplace-type energy of a scalar field in a volume, doc/theory/models.md):
   *    c = 6 mu / (pi delta^4).
   * The planar assumption does not enter (antiplane shear has the one constant mu). A bond
   * breaks, irreversibly, when |r| exceeds the critical slope of the fracture energy G_IIIc,
   * r_c = sqrt(2 pi G / (3 mu delta)) in 2D and sqrt(5 G / (3 mu delta)) in 3D
   * (doc/theory/models.md). Surface correction by the energy method with the test fields
   * w = s x and w = s y (and z); see apply_energy_surface_correction().
   *
   * Saint-Venant torsion (2D; <Twist per unit length> psi and <Twist axis> (x0, y0) in the
   * model's subsection, see Torsion): w is the warping, and the slope of a bond is the twisted
   * slope r = (w_j - w_i + psi ((x_i - x0)(y_j - y0) - (x_j - x0)(y_i - y0)))/|xi|, the bond
   * projection of the shear strain grad w + psi (-(y - y0), x - x0) (seed note 000, sec. 4.5;
   * TwistedSlopePairLaw), in the force, the energy and the breaking. The traction-free
   * condition of the outer faces and of crack faces then holds without fictitious layers
   * (doc/theory/models.md, "Torsion"). The surface correction is computed without the twist.
   * The static linear solve does not carry the twist (has_prestrain()); adaptive dynamic
   * relaxation does. Section integrals: the torque and the strain energy per unit length
   * (AntiplaneTorsion::section_integrals()); output: the shear stresses at the particles.
   *
   * Dissimilar materials (<Shear moduli by region>, RegionModuli): a bond's micromodulus is
   * that of the length-weighted harmonic mean of the shear moduli along it (seed eq. 60, the
   * series rule; c is proportional to mu, so the rule for c and for mu agree). The surface
   * correction is that of one material (its factors do not depend on mu); the critical slope
   * and torsion take the model's <Shear modulus>, so a twist with region moduli is rejected.
   */
  template <int dim>
  class AntiplaneBondBased : public AntiplaneModel<dim>
  {
  public:
    /**
     * @brief A model without parameters; parse_parameters() and initialize() set it up.
     */
    AntiplaneBondBased();

    /**
     * @brief Destructor (the kernel's data are defined in antiplane_bond_based.cc).
     */
    ~AntiplaneBondBased() override;

    /**
     * @brief Declare the entries of AntiplaneModel.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) override;

    void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &w,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_slope) override;

    /**
     * @brief Gershgorin bound (bond_pair_stiffness_bound()); defined in
     * source/pd/antiplane_bond_based_linearization.cc.
     */
    void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const override;

    /**
     * @brief One row (w_j - w_i) per intact bond with weight c G chi V_i V_j / |xi|; defined
     * in source/pd/antiplane_bond_based_linearization.cc.
     */
    void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const override;

    std::string
    summary() const override;

    std::unique_ptr<SurfaceCorrectionLaw<dim>>
    surface_correction_law(ParticleSystem<dim> &particles) override;

    /**
     * @brief The micromodulus c [N/m^6].
     */
    double
    micromodulus() const;

  private:
    using AntiplaneModel<dim>::mu;
    using AntiplaneModel<dim>::region_moduli;
    using AntiplaneModel<dim>::twist;
    using AntiplaneModel<dim>::context;

    double c = 0.;
    /// c G chi V_i V_j per bond (the pair force per unit slope).
    std::vector<double> bond_coefficient;
    /// The force kernel's data (bonds in SIMD blocks, kernel-order fields): defined in
    /// antiplane_bond_based.cc, compiled with the kernel options (source/pd/CMakeLists.txt).
    struct Kernel;
    std::unique_ptr<Kernel> kernel;

    /**
     * @brief Set bond_coefficient (bond_pair_coefficients(), with the region moduli's bond
     * moduli if @p with_surface_factor) and the kernel's lanes.
     */
    void
    set_bond_coefficients(const ParticleSystem<dim> &particles, const bool with_surface_factor);
  };
} // namespace perideal

#endif
