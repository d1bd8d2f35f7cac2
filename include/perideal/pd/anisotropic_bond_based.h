// ---------------------------------------------------------------------
// PeriDeal: anisotropic linearized bond-based PD in 3D and 2D (seed 004).
// ---------------------------------------------------------------------
#ifndef perideal_pd_anisotropic_bond_based_h
#define perideal_pd_anisotropic_bond_based_h

#include <perideal/base/elasticity.h>
#include <perideal/pd/anisotropic_fracture.h>
#include <perideal/pd/anisotropic_micromodulus.h>
#include <perideal/pd/grains.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/stiffness_fit.h>

#include <memory>

namespace perideal
{
  /**
   * @brief Anisotropic linearized bond-based model in 3D and 2D (Trageser & Seleson,
   * SAND2019-12685C, eq. 3 and the micromodulus of the "3D fully anisotropic PD model" slide; seed
   * note 004, secs. 1.2-1.3).
   *
   * Force density rho u_tt = int lambda(xi) xi (xi . eta) dx' with the micromodulus
   * lambda(xi) = omega(|xi|)/|xi|^2 Lambda_ijkl n_i n_j n_k n_l, omega = 1/|xi|, n = xi/|xi|,
   * eta = u' - u. Discretely the pair force is k_b s n with the linearized stretch
   * s = n . eta / |xi| and k_b = c(n_b) G chi V_i V_j, c(n) = Lambda_ijkl n_i n_j n_k n_l the
   * direction factor computed per bond at set-up (G surface correction, chi partial volume);
   * pair energy k_b s^2 |xi| / 2. Lambda (completely symmetric) follows from the elasticity
   * tensor C of the entries of ElasticMaterial (the FE side's: symmetry class, constants,
   * orientation) by C = M Lambda, C_ijkl = 1/2 sum_b lambda_b xi_i xi_j xi_k xi_l chi V_j:
   * - "discrete" calibration: M from the neighbour sums of an interior particle, so that a
   *   homogeneous deformation reproduces C there to round-off;
   * - "continuum": M from the integrals over the ball (the note's closed form); its error on
   *   the lattice is reported.
   * C must satisfy Cauchy's relations (complete symmetry); otherwise it is refused or, with
   * <Cauchy relations> = symmetrize, replaced by its completely symmetric part.
   * Set-up checks: directions where c(n) < 0 (a warning in the summary) and the Fourier symbol
   * of the interior operator (an error if it is not positive definite).
   * Fracture: the PMB critical stretch with the bond's own direction factor and the weight of
   * the fracture energies along the material axes (AnisotropicFractureEnergy),
   * s0(n) = sqrt(10 G0 g(n) / (pi |c(n)| delta^5)) (doc/theory/models.md); the linearized
   * stretch breaks the bond.
   * A polycrystal (Grains): every grain has the material rotated by its orientation, Lambda
   * and the fracture weights calibrated for it; a bond inside a grain has the grain's c(n) and
   * g(n), a bond between two grains the means of theirs and its critical energy times
   * <Grain boundary fracture energy ratio>.
   *
   * In 2D (particle volumes dx^2 h) the same model with the 5 components of a completely
   * symmetric 2D tensor: omega = 1/|xi|, lambda = c(n)/|xi|^3 (square symmetry: c(theta) = a + b
   * cos 4 theta; rectangular: a + b cos 2 theta + c cos 4 theta), fitted to the 2D tensor of the
   * planar assumption, the FE side's reduction of the same material (plane strain: the in-plane
   * block of C; plane stress: the reduced stiffness). That target must satisfy the 2D Cauchy
   * relation C66 = C12 (refused otherwise, or symmetrized); a 3D material whose reduced
   * stiffness does not is the domain of 'anisotropic plane stress'. Reference critical stretch
   * sqrt(4 G0 / (c_mean h delta^4)) (PMB's 2D relation G0 = c s0^2 h delta^4 / 4).
   *
   * A temperature change (set_temperature_change()) with the material's <Thermal expansion>
   * alpha (in the material axes, turned with them; in 2D the in-plane expansion of the planar
   * assumption, planar_thermal_expansion()): every measure of a bond takes the mechanical
   * stretch s - n . alpha . n (Delta T_i + Delta T_j) / 2, with a grain's own alpha in a
   * polycrystal and the mean of the two grains' n . alpha . n across a grain boundary
   * (doc/theory/thermal_strain.md).
   */
  template <int dim>
  class AnisotropicBondBased : public MaterialModel<dim>
  {
  public:
    /**
     * @brief A model without parameters; parse_parameters() and initialize() set it up.
     */
    AnisotropicBondBased();

