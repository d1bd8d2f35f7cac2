// ---------------------------------------------------------------------
// PeriDeal: bond-based peridynamics with Timoshenko-beam bonds and particle rotations (seed 003).
// ---------------------------------------------------------------------
#ifndef perideal_pd_timoshenko_bond_based_h
#define perideal_pd_timoshenko_bond_based_h

#include <deal.II/base/tensor.h>

#include <perideal/pd/material_model.h>
#include <perideal/pd/stiffness_fit.h>

#include <memory>

namespace perideal
{
  /**
   * @brief The constants of the Timoshenko-bond model and their calibration (seed 003, Chen et
   * al.; seed note 003), free of the particles so that tests can check them by themselves.
   *
   * Bond law (seed note 003, sec. 1.5; doc/theory/models.md, "Timoshenko bonds"): for the bond
   * xi = x_j - x_i, n = xi/|xi|, eta = u_j - u_i and the particle rotations theta_i, theta_j
   * (right-handed rotation vectors; one rz in 2D),
   *   s = n . eta / |xi|,                                   (stretch)
   *   gamma = (I - n n) eta / |xi| - (theta_i + theta_j) x n / 2,   (bond shear strain)
   *   kappa = (I - n n)(theta_j - theta_i),                 (relative bending rotation)
   *   w = C_N |xi| s^2 / 2 + 6 C_theta |gamma|^2 / |xi| + C_B |kappa|^2 / (2 |xi|),
   * the force on i f = C_N s n + 12 C_theta gamma / |xi|^2 and the moments on i and j
   * m_i,j = 6 C_theta n x gamma / |xi| +- C_B kappa / |xi|. The paper's single bond rotation is
   * theta^ = -(theta_i + theta_j) (the only invariant, positive and pair-symmetric reading),
   * with C_M = 3/4 C_theta, so that its relative-rotation stiffness C_B = 4 C_M - 3 C_theta is
   * 0; <Bending stiffness ratio> C_B / C_theta > 0 is the general Timoshenko bond (the note's
   * option G), which homogeneous deformations do not see.
   */
  namespace Timoshenko
  {
    /// How C_N and C_theta are fitted to the target stiffness.
    enum class Calibration
    {
      /// The paper's eqs. 9-11 (corrected): the continuum integrals over the horizon.
      continuum,
      /// The interior lattice sums of the particles' own family: D_11 and D_12 exact.
      lattice
    };

    /// The bond stiffnesses [C_N in N/m^6, C_theta and C_B in N/m^4].
    struct Stiffness
    {
      /// C_N, C_theta and C_B.
      ///@{
      double normal  = 0.;
      double shear   = 0.;
      double bending = 0.;
      ///@}
      /// The paper's C_M = (C_B + 3 C_theta) / 4.
      double
      paper_bending() const
      {
        return 0.25 * (bending + 3. * shear);
      }
    };

    /**
     * @brief The largest Poisson ratio the model reaches (C_theta >= 0): 1/3 in plane stress,
     * 1/4 in plane strain and 3D.
     */
    double
    poisson_limit(const PlanarAssumption planar);

    /**
     * @brief D_11 and D_12 of the isotropic target: the in-plane stiffness of plane stress or
     * plane strain, or the 3D one.
     */
    std::array<double, 2>
    target_moduli(const double E, const double nu, const PlanarAssumption planar);

    /**
     * @brief C_N and C_theta from the continuum integrals (seed eqs. 9-11, with eq. 11 the
     * plane-strain set): 3D C_N = 6 (D_11 + 2 D_12)/(pi delta^4), C_theta = (D_11 - 3 D_12)
     * /(4 pi delta^2); 2D C_N = 6 (D_11 + D_12)/(pi h delta^3), C_theta = (D_11 - 3 D_12)
     * /(6 pi h delta).
     */
    Stiffness
    continuum_stiffness(const std::array<double, 2> &D,
                        const int                    dim,
                        const double                 horizon,
                        const double                 thickness);

    /**
     * @brief The lattice sums of a family (relative positions @p xi, weights chi V_j):
     * D_11 = C_N a_11 + C_theta b_11 and D_12 = C_N a_12 + C_theta b_12 for a homogeneous
     * strain with theta = 0; returns {a_11, b_11, a_12, b_12}.
     */
    template <int dim>
    std::array<double, 4>
    lattice_sums(const std::vector<dealii::Tensor<1, dim>> &xi, const std::vector<double> &weight);

