// ---------------------------------------------------------------------
// Saint-Venant torsion of the 1 x 2 rectangular bar (seed 000, example 8.4) with the FE physics
// 'scalar laplace' and a twist per unit length (k = mu = 1 Pa, psi = 1 rad/m, axis at the
// centroid), through the problem's static path: the section |x| <= 1/2, |y| <= 1, only the
// load of the twist (the volume load of the energy, every face traction free), w held at the
// vertex at the axis.
// Checked against the Saint-Venant series (Timoshenko & Goodier 1970, sect. 109), computed here
// with 200 terms (tests/saint_venant.h): the torque T = k1 mu psi (2a)(2b)^3 with 2b = 1 the short
// side (k1 = 0.228682, T = 0.457363 mu psi), the largest stress tau_yz(1/2, 0) = 0.930060 mu psi,
// tau_xz(0, 1) = -0.739429 mu psi and the L2 error of the warping, under uniform refinement (Q1 and
// Q2): the torque is an energy (T psi = 2E) and converges like the energy error, h^(2p); the
// stresses at boundary points like the gradient, h^p or better; T psi = 2E holds for the Galerkin
// solution itself (integration by parts of the FE field), to the solver tolerance. A twist axis at
// (0.2, -0.3) changes the warping by a linear function only: the same torque.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include "fem_tests.h"

#include <cmath>
#include <cstdio>

#include <saint_venant.h>
#include <tests.h>

using namespace dealii;

namespace
{
  // Half-sides: a along x (the short one), b along y.
  const double a = 0.5, b = 1.;

  std::string
  problem_text(const unsigned int degree, const unsigned int level, const std::string &axis)
  {
    return fem_tests::static_problem(2, "plane strain", "0", "1e-12") +
           "subsection Finite elements\n"
           "  set Physics = scalar laplace\n"
           "  set Generator = subdivided_hyper_rectangle\n"
           "  set Generator arguments = 1, 2 : -0.5, -1 : 0.5, 1 : false\n"
           "  set Global refinements = " +
           std::to_string(level) +
           "\n"
           "  set Polynomial degree = " +
           std::to_string(degree) +
           "\n"
           "  subsection scalar laplace\n"
           "    set Coefficient = 1\n"
           "    set Twist per unit length = 1\n"
           "    set Twist axis = " +
           axis +
           "\n"
           "  end\n"
           "end\n";
  }

  // The FE shear stress mu (grad w + psi (-y, x)) at @p p, averaged over the cells that hold it.
  Tensor<1, 2>
  fe_stress(const perideal::FERegion<2>                      &fe,
            const LinearAlgebra::distributed::Vector<double> &w,
            const Point<2>                                   &p)
  {
    const MappingQ1<2> mapping;
    Tensor<1, 2>       sum;
    double             count = 0.;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->point_inside(p))
        {
          const Point<2> unit = mapping.transform_real_to_unit_cell(cell, p);
          FEValues<2>    values(mapping,
                             cell->get_fe(),
                             Quadrature<2>(std::vector<Point<2>>{unit}),
                             update_gradients);
          values.reinit(cell);
          std::vector<Tensor<1, 2>> gradient(1);
          values.get_function_gradients(w, gradient);
          Tensor<1, 2> twist;
          twist[0] = -p[1];
          twist[1] = p[0];
          sum += gradient[0] + twist;
          count += 1.;
        }
    for (unsigned int d = 0; d < 2; ++d)
      sum[d] = Utilities::MPI::sum(sum[d], MPI_COMM_WORLD);
    return sum / Utilities::MPI::sum(count, MPI_COMM_WORLD);
  }

  void
  run(const unsigned int degree, const unsigned int min_level, const unsigned int max_level)
  {
    const double       T_exact = saint_venant::torque(a, b);
    const Point<2>     side(0.5, 0.), end(0., 1.);
    const Tensor<1, 2> tau_side = saint_venant::stress(side, a, b),
                       tau_end  = saint_venant::stress(end, a, b);
    deallog << "FE_Q(" << degree << ")" << std::endl;
    double previous = 0.;
    for (unsigned int level = min_level; level <= max_level; ++level)
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        const auto   solution = fem_tests::solve(problem, problem_text(degree, level, "0, 0"));
        const auto  &fe       = problem.fe_region();
        const auto   T_E      = fe.section_integrals(solution);
        const double error    = T_E[0] / T_exact - 1.;
        const double rate     = level > min_level ? std::log2(std::abs(previous / error)) : 0.;
        previous              = error;

        dealii::Vector<float> cellwise(fe.get_triangulation().n_active_cells());
        VectorTools::integrate_difference(fe.get_dof_handler(),
                                          solution,
                                          saint_venant::Warping(a, b),
                                          cellwise,
                                          QGauss<2>(degree + 2),
                                          VectorTools::L2_norm);
        const double warping_error =
          VectorTools::compute_global_error(fe.get_triangulation(), cellwise, VectorTools::L2_norm);
        char line[240];
        std::snprintf(line,
                      sizeof(line),
                      "h = 1/%-3u T/(mu psi) %.6f error %+.2e rate %5.2f  tau_yz(1/2,0) %+.2e  "
                      "tau_xz(0,1) %+.2e  |w - w_h|_L2 %.2e  T psi/(2E) - 1 %+.0e",
                      1u << level,
                      T_E[0],
                      error,
                      rate,
                      fe_stress(fe, solution, side)[1] / tau_side[1] - 1.,
                      fe_stress(fe, solution, end)[0] / tau_end[0] - 1.,
                      warping_error,
                      std::abs(T_E[0] / (2. * T_E[1]) - 1.) < 1e-9 ? 0. :
                                                                     T_E[0] / (2. * T_E[1]) - 1.);
        deallog << line << std::endl;
        if (level == max_level)
          deallog << "finest torque rate within 0.3 of 2p = " << 2 * degree << ": "
                  << (std::abs(rate - 2. * degree) < 0.3 ? "yes" : "NO") << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);
  deallog << "Saint-Venant: T/(mu psi) = " << saint_venant::torque(a, b)
          << ", k1 = " << saint_venant::torque(a, b) / 2.
          << ", tau_yz(1/2, 0)/(mu psi) = " << saint_venant::stress(Point<2>(0.5, 0.), a, b)[1]
          << ", tau_xz(0, 1)/(mu psi) = " << saint_venant::stress(Point<2>(0., 1.), a, b)[0]
          << std::endl;
  run(1, 1, 6);
  run(2, 1, 5);

  // Another twist axis: the same torque.
  std::ostringstream          log;
  perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
  const auto                  solution = fem_tests::solve(problem, problem_text(2, 4, "0.2, -0.3"));
  deallog << "axis (0.2, -0.3), FE_Q(2), h = 1/16: T/(mu psi) = "
          << problem.fe_region().section_integrals(solution)[0] << std::endl;
}