    /**
     * @brief Destructor (the kernel's data are defined in anisotropic_bond_based.cc).
     */
    ~AnisotropicBondBased() override;

    /**
     * @brief Declare the entries of ElasticMaterial, "Cauchy relations", "Calibration" and
     * "Fracture energy ratios".
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /**
     * @brief Read the material and (3D) check Cauchy's relations (refuse or symmetrize); in 2D
     * the check waits for the planar assumption (initialize()).
     */
    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /**
     * @brief Calibrate Lambda, check its stability, set the per-bond coefficients and the
     * surface correction.
     */
    void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) override;

    void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &u,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_stretch) override;

    /// m_i = sum_j 1/2 k_b (n . alpha . n) s |xi| / V_i of the intact bonds (the coefficients of
    /// the forces, s the linearized stretch, n . alpha . n the bond's thermal stretch per kelvin):
    /// the derivative of the bond energies with respect to Delta T_i, which
    /// bond_temperature_change() shares half to each end; zero without an expansion.
    void
    thermoelastic_measure(ParticleSystem<dim>  &particles,
                          const ParticleVector &u,
                          std::vector<double>  &measure) override;

    /**
     * @brief Gershgorin bound with |k_b| (negative direction factors count with their size);
     * defined in source/pd/anisotropic_bond_based_linearization.cc.
     */
    void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const override;

    /**
     * @brief One row n_b . (u_j - u_i) per intact bond with weight k_b / |xi| (the model is
     * linear); defined in source/pd/anisotropic_bond_based_linearization.cc.
     */
    void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const override;

    /**
     * @brief The completely symmetric C that the model reproduces (the input, or its
     * completely symmetric part).
     */
    dealii::SymmetricTensor<4, dim>
    elasticity_tensor() const override;

    /// The material's expansion in the global axes, in 2D the in-plane one of the planar
    /// assumption (a polycrystal's grains turn it with their orientations).
    dealii::SymmetricTensor<2, dim>
    thermal_expansion() const override;

    /**
     * @brief The reference critical stretch sqrt(10 G0 / (pi c_mean delta^5)), c_mean the mean
     * of c(n) over the sphere; a bond of direction n breaks at sqrt(c_mean g(n) / |c(n)|) times
     * it, g(n) the weight of the Fracture energy ratios (AnisotropicFractureEnergy).
     */
    double
    critical_stretch(const double fracture_energy) const override;

    /**
     * @brief sqrt(|c_b| / (c_mean g_b)) per bond (the kernel's lanes hold the same).
     */
    std::vector<double>
    breaking_factors(const ParticleSystem<dim> &particles) const override;

    /**
     * @brief The material, the calibration and its errors, the Cauchy symmetrization and the
     * stability warnings.
     */
    std::string
    summary() const override;

    /// The stiffness fit is offered for one grain (the fit's target is one interior tensor).
    ModelCapabilities
    capabilities() const override;

    std::unique_ptr<SurfaceCorrectionLaw<dim>>
    surface_correction_law(ParticleSystem<dim> &particles) override;

    /// With a <Grains file>: "<Material/anisotropic bond based/Grains file> makes the
    /// particles a polycrystal".
    std::string
    nonuniform_constants() const override;

    /**
     * @brief The micromodulus tensor Lambda [N/m^6] (after initialize()).
     */
    const anisotropic_micromodulus::ComponentsOf<dim> &
    micromodulus_tensor() const;

    /**
     * @brief The relative lattice error |M_lattice Lambda_continuum - C| / |C| of the
     * continuum calibration (after initialize()).
     */
    double
    continuum_lattice_error() const;

    /**
     * @brief The scan of the directions where c(n) < 0 (after initialize()).
     */
    const anisotropic_micromodulus::DirectionScanOf<dim> &
    direction_scan() const;

    /**
     * @brief The scan of the Fourier symbol of the interior operator (after initialize()).
     */
    const anisotropic_micromodulus::SymbolScanOf<dim> &
    symbol_scan() const;

  private:
    /// The calibration of Lambda.
    enum class Calibration
    {
      discrete,
      continuum
    };

    ElasticMaterial                             material;
    Calibration                                 calibration = Calibration::discrete;
    bool                                        symmetrize  = false;
    anisotropic_micromodulus::ComponentsOf<dim> C{};
    anisotropic_micromodulus::ComponentsOf<dim> Lambda{};
    std::string                                 symmetrization_report;
    /// The fracture energies along the material axes and their report.
    AnisotropicFractureEnergy<dim>                 fracture;
    std::string                                    fracture_report;
    double                                         lattice_error = 0., calibration_residual = 0.;
    anisotropic_micromodulus::DirectionScanOf<dim> directions;
    anisotropic_micromodulus::SymbolScanOf<dim>    symbol;
    ModelContext                                   context;
    /// The grains (one without a Grains file), their Lambda and fracture weights, and the
    /// grain of every local particle (owned and ghosts).
    Grains<dim>                                              grains;
    std::vector<anisotropic_micromodulus::ComponentsOf<dim>> grain_Lambda;
    std::vector<AnisotropicFractureEnergy<dim>>              grain_fracture;
    std::vector<unsigned int>                                particle_grain;
    /// k_b = c(n_b) G chi V_i V_j and the breaking factor per bond.
    std::vector<double> bond_coefficient, bond_break_factor;
    /// n . alpha . n per bond (the thermal stretch per kelvin); empty without an expansion.
    std::vector<double> bond_expansion;
    StiffnessFitReport  fit_report;
    /// The force kernel's data (bonds in SIMD blocks, per-lane k_b, per-class breaking
    /// factors): defined in anisotropic_bond_based.cc, compiled with the kernel options.
    struct Kernel;
    std::unique_ptr<Kernel> kernel;

    /**
     * @brief Set bond_coefficient (with or without the surface factor) and the kernel's lanes.
     */
    void
    set_bond_coefficients(const ParticleSystem<dim> &particles, const bool with_surface_factor);

    /**
     * @brief The thermal expansion of grain @p g (the material turned by its orientation) in the
     * global axes, in 2D the in-plane one of the planar assumption.
     */
    dealii::SymmetricTensor<2, dim>
    grain_expansion(const unsigned int g) const;

    /**
     * @brief Set bond_expansion and the kernel's lanes of it (none without an expansion).
     */
    void
    set_bond_expansions(const ParticleSystem<dim> &particles);

    /**
     * @brief Lambda and the fracture weights of every grain (the material rotated by the
     * grain's orientation, calibrated like Lambda over @p family, its Fourier symbol checked
     * at the lattice @p spacing), and the grain of every local particle.
     */
    void
    set_up_grains(const ParticleSystem<dim>                   &particles,
                  const anisotropic_micromodulus::Family<dim> &family,
                  const double                                 spacing);

    /**
     * @brief The direction factor c(n) of a bond between grains @p g and @p h: grain g's
     * c(n) if g = h, the mean of the two grains' otherwise.
     */
    double
    bond_modulus(const unsigned int g, const unsigned int h, const dealii::Tensor<1, dim> &n) const;

    /**
     * @brief Set C, the completely symmetric tensor the model reproduces, from @p C_input:
     * refuse a violation of Cauchy's relations (naming @p what, the tensor's origin) or
     * symmetrize it.
     */
    void
    set_target(const dealii::SymmetricTensor<4, dim> &C_input, const std::string &what);
  };
} // namespace perideal

#endif