    /**
     * @brief C_N and C_theta with which the lattice sums @p sums reproduce @p D exactly.
     */
    Stiffness
    lattice_stiffness(const std::array<double, 2> &D, const std::array<double, 4> &sums);

    /**
     * @brief {D_11, D_12, D_66} that @p stiffness gives on the family (@p xi, @p weight) for
     * homogeneous deformations with theta equal to the macroscopic rotation.
     */
    template <int dim>
    std::array<double, 3>
    lattice_moduli(const Stiffness                           &stiffness,
                   const std::vector<dealii::Tensor<1, dim>> &xi,
                   const std::vector<double>                 &weight);

    /**
     * @brief The ratios of the brittle limits of shear strain and bending rotation to the
     * critical stretch, gamma_0 / s_0 and kappa_0 / s_0, from equal fracture energies of the
     * three modes (seed eqs. 13, 14 corrected; infinite for a stiffness 0): 2D gamma_0^2 =
     * C_N delta^2 s_0^2 / (24 C_theta), kappa_0^2 = C_N delta^2 s_0^2 / (2 C_B); 3D
     * gamma_0^2 = C_N delta^2 s_0^2 / (20 C_theta), kappa_0^2 = 3 C_N delta^2 s_0^2 / (5 C_B).
     */
    std::array<double, 2>
    limit_ratios(const Stiffness &stiffness, const int dim, const double horizon);

    /**
     * @brief The brittle critical stretch for the fracture energy @p G0 (seed eqs. 13, 14):
     * 2D s_0 = sqrt(4 G0 / (delta^4 h C_N)), 3D s_0 = sqrt(10 G0 / (pi C_N delta^5)).
     */
    double
    brittle_stretch(const Stiffness &stiffness,
                    const int        dim,
                    const double     horizon,
                    const double     thickness,
                    const double     G0);

    /**
     * @brief The softening factor mu(x) of seed eq. 15 for the largest strain @p x reached,
     * relative to its limit (x = |s| / s_0): 1 for x <= 1, exp(-k (x - 1)) / x beyond, so that
     * the force C s mu is continuous and decays exponentially; the work to complete separation is
     * (k + 2)/k times the brittle one, hence the limits of eqs. 18, 19 = brittle times
     * sqrt(k / (k + 2)).
     */
    inline double
    softening_factor(const double x, const double k)
    {
      return x <= 1. ? 1. : std::exp(-k * (x - 1.)) / x;
    }

    /**
     * @brief The softening parameter k with which a bond whose limits are @p ratio times the
     * brittle ones of the fracture energy (0 < ratio < 1) still dissipates the brittle work:
     * (k + 2)/k = 1/ratio^2, so k = 2 ratio^2 / (1 - ratio^2) (the inverse of the factor
     * sqrt(k / (k + 2)) of eqs. 18, 19).
     */
    double
    softening_for_limit_ratio(const double ratio);
  } // namespace Timoshenko

