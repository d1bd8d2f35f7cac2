// ---------------------------------------------------------------------
// PeriDeal: the unknowns of a point (particle or FE node).
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/base/field_layout.h>

namespace perideal
{
  namespace
  {
    const char *const axis_names = "xyz";
  }

  FieldLayout::FieldLayout(const std::vector<FieldComponent> &components)
    : components(components)
  {
    for (unsigned int a = 0; a < components.size(); ++a)
      for (unsigned int b = 0; b < a; ++b)
        Assert(components[a].name != components[b].name,
               dealii::ExcMessage("Two components of a field layout are called '" +
                                  components[a].name + "'."));
  }

  FieldLayout
  FieldLayout::displacement(const unsigned int dim)
  {
    std::vector<FieldComponent> components;
    for (unsigned int d = 0; d < dim; ++d)
      components.push_back({ComponentKind::translation, std::string(1, axis_names[d]), d});
    return FieldLayout(components);
  }

  FieldLayout
  FieldLayout::displacement_and_rotation(const unsigned int dim)
  {
    std::vector<FieldComponent> components = displacement(dim).components;
    // In 2D the only rotation is the one about the z axis.
    for (unsigned int d = (dim == 2 ? 2 : 0); d < 3; ++d)
      components.push_back({ComponentKind::rotation, std::string("r") + axis_names[d], d});
    return FieldLayout(components);
  }

  FieldLayout
  FieldLayout::scalar(const std::string &name)
  {
    return FieldLayout({{ComponentKind::scalar, name, 0}});
  }

  FieldLayout
  FieldLayout::temperature()
  {
    return FieldLayout({{ComponentKind::temperature, "T", 0}});
  }

  unsigned int
  FieldLayout::n_components(const ComponentKind kind) const
  {
    unsigned int n = 0;
    for (const auto &component : components)
      n += (component.kind == kind);
    return n;
  }

  unsigned int
  FieldLayout::index(const std::string &name, const std::string &entry) const
  {
    for (unsigned int c = 0; c < components.size(); ++c)
      if (components[c].name == name)
        return c;
    AssertThrow(false,
                dealii::ExcMessage("The parameter <" + entry + "> names the component '" + name +
                                   "', which the field of this problem does not have: accepted "
                                   "values are " +
                                   names() + " (" + description() + ")."));
    return 0;
  }

  bool
  FieldLayout::extends_by_rotations(const FieldLayout &base) const
  {
    if (base.n_components() >= n_components() || base.n_components(ComponentKind::rotation) > 0)
      return false;
    for (unsigned int c = 0; c < n_components(); ++c)
      if (c < base.n_components() ? !(components[c] == base[c]) :
                                    components[c].kind != ComponentKind::rotation)
        return false;
    return true;
  }

  std::string
  FieldLayout::names() const
  {
    std::string result;
    for (const auto &component : components)
      result += (result.empty() ? "" : ", ") + component.name;
    return result;
  }

  std::string
  FieldLayout::pattern() const
  {
    std::string result;
    for (const auto &component : components)
      result += (result.empty() ? "" : "|") + component.name;
    return result;
  }

  std::string
  FieldLayout::description() const
  {
    std::string result;
    for (const ComponentKind kind : {ComponentKind::translation,
                                     ComponentKind::rotation,
                                     ComponentKind::scalar,
                                     ComponentKind::temperature})
      {
        std::string names_of_kind;
        for (const auto &component : components)
          if (component.kind == kind)
            names_of_kind += (names_of_kind.empty() ? "" : ", ") + component.name;
        if (names_of_kind.empty())
          continue;
        const bool  several = n_components(kind) > 1;
        const char *word    = kind == ComponentKind::translation ? "translation" :
                              kind == ComponentKind::rotation    ? "rotation" :
                              kind == ComponentKind::scalar      ? "scalar" :
                                                                   "temperature";
        result +=
          (result.empty() ? "" : "; ") + std::string(word) + (several ? "s " : " ") + names_of_kind;
      }
    return result.empty() ? "no components" : result;
  }

  std::string
  FieldLayout::free_motions() const
  {
    if (n_components(ComponentKind::scalar) + n_components(ComponentKind::temperature) ==
        n_components())
      return std::string(n_components() > 1 ? "constants " : "a constant ") + names();
    return "rigid-body motions (2D: 3, 3D: 6)";
  }

  std::string
  quantity_name(const ComponentKind kind, const Quantity quantity)
  {
    switch (kind)
      {
        case ComponentKind::translation:
          return quantity == Quantity::value ? "displacement" :
                 quantity == Quantity::rate  ? "velocity" :
                                               "force";
        case ComponentKind::rotation:
          return quantity == Quantity::value ? "rotation" :
                 quantity == Quantity::rate  ? "angular velocity" :
                                               "moment";
        case ComponentKind::scalar:
          return quantity == Quantity::value ? "value" :
                 quantity == Quantity::rate  ? "rate" :
                                               "flux";
        case ComponentKind::temperature:
          return quantity == Quantity::value ? "temperature" :
                 quantity == Quantity::rate  ? "temperature rate" :
                                               "heat flux";
      }
    return "";
  }

  std::array<std::string, 3>
  output_names(const FieldComponent &component)
  {
    switch (component.kind)
      {
        case ComponentKind::translation:
          return {{"displacement", "velocity", "force_density"}};
        case ComponentKind::rotation:
          return {{"rotation", "angular_velocity", "moment_density"}};
        case ComponentKind::scalar:
          return {{component.name, component.name + "_rate", component.name + "_load"}};
        case ComponentKind::temperature:
          return {{"temperature", "temperature_rate", "heat_source"}};
      }
    return {};
  }
} // namespace perideal
