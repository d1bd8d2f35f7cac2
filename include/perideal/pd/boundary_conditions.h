// ---------------------------------------------------------------------
// PeriDeal: prescribed values, rates and loads on particle sets.
// ---------------------------------------------------------------------
#ifndef perideal_pd_boundary_conditions_h
#define perideal_pd_boundary_conditions_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/convection.h>
#include <perideal/base/field_layout.h>
#include <perideal/base/linear_algebra.h>
#include <perideal/base/region.h>
#include <perideal/pd/particle_system.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief Boundary conditions on the particles of named regions, and the body force.
   *
   * A condition prescribes one quantity (FieldLayout's Quantity) of the components of one kind:
   * - translations: 'displacement' [m] or 'velocity' [m/s] of the listed components, or
   *   'traction' [Pa] (all translations);
   * - rotations (micropolar models): 'rotation' [rad] or 'angular velocity' [rad/s] of the
   *   listed components, or 'moment' [N m/m^2] (all rotations);
   * - a scalar field: 'value' or 'rate' of it, or 'flux' (its load per unit area);
   * - a temperature: 'value' [K], 'flux' (a heat flux into the body [W/m^2]) or 'convection'
   *   (the heat flux h (T_inf - T), Convection).
   * A load ('traction', 'moment', 'flux', 'convection') T(x, t) acts as the force density T / d on
   * the particles of the region, a layer of thickness d ('Layer thickness') at the loaded surface;
   * the resultant is T times the area of the layer's face, to within the lattice resolution.
   * Functions are deal.II FunctionParser expressions of x, y, (z) and t, one per listed
   * component. A component may be prescribed by one condition only.
   *
   * The body force b(x, t) [N/m^3] (the problem's <Body force/Function>, set_body_force())
   * acts on every particle with the particle's energy weight (ParticleSystem::energy_weights():
   * 1 in a PD problem, beta_i in a blended coupled problem, whose FE region carries the rest,
   * 1 - beta), so that the load is weighted like the energy and a body force is not counted
   * twice in the overlap. Loads of conditions act in full on the particles of their region.
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    /// Declare "Names" of subsection "Boundary conditions" (first pass).
    static void
    declare_names(dealii::ParameterHandler &prm);
    /// Declare every condition's subsection.
    static void
    declare_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &names);
    /// The names read in the first pass.
    static std::vector<std::string>
    parse_names(dealii::ParameterHandler &prm);
    /**
     * @brief Read every condition for a field with the unknowns @p layout: region names are
     * checked against @p regions, types and components against the layout (a message names
     * the entry and the accepted values).
     */
    void
    parse_parameters(dealii::ParameterHandler    &prm,
                     const RegionCollection<dim> &regions,
                     const FieldLayout           &layout);

    /// Set the body force (the problem's, one expression per component), or none (nullptr).
    void
    set_body_force(const std::shared_ptr<dealii::Function<dim>> &function);

    /**
     * @brief Check the value and rate conditions with a <Layer thickness> > 0 (declared
     * fictitious layers) against the depth @p reach horizons @p horizon minus half the lattice
     * spacing @p spacing that the forces of the model @p model_name reach
     * (MaterialModel::force_reach()); throws, naming the entry and the accepted values.
     */
    void
    check_layer_depths(const double       horizon,
                       const double       spacing,
                       const unsigned int reach,
                       const std::string &model_name) const;

    /**
     * @brief Find the particles of every condition; throws (naming the condition) if a region
     * holds no particle or two conditions prescribe the same component of a particle.
     */
    void
    setup(const ParticleSystem<dim> &particles);

    /// Set the rate of prescribed components over the step from @p time to time + @p dt.
    void
    prescribe_step_velocity(const double time, const double dt, ParticleVector &v) const;
    /// Set the components with a prescribed value (displacement, rotation, value) at @p time.
    void
    prescribe_displacement(const double time, ParticleVector &u) const;
    /// Whether there is a body force or a load condition.
    bool
    has_loads() const;
    /// Add the body force (times the energy weights) and the loads of the conditions at @p time
    /// (convection aside: add_convection()) to the force density @p force.
    void
    add_loads(const double time, ParticleVector &force) const;
    /// @brief Whether a condition is a convection (its load depends on the temperature).
    bool
    has_convection() const;
    /**
     * @brief The largest h / d of the convection conditions [W/(m^3 K)] (0 without one): what
     * a convection adds to the Gershgorin bound of the particles of its layer (the stable step,
     * ExplicitDynamics).
     */
    double
    convection_bound() const;
    /**
     * @brief Add the heat source density h (T_inf(x, @p time) - T) / d of the convection
     * conditions (d the <Layer thickness>) at the temperature @p field to @p force; without
     * @p field (nullptr) its ambient part h T_inf / d alone, the load of a linear solve whose
     * matrix holds the conductance (add_convection_conductance()).
     */
    void
    add_convection(const double time, const ParticleVector *field, ParticleVector &force) const;
    /**
     * @brief Add the conductance h V_i / d [W/K] of the convection conditions to the diagonal
     * @p diagonal of the owned particle components they act on: the matrix term of
     * h (T_inf - T) / d in a static or implicit solve (CouplingMethod::set_equilibrium_diagonal()).
     */
    void
    add_convection_conductance(ParticleVector &diagonal) const;
    /// Whether component @p c of owned particle @p i is prescribed.
    bool
    is_prescribed(const unsigned int i, const unsigned int c) const
    {
      return prescribed[i * layout.n_components() + c] != 0;
    }
    /// Names of the conditions that prescribe the quantity @p quantity.
    std::vector<std::string>
    names_of(const Quantity quantity) const;
    /// Names of the conditions.
    const std::vector<std::string> &
    names() const;
    /// The <Type> of condition @p k as the file names it ("displacement", "moment", ...).
    const std::string &
    type_name(const unsigned int k) const;
    /// The components whose reaction condition @p k reports: all of its kind (all for 'value').
    const std::vector<unsigned int> &
    reaction_components(const unsigned int k) const;
    /**
     * @brief Reaction of every condition: minus the sum of the internal forces f V on its
     * particles, per component of reaction_components() (forces [N], moments [N m]).
     */
    std::vector<std::vector<double>>
    reactions(const ParticleVector &internal_force) const;

  private:
    struct Condition
    {
      std::string        name;
      std::string        region_name;
      const Region<dim> *region = nullptr;
      std::string        type_name;
      Quantity           quantity = Quantity::value;
      /// The listed components (all of the kind for a load).
      std::vector<unsigned int> components;
      /// Every component the condition's type acts on (its reactions).
      std::vector<unsigned int>                    kind_components;
      double                                       layer_thickness = 0.;
      std::unique_ptr<dealii::FunctionParser<dim>> function;
      /// A convection's coefficient and ambient temperature (its type is 'convection').
      std::optional<Convection<dim>> convection;
      std::vector<unsigned int>      particles;
    };
    FieldLayout                            layout;
    std::vector<Condition>                 conditions;
    std::vector<std::string>               condition_names;
    std::shared_ptr<dealii::Function<dim>> body_force;
    std::vector<std::uint8_t>              prescribed;
    const ParticleSystem<dim>             *particle_system = nullptr;
  };
} // namespace perideal

#endif
