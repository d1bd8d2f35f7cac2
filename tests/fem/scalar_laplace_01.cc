// ---------------------------------------------------------------------
// Manufactured solution of the FE physics 'scalar laplace', -div(k grad w) = f, on the unit
// square and cube, through the problem's static path (CoupledProblem, FE only): w = a phi(x) +
// c . x with phi = prod_d sin(pi x_d), a = 1e-3 m, c = 1e-3 (0.5, 0.25, 0.125) (antiplane
// shear: k = mu = 8e10 Pa), so f = k dim pi^2 a phi [N/m^3] (<Body force/Function>, first
// expression) and w = c . x on the whole boundary (a 'value' condition: the default <Type>). Under
// uniform refinement the errors must fall at the optimal rates, |w - w_h|_L2 ~ h^(p+1) and |w -
// w_h|_H1 ~ h^p (Q1 in 2D and 3D, Q2 in 2D). Printed: errors, rates and whether the finest rates
// lie within 0.1 of the optimal ones.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include "fem_tests.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  const double a = 1e-3, k = 8e10, c[3] = {0.5e-3, 0.25e-3, 0.125e-3};

  template <int dim>
  class ExactSolution : public Function<dim>
  {
  public:
    double
    value(const Point<dim> &x, const unsigned int = 0) const override
    {
      double phi = 1., linear = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          phi *= std::sin(numbers::PI * x[d]);
          linear += c[d] * x[d];
        }
      return a * phi + linear;
    }

    Tensor<1, dim>
    gradient(const Point<dim> &x, const unsigned int = 0) const override
    {
      Tensor<1, dim> g;
      for (unsigned int j = 0; j < dim; ++j)
        {
          double dphi = numbers::PI;
          for (unsigned int d = 0; d < dim; ++d)
            dphi *= (d == j ? std::cos(numbers::PI * x[d]) : std::sin(numbers::PI * x[d]));
          g[j] = a * dphi + c[j];
        }
      return g;
    }
  };

  template <int dim>
  std::string
  problem_text(const unsigned int degree, const unsigned int level)
  {
    const std::string x[] = {"x", "y", "z"};
    std::string       phi, linear;
    for (unsigned int d = 0; d < dim; ++d)
      {
        phi += (d > 0 ? "*" : "") + std::string("sin(pi*") + x[d] + ")";
        linear += (d > 0 ? " + " : "") + std::to_string(c[d]) + "*" + x[d];
      }
    std::ostringstream source;
    source.precision(17);
    source << k * dim * a << "*pi^2*" << phi;
    return fem_tests::static_problem(dim, "plane stress", source.str(), "1e-12") +
           "subsection Finite elements\n"
           "  set Physics = scalar laplace\n"
           "  set Generator = hyper_cube\n"
           "  set Generator arguments = 0 : 1 : false\n"
           "  set Global refinements = " +
           std::to_string(level) +
           "\n"
           "  set Polynomial degree = " +
           std::to_string(degree) +
           "\n"
           "  subsection scalar laplace\n"
           "    set Coefficient = 8e10\n"
           "  end\n"
           "  subsection Boundary conditions\n"
           "    set Names = boundary\n"
           "    subsection boundary\n"
           "      set Boundary ids = 0\n"
           "      set Components = w\n"
           "      set Function = " +
           linear +
           "\n"
           "    end\n"
           "  end\n"
           "end\n";
  }

  template <int dim>
  void
  run(const unsigned int degree, const unsigned int min_level, const unsigned int max_level)
  {
    deallog << dim << "D, FE_Q(" << degree << "), k = " << k << " Pa" << std::endl;
    double previous_l2 = 0., previous_h1 = 0.;
    for (unsigned int level = min_level; level <= max_level; ++level)
      {
        std::ostringstream            log;
        perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
        const auto  solution = fem_tests::solve(problem, problem_text<dim>(degree, level));
        const auto &fe       = problem.fe_region();

        const ExactSolution<dim>    exact;
        dealii::Vector<float>       cellwise(fe.get_triangulation().n_active_cells());
        const QGauss<dim>           quadrature(degree + 2);
        double                      errors[2];
        const VectorTools::NormType norms[2] = {VectorTools::L2_norm, VectorTools::H1_seminorm};
        for (unsigned int n = 0; n < 2; ++n)
          {
            VectorTools::integrate_difference(fe.get_dof_handler(),
                                              solution,
                                              exact,
                                              cellwise,
                                              quadrature,
                                              norms[n]);
            errors[n] =
              VectorTools::compute_global_error(fe.get_triangulation(), cellwise, norms[n]);
          }
        const double l2_rate = level > min_level ? std::log2(previous_l2 / errors[0]) : 0.;
        const double h1_rate = level > min_level ? std::log2(previous_h1 / errors[1]) : 0.;
        char         line[200];
        std::snprintf(line,
                      sizeof(line),
                      "h = 1/%-3u dofs %6u  L2 error %.4e  rate %5.2f  H1 error %.4e  rate %5.2f",
                      1u << level,
                      static_cast<unsigned int>(fe.n_dofs()),
                      errors[0],
                      l2_rate,
                      errors[1],
                      h1_rate);
        deallog << line << std::endl;
        if (level == max_level)
          deallog << "finest rates within 0.1 of the optimal " << degree + 1 << " and " << degree
                  << ": "
                  << (std::abs(l2_rate - (degree + 1.)) < 0.1 && std::abs(h1_rate - degree) < 0.1 ?
                        "yes" :
                        "NO")
                  << std::endl;
        previous_l2 = errors[0];
        previous_h1 = errors[1];
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no CG iteration lines
  run<2>(1, 2, 6);
  run<2>(2, 1, 5);
  run<3>(1, 1, 4);
}
