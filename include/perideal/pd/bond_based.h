// ---------------------------------------------------------------------
// PeriDeal: the prototype microelastic brittle (PMB) bond-based model.
// ---------------------------------------------------------------------
#ifndef perideal_pd_bond_based_h
#define perideal_pd_bond_based_h

#include <perideal/pd/material_model.h>
#include <perideal/pd/stiffness_fit.h>

#include <memory>

namespace perideal
{
  /**
   * @brief Bond-based PMB model (Silling & Askari 2005, Comput. Struct. 83, eqs. 4–6).
   *
   * Pairwise force density f = c G s (xi + eta)/|xi + eta| with stretch
   * s = (|xi + eta| - |xi|)/|xi| and G the surface-correction factor of the bond; the force on
   * particle i is sum_j f V_j chi_ij (chi the partial-volume factor). Strain-energy density
   * W_i = 1/4 sum_j c G s^2 |xi| V_j chi_ij. The micromodulus follows from the Young's modulus
   * by energy matching (seed 002, eqs. 4.107 and 5.164; seed note 002, sec. 2.3):
   *  - 3D: c = 18 K / (pi delta^4) = 12 E / (pi delta^4), implied nu = 1/4;
   *  - 2D plane stress: c = 9 E / (pi h delta^3), implied nu = 1/3;
   *  - 2D plane strain: c = 48 E / (5 pi h delta^3), implied nu = 1/4.
   * Critical stretch from the fracture energy G0 (Silling & Askari 2005; 2D by the same
   * integral over a disk, seed note 002, sec. 4.2): 3D s0 = sqrt(5 G0 / (6 E delta)); plane
   * stress s0 = sqrt(4 pi G0 / (9 E delta)); plane strain s0 = sqrt(5 pi G0 / (12 E delta)).
   * A temperature change (set_temperature_change()) with <Thermal expansion> alpha: every
   * measure of a bond (force, energy, breaking, released energy, the offsets of linearize())
   * takes the mechanical stretch s - alpha_p (Delta T_i + Delta T_j) / 2, alpha_p the in-plane
   * expansion (plane strain (1 + nu) alpha; seed 002, eq. 4.93; doc/theory/thermal_strain.md).
   * With ModelContext::softening linear (<Material/critical stretch/Failure law> = linear
   * softening), the bonds soften in saw-tooth form under the sequentially linear control
   * (BondSoftening): a bond of tooth t has the pair coefficient mu_t k and reaches its limit at
   * the stretch s_G drop_over_brittle(t) (breaking_factors()); doc/theory/models.md,
   * "Softening PMB bonds".
   */
  template <int dim>
  class BondBased : public MaterialModel<dim>
  {
  public:
    /**
     * @brief A model without parameters; parse_parameters() and initialize() set it up.
     */
    BondBased();

    /**
     * @brief Destructor (the kernel's data are defined in bond_based.cc).
     */
    ~BondBased() override;

    /**
     * @brief Declare "Young's modulus" and "Thermal expansion" (one value).
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
     * @brief The energy of the bonds broken since the last call, as
     * MaterialModel::released_energy() defines it: the sum over BondList::newly_broken of the
     * bond energy k s^2 |xi| / 2 at @p u (k = c G chi V_i V_j, the pair energy of both ends, s
     * the mechanical stretch), each times its share on this rank; no force evaluation, no
     * communication.
     */
    double
    released_energy(ParticleSystem<dim> &particles, const ParticleVector &u) override;

    /**
     * @brief With softening: s_G / (s_G drop_over_brittle(t_b)) = 1 / drop_over_brittle(t_b)
     * of each bond's tooth t_b, so that the sequentially linear control finds the bond at its
     * limit where its stretch reaches its tooth's drop; 1 for every bond without.
     */
    std::vector<double>
    breaking_factors(const ParticleSystem<dim> &particles) const override;

    /**
     * @brief Without softening true; with it, whether bond @p b is at its last tooth.
     */
    bool
    bond_breaks_at_limit(const std::size_t b) const override;

    /**
     * @brief Without softening, or at the last tooth, break bond @p b; otherwise lower its pair
     * coefficient from mu_t k to mu_{t+1} k and add the energy the drop releases at @p u,
     * 1/2 (mu_t - mu_{t+1}) k s^2 |xi| times the bond's share on this rank (s the mechanical
     * stretch), to the next released_energy().
     */
    void
    limit_reached(ParticleSystem<dim>  &particles,
                  const ParticleVector &u,
                  const std::size_t     b) override;

    /// With softening 1 (the tooth of each bond), 0 without.
    unsigned int
    n_bond_history_values() const override;

    /// The tooth of each bond with softening, empty without.
    std::vector<double>
    bond_history(const ParticleSystem<dim> &particles) const override;

    /// The teeth of a checkpoint, and the pair coefficients mu_t k of the kernel's lanes.
    void
    set_bond_history(const ParticleSystem<dim> &particles,
                     const std::vector<double> &values) override;

