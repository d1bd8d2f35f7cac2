// ---------------------------------------------------------------------
// PeriDeal: the anisotropic PD plane-stress model (seed 004, state form).
// ---------------------------------------------------------------------
#ifndef perideal_pd_anisotropic_plane_stress_h
#define perideal_pd_anisotropic_plane_stress_h

#include <deal.II/base/symmetric_tensor.h>

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_micromodulus.h>
#include <perideal/pd/material_model.h>

#include <memory>

namespace perideal
{
  /**
   * @brief The generalized plane-stress model of anisotropic linearized bond-based PD
   * (Trageser & Seleson, SAND2019-12685C, slides "PD plane stress", the state-based
   * reformulation; seed note 004, secs. 1.5-1.6, option M), 2D only.
   *
   * The 3D bond-based model of a plate, averaged through its thickness with the out-of-plane
   * displacement eliminated by the zero mean out-of-plane traction, is an ordinary state-based
   * 2D model. Per unit volume, with eta = u(x') - u(x) and w = chi V_j:
   *   W_i = 1/4 sum_j lambda_0(xi) (xi . eta)^2 w - 1/2 B_i A_i^2,
   *   A_i = sum_j lambda_2(xi) xi . eta w / B_i  (= -eps_33, the out-of-plane strain),
   *   f_i V_i = sum_j chi V_i V_j xi [lambda_0 (xi . eta) - lambda_2 (A_i + A_j)],
   * lambda_0 = c_0(n)/|xi|^3 with c_0(n) = Lambda0_abcd n_a n_b n_c n_d (the 2D anisotropic
   * bond-based kernel), lambda_2 = M_ab n_a n_b / |xi| and B_i = C_3333 m_i / m (m_i = sum_j |xi|
   * w, its interior or continuum value m: the note's per-node B_i = sum_j lambda_4 w with
   * lambda_4 proportional to |xi|). The moment conditions (the note's Proposition, in these
   * units) 1/2 sum lambda_0 xi^4 w = C_abcd, sum lambda_2 xi xi w = C_ab33 and B = C_3333 make a
   * homogeneous strain reproduce the reduced stiffness C' = C - C_ab33 C_33cd / C_3333 with
   * A = C_33ab eps_ab / C_3333; they are solved on the lattice's own neighbour sums (discrete
   * calibration, exact to round-off in the interior) or over the disc (continuum). C is the 3D
   * tensor of the FE side's ElasticMaterial entries; it must satisfy Cauchy's relations (the
   * model comes from a 3D bond-based one) and have z = 0 as a mirror plane. Surface correction:
   * B_i from m_i, and the bond coefficients by the energy method (apply_energy_surface_correction()
   * with C'_aaaa); without it B_i = C_3333 and the interior kernel everywhere.
   *
   * Thermal strain (doc/theory/thermal_strain_state_based.md): the <Thermal expansion> of the
   * material (a tensor in its axes) with z = 0 a mirror plane; with a temperature change each
   * bond's linearized stretch is measured from its free thermal stretch n . alpha' . n
   * DeltaT_b (alpha' the in-plane block, DeltaT_b the mean of the ends), in both passes, so
   * that a homogeneous state stores 1/2 (eps - alpha' DeltaT) : C' : (eps - alpha' DeltaT);
   * A becomes the mechanical -eps_33 and eps_33 takes alpha_33 DeltaT besides.
   */
  class AnisotropicPlaneStress : public MaterialModel<2>
  {
  public:
    /**
     * @brief A model without parameters; parse_parameters() and initialize() set it up.
     */
    AnisotropicPlaneStress();

    /**
     * @brief Destructor (the kernel's data are defined in anisotropic_plane_stress.cc).
     */
    ~AnisotropicPlaneStress() override;

    /**
     * @brief Declare the entries of ElasticMaterial, "Cauchy relations" and "Calibration".
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the material; check Cauchy's relations (refuse or symmetrize) and the mirror
     * plane z = 0.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /**
     * @brief Check the planar assumption and the thickness, calibrate lambda_0, lambda_2 and B,
     * check the operator's Fourier symbol, set the per-bond coefficients.
     */
    void
    initialize(ParticleSystem<2> &particles, const ModelContext &context) override;

    /// @brief The two passes through the bonds: A_i, then the pair forces with beta A.
    void
    compute_forces(ParticleSystem<2>    &particles,
                   const ParticleVector &u,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_stretch) override;

    /**
     * @brief Gershgorin bound of the bond term (|k_b|) plus that of the A coupling; defined in
     * anisotropic_plane_stress_linearization.cc.
     */
    void
    stiffness_bound(const ParticleSystem<2> &particles,
                    std::vector<double>     &per_particle) const override;

    /**
     * @brief One row n_b . (u_j - u_i) per intact bond with weight k_b/|xi| and one row A_i per
     * owned particle with weight -beta_i V_i B_i; defined in
     * anisotropic_plane_stress_linearization.cc.
     */
    void
    linearize(const ParticleSystem<2> &particles, LinearizedModel &linearized) const override;

