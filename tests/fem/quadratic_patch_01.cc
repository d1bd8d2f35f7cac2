// ---------------------------------------------------------------------
// FE part of the coupled linear-strain patch tests (tests/app-solid/
// coupled_static_*linear_strain_*): the same plates, meshes, materials, quadratic fields and
// constant body forces, FE only (no particles, weight 1). 2D plane stress, 100 mm square,
// 25 x 25 cells, nu = 1/3 and 0.3, u = a (x^2 + x y, (2 x^2 + y^2) / 2), a = 1e-3; 3D 24 mm cube,
// 6^3 cells, nu = 1/4, u = a (x^2 + x y, (2 x^2 + y^2) / 2, z^2 / 2 + y z), a = 1e-2; every
// boundary held to u, b = -div sigma; solved through the problem's static path (CoupledProblem,
// FE only). FE_Q(2) holds u, so its error is round-off. FE_Q(1) does
// not hold u, but on a uniform mesh of squares (cubes) its stencil is symmetric, hence exact for
// quadratic fields with the consistent load of a constant b: its nodal error is round-off too,
// and its error lies between the nodes (the L2 error). Printed: whether the largest nodal error
// is below 1e-12 of the largest nodal value, and the L2 error relative to the L2 norm.
// ---------------------------------------------------------------------
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/fem/fe_region.h>

#include "fem_tests.h"

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

using namespace dealii;

namespace
{
  template <int dim>
  void
  run(const unsigned int degree,
      const std::string &poisson_ratio,
      const std::string &mesh,
      const std::string &field,
      const std::string &body_force)
  {
    const std::string text =
      fem_tests::static_problem(dim, "plane stress", body_force, "1e-13") +
      "subsection Discretization\n"
      "  set Thickness = " +
      std::string(dim == 2 ? "1e-3" : "1") +
      "\n"
      "end\n"
      "subsection Finite elements\n"
      "  set Generator = subdivided_hyper_rectangle\n"
      "  set Generator arguments = " +
      mesh +
      "\n"
      "  set Polynomial degree = " +
      std::to_string(degree) +
      "\n"

      "  subsection Elasticity\n"
      "    set Young's modulus = 200e9\n"
      "    set Poisson's ratio = " +
      poisson_ratio +
      "\n"
      "  end\n"
      "  subsection Boundary conditions\n"
      "    set Names = boundary\n"
      "    subsection boundary\n"
      "      set Boundary ids = " +
      (dim == 2 ? std::string("0, 1, 2, 3") : std::string("0, 1, 2, 3, 4, 5")) +
      "\n"
      "      set Function = " +
      field +
      "\n"
      "    end\n"
      "  end\n"
      "end\n";
    std::ostringstream            log;
    perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
    const auto                    solution = fem_tests::solve(problem, text);
    const auto                   &fe       = problem.fe_region();

    FunctionParser<dim> exact(dim);
    exact.initialize(dim == 2 ? "x,y" : "x,y,z", field, {});
    LinearAlgebra::distributed::Vector<double> interpolant(solution);
    VectorTools::interpolate(fe.get_dof_handler(), exact, interpolant);
    const double largest = interpolant.linfty_norm();
    interpolant -= solution;
    const double nodal_error = interpolant.linfty_norm();

    // The L2 error over the domain against the L2 norm of the exact field.
    Vector<float>     cellwise(fe.get_triangulation().n_active_cells());
    const QGauss<dim> quadrature(degree + 3);
    VectorTools::integrate_difference(fe.get_dof_handler(),
                                      solution,
                                      exact,
                                      cellwise,
                                      quadrature,
                                      VectorTools::L2_norm);
    const double l2_error =
      VectorTools::compute_global_error(fe.get_triangulation(), cellwise, VectorTools::L2_norm);
    Functions::ZeroFunction<dim> zero(dim);
    VectorTools::integrate_difference(fe.get_dof_handler(),
                                      solution,
                                      zero,
                                      cellwise,
                                      quadrature,
                                      VectorTools::L2_norm);
    const double l2_norm =
      VectorTools::compute_global_error(fe.get_triangulation(), cellwise, VectorTools::L2_norm);

    // Round-off (Q2) prints as a bound: its digits depend on the number of ranks.
    char relative[20];
    std::snprintf(relative, sizeof(relative), "%.2e", l2_error / l2_norm);
    const std::string relative_l2 =
      l2_error < 1e-10 * l2_norm ? std::string("below 1e-10") : std::string(relative);
    char line[200];
    std::snprintf(line,
                  sizeof(line),
                  "%uD FE_Q(%u), nu = %s: nodal error %s 1e-12 of the largest nodal value, "
                  "L2 error / L2 norm %s",
                  dim,
                  degree,
                  poisson_ratio.c_str(),
                  nodal_error < 1e-12 * largest ? "below" : "ABOVE",
                  relative_l2.c_str());
    std::cout << line << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  const std::string plate    = "25, 25 : 0, 0 : 0.1, 0.1 : true";
  const std::string field_2d = "1e-3*(x^2 + x*y); 1e-3*(2*x^2 + y^2)/2";
  // b = -a (2 lambda + 4 mu, 2 lambda + 5 mu), plane stress lambda* = E nu / (1 - nu^2).
  const std::string pmb_2d = "-1e-3*(2*75e9 + 4*75e9); -1e-3*(2*75e9 + 5*75e9)";
  const std::string lps_2d =
    "-1e-3*(2*200e9*0.3/0.91 + 4*200e9/2.6); -1e-3*(2*200e9*0.3/0.91 + 5*200e9/2.6)";
  for (const unsigned int degree : {1u, 2u})
    run<2>(degree, "0.3333333333333333", plate, field_2d, pmb_2d);
  run<2>(1, "0.3", plate, field_2d, lps_2d);
  run<3>(1,
         "0.25",
         "6, 6, 6 : 0, 0, 0 : 0.024, 0.024, 0.024 : true",
         "1e-2*(x^2 + x*y); 1e-2*(2*x^2 + y^2)/2; 1e-2*(z^2/2 + y*z)",
         "-1e-2*(2*80e9 + 4*80e9); -1e-2*(3*80e9 + 6*80e9); -1e-2*(80e9 + 2*80e9)");
}
