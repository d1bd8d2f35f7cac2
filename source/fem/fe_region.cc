// ---------------------------------------------------------------------
// PeriDeal: the finite-element region: its parameters (mesh, degree, density, physics), the
// body force, and what it answers about itself. The algorithms are in their own files:
// fe_region_setup.cc (mesh, FE_Nothing activation, dofs), fe_region_assembly.cc (stiffness,
// lumped mass, loads, stable step), fe_region_thermal.cc (the thermal strain's load and energy),
// fe_region_conditions.cc (boundary conditions, interior values, reactions) and
// fe_region_output.cc (summary and field output).
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/fem/fe_region.h>

#include <filesystem>

namespace perideal
{
  using namespace dealii;

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
    prm.leave_subsection();
    declare_condition_names(prm);
  }

  template <int dim>
  void
  FERegion<dim>::declare_condition_names(ParameterHandler &prm)
  {
    prm.enter_subsection(section);
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
    prm.leave_subsection();
    declare_physics_entries(prm, condition_names);
  }

  template <int dim>
  void
  FERegion<dim>::declare_physics_parameters(ParameterHandler               &prm,
                                            const std::vector<std::string> &condition_names)
  {
    declare_condition_names(prm);
    declare_physics_entries(prm, condition_names);
  }

  template <int dim>
  void
  FERegion<dim>::declare_physics_entries(ParameterHandler               &prm,
                                         const std::vector<std::string> &condition_names)
  {
    prm.enter_subsection(section);
    prm.declare_entry("Density",
                      "0",
                      Patterns::Double(0.),
                      "Mass density rho [kg/m^3] (the inertia of every component; with <Physics> "
                      "= heat, times <heat/Specific heat>, the heat capacity rho c).");
    using Registry = PluginRegistry<FEPhysics<dim>>;
    prm.declare_entry("Physics",
                      "linear elasticity",
                      Patterns::Selection(Registry::pattern_string()),
                      "The equation of the FE region and its unknowns: " +
                        Registry::documentation() + "Each physics reads its own subsection.");
    for (const auto &name : Utilities::split_string_list(Registry::pattern_string(), '|'))
      Registry::create(name, section + "/Physics")->declare_parameters(prm);
    prm.enter_subsection("Boundary conditions");
    declare_condition_parameters(prm, condition_names);
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
    planar              = planar_assumption;
    // No mesh: no FE region, and nothing else of this section is read but the physics (its
    // layout sizes the empty region's vectors).
    if (!has_mesh())
      {
        prm.leave_subsection();
        parse_physics(prm, names);
        return;
      }
    AssertThrow(mesh_file.empty() || std::filesystem::exists(mesh_file),
                ExcMessage("The parameter <" + section + "/Mesh file> = <" + mesh_file +
                           "> names no file (paths are relative to the working directory)."));
    global_refinements = prm.get_integer("Global refinements");
    degree             = prm.get_integer("Polynomial degree");
    prm.leave_subsection();
    parse_physics(prm, names);
    prm.enter_subsection(section);
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
  FERegion<dim>::parse_physics_parameters(ParameterHandler &prm, const FERegion<dim> &geometry)
  {
    thickness           = geometry.thickness;
    planar              = geometry.planar;
    mesh_file           = geometry.mesh_file;
    generator           = geometry.generator;
    generator_arguments = geometry.generator_arguments;
    global_refinements  = geometry.global_refinements;
    degree              = geometry.degree;
    circular_boundaries = geometry.circular_boundaries;
    parse_physics(prm, parse_names(prm));
  }

  template <int dim>
  void
  FERegion<dim>::parse_physics(ParameterHandler &prm, const std::vector<std::string> &names)
  {
    prm.enter_subsection(section);
    condition_list.clear();
    const std::string physics_name = prm.get("Physics");
    physics_model = PluginRegistry<FEPhysics<dim>>::create(physics_name, section + "/Physics");
    layout        = physics_model->field_layout();
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
    density = prm.get_double("Density");
    physics_model->parse_parameters(prm, planar);
    // The body force is the problem's (<Body force/Function>), set by set_body_force().
    body_force.reset();
    prm.enter_subsection("Boundary conditions");
    parse_conditions(prm, names, physics_name);
    prm.leave_subsection();
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
  const FEVector &
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

  // The members defined in this file; the others are instantiated in the files that define
  // them.
  template class FERegion<2>;
  template class FERegion<3>;
} // namespace perideal