    /**
     * @brief Gershgorin bound (see MaterialModel::stiffness_bound()); defined in
     * source/pd/bond_based_linearization.cc.
     */
    void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const override;

    /**
     * @brief Linearization (see MaterialModel::linearize()); defined in
     * source/pd/bond_based_linearization.cc.
     */
    void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const override;

    dealii::SymmetricTensor<4, dim>
    elasticity_tensor() const override;

    /// alpha_p I, alpha_p the in-plane expansion of the bonds (bond_expansion()).
    dealii::SymmetricTensor<2, dim>
    thermal_expansion() const override;

    /// m_i = sum_j 1/2 c chi alpha s |xi| V_j of the intact bonds (the pair coefficients of the
    /// forces; alpha the in-plane expansion): the derivative of the bond energies with respect to
    /// Delta T_i, which bond_temperature_change() shares half to each end.
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

    std::unique_ptr<SurfaceCorrectionLaw<dim>>
    surface_correction_law(ParticleSystem<dim> &particles) override;

    /**
     * @brief The micromodulus c [N/m^6].
     */
    double
    micromodulus() const;

    /**
     * @brief The pair coefficient k_b = c G chi V_i V_j of bond @p b of row @p i of the bond
     * list of @p particles (bond_pair_coefficient() with the surface-correction factor), as the
     * force kernel holds it: the model keeps it per lane only, and frees
     * BondList::surface_factor after initialize().
     */
    double
    pair_coefficient(const ParticleSystem<dim> &particles,
                     const unsigned int         i,
                     const std::size_t          b) const;

    /**
     * @brief pair_coefficient() of every bond of the bond list, read from the kernel's lanes
     * through the lane of each bond (BondBlocks::lanes_of_bonds(): one pass over the lanes
     * instead of a search per bond; 4 B per bond while it exists).
     */
    class PairCoefficients
    {
    public:
      /// k_b of bond @p b.
      double
      operator()(const std::size_t b) const
      {
        return coefficient[lane[b]];
      }

    private:
      friend class BondBased<dim>;
      const double             *coefficient = nullptr;
      std::vector<unsigned int> lane;
    };

    /**
     * @brief The pair coefficients of all bonds of @p particles (PairCoefficients), for what
     * reads every bond's coefficient: the stiffness bound, the linearization, the lattice
     * calibration of the fracture energy.
     */
    PairCoefficients
    pair_coefficients(const ParticleSystem<dim> &particles) const;

    /**
     * @brief The Poisson ratio that the model implies (Cauchy relations).
     */
    double
    implied_poisson_ratio() const;

  private:
    double youngs_modulus = 0.;
    /// <Thermal expansion> (isotropic).
    ThermalExpansion expansion;
    ModelContext     context;
    double           c = 0.;
    /// The factor of the lattice calibration on the continuum's critical stretch (1 without it,
    /// ModelContext::lattice_fracture).
    double fracture_factor = 1.;
    /// The tooth of each bond with softening (ModelContext::softening), empty without.
    std::vector<std::uint8_t> tooth;
    /// The energy of the teeth dropped since the last released_energy() on this rank.
    double softened_energy = 0.;
    /// What the stiffness fit achieved (<Discretization/Surface correction method>).
    StiffnessFitReport fit_report;
    /// The force kernel's data (bonds in SIMD blocks, kernel-order fields): defined in
    /// bond_based.cc only, the one translation unit of the model compiled with the kernel
    /// options (source/pd/CMakeLists.txt).
    struct Kernel;
    std::unique_ptr<Kernel> kernel;

    /**
     * @brief Set the kernel's lane coefficients c G chi V_i V_j (the pair force per unit
     * stretch; bond_pair_coefficient(), kept per lane only) from the micromodulus, the
     * partial-volume factors, the particle volumes and, if @p surface_factor is given, the
     * surface-correction factors G it returns for (i, b) and the coupling's energy weights.
     */
    void
    set_bond_coefficients(
      const ParticleSystem<dim>                                          &particles,
      const std::function<double(const unsigned int, const std::size_t)> &surface_factor);

    /**
     * @brief The free strain per kelvin of the bonds: alpha in 3D and plane stress, (1 + nu)
     * alpha in plane strain (planar_thermal_expansion() with the implied nu).
     */
    double
    bond_expansion() const;

    /**
     * @brief The thermal stretch bond_expansion() (Delta T_i + Delta T_j) / 2 of bond @p b of
     * @p particles' bond list (0 without a temperature change).
     */
    double
    thermal_stretch(const ParticleSystem<dim> &particles, const std::size_t b) const;

    /**
     * @brief The mechanical stretch |xi + eta| / |xi| - 1 - thermal_stretch() of bond @p b of
     * @p particles' bond list at the displacement @p u (local values).
     */
    double
    mechanical_stretch(const ParticleSystem<dim> &particles,
                       const ParticleVector      &u,
                       const std::size_t          b) const;
  };
} // namespace perideal

#endif
