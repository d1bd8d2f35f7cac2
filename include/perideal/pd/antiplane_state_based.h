// ---------------------------------------------------------------------
// PeriDeal: the ordinary state-based peridynamic model of antiplane shear (one scalar per
// particle).
// ---------------------------------------------------------------------
#ifndef perideal_pd_antiplane_state_based_h
#define perideal_pd_antiplane_state_based_h

#include <perideal/pd/antiplane_shear.h>

#include <memory>
#include <vector>

namespace perideal
{
  /**
   * @brief Ordinary state-based peridynamics of antiplane shear (Oterkus & Madenci 2015, seed
   * 000, sec. 3 and 5.1; seed note 000, sec. 1.2 and 1.4): one unknown per particle, the
   * out-of-plane displacement w (field layout: the scalar "w").
   *
   * The PD shear angles (seed eqs. 23, 56) are a nonlocal gradient with the influence function
   * omega = delta/|xi|:
   *   r_i = b g_i (.) sum_j omega (w_j - w_i) n V_j chi,   n = xi/|xi|,
   * with b = 2/(pi h delta^3) in 2D (seed eq. 25, h the thickness) and 9/(4 pi delta^4) in 3D,
   * so that b delta int_H n_a^2 dV = 1 (r = grad w for a linear field in a full horizon), and
   * g_i the per-point surface-correction factors of the directions (.: componentwise; 1 without
   * correction). The energy density is that of the seed (eq. 22, a = mu/2) plus an optional
   * fraction alpha ("Stabilization") of the bond-based energy (AntiplaneBondBased):
   *   W_i = (1 - alpha) mu/2 |r_i|^2 + alpha 1/4 sum_j c G r_ij^2 |xi| V_j chi,
   * r_ij = (w_j - w_i)/|xi| the bond slope. Both terms equal mu |grad w|^2 / 2 for a uniform
   * gradient, so alpha changes nothing for uniform fields; it removes the zero-energy modes of
   * the first term, which sees only a weighted mean of the slopes (an odd-even field
   * (-1)^(i+j+k) on the lattice has r = 0 at every particle with a symmetric family). The force
   * density is -dE/dw_i / V_i of E = sum_i W_i V_i:
   *   f_i = sum_j [omega (s_i + s_j) . n + alpha c G r_ij] V_j chi,   s = (1 - alpha) mu b g (.)
   * r, i.e. the seed's eq. 55 with the factor b that the seed's eqs. 28-30 and 55 omit (seed note
   * 000, sec. 7 T1; doc/theory/models.md). The surface correction is the seed's per point:
   * g_i,a = 1 / (b sum_j omega x_a n_a V_j chi), the ratio of the classical to the PD shear
   * angle for w = x_a over the family without its pre-cracked bonds (crack faces are free
   * faces), so that r_i,a = zeta for w = zeta x_a at every particle (the cross terms near
   * corners stay); the bond-based term takes the energy method
   * of AntiplaneBondBased. A bond breaks, irreversibly, when |r_ij| exceeds the critical slope
   * of the bond-based model (the seed's criterion for both models, eqs. 68-78); broken bonds
   * leave the sums of r and of the force.
   *
   * Saint-Venant torsion (2D, AntiplaneModel): w is the warping and every bond slope r_ij, in
   * the shear angles, the bond-based term and the breaking, is the twisted slope of
   * TwistedSlopePairLaw, the bond projection of grad w + psi (-(y - y0), x - x0), exact for the
   * linear twist field; so r_i is the PD gradient of the whole shear strain and tau = mu r_i,
   * and the faces and crack faces are traction free without fictitious layers
   * (doc/theory/models.md, "Torsion").
   *
   * Dissimilar materials (<Shear moduli by region>, RegionModuli): the state term takes the
   * shear modulus mu_i of each particle, W_i = (1 - alpha) mu_i/2 |r_i|^2 (the variationally
   * consistent form; the seed gives its eq. 60 for the parameter a = mu/2 of a bond, which the
   * nonlocal gradient of this model does not have, seed note 000, sec. 7 A9), so the force
   * density reads f_i = sum_j omega (s_i + s_j) . n V_j chi with s = (1 - alpha) mu b g (.) r of
   * each end; the bond-based term takes the series rule of AntiplaneBondBased. The critical
   * slope takes the model's <Shear modulus>.
   */
  template <int dim>
  class AntiplaneStateBased : public AntiplaneModel<dim>
  {
  public:
    /**
     * @brief A model without parameters; parse_parameters() and initialize() set it up.
     */
    AntiplaneStateBased();

