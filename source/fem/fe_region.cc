// ---------------------------------------------------------------------
// PeriDeal: the finite-element region: mesh, FE space, assembly, conditions, output; the
// physics is a plugin (FEPhysics).
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/base/hdf5_xdmf_writer.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/fem/fe_region.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

namespace perideal
{
  using namespace dealii;
  using Vector = LinearAlgebra::distributed::Vector<double>;

  namespace
  {
    const std::string section = "Finite elements";

    // The first n components of a function with at least n (the problem's functions have dim
    // components; a field with fewer reads the first ones).
    template <int dim>
    class FirstComponents : public Function<dim>
    {
    public:
      FirstComponents(const Function<dim> &f, const unsigned int n)
        : Function<dim>(n)
        , f(f)
      {}

      double
      value(const Point<dim> &p, const unsigned int c) const override
      {
        return f.value(p, c);
      }

    private:
      const Function<dim> &f;
    };

    // The names of the registered physics.
    template <int dim>
    std::vector<std::string>
    physics_names()
    {
      return Utilities::split_string_list(PluginRegistry<FEPhysics<dim>>::pattern_string(), '|');
    }

    // The condition types of a component kind, by quantity: value, rate, load.
    std::array<std::string, 3>
    type_names(const ComponentKind kind)
    {
      switch (kind)
        {
          case ComponentKind::translation:
            return {{"displacement", "velocity", "traction"}};
          case ComponentKind::rotation:
            return {{"rotation", "angular velocity", "moment"}};
          case ComponentKind::scalar:
            return {{"value", "rate", "flux"}};
        }
      return {};
    }
  } // namespace

  template <int dim>
  FERegion<dim>::FERegion(const MPI_Comm comm)
    : comm(comm)
    , triangulation(comm)
    , dof_handler(triangulation)
  {}

  template <int dim>
  void
  FERegion<dim>::declare_names(ParameterHandler &prm)
  {
    prm.enter_subsection(section);
    prm.declare_entry(
      "Mesh file",
      "",
      Patterns::Anything(),
      "A gmsh .msh file (format 2.2, quadrilaterals/hexahedra, lengths in m; "
      "boundary ids from the physical curves/surfaces), relative to the working "
      "directory. Empty: use the generator (or no FE region if that is empty too).");
    prm.declare_entry("Generator",
                      "",
                      Patterns::Anything(),
                      "Name of a deal.II GridGenerator function (e.g. hyper_rectangle, "
                      "subdivided_hyper_rectangle, hyper_shell), used when 'Mesh file' is "
                      "empty. Both empty: the problem has no FE region.");
    ParameterUtilities::declare_name_list(prm,
                                          "Boundary conditions",
                                          "Comma-separated names of the FE boundary conditions, "
                                          "each described in a subsection of its own name.");
    prm.leave_subsection();
  }

  template <int dim>
  std::vector<std::string>
  FERegion<dim>::parse_names(ParameterHandler &prm)
  {
    prm.enter_subsection(section);
    const auto names = ParameterUtilities::parse_name_list(prm, "Boundary conditions");
    prm.leave_subsection();
    return names;
  }

