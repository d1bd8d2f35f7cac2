// ---------------------------------------------------------------------
// PeriDeal: the ordinary state-based linear peridynamic solid (LPS).
// ---------------------------------------------------------------------
#ifndef perideal_pd_linear_peridynamic_solid_h
#define perideal_pd_linear_peridynamic_solid_h

#include <perideal/pd/influence_function.h>
#include <perideal/pd/material_model.h>

#include <memory>

namespace perideal
{
  /**
   * @brief The linear peridynamic solid (Silling, Epton, Weckner, Xu & Askari 2007,
   * J. Elasticity 88, sec. 15), in 3D and in 2D plane stress and plane strain.
   *
   * With extension e = |xi + eta| - |xi|, weighted volume m_i = sum_j omega |xi|^2 V_j chi and
   * dilatation theta_i = (n/m_i) sum_j omega |xi| e V_j chi (n = dim), the energy density is
   * W_i = k theta_i^2 / 2 + (alpha_i / 2) sum_j omega (e - theta_i |xi| / n)^2 V_j chi with
   * alpha_i = mu n (n + 2) / m_i. The scalar force state is
   * t_ij = (n k - (n + 2) mu) omega |xi| theta_i / m_i + alpha_i omega e, and the force density
   * on i is sum_j (t_ij + t_ji) (xi + eta)/|xi + eta| V_j chi. Here k is the bulk modulus of the
   * represented dimension: K = E / (3 (1 - 2 nu)) in 3D, lambda + mu in plane strain and
   * E / (2 (1 - nu)) in plane stress; these reduce to Silling et al. (3 K, 15 mu / m) in 3D and
   * reproduce W = k (tr eps)^2 / 2 + mu eps_dev : eps_dev for any homogeneous strain inside
   * the body (derivation in doc/theory/lps.md).
   *
   * Weighted volume: m_i is the discrete sum over the actual family, with or without surface
   * correction, so theta is exact for any isotropic expansion at every particle and the force
   * is minus the gradient of the energy (with the continuum m of a full horizon it is not at
   * particles near a surface; doc/theory/models.md). Critical stretch from the fracture energy G0
   * for the inverse-distance influence function (Madenci & Oterkus 2014, Peridynamic Theory and
   * Its Applications, ordinary state-based critical stretch, 2D and 3D):
   * 3D s0 = sqrt(G0 / ((3 mu + (3/4)^4 (K - 5 mu / 3)) delta)),
   * 2D s0 = sqrt(G0 / ((6 mu / pi + 16 / (9 pi^2) (k - 2 mu)) delta)).
   *
   * Thermal strain (doc/theory/thermal_strain_state_based.md): with a temperature change
   * (set_temperature_change()) every extension is measured from the bond's free thermal
   * extension, e - a |xi| DeltaT_b with DeltaT_b = (DeltaT_i + DeltaT_j)/2 and a the in-plane
   * expansion thermal_expansion() (alpha; (1 + nu) alpha in plane strain), in the dilatation
   * and in the deviatoric part alike; bonds break by this mechanical stretch. A free body under
   * a uniform or linear temperature change then carries no force at any particle (under a
   * linear one up to the geometric nonlinearity of the extension, second order in DeltaT).
   */
  template <int dim>
  class LinearPeridynamicSolid : public MaterialModel<dim>
  {
  public:
    /**
     * @brief A model without parameters; parse_parameters() and initialize() set it up.
     */
    LinearPeridynamicSolid();

    /**
     * @brief Destructor (the kernel's data are defined in linear_peridynamic_solid.cc).
     */
    ~LinearPeridynamicSolid() override;

    /**
     * @brief Declare "Young's modulus", "Poisson's ratio", "Influence function" and
     * "Thermal expansion" (one value: the model is isotropic).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) override;

    void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &u,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_stretch) override;


    /**
     * @brief Gershgorin bound (see MaterialModel::stiffness_bound()); defined in
     * source/pd/linear_peridynamic_solid_linearization.cc.
     */
    void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const override;

    /**
     * @brief Linearization (see MaterialModel::linearize()); defined in
     * source/pd/linear_peridynamic_solid_linearization.cc.
     */
    void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const override;

    dealii::SymmetricTensor<4, dim>
    elasticity_tensor() const override;

    /**
     * @brief a I, with a = alpha in 3D and plane stress and (1 + nu) alpha in plane strain
     * (planar_thermal_expansion()).
     */
    dealii::SymmetricTensor<2, dim>
    thermal_expansion() const override;

    /**
     * @brief m_l = -(1/V_l) dE/dDeltaT_l of the whole strain's dilatation theta and extensions e:
     * n a k theta_l / 2 plus, over the bonds of l, 1/2 a omega chi |xi| V_j [n k theta_j |xi| /
     * m_j + alpha_j (e - theta_j |xi| / n)] (energy weights included;
     * doc/theory/thermoelasticity.md); n a k theta in the interior of a homogeneous strain.
     * Leaves dilatation() at the whole strain's.
     */
    void
    thermoelastic_measure(ParticleSystem<dim>  &particles,
                          const ParticleVector &u,
                          std::vector<double>  &measure) override;

    double
    critical_stretch(const double fracture_energy) const override;

    std::string
    summary() const override;

    ModelCapabilities
    capabilities() const override;

    /**
     * @brief 2: the force uses the neighbours' states.
     */
    unsigned int
    force_reach() const override;

    /**
     * @brief Dilatation of the owned particles from the last force computation (with a
     * temperature change the mechanical one, from the extensions less the thermal ones).
     */
    const ParticleVector &
    dilatation() const;

  private:
    /**
     * @brief Pass 1 of the kernel on the gathered displacement: bonds above @p critical_stretch
     * break (the mechanical stretch if @p thermal, with the gathered temperature change), the
     * dilatation of the owned and ghost particles (theta) and the kernel's theta / m for pass 2.
     */
    void
    dilatation_pass(ParticleSystem<dim> &particles,
                    const double         critical_stretch,
                    const bool           thermal);

    double youngs_modulus = 0.;
    double poisson_ratio  = 0.;
    /// The 3D thermal expansion alpha [1/K] (<Thermal expansion>).
    double                             expansion = 0.;
    std::unique_ptr<InfluenceFunction> influence;
    std::string                        influence_name;
    ModelContext                       context;
    double                             bulk_modulus  = 0.;
    double                             shear_modulus = 0.;
    /// The in-plane expansion a of the planar assumption [1/K] (thermal_expansion()).
    double planar_expansion = 0.;
    /// The factor of the lattice calibration on the continuum's critical stretch (1 without it,
    /// ModelContext::lattice_fracture): by a mode I cleave (cleave_fracture_energy()).
    double fracture_factor = 1.;
    /// omega chi V_i V_j per bond.
    std::vector<double> pair_weight;
    /// Weighted volume per local particle (owned and ghost).
    ParticleVector weighted_volume;
    ParticleVector theta;
    /// alpha = mu n (n + 2) / m per local particle.
    std::vector<double> alpha;

    /// The force kernel's data (bonds in SIMD blocks, kernel-order fields): defined in
    /// linear_peridynamic_solid.cc only, the one translation unit of the model compiled with
    /// the kernel options (source/pd/CMakeLists.txt).
    struct Kernel;
    std::unique_ptr<Kernel> kernel;
  };
} // namespace perideal

#endif
