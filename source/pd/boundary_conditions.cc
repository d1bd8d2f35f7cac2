// ---------------------------------------------------------------------
// PeriDeal: prescribed values, rates and loads on particle sets.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/boundary_conditions.h>

#include <algorithm>
#include <cmath>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief A value of <Type>: the quantity it prescribes of the components of one kind, or,
     * for 'value', of components of any kind.
     */
    struct ConditionType
    {
      const char   *name;
      ComponentKind kind;
      Quantity      quantity;
      bool          any_kind = false;

      bool
      acts_on(const ComponentKind component_kind) const
      {
        return any_kind || component_kind == kind;
      }
    };

    const ConditionType condition_types[] = {
      {"displacement", ComponentKind::translation, Quantity::value},
      {"velocity", ComponentKind::translation, Quantity::rate},
      {"traction", ComponentKind::translation, Quantity::load},
      {"rotation", ComponentKind::rotation, Quantity::value},
      {"angular velocity", ComponentKind::rotation, Quantity::rate},
      {"moment", ComponentKind::rotation, Quantity::load},
      {"value", ComponentKind::scalar, Quantity::value, true},
      {"rate", ComponentKind::scalar, Quantity::rate},
      {"flux", ComponentKind::scalar, Quantity::load},
      {"flux", ComponentKind::temperature, Quantity::load},
      {"convection", ComponentKind::temperature, Quantity::load}};

    /// Whether a field of @p layout has components that @p type acts on.
    bool
    acts_on_layout(const ConditionType &type, const FieldLayout &layout)
    {
      return type.any_kind || layout.n_components(type.kind) > 0;
    }

    /// The types (each name once) that act on the components of @p layout (all types without
    /// a layout), separated by @p separator.
    std::string
    type_names(const FieldLayout *layout, const std::string &separator)
    {
      std::vector<std::string> names;
      for (const auto &type : condition_types)
        if ((!layout || acts_on_layout(type, *layout)) &&
            std::find(names.begin(), names.end(), type.name) == names.end())
          names.emplace_back(type.name);
      std::string result;
      for (const auto &name : names)
        result += (result.empty() ? "" : separator) + name;
      return result;
    }
  } // namespace

  template <int dim>
  void
  BoundaryConditions<dim>::declare_names(ParameterHandler &prm)
  {
    ParameterUtilities::declare_name_list(prm,
                                          "Boundary conditions",
                                          "Comma-separated names of the boundary conditions, "
                                          "each described in a subsection of its own name.");
  }

  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler               &prm,
                                              const std::vector<std::string> &names)
  {
    declare_names(prm);
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Region",
                          "",
                          Patterns::Anything(),
                          "The region whose particles it acts on.");
        prm.declare_entry("Type",
                          "value",
                          Patterns::Selection(type_names(nullptr, "|")),
                          "What it prescribes. 'value' (the default, accepted by every model): "
                          "the value of the listed components of any kind, the displacement of "
                          "translations, the rotation of rotations, the scalar field itself; "
                          "with <Components> empty, every component (a clamp). Translations: "
                          "'displacement' [m] or 'velocity' [m/s] of the listed components, "
                          "'traction' [Pa] on all; rotations (micropolar models): 'rotation' "
                          "[rad] or 'angular velocity' [rad/s] of the listed components, "
                          "'moment' [N m/m^2] on all; a scalar field: 'value' or 'rate' of it, "
                          "'flux' (load per area); a temperature (conduction models): 'value' "
                          "[K], 'flux' (a heat flux into the body [W/m^2]) or 'convection' (the "
                          "heat flux h (T_inf - T) of <Heat transfer coefficient> and <Ambient "
                          "temperature>). A load ('traction', 'moment', 'flux', 'convection') "
                          "acts as a force (heat source) density in the region, a surface layer "
                          "of thickness 'Layer thickness'.");
        prm.declare_entry(
          "Components",
          "",
          Patterns::Anything(),
          "The prescribed components (values and rates), by the names of the "
          "field's components, separated by ',': x, y, z (translations); rx, ry, "
          "rz (rotations; rz only in 2D); w (the scalar field of antiplane "
          "models); T (a temperature). Empty: all components of the kind the type acts on (all "
          "components for 'value'). Loads act on all of them.");
        prm.declare_entry("Function",
                          "0",
                          Patterns::Anything(),
                          "One expression of x, y, (z) and the time t (s) per prescribed "
                          "component (for a load: per component of its kind), in the unit of its "
                          "Type, separated by ';'; a single 0 is zero for all.");
        prm.declare_entry("Layer thickness",
                          "0",
                          Patterns::Double(0.),
                          "A load ('traction', 'moment', 'flux', 'convection'): the thickness "
                          "of the loaded layer [m] (the region's extent normal to the surface; "
                          "required). A value or rate: 0 (the default) for a hold of any shape; "
                          "> 0 declares the region a fictitious layer of that depth beyond a "
                          "face of the body, checked against the depth the model's force "
                          "reaches: delta - dx/2 for bond-based models (3 lattice layers at "
                          "delta = 3.015 dx), 2 delta - dx/2 for state-based ones (6 layers), "
                          "whose forces use the neighbours' families.");
        Convection<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  std::vector<std::string>
  BoundaryConditions<dim>::parse_names(ParameterHandler &prm)
  {
    return ParameterUtilities::parse_name_list(prm, "Boundary conditions");
  }

  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler            &prm,
                                            const RegionCollection<dim> &regions,
                                            const FieldLayout           &field_layout)
  {
    layout          = field_layout;
    condition_names = parse_names(prm);
    conditions.clear();
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : condition_names)
      {
        const std::string prefix = "Boundary conditions/" + name + "/";
        prm.enter_subsection(name);
        Condition c;
        c.name              = name;
        c.region_name       = prm.get("Region");
        c.region            = &regions.get(c.region_name, prefix + "Region");
        const std::string t = prm.get("Type");
        // The type of that name that acts on this field (a name may act on several kinds:
        // 'flux' on a scalar and on a temperature), else the first of that name (refused).
        auto found = std::find_if(std::begin(condition_types),
                                  std::end(condition_types),
                                  [&](const auto &type) {
                                    return t == type.name && acts_on_layout(type, layout);
                                  });
        if (found == std::end(condition_types))
          found = std::find_if(std::begin(condition_types),
                               std::end(condition_types),
                               [&](const auto &type) { return t == type.name; });
        Assert(found != std::end(condition_types), ExcInternalError());
        AssertThrow(acts_on_layout(*found, layout),
                    ExcMessage("The parameter <" + prefix + "Type> is '" + t +
                               "', which acts on components the field of this problem (" +
                               layout.description() + ") does not have; accepted types: " +
                               type_names(&layout, ", ") + "."));
        c.type_name = t;
        c.quantity  = found->quantity;
        for (unsigned int k = 0; k < layout.n_components(); ++k)
          if (found->acts_on(layout.kind(k)))
            c.kind_components.push_back(k);
        std::string kind_names;
        for (const unsigned int k : c.kind_components)
          kind_names += (kind_names.empty() ? "" : ", ") + layout.name(k);
        const auto listed = Utilities::split_string_list(prm.get("Components"), ',');
        if (c.quantity == Quantity::load || listed.empty())
          c.components = c.kind_components;
        else
          for (const auto &component : listed)
            {
              const unsigned int k = layout.index(component, prefix + "Components");
              AssertThrow(found->acts_on(layout.kind(k)),
                          ExcMessage("The parameter <" + prefix + "Components> names '" +
                                     component + "', which <" + prefix + "Type> = '" + t +
                                     "' does not act on; accepted: " + kind_names + "."));
              c.components.push_back(k);
            }
        c.layer_thickness = prm.get_double("Layer thickness");
        if (c.quantity == Quantity::load)
          ParameterUtilities::require_positive(c.layer_thickness, prefix + "Layer thickness");
        if (t == "convection")
          c.convection = Convection<dim>::parse(prm, prefix);
        c.function = ParameterUtilities::make_function<dim>(prm.get("Function"),
                                                            c.components.size(),
                                                            prefix + "Function");
        conditions.push_back(std::move(c));
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  void
  BoundaryConditions<dim>::check_layer_depths(const double       horizon,
                                              const double       spacing,
                                              const unsigned int reach,
                                              const std::string &model_name) const
  {
    const double needed = reach * horizon - 0.5 * spacing;
    for (const auto &c : conditions)
      AssertThrow(c.quantity == Quantity::load || c.layer_thickness == 0. ||
                    c.layer_thickness >= needed * (1. - 1e-12),
                  ExcMessage("The parameter <Boundary conditions/" + c.name +
                             "/Layer thickness> is " +
                             ParameterUtilities::format_number(c.layer_thickness) +
                             " m: the fictitious layer is too thin for the model '" + model_name +
                             "', whose force reaches " + std::to_string(reach) + " horizon" +
                             (reach > 1 ? "s (the neighbours' families)" : "") +
                             ", so the held particles next to the body would have cut families. "
                             "Accepted: 0 (not a fictitious layer) or at least " +
                             std::to_string(reach) +
                             " delta - dx/2 = " + ParameterUtilities::format_number(needed) +
                             " m (" + std::to_string(int(std::ceil(needed / spacing - 1e-9))) +
                             " lattice layers); make the region <" + c.region_name +
                             "> that deep and the entry with it."));
  }

  template <int dim>
  void
  BoundaryConditions<dim>::set_body_force(const std::shared_ptr<Function<dim>> &function)
  {
    body_force = function;
  }

  template <int dim>
  void
  BoundaryConditions<dim>::setup(const ParticleSystem<dim> &particles)
  {
    particle_system       = &particles;
    const unsigned int nc = layout.n_components();
    prescribed.assign(std::size_t(particles.n_owned()) * nc, 0);
    std::vector<int> owner(std::size_t(particles.n_owned()) * nc, -1);
    const auto      &x = particles.positions();
    for (unsigned int k = 0; k < conditions.size(); ++k)
      {
        Condition &c = conditions[k];
        c.particles.clear();
        for (unsigned int i = 0; i < particles.n_owned(); ++i)
          if (c.region->contains(x[i]))
            c.particles.push_back(i);
        const auto n_total =
          Utilities::MPI::sum<unsigned long>(c.particles.size(), particles.get_communicator());
        AssertThrow(n_total > 0,
                    ExcMessage("The region <" + c.region->name() + "> of <Boundary conditions/" +
                               c.name +
                               "/Region> holds no particle; enlarge it to cover at least one "
                               "lattice point of the body."));
        if (c.quantity == Quantity::load)
          continue;
        for (const unsigned int i : c.particles)
          for (const unsigned int comp : c.components)
            {
              int &first = owner[i * nc + comp];
              AssertThrow(first < 0,
                          ExcMessage("The boundary conditions <" + conditions[first].name +
                                     "> and <" + c.name +
                                     "> both prescribe the same component of a particle; make "
                                     "their regions or <Components> disjoint."));
              first                     = k;
              prescribed[i * nc + comp] = 1;
            }
      }
  }

  template <int dim>
  void
  BoundaryConditions<dim>::prescribe_step_velocity(const double    time,
                                                   const double    dt,
                                                   ParticleVector &v) const
  {
    const auto        &x  = particle_system->positions();
    const unsigned int nc = layout.n_components();
    for (const auto &c : conditions)
      for (const unsigned int i : c.particles)
        for (unsigned int k = 0; k < c.components.size(); ++k)
          {
            double value = 0.;
            if (c.quantity == Quantity::rate)
              {
                c.function->set_time(time + 0.5 * dt);
                value = c.function->value(x[i], k);
              }
            else if (c.quantity == Quantity::value)
              {
                c.function->set_time(time + dt);
                value = c.function->value(x[i], k);
                c.function->set_time(time);
                value = (value - c.function->value(x[i], k)) / dt;
              }
            else
              continue;
            v.local_element(i * nc + c.components[k]) = value;
          }
  }

  template <int dim>
  void
  BoundaryConditions<dim>::prescribe_displacement(const double time, ParticleVector &u) const
  {
    const auto        &x  = particle_system->positions();
    const unsigned int nc = layout.n_components();
    for (const auto &c : conditions)
      if (c.quantity == Quantity::value)
        {
          c.function->set_time(time);
          for (const unsigned int i : c.particles)
            for (unsigned int k = 0; k < c.components.size(); ++k)
              u.local_element(i * nc + c.components[k]) = c.function->value(x[i], k);
        }
  }

  template <int dim>
  bool
  BoundaryConditions<dim>::has_loads() const
  {
    return body_force || std::any_of(conditions.begin(), conditions.end(), [](const auto &c) {
             return c.quantity == Quantity::load;
           });
  }

  template <int dim>
  void
  BoundaryConditions<dim>::add_loads(const double time, ParticleVector &force) const
  {
    const auto        &x  = particle_system->positions();
    const unsigned int nc = layout.n_components();
    for (const auto &c : conditions)
      if (c.quantity == Quantity::load && !c.convection)
        {
          c.function->set_time(time);
          for (const unsigned int i : c.particles)
            for (unsigned int k = 0; k < c.components.size(); ++k)
              force.local_element(i * nc + c.components[k]) +=
                c.function->value(x[i], k) / c.layer_thickness;
        }
    if (body_force)
      {
        const auto &weight = particle_system->energy_weights();
        body_force->set_time(time);
        for (unsigned int i = 0; i < particle_system->n_owned(); ++i)
          for (unsigned int k = 0; k < nc; ++k)
            force.local_element(i * nc + k) += weight[i] * body_force->value(x[i], k);
      }
  }

  template <int dim>
  bool
  BoundaryConditions<dim>::has_convection() const
  {
    return std::any_of(conditions.begin(), conditions.end(), [](const auto &c) {
      return c.convection.has_value();
    });
  }

  template <int dim>
  double
  BoundaryConditions<dim>::convection_bound() const
  {
    double bound = 0.;
    for (const auto &c : conditions)
      if (c.convection)
        bound = std::max(bound, c.convection->coefficient / c.layer_thickness);
    return bound;
  }

  template <int dim>
  void
  BoundaryConditions<dim>::add_convection(const double          time,
                                          const ParticleVector *field,
                                          ParticleVector       &force) const
  {
    const auto        &x  = particle_system->positions();
    const unsigned int nc = layout.n_components();
    for (const auto &c : conditions)
      if (c.convection)
        {
          c.convection->ambient->set_time(time);
          for (const unsigned int i : c.particles)
            for (const unsigned int k : c.components)
              force.local_element(i * nc + k) +=
                c.convection->flux(x[i], field ? field->local_element(i * nc + k) : 0.) /
                c.layer_thickness;
        }
  }

  template <int dim>
  void
  BoundaryConditions<dim>::add_convection_conductance(ParticleVector &diagonal) const
  {
    const auto        &volume = particle_system->volumes();
    const unsigned int nc     = layout.n_components();
    for (const auto &c : conditions)
      if (c.convection)
        for (const unsigned int i : c.particles)
          for (const unsigned int k : c.components)
            diagonal.local_element(i * nc + k) +=
              c.convection->coefficient * volume[i] / c.layer_thickness;
  }

  template <int dim>
  std::vector<std::string>
  BoundaryConditions<dim>::names_of(const Quantity quantity) const
  {
    std::vector<std::string> result;
    for (const auto &c : conditions)
      if (c.quantity == quantity)
        result.push_back(c.name);
    return result;
  }

  template <int dim>
  const std::vector<std::string> &
  BoundaryConditions<dim>::names() const
  {
    return condition_names;
  }

  template <int dim>
  const std::string &
  BoundaryConditions<dim>::type_name(const unsigned int k) const
  {
    return conditions[k].type_name;
  }

  template <int dim>
  const std::vector<unsigned int> &
  BoundaryConditions<dim>::reaction_components(const unsigned int k) const
  {
    return conditions[k].kind_components;
  }

  template <int dim>
  std::vector<std::vector<double>>
  BoundaryConditions<dim>::reactions(const ParticleVector &internal_force) const
  {
    std::vector<std::vector<double>> result(conditions.size());
    const auto                      &volume = particle_system->volumes();
    const unsigned int               nc     = layout.n_components();
    for (unsigned int k = 0; k < conditions.size(); ++k)
      {
        const auto &components = conditions[k].kind_components;
        result[k].assign(components.size(), 0.);
        for (const unsigned int i : conditions[k].particles)
          for (unsigned int j = 0; j < components.size(); ++j)
            result[k][j] -= internal_force.local_element(i * nc + components[j]) * volume[i];
        Utilities::MPI::sum(result[k], particle_system->get_communicator(), result[k]);
      }
    return result;
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace perideal
