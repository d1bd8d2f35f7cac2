// ---------------------------------------------------------------------
// PeriDeal: interface of peridynamic material models.
// ---------------------------------------------------------------------
#ifndef perideal_pd_material_model_h
#define perideal_pd_material_model_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <perideal/base/elasticity.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/base/plugin_registry.h>
#include <perideal/base/region.h>
#include <perideal/base/torsion.h>
#include <perideal/pd/bond_softening.h>
#include <perideal/pd/particle_system.h>
#include <perideal/pd/stiffness_fit.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief Data every material model needs besides its own parameters.
   */
  struct ModelContext
  {
    /// Horizon delta [m].
    double horizon = 0.;
    /// Thickness h of a 2D body [m].
    double thickness = 1.;
    /// Planar assumption in 2D; three_dimensional in 3D.
    PlanarAssumption planar = PlanarAssumption::three_dimensional;
    /// Whether to apply the model's surface correction.
    bool surface_correction = true;
    /// With it, the stiffness fit (apply_stiffness_fit()) instead of the energy method, for a
    /// model whose capabilities() say stiffness_fit.
    bool stiffness_fit = false;
    /// Whether the model calibrates its critical stretch (slope, mode limits) on the actual
    /// lattice (lattice_fracture_factor()) instead of the continuum, for a model whose
    /// capabilities() say lattice_fracture (<Material/critical stretch/Fracture energy
    /// calibration>).
    bool lattice_fracture = false;
    /// How the bonds fail beyond their elastic limit (<Material/critical stretch/Failure law>):
    /// brittle, or linear softening for a model whose capabilities() say bond_softening.
    BondSoftening softening;
  };

  /**
   * @brief What a model can do beyond its forces (MaterialModel::capabilities()): the
   * libraries ask these, never the model's name or class.
   */
  struct ModelCapabilities
  {
    /// Its surface_correction_law() has a bond stiffness law, so <Discretization/Surface
    /// correction method> = stiffness fit applies to it.
    bool stiffness_fit = false;
    /// Its bonds break by the linearized stretch n . (u_j - u_i) / |xi| of the displacement
    /// (times its breaking_factors()) and it linearizes itself: the sequentially linear control
    /// (<Solver/Control/Method> = sequentially linear) can break them event by event.
    bool sequentially_linear = false;
    /// It calibrates its critical values on the actual lattice when ModelContext says
    /// lattice_fracture (<Material/critical stretch/Fracture energy calibration> = lattice).
    bool lattice_fracture = false;
    /// It declares <Thermal expansion> and measures its strains from the thermal strain of a
    /// temperature change (set_temperature_change(); doc/theory/thermal_strain.md). A model
    /// without it (antiplane shear, conduction) refuses a temperature source.
    bool thermal_strain = false;
    /// It gives the thermoelastic measure beta : eps of its particles
    /// (thermoelastic_measure()), whose rate heats a two-way coupled temperature
    /// (<Temperature/Coupling> = two way; doc/theory/thermoelasticity.md).
    bool thermoelastic_heating = false;
    /// Its bonds soften linearly in saw-tooth form under the sequentially linear control when
    /// ModelContext::softening says so (<Material/critical stretch/Failure law> = linear
    /// softening; breaking_factors(), bond_breaks_at_limit(), limit_reached()).
    bool bond_softening = false;
  };

  /**
   * @brief What the shared surface correction (apply_surface_correction()) needs of a model:
   * its optional law, given by MaterialModel::surface_correction_law().
   */
  template <int dim>
  struct SurfaceCorrectionLaw
  {
    /// The energy method: set the model's bond coefficients without surface factors and energy
    /// weights, the state in which @p energy_density measures the model's energy.
    std::function<void()> uncorrected_coefficients;
    /// The energy method: the strain-energy density of the owned particles for a field of the
    /// model's layout (apply_energy_surface_correction()).
    std::function<void(const ParticleVector &, std::vector<double> &)> energy_density;
    /// The energy method: the classical modulus of the test field along each axis (C_aaaa of
    /// the target elasticity tensor, the shear modulus of antiplane shear).
    std::array<double, dim> modulus{};
    /// The stiffness fit: the bond's energy under a homogeneous strain (empty: the model has no
    /// stiffness fit), and the target C_1111 (apply_stiffness_fit()).
    ///@{
    BondStiffnessLaw<dim> stiffness;
    double                stiffness_modulus = 0.;
    ///@}
  };

  /**
   * @brief The small-displacement linearization of a model about the reference configuration,
   * as the rows of its strain operator G with their weights w and offsets o (what a model gives
   * to assemble its stiffness matrix K = G^T diag(w) G and load G^T diag(w) o):
   *   E = 1/2 sum_r w_r (G_r u - o_r)^2,   G_r u = sum_{(p, c, g) in row r} g u_{p,c},
   * so that the nodal force (force density times V_p) is -dE/du. The offset is the row's
   * strain at which it stores no energy: the thermal strain of a temperature change
   * (MaterialModel::set_temperature_change()), 0 without one. A row is a list of entries
   * (local particle p, owned or ghost; component c of the model's field_layout(); coefficient
   * g); entries of one row that name the same unknown add up, in their order. The model
   * decides what a row is: a bond's linearized extension n . (u_j - u_i) (PMB, LPS), a
   * particle's dilatation (LPS), (w_j - w_i)/|xi| of a scalar field, the strains of a
   * micropolar bond. Each rank emits the rows of its owned particles; a row shared with
   * another rank (a bond to a ghost) is emitted by both, with its weight times
   * ParticleSystem::bond_share().
   */
  class LinearizedModel
  {
  public:
    /// One entry of a row of G.
    struct Entry
    {
      /// Local particle index (owned or ghost).
      unsigned int particle;
      /// Component of the model's field_layout().
      unsigned int component;
      /// The coefficient [1/m for a bond strain, 1 for an extension].
      double coefficient;
    };

    /**
     * @brief No rows, @p n_components unknowns per particle, and stiffness_scale() of
     * @p n_owned zeros.
     */
    void
    reinit(const unsigned int n_components, const unsigned int n_owned);

    /**
     * @brief Append a row of weight @p weight and offset @p offset with the entries @p entries.
     */
    void
    add_row(const double                          weight,
            const dealii::ArrayView<const Entry> &entries,
            const double                          offset = 0.);

    /**
     * @brief The number of unknowns per particle (the columns of a particle).
     */
    unsigned int
    n_components() const;

    /**
     * @brief The number of rows.
     */
    std::size_t
    n_rows() const;

    /**
     * @brief The weight w_r of row @p r.
     */
    double
    weight(const std::size_t r) const;

    /**
     * @brief The offset o_r of row @p r (its strain of no energy).
     */
    double
    offset(const std::size_t r) const;

    /**
     * @brief The first entry of row @p r; row_end(r) is one past its last.
     */
    const Entry *
    row_begin(const std::size_t r) const;

    /**
     * @brief One past the last entry of row @p r.
     */
    const Entry *
    row_end(const std::size_t r) const;

    /**
     * @brief A stiffness per owned particle [N/m] that scales the rows of its prescribed
     * components in a static solve (any positive value yields the same solution; a value of
     * the size of the particle's stiffness keeps the condition number). Zero where the model
     * has none; the solver then uses 1.
     */
    std::vector<double> &
    stiffness_scale();

    /**
     * @brief The stiffness scales (read).
     */
    const std::vector<double> &
    stiffness_scale() const;

  private:
    unsigned int        components = 0;
    std::vector<size_t> row_start{0};
    std::vector<Entry>  entries;
    std::vector<double> weights;
    std::vector<double> offsets;
    std::vector<double> scale;
  };

  /**
   * @brief A field a model derives from the particles' unknowns for output (shear stresses):
   * its name, its number of components and the values of the owned particles
   * (values[i * n_components + c]).
   */
  struct DerivedParticleField
  {
    /// Its name in the output, its number of components and its values per owned particle
    /// (component c of particle i at i * n_components + c).
    ///@{
    std::string         name;
    unsigned int        n_components = 1;
    std::vector<double> values;
    ///@}
  };

  /**
   * @brief Interface of a peridynamic material model (a plugin, chosen per region by name).
   *
   * The plugin boundary is per region: one virtual call computes the forces of all particles
   * with a tight loop over the bonds inside; no call per bond. The unknowns of a particle are
   * the model's field_layout().
   */
  template <int dim>
  class MaterialModel
  {
  public:
    virtual ~MaterialModel() = default;

    /**
     * @brief Read the model's own subsection (the caller has entered it).
     */
    virtual void
    parse_parameters(dealii::ParameterHandler &prm) = 0;

    /**
     * @brief Look up the regions that the model's parameters name (per-region moduli,
     * RegionModuli) in @p regions, which outlive the model; throws, naming the entry, for a
     * region that does not exist. Called right after parse_parameters(); nothing by default.
     */
    virtual void
    resolve_regions(const RegionCollection<dim> &regions);

    /**
     * @brief Compute the per-bond and per-particle constants (micromoduli, weighted volumes,
     * surface corrections); called once the particles and bonds exist.
     */
    virtual void
    initialize(ParticleSystem<dim> &particles, const ModelContext &context) = 0;

    /**
     * @brief The unknowns of a particle (FieldLayout): the displacement x, y(, z) unless the
     * model says otherwise (a scalar antiplane field, translations and rotations).
     */
    virtual FieldLayout
    field_layout() const
    {
      return FieldLayout::displacement(dim);
    }

    /**
     * @brief Force density on each owned particle [N/m^3] for the displacement @p u (ghost
     * values must be current). Bonds stretched beyond @p critical_stretch break first. If
     * @p energy_density is given, it receives the strain-energy density of each owned particle
     * [J/m^3].
     */
    virtual void
    compute_forces(ParticleSystem<dim>  &particles,
                   const ParticleVector &u,
                   ParticleVector       &force,
                   std::vector<double>  *energy_density,
                   const double          critical_stretch) = 0;

    /**
     * @brief The thermal expansion the model's strains are measured from
     * (doc/theory/thermal_strain.md): its <Thermal expansion> in the global axes, in 2D the
     * in-plane expansion of its planar assumption (planar_thermal_expansion()); zero (the
     * default) for none. Known after initialize().
     */
    virtual dealii::SymmetricTensor<2, dim>
    thermal_expansion() const;

    /**
     * @brief The temperature change Delta T = T - T_ref [K] that compute_forces(),
     * released_energy(), derived_fields() and the offsets of linearize() read from now on:
     * one value per particle, local_element(i) of local particle i (owned and ghost, ghost
     * values current); nullptr (the default) for none. The vector is the caller's: it must
     * outlive the calls and is updated in place between evaluations. Only for a model whose
     * capabilities() say thermal_strain.
     */
    void
    set_temperature_change(const ParticleVector *delta_T);

    /**
     * @brief The temperature change of set_temperature_change(), nullptr for none.
     */
    const ParticleVector *
    temperature_change() const;

    /**
     * @brief The thermoelastic measure m_i = (beta : eps)_i [Pa] of each owned particle at the
     * displacement @p u (ghost values current) into @p measure: minus the derivative of the
     * strain energy with respect to the particle's temperature change, at no temperature change,
     * per unit volume (beta = C : alpha in the continuum; doc/theory/thermoelasticity.md). The
     * two-way coupling heats particle i by -T_0 dm_i/dt. Intact bonds only; the same bond
     * coefficients (surface factors, energy weights) as the forces. Only for a model whose
     * capabilities() say thermoelastic_heating (the default throws).
     */
    virtual void
    thermoelastic_measure(ParticleSystem<dim>  &particles,
                          const ParticleVector &u,
                          std::vector<double>  &measure);

    /**
     * @brief The strain energy that the bonds broken since the last call released
     * (BondList::newly_broken, which it clears) [J]: the drop of the model's energy at the
     * displacement @p u at which they broke, E(u, with them) - E(u, without them), counted on
     * this rank's particles (the sum over the ranks is the total). Call it on every rank right
     * after the compute_forces() that may have broken them, with the same @p u (ghost values
     * current).
     *
     * The default evaluates the energy at @p u twice (infinite critical stretch), with the broken
     * bonds restored and broken again, and only when some rank broke a bond (otherwise one
     * reduction of a flag over the ranks): exact for every model, the state-based ones included,
     * where a broken bond changes the dilatation of both ends so that its energy is not its own.
     * A model whose energy is a sum of bond energies overrides it with the sum over the broken
     * bonds (no force evaluation, no communication).
     */
    virtual double
    released_energy(ParticleSystem<dim> &particles, const ParticleVector &u);

    /**
     * @brief Whether the last compute_forces() that could break bonds (a finite critical
     * stretch) changed the bonds' damage other than by breaking them: a softening law whose
     * histories grew by more than 1e-3 of their limits (the load stepping then solves again).
     * Collective; false by default.
     */
    virtual bool
    damage_changed() const;

    /**
     * @brief The number of values per bond of the model's bond histories, the state of its bonds
     * beyond intact and broken that a checkpoint must keep (the softening histories of a
     * damage law and what they dissipated); 0, the default, for models without one.
     */
    virtual unsigned int
    n_bond_history_values() const;

    /**
     * @brief The bond histories, n_bond_history_values() per bond of the bond list, in its
     * order (owned rows, ghost bonds included): value v of bond b at
     * `b * n_bond_history_values() + v`.
     */
    virtual std::vector<double>
    bond_history(const ParticleSystem<dim> &particles) const;

    /**
     * @brief Restore the bond histories of @p particles' bonds from values laid out as
     * bond_history() gives them, and everything the model derives from them (a checkpoint's
     * restart, after initialize()).
     */
    virtual void
    set_bond_history(const ParticleSystem<dim> &particles, const std::vector<double> &values);

    /**
     * @brief The inertia per unit volume of each component of field_layout() for the mass
     * density @p density [kg/m^3]: @p density for translations and scalars; for a rotation the
     * model's rotational inertia per unit volume [kg/m] (what multiplies the angular
     * acceleration in the balance of moment densities). The default throws for a layout with
     * rotations: a micropolar model must state its rotational inertia.
     */
    virtual std::vector<double>
    inertia_densities(const double density) const;

    /**
     * @brief The inertia per unit mass of each component of field_layout():
     * inertia_densities(@p density) / @p density (1 for translations and scalars, the specific
     * heat c for a temperature), what multiplies a particle's mass rho V to give the inertia of
     * its component (the capacity rho c V of a temperature). A density of zero or less (a
     * static run) evaluates inertia_densities(1).
     */
    std::vector<double>
    inertia_ratios(const double density) const;

    /**
     * @brief Per owned particle of @p particles, the factor of its inertia relative to the
     * uniform one of inertia_densities(@p density) (a model with materials by region: the heat
     * capacity rho_i c_i / (rho c) of the conduction model), which multiplies the particle's
     * mass (CouplingMethod::lumped_masses()) and its stable step; empty (the default): 1 for
     * every particle.
     */
    virtual std::vector<double>
    inertia_scales(const ParticleSystem<dim> &particles, const double density) const;

    /**
     * @brief The largest stable explicit time step for density @p density [kg/m^3]: the
     * Silling–Askari bound dt = min_i sqrt(2 rho / sum_j V_j C_ij) (Silling & Askari 2005,
     * Comput. Struct. 83, eq. 31) with the model's bond stiffness C_ij, i.e.
     * min_(i,c) sqrt(4 rho_c / stiffness_bound_(i,c)) with rho_c the inertia density of
     * component c (inertia_densities(): a rotational inertia enters here); for a temperature
     * (first order, forward Euler) 2 rho_c / stiffness_bound_(i,c) with rho_c = rho c the heat
     * capacity per volume (doc/theory/heat_conduction.md). Same on every rank.
     */
    double
    stable_time_step(const ParticleSystem<dim> &particles, const double density) const;

    /**
     * @brief Gershgorin bound of the linearized operator per particle component:
     * @p per_particle[i * n + c] (n = field_layout().n_components()) is an upper bound of
     * sum_j |K_ij| over the row of component c of owned particle i, K the derivative of the
     * force (moment) density by the unknowns (displacement models: block rows, the spectral
     * norms of the dim x dim blocks, the same bound for each component). It is twice the
     * stiffness sum of stable_time_step(), so that dt_stable = sqrt(4 rho_c / bound_(i,c)).
     * Broken bonds do not count.
     */
    virtual void
    stiffness_bound(const ParticleSystem<dim> &particles,
                    std::vector<double>       &per_particle) const = 0;

    /**
     * @brief The linearization of the model about the reference configuration (intact bonds
     * only): the rows of its strain operator and their weights, with
     * field_layout().n_components() columns per particle, see LinearizedModel.
     */
    virtual void
    linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const;

    /**
     * @brief The classical elasticity tensor the model reproduces for homogeneous deformation.
     * Models of the displacement field override it; the default throws (a scalar or micropolar
     * model states its classical constants by its own accessors).
     */
    virtual dealii::SymmetricTensor<4, dim>
    elasticity_tensor() const;

    /**
     * @brief Whether the energy has a strain at zero displacement (the twist of torsion, whose
     * bond strain is the projection of psi (-(y - y0), x - x0)): linearize() gives only the
     * stiffness, so the static linear solve would miss this load; adaptive dynamic relaxation,
     * which uses compute_forces(), carries it. False by default.
     */
    virtual bool
    has_prestrain() const;

    /**
     * @brief The Saint-Venant twist the model carries (Torsion: its axis is checked against
     * the whole body, particles and FE mesh, by the coupled problem), nullptr for none (the
     * default).
     */
    virtual const Torsion *
    torsion() const;

    /**
     * @brief Why one set of elastic constants does not describe every particle (a
     * polycrystal's grains: "<Material/.../Grains file> makes the particles a polycrystal"),
     * empty if it does (the default): an FE region cannot then share the particles' constants
     * (<Finite elements/Elasticity/Same material as the particles>).
     */
    virtual std::string
    nonuniform_constants() const;

    /**
     * @brief The names of the section integrals the model computes from the particles' field
     * (statistics columns pd_<name>: the torque and strain energy per unit length of torsion);
     * none by default.
     */
    virtual std::vector<std::string>
    integral_names() const;

    /**
     * @brief The section integrals of integral_names() for the field @p u (ghost values
     * current) and the particles' strain energy @p strain_energy [J] (collective).
     */
    virtual std::vector<double>
    section_integrals(const ParticleSystem<dim> &particles,
                      const ParticleVector      &u,
                      const double               strain_energy) const;

    /**
     * @brief The fields the model derives from the field @p u (ghost values current) for the
     * particle output (ParaView); none by default.
     */
    virtual std::vector<DerivedParticleField>
    derived_fields(const ParticleSystem<dim> &particles, const ParticleVector &u) const;

    /**
     * @brief The critical stretch that dissipates @p fracture_energy [J/m^2] per unit crack area.
     */
    virtual double
    critical_stretch(const double fracture_energy) const = 0;

    /**
     * @brief The factor of every bond of @p particles (bond-list order, owned rows) by which its
     * stretch is multiplied before the comparison with the critical stretch (the reference
     * value of critical_stretch()): 1 for every bond by default; the anisotropic bond-based
     * model's factors of direction, fracture energies and grains. The sequentially linear
     * control breaks bonds by it.
     */
    virtual std::vector<double>
    breaking_factors(const ParticleSystem<dim> &particles) const;

    /**
     * @brief The sequentially linear control: whether bond @p b (bond-list index) breaks when it
     * next reaches its limit (breaking_factors()), rather than softening: true by default.
     */
    virtual bool
    bond_breaks_at_limit(const std::size_t b) const;

    /**
     * @brief The sequentially linear control: bond @p b of @p particles reached its limit
     * (breaking_factors()) at the displacement @p u (ghost values current). By default it breaks
     * (BondList::break_bond(), listed for released_energy()); a softening model lowers its
     * secant stiffness by one tooth and counts the energy the drop releases in the next
     * released_energy(), breaking it at its last tooth. Called on every rank that stores the
     * bond (the limits are the same there).
     */
    virtual void
    limit_reached(ParticleSystem<dim> &particles, const ParticleVector &u, const std::size_t b);

    /**
     * @brief What the model can do beyond its forces (ModelCapabilities): nothing by default.
     * Asked after parse_parameters().
     */
    virtual ModelCapabilities
    capabilities() const;

    /**
     * @brief The model's law for the shared surface correction (SurfaceCorrectionLaw), or
     * nullptr (the default) if it takes none. Called by apply_surface_correction() from the
     * model's initialize(), once its constants are set.
     */
    virtual std::unique_ptr<SurfaceCorrectionLaw<dim>>
    surface_correction_law(ParticleSystem<dim> &particles);

    /**
     * @brief How far, in horizons, the force on a particle depends on the field: 1 for
     * bond-based models (the default), 2 for state-based ones, whose force uses the neighbours'
     * states over their own families. Fictitious layers must be that deep
     * (BoundaryConditions::check_layer_depths()).
     */
    virtual unsigned int
    force_reach() const;

    /**
     * @brief A few lines for the log: the model's constants, including implied ones.
     */
    virtual std::string
    summary() const = 0;

  private:
    const ParticleVector *delta_T = nullptr;
  };

  /**
   * @brief The names of the registered material models whose default capabilities() have
   * @p capability, separated by commas: the accepted values of a message that refuses a model
   * without it.
   */
  template <int dim>
  std::string
  material_models_with(bool ModelCapabilities::*capability);

  /**
   * @brief The pair coefficient k_b = c G chi V_i V_j of bond @p b of row @p i of a bond-based
   * model with micromodulus @p micromodulus (PMB, antiplane): with the surface-correction factor
   * and the coupling's energy weight G (BondList::surface_factor,
   * ParticleSystem::bond_energy_weight()) if @p with_surface_factor, without them (G = 1)
   * otherwise; chi the partial-volume factor.
   */
  template <int dim>
  inline double
  bond_pair_coefficient(const ParticleSystem<dim> &particles,
                        const double               micromodulus,
                        const bool                 with_surface_factor,
                        const unsigned int         i,
                        const std::size_t          b)
  {
    const BondList    &bonds  = particles.bonds();
    const auto        &volume = particles.volumes();
    const unsigned int j      = bonds.neighbor[b];
    return micromodulus *
           (with_surface_factor ? bonds.surface_factor[b] * particles.bond_energy_weight(i, j) :
                                  1.) *
           bonds.volume_factor(b) * volume[i] * volume[j];
  }

  /**
   * @brief The pair coefficients bond_pair_coefficient() of all bonds. @p coefficient is sized
   * like the bond list (the entries of owned rows are set).
   */
  template <int dim>
  void
  bond_pair_coefficients(const ParticleSystem<dim> &particles,
                         const double               micromodulus,
                         const bool                 with_surface_factor,
                         std::vector<double>       &coefficient);

  /**
   * @brief The Gershgorin bound (MaterialModel::stiffness_bound()) of a bond-based model whose
   * bond b adds k_b / |xi| to the stiffness of both ends, k_b = @p coefficient[b] the pair
   * coefficient of bond_pair_coefficients(): 2 sum_b k_b / (|xi| V_i) over intact bonds, the
   * same for each of the @p n_components components of a particle.
   */
  template <int dim>
  void
  bond_pair_stiffness_bound(const ParticleSystem<dim> &particles,
                            const std::vector<double> &coefficient,
                            const unsigned int         n_components,
                            std::vector<double>       &per_particle);

  /**
   * @brief The bound of the other bond_pair_stiffness_bound() with k_b = @p coefficient(i, b)
   * (bond b of row i), for a model that keeps no per-bond coefficients.
   */
  template <int dim>
  void
  bond_pair_stiffness_bound(
    const ParticleSystem<dim>                                          &particles,
    const std::function<double(const unsigned int, const std::size_t)> &coefficient,
    const unsigned int                                                  n_components,
    std::vector<double>                                                &per_particle);

  /**
   * @brief Register a material model for dim = 2 and 3.
   */
#define PERIDEAL_REGISTER_MATERIAL_MODEL(classname, name, description)                    \
  PERIDEAL_REGISTER_PLUGIN(::perideal::MaterialModel<2>, classname<2>, name, description) \
  PERIDEAL_REGISTER_PLUGIN(::perideal::MaterialModel<3>, classname<3>, name, description)
} // namespace perideal

#endif
