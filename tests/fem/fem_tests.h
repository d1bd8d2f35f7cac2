// Helpers shared by the tests in tests/fem: FE problems run through the problem's static path.
#ifndef perideal_fem_tests_h
#define perideal_fem_tests_h

#include <deal.II/base/parameter_handler.h>

#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/boundary_conditions.h>

#include <string>

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
   * assumption, body force, solver tolerance; statistics in results/, no field output, no
   * progress lines.
   */
  inline std::string
  static_problem(const unsigned int dim,
                 const std::string &planar,
                 const std::string &body_force,
                 const std::string &tolerance)
  {
    return "set Dimension = " + std::to_string(dim) +
           "\n"
           "subsection Material\n"
           "  set Planar assumption = " +
           planar +
           "\n"
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
} // namespace fem_tests

#endif
