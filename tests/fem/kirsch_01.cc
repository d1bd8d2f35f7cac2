// ---------------------------------------------------------------------
// Plate with a circular hole (Kirsch): the quarter plate of meshes/plate_with_hole_2d.msh
// (hole radius a = 0.01 m, quarter 0.1 m x 0.1 m), symmetry conditions on x = 0 and y = 0, and
// on the outer edges the tractions of the exact infinite-plate solution under a remote stress
// S along x (2D plane strain, isotropic), so that the FE solution converges to the exact field;
// solved through the problem's static path (CoupledProblem, FE only).
// Printed under uniform refinement (the hole boundary follows the circle): the stress
// concentration sigma_xx(0, a) / S (exact 3), the relative L2 error of the stress over the
// plate, and its rate.
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>

#include <perideal/fem/physics/linear_elasticity.h>

#include "fem_tests.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

using namespace dealii;

namespace
{
  const double S = 100e6, a = 0.01;

  // The exact Kirsch stress (sigma_xx, sigma_yy, sigma_xy) at p.
  SymmetricTensor<2, 2>
  kirsch_stress(const Point<2> &p)
  {
    const double r2 = p.square(), c2 = (p[0] * p[0] - p[1] * p[1]) / r2, s2 = 2. * p[0] * p[1] / r2,
                 c4 = c2 * c2 - s2 * s2, s4 = 2. * s2 * c2;
    const double          q2 = a * a / r2, q4 = q2 * q2;
    SymmetricTensor<2, 2> sigma;
    sigma[0][0] = S * (1. - q2 * (1.5 * c2 + c4) + 1.5 * q4 * c4);
    sigma[1][1] = S * (-q2 * (0.5 * c2 - c4) - 1.5 * q4 * c4);
    sigma[0][1] = S * (-q2 * (0.5 * s2 + s4) + 1.5 * q4 * s4);
    return sigma;
  }

  // The same as FunctionParser expressions of x and y.
  std::string
  kirsch_expressions(const bool top)
  {
    const std::string r2 = "(x^2+y^2)", c2 = "((x^2-y^2)/" + r2 + ")", s2 = "(2*x*y/" + r2 + ")";
    const std::string c4 = "(" + c2 + "^2-" + s2 + "^2)", s4 = "(2*" + s2 + "*" + c2 + ")";
    const std::string q2 = "(1e-4/" + r2 + ")", q4 = "(" + q2 + "^2)";
    const std::string sxx =
      "1e8*(1-" + q2 + "*(1.5*" + c2 + "+" + c4 + ")+1.5*" + q4 + "*" + c4 + ")";
    const std::string syy =
      "1e8*(-" + q2 + "*(0.5*" + c2 + "-" + c4 + ")-1.5*" + q4 + "*" + c4 + ")";
    const std::string sxy =
      "1e8*(-" + q2 + "*(0.5*" + s2 + "+" + s4 + ")+1.5*" + q4 + "*" + s4 + ")";
    // Right edge (normal +x): (sxx, sxy); top edge (normal +y): (sxy, syy).
    return top ? sxy + "; " + syy : sxx + "; " + sxy;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm           = MPI_COMM_WORLD;
  const bool                       is_root        = Utilities::MPI::this_mpi_process(comm) == 0;
  double                           previous_error = 0.;
  for (unsigned int level = 0; level <= 3; ++level)
    {
      const std::string text = fem_tests::static_problem(2, "plane strain", "0; 0", "1e-12") +
                               "subsection Finite elements\n"
                               "  set Mesh file = " SOURCE_DIR
                               "/../../meshes/plate_with_hole_2d.msh\n"
                               "  set Circular boundaries = 5: 0, 0\n"
                               "  set Global refinements = " +
                               std::to_string(level) +
                               "\n"
                               "  subsection Elasticity\n"
                               "    set Young's modulus = 200e9\n"
                               "    set Poisson's ratio = 0.3\n"
                               "  end\n"
                               "  subsection Boundary conditions\n"
                               "    set Names = symmetry x, symmetry y, right, top\n"
                               "    subsection symmetry x\n"
                               "      set Boundary ids = 1\n"
                               "      set Components = x\n"
                               "    end\n"
                               "    subsection symmetry y\n"
                               "      set Boundary ids = 2\n"
                               "      set Components = y\n"
                               "    end\n"
                               "    subsection right\n"
                               "      set Boundary ids = 3\n"
                               "      set Type = traction\n"
                               "      set Function = " +
                               kirsch_expressions(false) +
                               "\n"
                               "    end\n"
                               "    subsection top\n"
                               "      set Boundary ids = 4\n"
                               "      set Type = traction\n"
                               "      set Function = " +
                               kirsch_expressions(true) +
                               "\n"
                               "    end\n"
                               "  end\n"
                               "end\n";
      std::ostringstream          log;
      perideal::CoupledProblem<2> problem(comm, log);
      const auto                  solution = fem_tests::solve(problem, text);
      const auto                 &fe       = problem.fe_region();

      // Relative L2 error of the stress, and the stress at the vertex (0, a) from the cell
      // that owns it (averaged over the owning cells).
      const auto &C =
        dynamic_cast<const perideal::LinearElasticity<2> &>(fe.physics()).elasticity_tensor();
      const QGauss<2>                    quadrature(3);
      FEValues<2>                        fe_values(fe.get_fe_collection()[0],
                            quadrature,
                            update_gradients | update_quadrature_points | update_JxW_values);
      const FEValuesExtractors::Vector   displacement(0);
      std::vector<SymmetricTensor<2, 2>> strain(quadrature.size());
      double                             error2 = 0., norm2 = 0., peak = 0., n_peak = 0.;
      for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[displacement].get_function_symmetric_gradients(solution, strain);
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                const auto exact = kirsch_stress(fe_values.quadrature_point(q));
                error2 += std::pow((C * strain[q] - exact).norm(), 2) * fe_values.JxW(q);
                norm2 += std::pow(exact.norm(), 2) * fe_values.JxW(q);
              }
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex(v).distance(Point<2>(0., a)) < 1e-9)
                {
                  // The strain at the vertex, from this cell's shape functions.
                  const Quadrature<2> at_vertex(GeometryInfo<2>::unit_cell_vertex(v));
                  FEValues<2> vertex_values(fe.get_fe_collection()[0], at_vertex, update_gradients);
                  vertex_values.reinit(cell);
                  std::vector<SymmetricTensor<2, 2>> eps(1);
                  vertex_values[displacement].get_function_symmetric_gradients(solution, eps);
                  peak += (C * eps[0])[0][0];
                  n_peak += 1.;
                }
          }
      error2             = Utilities::MPI::sum(error2, comm);
      norm2              = Utilities::MPI::sum(norm2, comm);
      peak               = Utilities::MPI::sum(peak, comm) / Utilities::MPI::sum(n_peak, comm);
      const double error = std::sqrt(error2 / norm2);
      char         line[200];
      std::snprintf(line,
                    sizeof(line),
                    "refinement %u: %6u cells  sigma_xx(0, a) / S = %.4f (exact 3)  stress L2 "
                    "error %.4e  rate %5.2f",
                    level,
                    fe.get_triangulation().n_global_active_cells(),
                    peak / S,
                    error,
                    level > 0 ? std::log2(previous_error / error) : 0.);
      if (is_root)
        std::cout << line << std::endl;
      previous_error = error;
    }
}
