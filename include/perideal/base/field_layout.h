// ---------------------------------------------------------------------
// PeriDeal: the unknowns of a point (particle or FE node).
// ---------------------------------------------------------------------
#ifndef perideal_base_field_layout_h
#define perideal_base_field_layout_h

#include <array>
#include <string>
#include <vector>

namespace perideal
{
  /**
   * @brief What one unknown of a point is.
   *
   * - translation: a displacement component along an axis [m]; its conditions are displacement,
   *   velocity and force (density); its inertia is the mass;
   * - rotation: a rotation about an axis [rad] (micropolar models); its conditions are
   *   rotation, angular velocity and moment (density); its inertia is a rotational inertia;
   * - scalar: a field that is not a vector component (the antiplane displacement, a warping
   *   function); its conditions are value, rate and flux (source); its inertia is the mass.
   * - temperature: the temperature [K] of heat conduction, first order in time (forward Euler
   *   of rho c dT/dt = q, no velocity); its conditions are value (the temperature), flux (a heat
   *   flux into the body [W/m^2]) and convection (h (T_inf - T) [W/m^2]); its capacity is
   *   rho c.
   */
  enum class ComponentKind
  {
    translation,
    rotation,
    scalar,
    temperature
  };

  /**
   * @brief One unknown of a point: its kind, the name that <Components> entries and output use,
   * and for translations and rotations the axis (0, 1, 2 for x, y, z).
   */
  struct FieldComponent
  {
    /// Its kind, its name and its axis.
    ///@{
    ComponentKind kind = ComponentKind::translation;
    std::string   name;
    unsigned int  axis = 0;
    ///@}

    /// @brief Equal kind, name and axis.
    bool
    operator==(const FieldComponent &other) const
    {
      return kind == other.kind && name == other.name && axis == other.axis;
    }
  };

  /**
   * @brief The unknowns of every point of a region, in the order they are stored (component c
   * of local point i at i * n_components() + c): what a PD material model and an FE physics
   * declare, and what everything that loops over components (inertia, motion, boundary
   * conditions, reactions, output, statistics, the near-null space of AMG) works from.
   *
   * Names in the .prm: translations "x", "y", "z"; rotations "rx", "ry", "rz" (a 2D
   * micropolar point has only "rz"); a scalar field its own name ("w" for the out-of-plane
   * displacement of antiplane shear and torsion warping).
   */
  class FieldLayout
  {
  public:
    /// No components (a layout not yet declared).
    FieldLayout() = default;

    /// @p dim translations x, y(, z): the displacement of the in-plane and 3D solids.
    static FieldLayout
    displacement(const unsigned int dim);

    /**
     * @brief @p dim translations and the rotations of a micropolar point: x, y, rz in 2D;
     * x, y, z, rx, ry, rz in 3D.
     */
    static FieldLayout
    displacement_and_rotation(const unsigned int dim);

    /// One scalar field called @p name.
    static FieldLayout
    scalar(const std::string &name = "w");

    /// @brief One temperature "T" [K] (heat conduction).
    static FieldLayout
    temperature();

    /// @brief Whether some component is of the first-order kind temperature.
    bool
    has_temperature() const
    {
      return n_components(ComponentKind::temperature) > 0;
    }

    /// A layout of the given components (names must differ).
    explicit FieldLayout(const std::vector<FieldComponent> &components);

    /// Number of unknowns per point.
    unsigned int
    n_components() const
    {
      return static_cast<unsigned int>(components.size());
    }

    /// Component @p c.
    const FieldComponent &
    operator[](const unsigned int c) const
    {
      return components[c];
    }

    /// The kind of component @p c.
    ComponentKind
    kind(const unsigned int c) const
    {
      return components[c].kind;
    }

    /// The name of component @p c.
    const std::string &
    name(const unsigned int c) const
    {
      return components[c].name;
    }

    /// Number of components of the kind @p kind.
    unsigned int
    n_components(const ComponentKind kind) const;

    /**
     * @brief The index of the component named @p name; throws, naming the entry @p entry and
     * the accepted names, if the layout has none of that name.
     */
    unsigned int
    index(const std::string &name, const std::string &entry) const;

    /**
     * @brief Whether this layout is @p base followed by rotations only (x, y, rz over x, y): a
     * micropolar particle field over FE translations, whose rotations follow 1/2 curl of the
     * FE displacement. The components shared keep their indices.
     */
    bool
    extends_by_rotations(const FieldLayout &base) const;

    /// The names joined by ", " (for messages and documentation): "x, y, z".
    std::string
    names() const;

    /// The names joined by '|' (for Patterns::MultipleSelection).
    std::string
    pattern() const;

    /// "translations x, y; rotation rz" (for the log and mismatch messages).
    std::string
    description() const;

    /**
     * @brief The motions without energy that conditions must hold in a static solve, for
     * messages: "rigid-body motions (2D: 3, 3D: 6)", or "a constant w" for scalar fields and
     * "a constant T" for a temperature.
     */
    std::string
    free_motions() const;

    /// @brief The same components in the same order.
    bool
    operator==(const FieldLayout &other) const
    {
      return components == other.components;
    }

    /// @brief Not operator==().
    bool
    operator!=(const FieldLayout &other) const
    {
      return !(*this == other);
    }

  private:
    std::vector<FieldComponent> components;
  };

  /**
   * @brief The quantities of a component that conditions, reactions and output name.
   */
  enum class Quantity
  {
    /// displacement, rotation, value
    value,
    /// velocity, angular velocity, rate
    rate,
    /// force, moment, flux
    load
  };

  /**
   * @brief The name of @p quantity of a component of kind @p kind ("displacement", "moment",
   * "temperature", "heat flux", ...).
   */
  std::string
  quantity_name(const ComponentKind kind, const Quantity quantity);

  /**
   * @brief The names of the output fields of @p component's value, rate and load (density):
   * displacement, velocity, force_density (translations); rotation, angular_velocity,
   * moment_density (rotations); w, w_rate, w_load (a scalar w); temperature, temperature_rate,
   * heat_source (a temperature).
   */
  std::array<std::string, 3>
  output_names(const FieldComponent &component);
} // namespace perideal

#endif