  template <int dim>
  void
  FERegion<dim>::declare_parameters(ParameterHandler               &prm,
                                    const std::vector<std::string> &condition_names)
  {
    declare_names(prm);
    prm.enter_subsection(section);
    prm.declare_entry("Generator arguments",
                      "",
                      Patterns::Anything(),
                      "The generator's arguments as deal.II's generate_from_name_and_arguments() "
                      "reads them, separated by ':' (e.g. for hyper_rectangle in 2D: "
                      "'0, 0 : 0.1, 0.05 : false').");
    prm.declare_entry("Global refinements",
                      "0",
                      Patterns::Integer(0, 20),
                      "Uniform refinements of the mesh.");
    prm.declare_entry("Circular boundaries",
                      "",
                      Patterns::Anything(),
                      "Boundary ids that lie on circles (2D) or cylinders about the z axis (3D), "
                      "as 'id: cx, cy' items separated by ';', so that refinement follows the "
                      "curve (e.g. '5: 0, 0' for a hole centred at the origin).");
    prm.declare_entry("Polynomial degree",
                      "1",
                      Patterns::Integer(1, 4),
                      "Degree p of the FE_Q(p) elements of every component.");
    prm.declare_entry("Density",
                      "0",
                      Patterns::Double(0.),
                      "Mass density rho [kg/m^3] (the inertia of every component).");
    using Registry = PluginRegistry<FEPhysics<dim>>;
    prm.declare_entry("Physics",
                      "linear elasticity",
                      Patterns::Selection(Registry::pattern_string()),
                      "The equation of the FE region and its unknowns: " +
                        Registry::documentation() + "Each physics reads its own subsection.");
    for (const auto &name : physics_names<dim>())
      Registry::create(name, section + "/Physics")->declare_parameters(prm);
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : condition_names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Boundary ids",
                          "",
                          Patterns::List(Patterns::Integer(0, 254)),
                          "The boundary ids (gmsh physical groups or generator ids) it acts on.");
        prm.declare_entry(
          "Type",
          "displacement",
          Patterns::Selection("displacement|velocity|traction|value|rate|flux"),
          "On translations (linear elasticity): 'displacement' [m] or 'velocity' [m/s, explicit "
          "dynamics only] of the listed components, or 'traction' [Pa] (all components). On a "
          "scalar field w (scalar laplace): 'value' [w] or 'rate' [w/s, explicit dynamics only], "
          "or 'flux' (the normal flux k dw/dn [k w/m] into the body).");
        prm.declare_entry("Components",
                          "",
                          Patterns::Anything(),
                          "The prescribed components, by the names of the physics' field (x, "
                          "y, z for linear elasticity; w for scalar laplace), separated by ','; "
                          "empty: all. Ignored for traction and flux (all components).");
        prm.declare_entry("Function",
                          "0",
                          Patterns::Anything(),
                          "One expression of x, y, (z) and t [s] per listed component (all "
                          "components for traction and flux), separated by ';'; a single 0 is "
                          "zero for all.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  FERegion<dim>::parse_parameters(ParameterHandler      &prm,
                                  const PlanarAssumption planar_assumption,
                                  const double           thickness_2d)
  {
    thickness        = (dim == 2 ? thickness_2d : 1.);
    const auto names = parse_names(prm);
    prm.enter_subsection(section);
    mesh_file           = prm.get("Mesh file");
    generator           = prm.get("Generator");
    generator_arguments = prm.get("Generator arguments");
    condition_list.clear();
    // The physics exists without a mesh too (its layout sizes the empty region's vectors).
    const std::string physics_name = prm.get("Physics");
    physics_model = PluginRegistry<FEPhysics<dim>>::create(physics_name, section + "/Physics");
    layout        = physics_model->field_layout();
    // No mesh: no FE region, and nothing else of this section is read.
    if (!has_mesh())
      {
        AssertThrow(names.empty(),
                    ExcMessage("<" + section +
                               "/Boundary conditions/Names> lists FE boundary conditions, but "
                               "there is no FE region: give <" +
                               section + "/Mesh file> or <" + section +
                               "/Generator>, or remove the conditions."));
        prm.leave_subsection();
        return;
      }
    AssertThrow(mesh_file.empty() || std::filesystem::exists(mesh_file),
                ExcMessage("The parameter <" + section + "/Mesh file> = <" + mesh_file +
                           "> names no file (paths are relative to the working directory)."));
    global_refinements = prm.get_integer("Global refinements");
    degree             = prm.get_integer("Polynomial degree");
    density            = prm.get_double("Density");
    physics_model->parse_parameters(prm, planar_assumption);
    // The body force is the problem's (<Body force/Function>), set by set_body_force().
    body_force.reset();

    prm.enter_subsection("Boundary conditions");
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
        // The types of the field's kind (a field of one kind: all of its components).
        const auto        names_of_kind = type_names(layout.kind(0));
        const std::string type          = prm.get("Type");
        const auto        found = std::find(names_of_kind.begin(), names_of_kind.end(), type);
        AssertThrow(found != names_of_kind.end(),
                    ExcMessage("The parameter <" + prefix + "Type> = <" + type +
                               "> is not a condition on the field of <" + section +
                               "/Physics> = <" + physics_name + "> (" + layout.description() +
                               "): accepted values are " + names_of_kind[0] + ", " +
                               names_of_kind[1] + ", " + names_of_kind[2] + "."));
        c.type            = static_cast<Quantity>(found - names_of_kind.begin());
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
    prm.leave_subsection();

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

    // Circular boundaries, checked here so that a typo stops before any work.
    circular_boundaries.clear();
    for (const auto &item : Utilities::split_string_list(prm.get("Circular boundaries"), ';'))
      {
        const auto parts = Utilities::split_string_list(item, ':');
        AssertThrow(parts.size() == 2,
                    ExcMessage("The parameter <" + section + "/Circular boundaries> item <" + item +
                               "> is not of the form 'id: cx, cy'."));
        circular_boundaries.emplace_back(
          static_cast<types::boundary_id>(Utilities::string_to_int(parts[0])),
          ParameterUtilities::parse_point<2>(parts[1], section + "/Circular boundaries"));
      }
    prm.leave_subsection();
  }

