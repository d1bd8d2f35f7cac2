// ---------------------------------------------------------------------
// PeriDeal: bond-based peridynamic heat conduction (one temperature per particle).
// ---------------------------------------------------------------------
#ifndef perideal_pd_bond_based_conduction_h
#define perideal_pd_bond_based_conduction_h

#include <perideal/pd/material_model.h>
#include <perideal/pd/region_moduli.h>

#include <memory>

namespace perideal
{
  /**
   * @brief Bond-based peridynamic heat conduction (Bobaru & Duangpanya, "The peridynamic
   * formulation for transient heat conduction", Int. J. Heat Mass Transf. 53 (2010)
   * 4047-4059): one unknown per particle, the temperature T (field layout
   * FieldLayout::temperature()).
   *
   * The heat flow density of a bond into particle i is kappa G (T_j - T_i)/|xi| chi V_j (G the
   * surface-correction factor, chi the partial-volume factor), so that
   *   rho c dT_i/dt = sum_j kappa G chi (T_j - T_i)/|xi| V_j + q_i
   * with q_i the heat sources of the conditions. The influence function is constant: the
   * 1/|xi| of the bond's temperature slope is the whole weighting (Bobaru & Duangpanya's
   * kernel). The micro-conductivity follows from the conductivity k by matching the
   * functional 1/4 sum_j kappa G chi (T_j - T_i)^2/|xi| V_j of a linear temperature to k |grad
   * T|^2 / 2 (doc/theory/heat_conduction.md), the calibration of the antiplane models:
   *  - 2D (a plate of thickness h): kappa = 6 k / (pi h delta^3);
   *  - 3D: kappa = 6 k / (pi delta^4).
   * A broken bond (pre-cracks) conducts nothing: a crack insulates. Bonds do not break by the
   * temperature. Surface correction: the energy method with the test fields T = s x, s y (,
   * s z) (apply_energy_surface_correction()).
   *
   * Several materials (<Conductivities by region>, RegionModuli): a bond's micro-conductivity is
   * that of the length-weighted harmonic mean of the conductivities along it, the series rule
   * of two thermal resistances |xi_1|/k_1 + |xi_2|/k_2 in one bond (the same rule as the
   * antiplane models' shear moduli).
   *
   * Its capacity: inertia_densities(rho) = rho c (c the specific heat), so that the explicit
   * solver's factor from heat source density to rate is 1/(rho c) and the stable forward-Euler
   * step is 2 rho c / B with B the Gershgorin bound (MaterialModel::stable_time_step()). By
   * region (<Densities by region>, <Specific heats by region>, RegionModuli::at() at the
   * particle): a particle's capacity is rho_i c_i, inertia_scales() = rho_i c_i / (rho c).
   */
  template <int dim>
  class BondBasedConduction : public MaterialModel<dim>
  {
  public:
    /// @brief A model without parameters; parse_parameters() and initialize() set it up.
    BondBasedConduction();

    /// @brief Destructor (the kernel's data are defined in bond_based_conduction.cc).
    ~BondBasedConduction() override;

    /// @brief Declare <Conductivity>, <Specific heat> and the entries by region
    /// (<Conductivities by region>, <Densities by region>, <Specific heats by region>).
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// @brief Read the entries (conductivity and specific heat must be positive).
    void
    parse_parameters(dealii::ParameterHandler &prm) override;

    /// @brief Look up the regions of the entries by region.
    void
    resolve_regions(const RegionCollection<dim> &regions) override;

    /// @brief The micro-conductivity, the pair coefficients and the surface correction.
    void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) override;

    /// @brief One temperature "T".
    FieldLayout
    field_layout() const override;

    /**
     * @brief The heat flow density of the bonds at the temperature @p temperature into
     * @p heat (W/m^3) and, if @p functional is given, 1/4 sum_j kappa G chi (T_j - T_i)^2 /
     * |xi| V_j per particle (the functional of the calibration and the surface correction);
     * bonds do not break (@p critical_stretch is not read).
     */
    void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &temperature,
                   ParticleVector       &heat,
                   std::vector<double>  *functional,
                   const double          critical_stretch) override;

    /// @brief The heat capacity per unit volume rho c of the temperature.
    std::vector<double>
    inertia_densities(const double density) const override;

    /**
     * @brief rho_i c_i / (rho c) per owned particle, rho_i and c_i of <Densities by region> and
     * <Specific heats by region> at the particle (rho = @p density, <Material/Density>, and c =
     * <Specific heat> elsewhere); empty without entries by region.
     */
    std::vector<double>
    inertia_scales(const ParticleSystem<dim> &particles, const double density) const override;

    /**
     * @brief Gershgorin bound (bond_pair_stiffness_bound()); defined in
     * source/pd/bond_based_conduction_linearization.cc.
     */
    void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const override;

    /**
     * @brief One row (T_j - T_i) per intact bond with weight kappa G chi V_i V_j / |xi| (the
     * conductance matrix of the steady state K T = Q); defined in
     * source/pd/bond_based_conduction_linearization.cc.
     */
    void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const override;

    /**
     * @brief The output field "heat_flux" [W/m^2], the particle's heat flux vector
     *   phi_i = -1/2 sum_j kappa G chi (T_j - T_i) / |xi| (xi / |xi|) |xi| V_j
     *         = -1/(2 V_i) sum_j k_b (T_j - T_i) xi / |xi|
     * over intact bonds (k_b the pair coefficient), the counterpart of the PD stress
     * 1/2 sum_j f xi V_j: -k grad T exactly at interior particles of a linear temperature
     * (doc/theory/heat_conduction.md). @p temperature must have current ghost values.
     */
    std::vector<DerivedParticleField>
    derived_fields(const ParticleSystem<dim> &particles,
                   const ParticleVector      &temperature) const override;

    /// @brief Bonds do not break by the temperature: infinity.
    double
    critical_stretch(const double fracture_energy) const override;

    std::string
    summary() const override;

    /// @brief The micro-conductivity kappa [W/(m^5 K)] in 3D, [W/(m^4 K)] / h in 2D.
    double
    micro_conductivity() const;

  private:
    double            conductivity  = 0.;
    double            specific_heat = 0.;
    double            kappa         = 0.;
    RegionModuli<dim> region_conductivities;
    /// The densities [kg/m^3] and specific heats [J/(kg K)] by region.
    RegionModuli<dim> region_densities, region_specific_heats;
    ModelContext      context;
    /// kappa G chi V_i V_j per bond (the heat flow per unit temperature slope).
    std::vector<double> bond_coefficient;
    /// The kernel's data (bonds in SIMD blocks, kernel-order fields): defined in
    /// bond_based_conduction.cc, compiled with the kernel options (source/pd/CMakeLists.txt).
    struct Kernel;
    std::unique_ptr<Kernel> kernel;

    /**
     * @brief Set bond_coefficient (bond_pair_coefficients(), with the region conductivities'
     * bond values if @p with_surface_factor) and the kernel's lanes.
     */
    void
    set_bond_coefficients(const ParticleSystem<dim> &particles, const bool with_surface_factor);
  };
} // namespace perideal

#endif
