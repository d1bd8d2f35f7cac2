// Helpers of the FE thermal-strain tests (tests/fem/thermal_strain_*): a linear-elasticity FE
// region with a temperature change, rigid motions held at three vertices, the static solve
// K u = f_th with a direct solver, and the derived quantities of the output at Gauss points.
#ifndef perideal_thermal_strain_tests_h
#define perideal_thermal_strain_tests_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <perideal/base/elasticity.h>
#include <perideal/fem/fe_region.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace thermal_strain_tests
{
  using FEVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /**
   * A 'linear elasticity' FE region (thickness 1 in 2D) from the lines @p text inside
   * <Finite elements> (mesh, degree, <Elasticity>, <Boundary conditions> named @p conditions),
   * set up, with the temperature change @p delta_T(x) [K] (an expression in x, y(, z)).
   * @p material: lines of a particles' block <Material> (its <Model> and the elastic entries of
   * <Material/anisotropic bond based>), which <Same material as the particles> reads.
   */
  template <int dim>
  std::unique_ptr<perideal::FERegion<dim>>
  make_region(const std::string               &text,
              const std::vector<std::string>  &conditions,
              const perideal::PlanarAssumption planar,
              const std::string               &delta_T,
              const std::string               &material = "")
  {
    dealii::ParameterHandler prm;
    perideal::FERegion<dim>::declare_parameters(prm, conditions);
    prm.enter_subsection("Material");
    prm.declare_entry("Model", "anisotropic bond based", dealii::Patterns::Anything());
    prm.enter_subsection("anisotropic bond based");
    perideal::ElasticMaterial::declare_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Finite elements\n" + text + "end\n" + material);
    auto fe = std::make_unique<perideal::FERegion<dim>>(MPI_COMM_WORLD);
    fe->parse_parameters(prm, planar, 1.);
    fe->setup();
    auto function = std::make_shared<dealii::FunctionParser<dim>>(1);
    function->initialize(dim == 2 ? "x,y" : "x,y,z", delta_T, {});
    fe->set_temperature_change(
      [function](const dealii::FEValues<dim> &fe_values, const double, std::vector<double> &dT) {
        for (const unsigned int q : fe_values.quadrature_point_indices())
          dT[q] = function->value(fe_values.quadrature_point(q));
      });
    return fe;
  }

  /// Points and the components of u held at 0 there.
  template <int dim>
  using Supports = std::vector<std::pair<dealii::Point<dim>, std::vector<unsigned int>>>;

  /**
   * The least supports of a free body: u = 0 at the origin, u_y (and u_z) at (@p length, 0(, 0)),
   * u_z at (0, @p length, 0).
   */
  template <int dim>
  Supports<dim>
  free_body_supports(const double length)
  {
    const auto e = [length](const unsigned int i) {
      return length * dealii::Point<dim>::unit_vector(i);
    };
    if (dim == 2)
      return {{dealii::Point<dim>(), {0, 1}}, {e(0), {1}}};
    return {{dealii::Point<dim>(), {0, 1, 2}}, {e(0), {1, 2}}, {e(1), {2}}};
  }

  /**
   * Hold the components of u at the vertices of @p supports at 0
   * (FERegion::set_interior_values()); a vertex matches within 1e-9 of @p length.
   */
  template <int dim>
  void
  hold(perideal::FERegion<dim> &fe, const Supports<dim> &supports, const double length)
  {
    std::vector<dealii::types::global_dof_index> local, dofs;
    unsigned int                                 n_held = 0;
    for (const auto &support : supports)
      n_held += support.second.size();
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (const auto &[point, components] : supports)
            if (cell->vertex(v).distance(point) < 1e-9 * length)
              for (const unsigned int c : components)
                local.push_back(cell->vertex_dof_index(v, c));
    for (const auto &part : dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      dofs.insert(dofs.end(), part.begin(), part.end());
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    AssertThrow(dofs.size() == n_held, dealii::ExcInternalError());
    fe.set_interior_values(dofs, std::vector<double>(dofs.size(), 0.));
  }

  /**
   * Solve K u = @p rhs with the prescribed dofs (conditions and interior values at time 0)
   * held, by a direct solver (KLU); return u with ghost values.
   */
  template <int dim>
  FEVector
  solve(const perideal::FERegion<dim> &fe, const FEVector &rhs)
  {
    FEVector g, v, Kg, z, b;
    for (FEVector *x : {&g, &v, &Kg, &z, &b})
      fe.initialize_vector(*x);
    fe.prescribe(0., g, v);
    fe.stiffness_matrix().vmult(Kg, g);
    b = rhs;
    b -= Kg;
    const auto                                  &mask  = fe.prescribed_mask();
    const auto                                  &owned = fe.get_dof_handler().locally_owned_dofs();
    std::vector<dealii::types::global_dof_index> rows;
    for (unsigned int k = 0; k < mask.size(); ++k)
      if (mask[k])
        {
          rows.push_back(owned.nth_index_in_set(k));
          b.local_element(k) = 0.;
        }
    perideal::SparseMatrix A;
    A.copy_from(fe.stiffness_matrix());
    A.clear_rows(rows, 1.);
    dealii::SolverControl                  control(1, 0., false, false);
    dealii::TrilinosWrappers::SolverDirect direct(control);
    direct.solve(A, z, b);
    FEVector u = g;
    u += z;
    u.update_ghost_values();
    return u;
  }

  /**
   * The energy of the mechanical strain, 1/2 u.K.u - u.f_th + c_th (FERegion::
   * assemble_thermal_load()), of @p u (ghosted) at time 0.
   */
  template <int dim>
  double
  mechanical_energy(const perideal::FERegion<dim> &fe, const FEVector &u)
  {
    FEVector f_th;
    fe.initialize_vector(f_th);
    const double c_th = fe.assemble_thermal_load(0., f_th);
    return fe.strain_energy(u) - (u * f_th) + c_th;
  }

  /**
   * The largest |d_k - @p expected.at(name_k)| over the Gauss points of the owned cells and the
   * output quantities name_k of @p expected, d the derived quantities of the output
   * (FEPhysics::thermal_postprocessor() with FERegion::point_temperature_change() at time 0)
   * of the displacement @p u (ghosted). Collective.
   */
  template <int dim>
  double
  output_deviation(const perideal::FERegion<dim>       &fe,
                   const FEVector                      &u,
                   const std::map<std::string, double> &expected)
  {
    const auto  output  = fe.physics().thermal_postprocessor(fe.point_temperature_change(0.));
    const auto  names   = output->get_names();
    const auto &element = fe.get_fe_collection()[0];
    const dealii::QGauss<dim> quadrature(element.degree + 1);
    dealii::FEValues<dim>     values(element,
                                 quadrature,
                                 dealii::update_gradients | dealii::update_quadrature_points);
    double                    largest = 0.;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell);
          dealii::DataPostprocessorInputs::Vector<dim> inputs;
          inputs.solution_gradients.assign(quadrature.size(),
                                           std::vector<dealii::Tensor<1, dim>>(dim));
          values.get_function_gradients(u, inputs.solution_gradients);
          inputs.evaluation_points = values.get_quadrature_points();
          inputs.template set_cell<dim>(cell);
          std::vector<dealii::Vector<double>> computed(quadrature.size(),
                                                       dealii::Vector<double>(names.size()));
          output->evaluate_vector_field(inputs, computed);
          for (const auto &d : computed)
            for (unsigned int k = 0; k < names.size(); ++k)
              if (expected.count(names[k]) > 0)
                largest = std::max(largest, std::abs(d[k] - expected.at(names[k])));
        }
    return dealii::Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }

  /// "below <bound>" if @p value is, else the value with 3 digits.
  inline std::string
  bounded(const double value, const double bound)
  {
    std::ostringstream out;
    out.precision(3);
    if (std::abs(value) < bound)
      out << "below " << bound;
    else
      out << value;
    return out.str();
  }
} // namespace thermal_strain_tests

#endif