    /**
     * @brief The reduced stiffness C' = C - C_ab33 C_33cd / C_3333 the model reproduces.
     */
    dealii::SymmetricTensor<4, 2>
    elasticity_tensor() const override;

    /**
     * @brief The in-plane block alpha' of the material's thermal expansion (global axes):
     * planar_thermal_expansion() of plane stress.
     */
    dealii::SymmetricTensor<2, 2>
    thermal_expansion() const override;

    /**
     * @brief m_l = -(1/V_l) dE/dDeltaT_l at no temperature change: pass 1 for A of the whole
     * strain, then sum over the bonds of l of 1/2 (n . alpha' . n) |xi| [k_b s - g_b (beta_i A_i
     * + beta_j A_j)] / V_l (doc/theory/thermoelasticity.md); alpha' : C' : eps in the interior of
     * a homogeneous strain.
     */
    void
    thermoelastic_measure(ParticleSystem<2>    &particles,
                          const ParticleVector &u,
                          std::vector<double>  &measure) override;

    /**
     * @brief thermal_strain, thermoelastic_heating.
     */
    ModelCapabilities
    capabilities() const override;

    /**
     * @brief Not calibrated for this model: throws (give the damage model a critical stretch).
     */
    double
    critical_stretch(const double fracture_energy) const override;

    /**
     * @brief 2: the force on a particle uses the neighbours' A.
     */
    unsigned int
    force_reach() const override;

    /**
     * @brief The out-of-plane strain eps_33 = -A of the owned particles.
     */
    std::vector<DerivedParticleField>
    derived_fields(const ParticleSystem<2> &particles, const ParticleVector &u) const override;

    /**
     * @brief eps_33 = -A_i (+ alpha_33 DeltaT_i with a temperature change) of the owned
     * particles for the field @p u (ghost values current), by a plain loop over the bond list.
     */
    std::vector<double>
    out_of_plane_strain(const ParticleSystem<2> &particles, const ParticleVector &u) const;

    std::string
    summary() const override;

    /**
     * @brief The energy method on the whole model (B_i corrected) with the reduced stiffness
     * C'_aaaa of the uniaxial test fields (elastic_surface_correction_law()).
     */
    std::unique_ptr<SurfaceCorrectionLaw<2>>
    surface_correction_law(ParticleSystem<2> &particles) override;

    /**
     * @brief The relative error |M_lattice X - target| / |target| of the continuum calibration
     * on this lattice, the largest over lambda_0 and lambda_2 (after initialize()).
     */
    double
    continuum_lattice_error() const;

    /**
     * @brief The smallest eigenvalue of the interior operator's Fourier symbol relative to the
     * largest (after initialize()).
     */
    double
    symbol_minimum() const;

  private:
    /// The calibration of the kernels.
    enum class Calibration
    {
      discrete,
      continuum
    };

    ElasticMaterial material;
    Calibration     calibration = Calibration::discrete;
    std::string     symmetrization_report;
    /// The completely symmetric 3D C, its in-plane part, P_ab = C_ab33 (11, 22, 12), C_3333.
    anisotropic_micromodulus::Components      C3{};
    anisotropic_micromodulus::ComponentsOf<2> C_in{}, Lambda0{};
    std::array<double, 3>                     P{}, M{};
    double                                    C33 = 0.;
    /// The in-plane thermal expansion alpha' (11, 22, 12) and alpha_33 [1/K], global axes.
    std::array<double, 3> in_plane_expansion{};
    double                expansion_33  = 0.;
    double                lattice_error = 0., calibration_residual = 0., symbol_min = 0.;
    ModelContext          context;
    /// Per bond (BondList entries of owned rows): k_b = c_0(n) chi V_i V_j (times the
    /// coupling's energy weight) and g_b = M:nn chi V_i V_j.
    std::vector<double> k0, g;
    /// B_i of the owned and ghost particles.
    std::vector<double> B;
    /// The kernel's data, defined in the kernel header anisotropic_plane_stress_kernel.h.
    struct Kernel;
    std::unique_ptr<Kernel> kernel;

    /**
     * @brief Set k0 (with or without the surface factor), g and the kernel's lanes.
     */
    void
    set_bond_coefficients(const ParticleSystem<2> &particles, const bool with_surface_factor);

    /**
     * @brief Pass 1 on the displacement (and, if @p thermal, the temperature change) gathered in
     * the kernel: breaks the bonds stretched beyond @p critical_stretch and returns A_i of the
     * owned and ghost particles; sets the kernel's beta A for pass 2.
     */
    ParticleVector
    out_of_plane_pass(ParticleSystem<2> &particles,
                      const double       critical_stretch,
                      const bool         thermal);

    /**
     * @brief The free thermal extension |xi| n . alpha' . n DeltaT_b of every bond of the owned
     * rows for temperature_change() (sized like the bond list; zeros without one).
     */
    std::vector<double>
    thermal_extensions(const ParticleSystem<2> &particles) const;
  };
} // namespace perideal

#endif