  template <int dim>
  void
  FERegion<dim>::set_body_force(const std::shared_ptr<Function<dim>> &function)
  {
    Assert(function->n_components >= layout.n_components(),
           ExcMessage("The body force has fewer components than the field."));
    body_force = function;
  }

  template <int dim>
  void
  FERegion<dim>::make_mesh()
  {
    // No FE region: one cell without FE unknowns (its position does not matter: no particle
    // is looked up in a mesh without unknowns).
    if (!has_mesh())
      GridGenerator::hyper_cube(triangulation);
    else if (!mesh_file.empty())
      {
        GridIn<dim>   grid_in(triangulation);
        std::ifstream in(mesh_file);
        grid_in.read_msh(in);
      }
    else
      {
        try
          {
            GridGenerator::generate_from_name_and_arguments(triangulation,
                                                            generator,
                                                            generator_arguments);
          }
        catch (const std::exception &exc)
          {
            AssertThrow(false,
                        ExcMessage("The mesh generator <" + section + "/Generator> = <" +
                                   generator + "> with <" + section + "/Generator arguments> = <" +
                                   generator_arguments + "> failed: " + exc.what()));
          }
      }
    types::manifold_id manifold = 1;
    for (const auto &[id, centre] : circular_boundaries)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == id)
              face->set_manifold_id(manifold);
        if constexpr (dim == 2)
          triangulation.set_manifold(manifold, PolarManifold<2>(centre));
        else
          triangulation.set_manifold(manifold,
                                     CylindricalManifold<3>(Tensor<1, 3>({0., 0., 1.}),
                                                            Point<3>(centre[0], centre[1], 0.)));
        ++manifold;
      }
    triangulation.refine_global(global_refinements);
  }

  template <int dim>
  void
  FERegion<dim>::setup(const WeightFunction &weight)
  {
    fe_weight = has_mesh() ? weight : [](const Point<dim> &) { return 0.; };
    make_mesh();

    const unsigned int n_components = layout.n_components();
    fe_collection.push_back(FESystem<dim>(FE_Q<dim>(degree), n_components));
    fe_collection.push_back(FESystem<dim>(FE_Nothing<dim>(), n_components));
    if (fe_weight)
      {
        // A cell carries no FE unknowns if the weight vanishes at its vertices and at its
        // quadrature points.
        const QGauss<dim>    quadrature(degree + 1);
        const MappingQ1<dim> mapping;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              bool active = false;
              for (const unsigned int v : cell->vertex_indices())
                active = active || fe_weight(cell->vertex(v)) > 0.;
              for (const auto &q : quadrature.get_points())
                active = active || fe_weight(mapping.transform_unit_to_real_cell(cell, q)) > 0.;
              cell->set_active_fe_index(active ? 0 : 1);
            }
      }
    dof_handler.distribute_dofs(fe_collection);
    // A coupled problem may leave the FE region empty (beta = 1 everywhere): no dofs, empty
    // vectors and matrices, and none of deal.II's dof functions (which require dofs) called.
    const bool has_dofs = dof_handler.n_dofs() > 0;
    owned_dofs          = dof_handler.locally_owned_dofs();
    relevant_dofs       = owned_dofs;
    hanging_constraints.clear();
    if (has_dofs)
      {
        DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
        hanging_constraints.reinit(relevant_dofs);
        DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
      }
    hanging_constraints.close();

    DynamicSparsityPattern dsp(relevant_dofs);
    if (has_dofs)
      {
        DoFTools::make_sparsity_pattern(dof_handler, dsp, hanging_constraints, false);
        SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs, comm, relevant_dofs);
      }
    stiffness.reinit(owned_dofs, owned_dofs, dsp, comm);
    initialize_vector(mass);

    // The prescribed dofs: their condition, component and support point.
    prescribed.assign(owned_dofs.n_elements(), false);
    prescribed_dofs.clear();
    interior_dofs.clear();
    interior_values.clear();
    {
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
    }

    check_conditions_act();
    assemble_matrices();
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
          "<Finite elements/Boundary conditions/" + condition_list[k].name + "/Boundary ids>";
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
  double
  FERegion<dim>::weight(const Point<dim> &p) const
  {
    return fe_weight ? fe_weight(p) : 1.;
  }

  template <int dim>
  bool
  FERegion<dim>::has_mesh() const
  {
    return !mesh_file.empty() || !generator.empty();
  }

  template <int dim>
  types::global_dof_index
  FERegion<dim>::n_dofs() const
  {
    return dof_handler.n_dofs();
  }

  template <int dim>
  bool
  FERegion<dim>::has_hanging_nodes() const
  {
    return Utilities::MPI::sum(hanging_constraints.n_constraints(), comm) > 0;
  }

  template <int dim>
  void
  FERegion<dim>::interpolate(const Function<dim> &function, Vector &vector) const
  {
    Assert(function.n_components >= layout.n_components(),
           ExcMessage("The function has fewer components than the field."));
    if (n_dofs() > 0)
      VectorTools::interpolate(dof_handler,
                               FirstComponents<dim>(function, layout.n_components()),
                               vector);
  }

  template <int dim>
  std::vector<std::vector<bool>>
  FERegion<dim>::component_masks() const
  {
    std::vector<std::vector<bool>> masks(layout.n_components());
    if (n_dofs() > 0)
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(layout.n_components(), true),
                                       masks);
    return masks;
  }

  template <int dim>
  void
  FERegion<dim>::initialize_vector(Vector &vector) const
  {
    // Without FE unknowns there are no ghosts (deal.II's owner lookup divides by the size).
    if (n_dofs() == 0)
      vector.reinit(owned_dofs, comm);
    else
      vector.reinit(owned_dofs, relevant_dofs, comm);
  }

  template <int dim>
  void
  FERegion<dim>::quadrature_weights(const FEValuesBase<dim> &fe_values,
                                    std::vector<double>     &weights) const
  {
    weights.resize(fe_values.n_quadrature_points);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      weights[q] = weight(fe_values.quadrature_point(q)) * thickness * fe_values.JxW(q);
  }

  template <int dim>
  void
  FERegion<dim>::assemble_cell_load(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                    const double                                          time,
                                    FEValues<dim>                                        &fe_values,
                                    FEFaceValues<dim>      &fe_face_values,
                                    dealii::Vector<double> &cell_rhs) const
  {
    const unsigned int n  = fe_values.dofs_per_cell;
    const auto        &fe = fe_values.get_fe();
    cell_rhs              = 0.;
    std::vector<double>    weights;
    dealii::Vector<double> value(layout.n_components());
    if (body_force)
      {
        body_force->set_time(time);
        quadrature_weights(fe_values, weights);
        value.reinit(body_force->n_components);
      }
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        if (!body_force)
          break;
        const double w = weights[q];
        if (w == 0.)
          continue;
        body_force->vector_value(fe_values.quadrature_point(q), value);
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            cell_rhs(i) += value(c) * fe_values.shape_value(i, q) * w;
          }
      }
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        for (const auto &c : condition_list)
          if (c.type == Quantity::load && c.boundary_ids.count(cell->face(f)->boundary_id()) > 0)
            {
              fe_face_values.reinit(cell, f);
              c.function->set_time(time);
              quadrature_weights(fe_face_values, weights);
              value.reinit(c.function->n_components);
              for (const unsigned int q : fe_face_values.quadrature_point_indices())
                {
                  const double w = weights[q];
                  c.function->vector_value(fe_face_values.quadrature_point(q), value);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int comp = fe.system_to_component_index(i).first;
                      cell_rhs(i) += value(comp) * fe_face_values.shape_value(i, q) * w;
                    }
                }
            }
  }

  template <int dim>
  void
  FERegion<dim>::assemble_matrices()
  {
    const auto   &fe = fe_collection[0];
    FEValues<dim> fe_values(fe,
                            QGauss<dim>(degree + 1),
                            update_gradients | update_quadrature_points | update_JxW_values);
    // Nodal (Gauss-Lobatto) quadrature: a diagonal, positive mass for every degree.
    FEValues<dim>                        nodal_values(fe,
                               QGaussLobatto<dim>(degree + 1),
                               update_values | update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    dealii::Vector<double>               cell_mass(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  weights;
    stiffness = 0.;
    mass      = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          fe_values.reinit(cell);
          quadrature_weights(fe_values, weights);
          cell_matrix = 0.;
          physics_model->add_cell_stiffness(fe_values, cell->material_id(), weights, cell_matrix);
          nodal_values.reinit(cell);
          cell_mass = 0.;
          for (const unsigned int q : nodal_values.quadrature_point_indices())
            {
              const double w = weight(nodal_values.quadrature_point(q)) * thickness * density *
                               nodal_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                cell_mass(i) += nodal_values.shape_value(i, q) * w;
            }
          cell->get_dof_indices(dofs);
          hanging_constraints.distribute_local_to_global(cell_matrix, dofs, stiffness);
          hanging_constraints.distribute_local_to_global(cell_mass, dofs, mass);
        }
    stiffness.compress(VectorOperation::add);
    mass.compress(VectorOperation::add);
  }

  template <int dim>
  void
  FERegion<dim>::assemble_load(const double time, Vector &f) const
  {
    const bool has_load = std::any_of(condition_list.begin(),
                                      condition_list.end(),
                                      [](const Condition &c) { return c.type == Quantity::load; });
    if (!body_force && !has_load)
      {
        f = 0.;
        return;
      }
    const auto                          &fe = fe_collection[0];
    FEValues<dim>                        fe_values(fe,
                            QGauss<dim>(degree + 1),
                            update_values | update_quadrature_points | update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     QGauss<dim - 1>(degree + 1),
                                     update_values | update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    dealii::Vector<double>               cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    f = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          fe_values.reinit(cell);
          assemble_cell_load(cell, time, fe_values, fe_face_values, cell_rhs);
          cell->get_dof_indices(dofs);
          hanging_constraints.distribute_local_to_global(cell_rhs, dofs, f);
        }
    f.compress(VectorOperation::add);
  }

  template <int dim>
  void
  FERegion<dim>::prescribe(const double time, Vector &u, Vector &v) const
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
  FERegion<dim>::interior_reactions(const Vector &residual) const
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
  double
  FERegion<dim>::stable_time_step(const Vector *mass_in) const
  {
    const Vector &m = mass_in ? *mass_in : mass;
    // Gershgorin: lambda_max(M^-1 K) <= max_i sum_j |K_ij| / m_i.
    const auto sums  = absolute_row_sums();
    double     bound = 0.;
    for (unsigned int k = 0; k < sums.size(); ++k)
      if (m.local_element(k) > 0.)
        bound = std::max(bound, sums[k] / m.local_element(k));
    bound = Utilities::MPI::max(bound, comm);
    return bound > 0. ? 2. / std::sqrt(bound) : std::numeric_limits<double>::max();
  }

  template <int dim>
  std::vector<double>
  FERegion<dim>::absolute_row_sums(const Vector *x) const
  {
    // Rows read through Epetra views: deal.II's row iterator copies every row.
    const auto         &matrix = stiffness.trilinos_matrix();
    std::vector<double> sums(owned_dofs.n_elements(), 0.);
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n_entries = 0;
        double *values    = nullptr;
        int    *columns   = nullptr;
        matrix.ExtractMyRowView(row, n_entries, values, columns);
        double sum = 0.;
        for (int k = 0; k < n_entries; ++k)
          sum += std::abs(values[k] * (x ? (*x)(matrix.ColMap().GID(columns[k])) : 1.));
        sums[owned_dofs.index_within_set(matrix.RowMap().GID(row))] = sum;
      }
    return sums;
  }

  template <int dim>
  double
  FERegion<dim>::strain_energy(const Vector &u) const
  {
    Vector Ku;
    initialize_vector(Ku);
    stiffness.vmult(Ku, u);
    return 0.5 * (Ku * u);
  }

  template <int dim>
  std::vector<std::vector<double>>
  FERegion<dim>::reactions(const Vector &residual) const
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

  template <int dim>
  void
  FERegion<dim>::write_output(const std::string &directory,
                              const std::string &base_name,
                              const unsigned int step,
                              const double       time,
                              const Vector      &u)
  {
    if (n_dofs() == 0)
      return;
    const auto   derived = physics_model->postprocessor();
    DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    // Only the locally owned cells that carry FE unknowns (not the FE_Nothing ones).
    using CellIterator       = typename Triangulation<dim>::cell_iterator;
    using ActiveCellIterator = typename Triangulation<dim>::active_cell_iterator;
    const auto selected      = [this](const ActiveCellIterator &cell) {
      return cell->is_locally_owned() &&
             typename DoFHandler<dim>::active_cell_iterator(&triangulation,
                                                            cell->level(),
                                                            cell->index(),
                                                            &dof_handler)
                 ->active_fe_index() == 0;
    };
    const auto next_selected = [selected](const Triangulation<dim> &tria, ActiveCellIterator cell) {
      while (cell != tria.end() && !selected(cell))
        ++cell;
      return cell == tria.end() ? tria.end() : CellIterator(cell);
    };
    data_out.set_cell_selection(
      [next_selected](const Triangulation<dim> &tria) {
        return next_selected(tria, tria.begin_active());
      },
      [next_selected](const Triangulation<dim> &tria, const CellIterator &cell) {
        ActiveCellIterator next(cell);
        return next_selected(tria, ++next);
      });
    // The translations as the vector 'displacement', every other component by its name.
    std::vector<std::string>                                              names;
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation;
    for (unsigned int c = 0; c < layout.n_components(); ++c)
      {
        const bool translation = layout.kind(c) == ComponentKind::translation;
        names.push_back(translation ? "displacement" : layout.name(c));
        interpretation.push_back(translation ?
                                   DataComponentInterpretation::component_is_part_of_vector :
                                   DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(u, names, DataOut<dim>::type_dof_data, interpretation);
    data_out.add_data_vector(u, *derived);
    data_out.build_patches();
    write_hdf5_xdmf_step(data_out,
                         !data_out.get_patches().empty(),
                         true,
                         comm,
                         directory,
                         base_name,
                         step,
                         time,
                         xdmf_entries);
  }

  template <int dim>
  std::string
  FERegion<dim>::summary() const
  {
    if (!has_mesh())
      return "FE region: none";
    std::ostringstream out;
    const auto         n_active = Utilities::MPI::sum<std::uint64_t>(
      [&] {
        std::uint64_t count = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && cell->active_fe_index() == 0)
            ++count;
        return count;
      }(),
      comm);
    out << "FE region: " << triangulation.n_global_active_cells() << " cells (" << n_active
        << " with FE_Q(" << degree << ")";
    if (layout.n_components() > 1)
      out << "^" << layout.n_components();
    out << "), " << dof_handler.n_dofs() << " dofs; " << physics_model->summary()
        << ", rho = " << density << " kg/m^3";
    return out.str();
  }

  template <int dim>
  const parallel::distributed::Triangulation<dim> &
  FERegion<dim>::get_triangulation() const
  {
    return triangulation;
  }

  template <int dim>
  const DoFHandler<dim> &
  FERegion<dim>::get_dof_handler() const
  {
    return dof_handler;
  }

  template <int dim>
  const hp::FECollection<dim> &
  FERegion<dim>::get_fe_collection() const
  {
    return fe_collection;
  }

  template <int dim>
  const SparseMatrix &
  FERegion<dim>::stiffness_matrix() const
  {
    return stiffness;
  }

  template <int dim>
  const Vector &
  FERegion<dim>::lumped_mass() const
  {
    return mass;
  }

  template <int dim>
  const FEPhysics<dim> &
  FERegion<dim>::physics() const
  {
    return *physics_model;
  }

  template <int dim>
  const FieldLayout &
  FERegion<dim>::field_layout() const
  {
    return layout;
  }

  template <int dim>
  double
  FERegion<dim>::get_density() const
  {
    return density;
  }

  template <int dim>
  const std::vector<typename FERegion<dim>::Condition> &
  FERegion<dim>::conditions() const
  {
    return condition_list;
  }

  template class FERegion<2>;
  template class FERegion<3>;
} // namespace perideal