  /**
   * @brief Bond-based peridynamics with Timoshenko-beam bonds (Chen, Chen, Wang, Shen, Yu; seed
   * 003): translations and rotations per particle (FieldLayout::displacement_and_rotation(): x,
   * y, rz in 2D; x, y, z, rx, ry, rz in 3D), any Poisson ratio up to 1/3 (plane stress) or 1/4
   * (plane strain, 3D), with the bond law of Timoshenko's namespace, linear (small deformation).
   *
   * Constants from E and nu by <Calibration>: `lattice` (default: C_N and C_theta fitted to the
   * interior lattice sums of the particles' family, so that D_11 and D_12 are exact in the
   * interior; the square lattice then has its own shear modulus, reported) or `continuum` (the
   * paper's constants, whose lattice Poisson ratio misses by up to 57 % at delta = 3 dx, seed
   * note 003 sec. 3.1.1). Rotational inertia J = j rho dx^2 per unit volume (<Rotational
   * inertia factor> j, default 1/12: the paper's rho I / A for a square bond section of side
   * dx). Surface correction by the energy method on the translations (one factor per bond for
   * the whole law).
   *
   * Failure (doc/theory/models.md): the critical stretch s_0 of the damage model and the limits
   * gamma_0, kappa_0 of equal fracture energy (limit_ratios()). `brittle`: a bond breaks when
   * |s| / s_0, |gamma| / gamma_0 or |kappa| / kappa_0 exceeds 1 (seed eq. 15 is symmetric in
   * s). `softening` (parameter k): each mode softens by its factor (softening_factor()) at the
   * largest value it has reached, irreversibly (secant unloading); the limits are the brittle
   * ones times sqrt(k / (k + 2)) so that a bond dissipates the same energy. With a <Tensile
   * strength> sigma_t the limits are instead the brittle ones times r = (sigma_t / E) / s_G
   * (s_0 = sigma_t / E, s_G the brittle critical stretch of the damage model's fracture energy
   * G0, critical_stretch()) and k follows from G0 (Timoshenko::
   * softening_for_limit_ratio(r)): the bond's elastic limit is the concrete's strength and its
   * work to separation is still G0's (doc/theory/models.md, "Tensile strength"). A
   * <Compressive strength> sigma_c then sets the stretch limit of compression, sigma_c / E
   * (seed note 003, A12; otherwise compression fails at -s_0, as printed).
   *
   * A temperature change (set_temperature_change()) with <Thermal expansion> alpha strains the
   * bonds' axial part only: every measure takes the mechanical stretch s - alpha_p (Delta T_i +
   * Delta T_j) / 2 (alpha_p = (1 + nu) alpha in plane strain); shear and bending take none
   * (doc/theory/thermal_strain.md).
   */
  template <int dim>
  class TimoshenkoBondBased : public MaterialModel<dim>
  {
  public:
    /// How a bond fails.
    enum class FailureLaw
    {
      brittle,
      softening
    };

    /**
     * @brief A model without parameters; parse_parameters() and initialize() set it up.
     */
    TimoshenkoBondBased();

    /**
     * @brief Destructor (the kernel's data are defined in timoshenko_bond_based.cc).
     */
    ~TimoshenkoBondBased() override;

    /**
     * @brief Declare the model's entries.
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) override;

    /// Translations and rotations.
    FieldLayout
    field_layout() const override;

    void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &u,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_stretch) override;

    /// m_i = sum_j 1/2 k C_N alpha s |xi| / V_i of the intact bonds (the axial part: s the
    /// axial stretch, k the pair coefficient times the axial softening factor, alpha the
    /// in-plane expansion): the derivative of the bond energies with respect to Delta T_i, which
    /// bond_temperature_change() shares half to each end; shear and bending take no thermal
    /// strain.
    void
    thermoelastic_measure(ParticleSystem<dim>  &particles,
                          const ParticleVector &u,
                          std::vector<double>  &measure) override;

    /**
     * @brief The energy the bonds broken since the last call released: each one's bond energy
     * at @p u (a sum of bond energies, no force evaluation).
     */
    double
    released_energy(ParticleSystem<dim> &particles, const ParticleVector &u) override;

    /// Softening: whether a history beyond its limit (a factor below one) grew by more than
    /// <Softening tolerance> of the limit in the last commit.
    bool
    damage_changed() const override;

    /// Softening: 4 (the histories of the three modes and the energy the bond dissipated).
    unsigned int
    n_bond_history_values() const override;

    std::vector<double>
    bond_history(const ParticleSystem<dim> &particles) const override;

    /// Also the factors (from the histories) and the energy reported as dissipated so far.
    void
    set_bond_history(const ParticleSystem<dim> &particles,
                     const std::vector<double> &values) override;

    /// rho for translations, J = j rho dx^2 for rotations.
    std::vector<double>
    inertia_densities(const double density) const override;

    /**
     * @brief Gershgorin bound of the rows of the strain operator with the translations and
     * rotations scaled by their inertias (so that dt = sqrt(4 rho_c / bound) bounds the
     * spectrum of the scaled operator; the units of u and theta differ by |xi|).
     */
    void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const override;

    /**
     * @brief Per bond the rows of its stretch (weight k C_N / |xi|), of its shear strains
     * (dim - 1 rows, weight 12 k C_theta / |xi|) and of its bending rotations (weight
     * k C_B / |xi|, if C_B > 0), k = G chi V_i V_j.
     */
    void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const override;

    /// The isotropic target (E, nu) of the planar assumption.
    dealii::SymmetricTensor<4, dim>
    elasticity_tensor() const override;

