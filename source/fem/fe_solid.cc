// ---------------------------------------------------------------------
// PeriDeal: the finite-element region, linear elasticity on a distributed mesh.
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
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/base/hdf5_xdmf_writer.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/fem/fe_solid.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace perideal
{
  using namespace dealii;
  using Vector = LinearAlgebra::distributed::Vector<double>;

  namespace
  {
    const std::string section = "Finite elements";

    // A dim-component function that is g_k on component components[k] and 0 elsewhere.
    template <int dim>
    class ComponentFunction : public Function<dim>
    {
    public:
      ComponentFunction(const Function<dim> &g, const std::vector<unsigned int> &components)
        : Function<dim>(dim)
        , g(g)
        , components(components)
      {}

      double
      value(const Point<dim> &p, const unsigned int c) const override
      {
        for (unsigned int k = 0; k < components.size(); ++k)
          if (components[k] == c)
            return g.value(p, k);
        return 0.;
      }

    private:
      const Function<dim>             &g;
      const std::vector<unsigned int> &components;
    };

    // Strain, stress and von Mises stress from the displacement gradient.
    template <int dim>
    class StressPostprocessor : public DataPostprocessor<dim>
    {
    public:
      StressPostprocessor(const SymmetricTensor<4, dim> &C,
                          const FullMatrix<double>      &voigt,
                          const PlanarAssumption         planar)
        : C(C)
        , voigt(voigt)
        , planar(planar)
      {}

      std::vector<std::string>
      get_names() const override
      {
        std::vector<std::string> names;
        const char               axes[] = {'x', 'y', 'z'};
        for (const std::string quantity : {"strain", "stress"})
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              names.push_back(quantity + "_" + axes[i] + axes[j]);
        if (dim == 2)
          names.push_back("stress_zz");
        names.push_back("von_mises_stress");
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          get_names().size(),
          DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags
      get_needed_update_flags() const override
      {
        return update_gradients;
      }

      void
      evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                            std::vector<dealii::Vector<double>>        &computed) const override
      {
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            Tensor<2, dim> grad;
            for (unsigned int c = 0; c < dim; ++c)
              grad[c] = inputs.solution_gradients[q][c];
            const SymmetricTensor<2, dim> eps   = symmetrize(grad);
            const SymmetricTensor<2, dim> sigma = C * eps;
            unsigned int                  k     = 0;
            for (const auto *t : {&eps, &sigma})
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = i; j < dim; ++j)
                  computed[q][k++] = (*t)[i][j];
            // The out-of-plane stress: 0 in plane stress, C_33kl eps_kl in plane strain.
            double s33 = 0.;
            if (dim == 2 && planar == PlanarAssumption::plane_strain)
              s33 = voigt(2, 0) * eps[0][0] + voigt(2, 1) * eps[1][1] +
                    voigt(2, 5) * 2. * eps[0][dim - 1];
            if (dim == 2)
              computed[q][k++] = s33;
            SymmetricTensor<2, 3> s3;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                s3[i][j] = sigma[i][j];
            if (dim == 2)
              s3[2][2] = s33;
            const SymmetricTensor<2, 3> dev = deviator(s3);
            computed[q][k++]                = std::sqrt(1.5 * (dev * dev));
          }
      }

    private:
      const SymmetricTensor<4, dim> C;
      const FullMatrix<double>      voigt;
      const PlanarAssumption        planar;
    };
  } // namespace

  template <int dim>
  FESolid<dim>::FESolid(const MPI_Comm comm)
    : comm(comm)
    , triangulation(comm)
    , dof_handler(triangulation)
  {}

  template <int dim>
  void
  FESolid<dim>::declare_names(ParameterHandler &prm)
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
  FESolid<dim>::parse_names(ParameterHandler &prm)
  {
    prm.enter_subsection(section);
    const auto names = ParameterUtilities::parse_name_list(prm, "Boundary conditions");
    prm.leave_subsection();
    return names;
  }

  template <int dim>
  void
  FESolid<dim>::declare_parameters(ParameterHandler               &prm,
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
                      "Degree p of the FE_Q(p) displacement elements.");
    prm.declare_entry("Density", "0", Patterns::Double(0.), "Mass density rho [kg/m^3].");
    prm.enter_subsection("Elasticity");
    ElasticMaterial::declare_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : condition_names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Boundary ids",
                          "",
                          Patterns::List(Patterns::Integer(0, 254)),
                          "The boundary ids (gmsh physical groups or generator ids) it acts on.");
        prm.declare_entry("Type",
                          "displacement",
                          Patterns::Selection("displacement|velocity|traction"),
                          "'displacement' [m] or 'velocity' [m/s, explicit dynamics only] of the "
                          "listed components, or 'traction' [Pa] (all components).");
        ParameterUtilities::declare_prescribed_components<dim>(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  FESolid<dim>::parse_parameters(ParameterHandler      &prm,
                                 const PlanarAssumption planar_assumption,
                                 const double           thickness_2d)
  {
    planar           = planar_assumption;
    thickness        = (dim == 2 ? thickness_2d : 1.);
    const auto names = parse_names(prm);
    prm.enter_subsection(section);
    mesh_file           = prm.get("Mesh file");
    generator           = prm.get("Generator");
    generator_arguments = prm.get("Generator arguments");
    condition_list.clear();
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
    prm.enter_subsection("Elasticity");
    material.parse_parameters(prm, section + "/Elasticity");
    prm.leave_subsection();
    C = material.tensor<dim>(planar);
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
        const std::string type = prm.get("Type");
        c.type                 = (type == "displacement" ? ConditionType::displacement :
                                  type == "velocity"     ? ConditionType::velocity :
                                                           ConditionType::traction);
        if (c.type == ConditionType::traction)
          for (unsigned int d = 0; d < dim; ++d)
            c.components.push_back(d);
        else
          c.components = ParameterUtilities::parse_components(prm);
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
          if (ca.type == ConditionType::traction || cb.type == ConditionType::traction)
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
  FESolid<dim>::set_body_force(const std::shared_ptr<Function<dim>> &function)
  {
    AssertDimension(function->n_components, dim);
    body_force = function;
  }

  template <int dim>
  void
  FESolid<dim>::make_mesh()
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
  FESolid<dim>::setup(const WeightFunction &weight)
  {
    fe_weight = has_mesh() ? weight : [](const Point<dim> &) { return 0.; };
    make_mesh();

    fe_collection.push_back(FESystem<dim>(FE_Q<dim>(degree), dim));
    fe_collection.push_back(FESystem<dim>(FE_Nothing<dim>(), dim));
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
    system_matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
    initialize_vector(mass);
    initialize_vector(displacement);

    // The prescribed dofs: their condition, component and support point.
    prescribed.assign(owned_dofs.n_elements(), false);
    prescribed_dofs.clear();
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
                  if (c.type == ConditionType::traction ||
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
  FESolid<dim>::check_conditions_act() const
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
  FESolid<dim>::weight(const Point<dim> &p) const
  {
    return fe_weight ? fe_weight(p) : 1.;
  }

  template <int dim>
  bool
  FESolid<dim>::has_mesh() const
  {
    return !mesh_file.empty() || !generator.empty();
  }

  template <int dim>
  types::global_dof_index
  FESolid<dim>::n_dofs() const
  {
    return dof_handler.n_dofs();
  }

  template <int dim>
  bool
  FESolid<dim>::has_hanging_nodes() const
  {
    return Utilities::MPI::sum(hanging_constraints.n_constraints(), comm) > 0;
  }

  template <int dim>
  void
  FESolid<dim>::interpolate(const Function<dim> &function, Vector &vector) const
  {
    if (n_dofs() > 0)
      VectorTools::interpolate(dof_handler, function, vector);
  }

  template <int dim>
  std::vector<std::vector<bool>>
  FESolid<dim>::component_masks() const
  {
    std::vector<std::vector<bool>> masks(dim);
    if (n_dofs() > 0)
      DoFTools::extract_constant_modes(dof_handler, ComponentMask(dim, true), masks);
    return masks;
  }

  template <int dim>
  void
  FESolid<dim>::initialize_vector(Vector &vector) const
  {
    // Without FE unknowns there are no ghosts (deal.II's owner lookup divides by the size).
    if (n_dofs() == 0)
      vector.reinit(owned_dofs, comm);
    else
      vector.reinit(owned_dofs, relevant_dofs, comm);
  }

  template <int dim>
  void
  FESolid<dim>::assemble_cell_matrix(FEValues<dim>      &fe_values,
                                     FullMatrix<double> &cell_matrix) const
  {
    const unsigned int                   n = fe_values.dofs_per_cell;
    const FEValuesExtractors::Vector     displacements(0);
    std::vector<SymmetricTensor<2, dim>> eps(n);
    cell_matrix = 0.;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double w = weight(fe_values.quadrature_point(q)) * thickness * fe_values.JxW(q);
        if (w == 0.)
          continue;
        for (unsigned int i = 0; i < n; ++i)
          eps[i] = fe_values[displacements].symmetric_gradient(i, q);
        for (unsigned int i = 0; i < n; ++i)
          {
            const SymmetricTensor<2, dim> C_eps = C * eps[i];
            for (unsigned int j = i; j < n; ++j)
              cell_matrix(i, j) += (C_eps * eps[j]) * w;
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < i; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
  }

  template <int dim>
  void
  FESolid<dim>::assemble_cell_load(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                   const double                                          time,
                                   FEValues<dim>                                        &fe_values,
                                   FEFaceValues<dim>      &fe_face_values,
                                   dealii::Vector<double> &cell_rhs) const
  {
    const unsigned int n  = fe_values.dofs_per_cell;
    const auto        &fe = fe_values.get_fe();
    cell_rhs              = 0.;
    dealii::Vector<double> value(dim);
    if (body_force)
      body_force->set_time(time);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        if (!body_force)
          break;
        const Point<dim> &x = fe_values.quadrature_point(q);
        const double      w = weight(x) * thickness * fe_values.JxW(q);
        if (w == 0.)
          continue;
        body_force->vector_value(x, value);
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            cell_rhs(i) += value(c) * fe_values.shape_value(i, q) * w;
          }
      }
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary())
        for (const auto &c : condition_list)
          if (c.type == ConditionType::traction &&
              c.boundary_ids.count(cell->face(f)->boundary_id()) > 0)
            {
              fe_face_values.reinit(cell, f);
              c.function->set_time(time);
              for (const unsigned int q : fe_face_values.quadrature_point_indices())
                {
                  const Point<dim> &x = fe_face_values.quadrature_point(q);
                  const double      w = weight(x) * thickness * fe_face_values.JxW(q);
                  c.function->vector_value(x, value);
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
  FESolid<dim>::assemble_matrices()
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
    stiffness = 0.;
    mass      = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          fe_values.reinit(cell);
          assemble_cell_matrix(fe_values, cell_matrix);
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
  FESolid<dim>::assemble_load(const double time, Vector &f) const
  {
    const bool has_traction =
      std::any_of(condition_list.begin(), condition_list.end(), [](const Condition &c) {
        return c.type == ConditionType::traction;
      });
    if (!body_force && !has_traction)
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
  FESolid<dim>::make_constraints(const double time, AffineConstraints<double> &constraints) const
  {
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (const auto &c : condition_list)
      if (c.type == ConditionType::displacement)
        {
          c.function->set_time(time);
          const ComponentFunction<dim> g(*c.function, c.components);
          std::vector<bool>            mask(dim, false);
          for (const unsigned int comp : c.components)
            mask[comp] = true;
          for (const auto id : c.boundary_ids)
            VectorTools::interpolate_boundary_values(dof_handler,
                                                     id,
                                                     g,
                                                     constraints,
                                                     ComponentMask(mask));
        }
    constraints.close();
  }

  template <int dim>
  unsigned int
  FESolid<dim>::solve_static(const double time, const double tolerance)
  {
    for (const auto &c : condition_list)
      AssertThrow(c.type != ConditionType::velocity,
                  ExcMessage("The FE boundary condition <" + c.name +
                             "> is of type 'velocity', which only explicit dynamics accepts; use "
                             "'displacement' for a static solve."));
    AffineConstraints<double> constraints;
    make_constraints(time, constraints);

    const auto                          &fe = fe_collection[0];
    FEValues<dim>                        fe_values(fe,
                            QGauss<dim>(degree + 1),
                            update_values | update_gradients | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim>                    fe_face_values(fe,
                                     QGauss<dim - 1>(degree + 1),
                                     update_values | update_quadrature_points | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    dealii::Vector<double>               cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    Vector                               rhs, u;
    initialize_vector(rhs);
    initialize_vector(u);
    system_matrix = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == 0)
        {
          fe_values.reinit(cell);
          assemble_cell_matrix(fe_values, cell_matrix);
          assemble_cell_load(cell, time, fe_values, fe_face_values, cell_rhs);
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, system_matrix, rhs);
        }
    system_matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);

    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.constant_modes        = component_masks();
    amg_data.elliptic              = true;
    amg_data.higher_order_elements = degree > 1;
    amg_data.smoother_sweeps       = 2;
    amg_data.aggregation_threshold = 0.02;
    amg.initialize(system_matrix, amg_data);

    const double     rhs_norm = rhs.l2_norm();
    SolverControl    control(10000, tolerance * std::max(rhs_norm, 1e-300));
    SolverCG<Vector> cg(control);
    if (rhs_norm > 0.)
      {
        try
          {
            cg.solve(system_matrix, u, rhs, amg);
          }
        catch (const SolverControl::NoConvergence &exc)
          {
            AssertThrow(false,
                        ExcMessage("The FE static solve did not converge: residual " +
                                   ParameterUtilities::format_number(exc.last_residual) +
                                   " after " + std::to_string(exc.last_step) +
                                   " CG iterations (target " +
                                   ParameterUtilities::format_number(control.tolerance()) +
                                   "). Is every rigid motion constrained by the displacement "
                                   "conditions in <" +
                                   section + "/Boundary conditions>?"));
          }
      }
    constraints.distribute(u);
    displacement = u;
    displacement.update_ghost_values();
    return control.last_step();
  }

  template <int dim>
  void
  FESolid<dim>::prescribe(const double time, Vector &u, Vector &v) const
  {
    for (const auto &c : condition_list)
      c.function->set_time(time);
    for (const auto &d : prescribed_dofs)
      {
        const Condition &c     = condition_list[d.condition];
        const double     value = c.function->value(d.support_point, d.function_component);
        if (c.type == ConditionType::displacement)
          u.local_element(d.local_index) = value;
        else
          v.local_element(d.local_index) = value;
      }
  }

  template <int dim>
  const std::vector<bool> &
  FESolid<dim>::prescribed_mask() const
  {
    return prescribed;
  }

  template <int dim>
  double
  FESolid<dim>::stable_time_step(const Vector *mass_in) const
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
  FESolid<dim>::absolute_row_sums(const Vector *x) const
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
  FESolid<dim>::strain_energy(const Vector &u) const
  {
    Vector Ku;
    initialize_vector(Ku);
    stiffness.vmult(Ku, u);
    return 0.5 * (Ku * u);
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  FESolid<dim>::reactions(const Vector &residual) const
  {
    std::vector<Tensor<1, dim>> result(condition_list.size());
    for (const auto &d : prescribed_dofs)
      {
        const unsigned int comp = condition_list[d.condition].components[d.function_component];
        result[d.condition][comp] += residual.local_element(d.local_index);
      }
    for (auto &r : result)
      r = Utilities::MPI::sum(r, comm);
    return result;
  }

  template <int dim>
  void
  FESolid<dim>::write_output(const std::string &directory,
                             const std::string &base_name,
                             const unsigned int step,
                             const double       time,
                             const Vector      &u)
  {
    if (n_dofs() == 0)
      return;
    const StressPostprocessor<dim> stress(C, material.voigt_stiffness(), planar);
    DataOut<dim>                   data_out;
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
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> vector(
      dim,
      DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(u,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data,
                             vector);
    data_out.add_data_vector(u, stress);
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
  FESolid<dim>::summary() const
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
        << " with FE_Q(" << degree << ")^" << dim << "), " << dof_handler.n_dofs()
        << " dofs; material " << material.summary() << ", rho = " << density << " kg/m^3";
    return out.str();
  }

  template <int dim>
  const parallel::distributed::Triangulation<dim> &
  FESolid<dim>::get_triangulation() const
  {
    return triangulation;
  }

  template <int dim>
  const DoFHandler<dim> &
  FESolid<dim>::get_dof_handler() const
  {
    return dof_handler;
  }

  template <int dim>
  const hp::FECollection<dim> &
  FESolid<dim>::get_fe_collection() const
  {
    return fe_collection;
  }

  template <int dim>
  const SparseMatrix &
  FESolid<dim>::stiffness_matrix() const
  {
    return stiffness;
  }

  template <int dim>
  const Vector &
  FESolid<dim>::lumped_mass() const
  {
    return mass;
  }

  template <int dim>
  const Vector &
  FESolid<dim>::solution() const
  {
    return displacement;
  }

  template <int dim>
  const SymmetricTensor<4, dim> &
  FESolid<dim>::elasticity_tensor() const
  {
    return C;
  }

  template <int dim>
  double
  FESolid<dim>::get_density() const
  {
    return density;
  }

  template <int dim>
  const std::vector<typename FESolid<dim>::Condition> &
  FESolid<dim>::conditions() const
  {
    return condition_list;
  }

  template <int dim>
  FieldLayout
  FESolid<dim>::field_layout() const
  {
    return FieldLayout::displacement(dim);
  }

  template class FESolid<2>;
  template class FESolid<3>;
} // namespace perideal
