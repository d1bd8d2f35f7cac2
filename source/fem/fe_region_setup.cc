// ---------------------------------------------------------------------
// PeriDeal: the set-up of the finite-element region: the mesh (generator or gmsh file, circular
// boundaries), the FE_Nothing activation of the cells where the FE weight vanishes, the dofs,
// the hanging-node constraints and the sparsity; the vectors and the dof queries built on them.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/base/setup_times.h>
#include <perideal/fem/fe_region.h>

#include <fstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
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
  } // namespace

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
    const SetupTimes::Scope time(SetupStage::fe_assembly);
    make_mesh();
    check_held_point();

    const unsigned int n_components = layout.n_components();
    fe_collection.push_back(FESystem<dim>(FE_Q<dim>(degree), n_components));
    fe_collection.push_back(FESystem<dim>(FE_Nothing<dim>(), n_components));
    distribute(weight);
  }

  template <int dim>
  void
  FERegion<dim>::reweight(const WeightFunction &weight)
  {
    Assert(has_mesh() && fe_collection.size() == 2, ExcMessage("Call setup() first."));
    const SetupTimes::Scope time(SetupStage::fe_assembly);
    distribute(weight);
  }

  template <int dim>
  void
  FERegion<dim>::distribute(const WeightFunction &weight)
  {
    fe_weight = has_mesh() ? weight : [](const Point<dim> &) { return 0.; };
    if (fe_weight)
      {
        // A cell carries no FE unknowns if the weight vanishes at its quadrature points
        // (where its stiffness and mass are integrated).
        const QGauss<dim>    quadrature(degree + 1);
        const MappingQ1<dim> mapping;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              bool active = false;
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

    locate_prescribed_dofs();
    check_conditions_act();
    assemble_matrices();
  }

  template <int dim>
  bool
  FERegion<dim>::has_hanging_nodes() const
  {
    return Utilities::MPI::sum(hanging_constraints.n_constraints(), comm) > 0;
  }

  template <int dim>
  void
  FERegion<dim>::interpolate(const Function<dim> &function, FEVector &vector) const
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
  FERegion<dim>::initialize_vector(FEVector &vector) const
  {
    // Without FE unknowns there are no ghosts (deal.II's owner lookup divides by the size).
    if (n_dofs() == 0)
      vector.reinit(owned_dofs, comm);
    else
      vector.reinit(owned_dofs, relevant_dofs, comm);
  }

  // The members defined in this file (the class is instantiated in fe_region.cc).
#define PERIDEAL_INSTANTIATE(dim)                                                    \
  template void FERegion<dim>::setup(const WeightFunction &);                        \
  template void FERegion<dim>::reweight(const WeightFunction &);                     \
  template void FERegion<dim>::distribute(const WeightFunction &);                   \
  template bool FERegion<dim>::has_hanging_nodes() const;                            \
  template void FERegion<dim>::interpolate(const Function<dim> &, FEVector &) const; \
  template std::vector<std::vector<bool>> FERegion<dim>::component_masks() const;    \
  template void                           FERegion<dim>::initialize_vector(FEVector &) const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