    /// alpha_p I, alpha_p the in-plane expansion of the axial stretch (bond_expansion()).
    dealii::SymmetricTensor<2, dim>
    thermal_expansion() const override;

    /// s_0 of the fracture energy, times sqrt(k / (k + 2)) for the softening law; with a
    /// <Tensile strength> sigma_t / E, and k then follows from @p fracture_energy (set here).
    double
    critical_stretch(const double fracture_energy) const override;

    /// The softening parameter k in use: <Softening parameter>, or the one critical_stretch()
    /// derived from the <Tensile strength> and the fracture energy.
    double
    softening_parameter() const;

    std::string
    summary() const override;

    ModelCapabilities
    capabilities() const override;

    std::unique_ptr<SurfaceCorrectionLaw<dim>>
    surface_correction_law(ParticleSystem<dim> &particles) override;

    /// The bond stiffnesses in use.
    const Timoshenko::Stiffness &
    stiffness() const;

    /**
     * @brief The limits s_0, gamma_0, kappa_0 of the failure modes for the critical stretch
     * @p critical_stretch = s_0 (critical_stretch()): of equal fracture energy
     * (Timoshenko::limit_ratios()), with the lattice calibration's factor of each mode;
     * infinite for a mode that does not fail.
     */
    std::array<double, 3>
    failure_limits(const double critical_stretch) const;

  private:
    double youngs_modulus = 0., poisson_ratio = 0., bending_ratio = 0.;
    /// <Thermal expansion> (isotropic).
    ThermalExpansion expansion;
    double           inertia_factor = 1. / 12.;
    /// k: <Softening parameter>, or, with a <Tensile strength>, derived from the fracture energy
    /// by critical_stretch() (which the damage model asks once, after initialize(); NaN until
    /// then).
    mutable double softening = 10.;
    /// <Tensile strength> sigma_t [Pa]; 0: the limits follow from the fracture energy alone.
    double tensile_strength = 0.;
    /// <Compressive strength> sigma_c [Pa] (with a tensile strength): the stretch limit of
    /// compression is sigma_c / E; 0: -s_0, as in tension.
    double compressive_strength = 0.;
    /// Softening: damage_changed() while a history beyond its limit grows by more than this.
    double                  softening_tolerance = 1e-3;
    Timoshenko::Calibration calibration         = Timoshenko::Calibration::lattice;
    FailureLaw              failure             = FailureLaw::brittle;
    ModelContext            context;
    double                  spacing      = 0.;
    MPI_Comm                communicator = MPI_COMM_WORLD;
    Timoshenko::Stiffness   bond_stiffness;
    /// {D_11, D_12, D_66} of the interior lattice (for the summary).
    std::array<double, 3> lattice_moduli{};
    /// G chi V_i V_j per bond.
    std::vector<double> bond_coefficient;
    /// The factors of the lattice calibration on the continuum's limits s_0, gamma_0, kappa_0
    /// (1 without it, ModelContext::lattice_fracture; 1 for a mode that does not fail).
    std::array<double, 3> fracture_factor{{1., 1., 1.}};
    /// What the stiffness fit achieved (<Discretization/Surface correction method>).
    StiffnessFitReport fit_report;
    /// The kernel's data: defined in timoshenko_bond_based.cc only (kernel options).
    struct Kernel;
    std::unique_ptr<Kernel> kernel;

    void
    set_bond_coefficients(const ParticleSystem<dim> &particles, const bool with_surface_factor);

    /**
     * @brief The free in-plane strain per kelvin of the axial stretch: alpha in 3D and plane
     * stress, (1 + nu) alpha in plane strain.
     */
    double
    bond_expansion() const;

    /**
     * @brief The rows of the strain operator of bond @p b of owned particle @p i, handed to
     * @p emit(weight, entries, mode, offset) with the mode 0 (stretch), 1 (shear strains,
     * dim - 1 rows, if C_theta != 0) or 2 (bending rotations, if C_B != 0); weights without the
     * bond's share of the rank; offset the thermal extension bond_expansion() Delta T_b |xi| of
     * the stretch row (0 for the others and without a temperature change).
     */
    template <typename Emit>
    void
    bond_rows(const ParticleSystem<dim> &particles,
              const unsigned int         i,
              const std::size_t          b,
              const Emit                &emit) const;
  };
} // namespace perideal

#endif
