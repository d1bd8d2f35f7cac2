// Helpers shared by the tests in tests/fem: FE problems run through the problem's static path.
#ifndef perideal_fem_tests_h
#define perideal_fem_tests_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/boundary_conditions.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace fem_tests
{
  /**
   * Declare and read the parameters in @p text (a .prm's content) and hand them to
   * @p problem, as perideal-solid does: a first pass reads the names of the regions and of the
   * particle and FE boundary conditions, which decide the subsections.
   */
  template <int dim>
  void
  parse_problem(perideal::CoupledProblem<dim> &problem, const std::string &text)
  {
    dealii::ParameterHandler first;
    perideal::RegionCollection<dim>::declare_names(first);
    perideal::BoundaryConditions<dim>::declare_names(first);
    perideal::FERegion<dim>::declare_names(first);
    first.parse_input_from_string(text, "", /*skip_undefined=*/true);
    dealii::ParameterHandler prm;
    perideal::CoupledProblem<dim>::declare_parameters(
      prm,
      perideal::RegionCollection<dim>::parse_names(first),
      perideal::BoundaryConditions<dim>::parse_names(first),
      perideal::FERegion<dim>::parse_names(first));
    prm.parse_input_from_string(text);
    problem.parse_parameters(prm);
  }

  /**
   * Run the problem in @p text on @p problem (declared by the caller, with a log stream that
   * may be discarded) and return its FE solution with ghost values.
   */
  template <int dim>
  dealii::LinearAlgebra::distributed::Vector<double>
  solve(perideal::CoupledProblem<dim> &problem, const std::string &text)
  {
    parse_problem(problem, text);
    problem.setup();
    problem.run();
    dealii::LinearAlgebra::distributed::Vector<double> solution;
    problem.fe_region().initialize_vector(solution);
    solution = problem.fe_displacement();
    solution.update_ghost_values();
    return solution;
  }

  /**
   * The lines of a static, FE-only problem besides <Finite elements>: dimension, planar
   * assumption (2D only: a 3D problem refuses one), body force, solver tolerance; statistics in
   * results/, no field output, no progress lines.
   */
  inline std::string
  static_problem(const unsigned int dim,
                 const std::string &planar,
                 const std::string &body_force,
                 const std::string &tolerance)
  {
    return "set Dimension = " + std::to_string(dim) +
           "\n"
           "subsection Material\n" +
           (dim == 2 ? "  set Planar assumption = " + planar + "\n" : std::string()) +
           "end\n"
           "subsection Body force\n"
           "  set Function = " +
           body_force +
           "\n"
           "end\n"
           "subsection Solver\n"
           "  set Type      = static\n"
           "  set Tolerance = " +
           tolerance +
           "\n"
           "end\n"
           "subsection Output\n"
           "  set Directory  = results\n"
           "  set Write HDF5 = false\n"
           "  set Progress   = false\n"
           "end\n";
  }

  /**
   * The largest |d - @p expected| over the owned cells for which @p selected holds and the
   * points @p points (unit cell), d the first dim quantities of the physics' output
   * (FEPhysics::postprocessor(), a scalar field's) from the gradient of @p solution: e.g. the
   * heat flux -K grad T of 'heat' (collective).
   */
  template <int dim, typename Selected>
  double
  output_error(const perideal::FERegion<dim>                            &fe,
               const dealii::LinearAlgebra::distributed::Vector<double> &solution,
               const dealii::Quadrature<dim>                            &points,
               const Selected                                           &selected,
               const dealii::Tensor<1, dim>                             &expected)
  {
    const auto            output = fe.physics().postprocessor();
    dealii::FEValues<dim> values(fe.get_fe_collection()[0],
                                 points,
                                 dealii::update_gradients | dealii::update_quadrature_points);
    double                largest = 0.;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && selected(cell))
        {
          values.reinit(cell);
          dealii::DataPostprocessorInputs::Scalar<dim> inputs;
          inputs.solution_gradients.resize(points.size());
          values.get_function_gradients(solution, inputs.solution_gradients);
          std::vector<dealii::Vector<double>> computed(points.size(),
                                                       dealii::Vector<double>(
                                                         output->get_names().size()));
          output->evaluate_scalar_field(inputs, computed);
          for (const auto &d : computed)
            for (unsigned int i = 0; i < dim; ++i)
              largest = std::max(largest, std::abs(d[i] - expected[i]));
        }
    return dealii::Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }

  /**
   * @p value with 17 significant digits, for the parameter text of a test.
   */
  inline std::string
  number(const double value)
  {
    std::ostringstream out;
    out.precision(17);
    out << value;
    return out.str();
  }

  /**
   * A transient FE-only 'heat' problem on the strip 0 <= x <= @p length of @p n x 1 square
   * cells (thickness 0.01 m; boundary ids 0 at x = 0, 1 at x = length, 2 and 3 the insulated
   * long sides) with <Solver/Type> = @p solver (tolerance 1e-12), <Time stepping> @p end_time,
   * @p time_step, @p theta, the initial temperature @p initial, conductivity @p k, density
   * @p rho, specific heat @p c and the boundary conditions @p conditions (the lines inside
   * <Finite elements/Boundary conditions>); statistics in results/, no field output.
   */
  inline std::string
  heat_strip(const std::string &solver,
             const unsigned int n,
             const double       length,
             const std::string &initial,
             const double       end_time,
             const double       time_step,
             const double       theta,
             const double       k,
             const double       rho,
             const double       c,
             const std::string &conditions)
  {
    return "set Dimension = 2\n"
           "subsection Discretization\n"
           "  set Thickness = 0.01\n"
           "end\n"
           "subsection Initial conditions\n"
           "  set Displacement = " +
           initial +
           "\n"
           "end\n"
           "subsection Solver\n"
           "  set Type      = " +
           solver +
           "\n"
           "  set Tolerance = 1e-12\n"
           "end\n"
           "subsection Time stepping\n"
           "  set End time  = " +
           number(end_time) + "\n  set Time step = " + number(time_step) +
           "\n  set Theta     = " + number(theta) +
           "\n"
           "end\n"
           "subsection Output\n"
           "  set Directory  = results\n"
           "  set Write HDF5 = false\n"
           "  set Progress   = false\n"
           "end\n"
           "subsection Finite elements\n"
           "  set Physics = heat\n"
           "  set Density = " +
           number(rho) +
           "\n"
           "  set Generator = subdivided_hyper_rectangle\n"
           "  set Generator arguments = " +
           std::to_string(n) + ", 1 : 0, 0 : " + number(length) + ", " + number(length / n) +
           " : true\n"
           "  subsection heat\n"
           "    set Conductivity  = " +
           number(k) + "\n    set Specific heat = " + number(c) +
           "\n"
           "  end\n"
           "  subsection Boundary conditions\n" +
           conditions +
           "  end\n"
           "end\n";
  }
} // namespace fem_tests

#endif
