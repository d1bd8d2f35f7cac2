// ---------------------------------------------------------------------
// PeriDeal: the conditions of the finite-element region: the boundary conditions (their
// parameters, the dofs they prescribe, the check that they act on something), the given values
// on interior dofs (set_interior_values), the prescription of both at a time, and their
// reactions.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>
#include <deal.II/fe/mapping_q1.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/fem/fe_region.h>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The condition types of a component kind, by quantity: value, rate, load (a temperature:
    // no rate; its loads are 'flux' and 'convection', listed after the three).
    std::vector<std::string>
    type_names(const ComponentKind kind)
    {
      switch (kind)
        {
          case ComponentKind::translation:
            return {"displacement", "velocity", "traction"};
          case ComponentKind::rotation:
            return {"rotation", "angular velocity", "moment"};
          case ComponentKind::scalar:
            return {"value", "rate", "flux"};
          case ComponentKind::temperature:
            return {"value", "", "flux", "convection"};
        }
      return {};
    }
  } // namespace

  template <int dim>
  void
  FERegion<dim>::declare_condition_parameters(ParameterHandler               &prm,
                                              const std::vector<std::string> &names)
  {
    for (const auto &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Boundary ids",
                          "",
                          Patterns::List(Patterns::Integer(0, 254)),
                          "The boundary ids (gmsh physical groups or generator ids) it acts on.");
        prm.declare_entry(
          "Type",
          "value",
          Patterns::Selection("value|displacement|velocity|traction|rate|flux|convection"),
          "What it prescribes. 'value' (the default, accepted by every physics): the value of "
          "the listed components of the field, the displacement of translations. On "
          "translations (linear elasticity): 'displacement' [m] (the same as 'value') or "
          "'velocity' [m/s, explicit dynamics only] of the listed components, or 'traction' "
          "[Pa] (all components). On a scalar field w (scalar laplace): 'value' [w] or 'rate' "
          "[w/s, explicit dynamics only], or 'flux' (the normal flux k dw/dn [k w/m] into the "
          "body). On a temperature T: 'value' [K], 'flux' (the heat flux into the body "
          "[W/m^2]) or 'convection' (the heat flux h (T_inf - T) of <Heat transfer "
          "coefficient> and <Ambient temperature>).");
        prm.declare_entry("Components",
                          "",
                          Patterns::Anything(),
                          "The prescribed components, by the names of the physics' field (x, "
                          "y, z for linear elasticity; w for scalar laplace), separated by ','; "
                          "empty: all. Ignored for traction and flux (all components).");
        prm.declare_entry("Function",
                          "0",
                          Patterns::Anything(),
                          "One expression of x, y, (z) and the time t (s) per listed component "
                          "(all components for traction and flux), in the unit of its Type, "
                          "separated by ';'; a single 0 is zero for all.");
        Convection<dim>::declare_parameters(prm);
        prm.leave_subsection();
      }
  }

  template <int dim>
  void
  FERegion<dim>::parse_conditions(ParameterHandler               &prm,
                                  const std::vector<std::string> &names,
                                  const std::string              &physics_name)
  {
    for (const auto &name : names)
      {
        const std::string prefix = section + "/Boundary conditions/" + name + "/";
        prm.enter_subsection(name);
        Condition c;
        c.name = name;
        for (const auto &id : Utilities::split_string_list(prm.get("Boundary ids"), ','))
          c.boundary_ids.insert(static_cast<types::boundary_id>(Utilities::string_to_int(id)));
        AssertThrow(!c.boundary_ids.empty(),
                    ExcMessage("The parameter <" + prefix +
                               "Boundary ids> is empty; list the "
                               "boundary ids the condition acts on."));
        // The types of the field's kind (a field of one kind: all of its components), and
        // 'value', the value of any kind.
        const auto        names_of_kind = type_names(layout.kind(0));
        const std::string type          = prm.get("Type");
        const auto        found = std::find(names_of_kind.begin(), names_of_kind.end(), type);
        std::string       accepted;
        for (const auto &name : names_of_kind)
          if (!name.empty())
            accepted += (accepted.empty() ? "" : ", ") + name;
        AssertThrow(found != names_of_kind.end() || type == "value",
                    ExcMessage("The parameter <" + prefix + "Type> = <" + type +
                               "> is not a condition on the field of <" + section +
                               "/Physics> = <" + physics_name + "> (" + layout.description() +
                               "): accepted values are " + accepted +
                               (names_of_kind[0] == "value" ? "" : " (or value)") + "."));
        const auto index = found - names_of_kind.begin();
        c.type           = (found == names_of_kind.end() ? Quantity::value :
                                                           static_cast<Quantity>(std::min<long>(index, 2)));
        if (type == "convection")
          c.convection = Convection<dim>::parse(prm, prefix);
        const auto listed = Utilities::split_string_list(prm.get("Components"), ',');
        for (unsigned int k = 0; k < layout.n_components(); ++k)
          if (c.type == Quantity::load || listed.empty())
            c.components.push_back(k);
        if (c.type != Quantity::load)
          for (const auto &name : listed)
            c.components.push_back(layout.index(name, prefix + "Components"));
        c.function = ParameterUtilities::make_function<dim>(prm.get("Function"),
                                                            c.components.size(),
                                                            prefix + "Function");
        prm.leave_subsection();
        condition_list.push_back(std::move(c));
      }

    // Two conditions may not prescribe the same component on the same boundary id.
    for (unsigned int a = 0; a < condition_list.size(); ++a)
      for (unsigned int b = a + 1; b < condition_list.size(); ++b)
        {
          const auto &ca = condition_list[a], &cb = condition_list[b];
          if (ca.type == Quantity::load || cb.type == Quantity::load)
            continue;
          for (const auto id : ca.boundary_ids)
            for (const unsigned int comp : ca.components)
              AssertThrow(cb.boundary_ids.count(id) == 0 ||
                            std::find(cb.components.begin(), cb.components.end(), comp) ==
                              cb.components.end(),
                          ExcMessage("The FE boundary conditions <" + ca.name + "> and <" +
                                     cb.name + "> both prescribe component " +
                                     std::to_string(comp) + " on boundary id " +
                                     std::to_string(id) +
                                     "; make their <Boundary ids> or <Components> disjoint."));
        }
  }

  template <int dim>
  void
  FERegion<dim>::locate_prescribed_dofs()
  {
    prescribed.assign(owned_dofs.n_elements(), false);
    prescribed_dofs.clear();
    interior_dofs.clear();
    interior_values.clear();
    std::vector<types::global_dof_index> face_dofs;
    const MappingQ1<dim>                 mapping;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            for (unsigned int k = 0; k < condition_list.size(); ++k)
              {
                const Condition &c = condition_list[k];
                if (c.type == Quantity::load ||
                    c.boundary_ids.count(cell->face(f)->boundary_id()) == 0)
                  continue;
                const auto &fe = cell->get_fe();
                face_dofs.resize(fe.n_dofs_per_face(f));
                cell->face(f)->get_dof_indices(face_dofs, cell->active_fe_index());
                for (unsigned int i = 0; i < face_dofs.size(); ++i)
                  {
                    const unsigned int comp = fe.face_system_to_component_index(i, f).first;
                    const auto k_comp = std::find(c.components.begin(), c.components.end(), comp);
                    if (k_comp == c.components.end() || !owned_dofs.is_element(face_dofs[i]))
                      continue;
                    const auto local = owned_dofs.index_within_set(face_dofs[i]);
                    if (prescribed[local])
                      continue;
                    prescribed[local]  = true;
                    const Point<dim> x = mapping.transform_unit_to_real_cell(
                      cell,
                      fe.unit_support_point(fe.face_to_cell_index(i,
                                                                  f,
                                                                  cell->face_orientation(f),
                                                                  cell->face_flip(f),
                                                                  cell->face_rotation(f))));
                    prescribed_dofs.push_back(
                      {static_cast<unsigned int>(local),
                       k,
                       static_cast<unsigned int>(k_comp - c.components.begin()),
                       x});
                  }
              }

    // A field defined up to a constant (held_point()) is held at the vertex nearest to the
    // point unless a condition prescribes its value.
    held_dof.reset();
    const auto held = physics_model->held_point();
    if (!held || std::any_of(condition_list.begin(), condition_list.end(), [](const auto &c) {
          return c.type == Quantity::value;
        }))
      return;
    double                  distance = std::numeric_limits<double>::max();
    types::global_dof_index nearest  = numbers::invalid_dof_index;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        for (const unsigned int v : cell->vertex_indices())
          {
            const double d = cell->vertex(v).distance(held->first);
            if (d < distance)
              {
                distance = d;
                nearest  = cell->vertex_dof_index(v, 0, 0);
              }
          }
    // The nearest vertex over all ranks; of equal distances the smallest dof index.
    const double min_distance = Utilities::MPI::min(distance, comm);
    nearest                   = Utilities::MPI::min(distance == min_distance ?
                                    nearest :
                                    std::numeric_limits<types::global_dof_index>::max(),
                                  comm);
    if (owned_dofs.is_element(nearest))
      {
        held_dof              = static_cast<unsigned int>(owned_dofs.index_within_set(nearest));
        prescribed[*held_dof] = true;
      }
  }

  template <int dim>
  void
  FERegion<dim>::check_held_point() const
  {
    const auto held = physics_model->held_point();
    if (!held || !has_mesh())
      return;
    bool inside = false;
    for (const auto &cell : triangulation.active_cell_iterators())
      inside = inside || (cell->is_locally_owned() && cell->point_inside(held->first));
    AssertThrow(Utilities::MPI::logical_or(inside, comm),
                ExcMessage("The parameter " + held->second + " is the point (" +
                           ParameterUtilities::format_number(held->first[0]) + ", " +
                           ParameterUtilities::format_number(held->first[1]) +
                           "), outside the mesh; accepted are points of the section (the "
                           "twist axis must pierce the bar's cross-section)."));
  }

  template <int dim>
  void
  FERegion<dim>::check_conditions_act() const
  {
    // Per condition, the boundary faces with its ids: on cells with FE unknowns, and on any.
    std::vector<std::uint64_t>   on_fe(condition_list.size(), 0), on_mesh(condition_list.size(), 0);
    std::set<types::boundary_id> mesh_ids;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto id = cell->face(f)->boundary_id();
              mesh_ids.insert(id);
              for (unsigned int k = 0; k < condition_list.size(); ++k)
                if (condition_list[k].boundary_ids.count(id) > 0)
                  {
                    ++on_mesh[k];
                    on_fe[k] += (cell->active_fe_index() == 0);
                  }
            }
    std::vector<types::boundary_id> all_ids;
    for (const auto &ids :
         Utilities::MPI::all_gather(comm,
                                    std::vector<types::boundary_id>(mesh_ids.begin(),
                                                                    mesh_ids.end())))
      all_ids.insert(all_ids.end(), ids.begin(), ids.end());
    std::sort(all_ids.begin(), all_ids.end());
    all_ids.erase(std::unique(all_ids.begin(), all_ids.end()), all_ids.end());
    for (unsigned int k = 0; k < condition_list.size(); ++k)
      {
        const std::string entry =
          "<" + section + "/Boundary conditions/" + condition_list[k].name + "/Boundary ids>";
        std::string ids;
        for (const auto id : all_ids)
          ids += (ids.empty() ? "" : ", ") + std::to_string(id);
        AssertThrow(Utilities::MPI::sum(on_mesh[k], comm) > 0,
                    ExcMessage(entry + " names no boundary of the mesh; its boundary ids are " +
                               ids + "."));
        AssertThrow(Utilities::MPI::sum(on_fe[k], comm) > 0,
                    ExcMessage(entry + ": no cell with FE unknowns touches these boundaries "
                                       "(1 - <Coupling/Blending function> is 0 on all cells "
                                       "there), so the condition would act on nothing. Prescribe "
                                       "it on the particles (<Boundary conditions>) or make the "
                                       "blending function smaller than 1 there."));
      }
  }

  template <int dim>
  void
  FERegion<dim>::prescribe(const double time, FEVector &u, FEVector &v) const
  {
    for (const auto &c : condition_list)
      c.function->set_time(time);
    for (const auto &d : prescribed_dofs)
      {
        const Condition &c     = condition_list[d.condition];
        const double     value = c.function->value(d.support_point, d.function_component);
        if (c.type == Quantity::value)
          u.local_element(d.local_index) = value;
        else
          v.local_element(d.local_index) = value;
      }
    for (const auto &[local_index, value] : interior_values)
      u.local_element(local_index) = value;
    if (held_dof)
      u.local_element(*held_dof) = 0.;
  }

  template <int dim>
  void
  FERegion<dim>::set_interior_values(const std::vector<types::global_dof_index> &dofs,
                                     const std::vector<double>                  &values)
  {
    AssertDimension(dofs.size(), values.size());
    for (const auto &[local_index, value] : interior_values)
      prescribed[local_index] = false;
    interior_dofs = dofs;
    interior_values.clear();
    for (unsigned int k = 0; k < dofs.size(); ++k)
      if (owned_dofs.is_element(dofs[k]))
        {
          const auto local = static_cast<unsigned int>(owned_dofs.index_within_set(dofs[k]));
          Assert(!prescribed[local],
                 ExcMessage("Dof " + std::to_string(dofs[k]) +
                            " is prescribed by a boundary condition already."));
          prescribed[local] = true;
          interior_values.emplace_back(local, values[k]);
        }
  }

  template <int dim>
  std::vector<double>
  FERegion<dim>::interior_reactions(const FEVector &residual) const
  {
    std::vector<double> result(interior_dofs.size(), 0.);
    for (unsigned int k = 0; k < interior_dofs.size(); ++k)
      if (owned_dofs.is_element(interior_dofs[k]))
        result[k] = residual(interior_dofs[k]);
    Utilities::MPI::sum(make_array_view(std::as_const(result)), comm, make_array_view(result));
    return result;
  }

  template <int dim>
  const std::vector<bool> &
  FERegion<dim>::prescribed_mask() const
  {
    return prescribed;
  }

  template <int dim>
  std::vector<std::vector<double>>
  FERegion<dim>::reactions(const FEVector &residual) const
  {
    std::vector<std::vector<double>> result(condition_list.size(),
                                            std::vector<double>(layout.n_components(), 0.));
    for (const auto &d : prescribed_dofs)
      {
        const unsigned int comp = condition_list[d.condition].components[d.function_component];
        result[d.condition][comp] += residual.local_element(d.local_index);
      }
    for (auto &r : result)
      Utilities::MPI::sum(r, comm, r);
    return result;
  }

  // The members defined in this file (the class is instantiated in fe_region.cc).
#define PERIDEAL_INSTANTIATE(dim)                                                                \
  template void FERegion<dim>::declare_condition_parameters(ParameterHandler &,                  \
                                                            const std::vector<std::string> &);   \
  template void FERegion<dim>::parse_conditions(ParameterHandler &,                              \
                                                const std::vector<std::string> &,                \
                                                const std::string &);                            \
  template void FERegion<dim>::locate_prescribed_dofs();                                         \
  template void FERegion<dim>::check_held_point() const;                                         \
  template void FERegion<dim>::check_conditions_act() const;                                     \
  template void FERegion<dim>::prescribe(const double, FEVector &, FEVector &) const;            \
  template void FERegion<dim>::set_interior_values(const std::vector<types::global_dof_index> &, \
                                                   const std::vector<double> &);                 \
                                                                                                 \
  template std::vector<double> FERegion<dim>::interior_reactions(const FEVector &) const;        \
                                                                                                 \
  template const std::vector<bool> &FERegion<dim>::prescribed_mask() const;                      \
                                                                                                 \
  template std::vector<std::vector<double>> FERegion<dim>::reactions(const FEVector &) const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