    /**
     * @brief Destructor (the kernel's data are defined in antiplane_state_based.cc).
     */
    ~AntiplaneStateBased() override;

    /**
     * @brief Declare the entries of AntiplaneModel and "Stabilization".
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) override;

    /**
     * @brief Two passes of the shared bond-block loop: the shear angles r (breaking bonds whose
     * slope exceeds @p critical_slope), then the forces (and the energy density).
     */
    void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &w,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_slope) override;

    /**
     * @brief Gershgorin bound of the linearized operator (that of linearize()'s rows) plus the
     * bond-based term's; defined in source/pd/antiplane_state_based_linearization.cc.
     */
    void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const override;

    /**
     * @brief Per owned particle and direction a the row r_i,a (weight (1 - alpha) mu beta_i V_i,
     * beta_i the energy weight), and per intact bond the row w_j - w_i of the bond-based term
     * (weight alpha c G chi V_i V_j / |xi|); defined in
     * source/pd/antiplane_state_based_linearization.cc.
     */
    void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const override;

    std::string
    summary() const override;

    std::unique_ptr<SurfaceCorrectionLaw<dim>>
    surface_correction_law(ParticleSystem<dim> &particles) override;

    /**
     * @brief 2: the force uses the neighbours' states.
     */
    unsigned int
    force_reach() const override;

    /**
     * @brief The constant b of the shear angles [1/m^4]: 2 / (pi h delta^3) in 2D,
     * 9 / (4 pi delta^4) in 3D.
     */
    double
    shear_angle_constant() const;

    /**
     * @brief The stabilization fraction alpha in [0, 1).
     */
    double
    stabilization() const;

    /**
     * @brief The shear angles r_i (dim components per owned particle: the PD gradient of w,
     * tau = mu r) from the last force computation.
     */
    const ParticleVector &
    shear_angles() const;

  private:
    using AntiplaneModel<dim>::mu;
    using AntiplaneModel<dim>::region_moduli;
    using AntiplaneModel<dim>::twist;
    using AntiplaneModel<dim>::context;

    double alpha   = 0.;
    double b_state = 0.;
    double c       = 0.;
    /// (1 - alpha) mu_i per owned particle (mu_i the shear modulus at the particle).
    std::vector<double> state_modulus;
    /// delta chi V_i V_j per bond (omega |xi| chi V_i V_j: what r and the force share).
    std::vector<double> state_coefficient;
    /// alpha c G chi V_i V_j per bond (the bond-based term's pair force per unit slope).
    std::vector<double> bond_coefficient;
    /// b g_i,a per owned particle and direction (r_i,a = this times the sum over j / V_i).
    std::vector<double> angle_factor;
    /// The shear angles r (owned), and s = (1 - alpha) mu beta_i b g (.) r (owned and ghost).
    ParticleVector angles, force_state;
    /// The force kernel's data (bonds in SIMD blocks, kernel-order fields): defined in
    /// antiplane_state_based.cc, compiled with the kernel options (source/pd/CMakeLists.txt).
    struct Kernel;
    std::unique_ptr<Kernel> kernel;

    /**
     * @brief Set bond_coefficient (bond_pair_coefficients() of the micromodulus
     * @p micromodulus, with the region moduli's bond moduli if @p with_surface_factor) and the
     * kernel's lanes.
     */
    void
    set_bond_coefficients(const ParticleSystem<dim> &particles,
                          const double               micromodulus,
                          const bool                 with_surface_factor);
  };
} // namespace perideal

#endif
