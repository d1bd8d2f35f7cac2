// ---------------------------------------------------------------------
// Manufactured solution on the unit square/cube for an anisotropic material (orthotropic,
// rotated): u_k = a_k phi(x) + L_kj x_j with phi = prod_d sin(pi x_d), body force
// b_i = -C_ijkl d_j d_l u_k (an expression of <Body force/Function>), and the linear part L x
// prescribed on the whole boundary, both through the parameter text; solved through the
// problem's static path (CoupledProblem, FE only). The errors must fall at the optimal rates
// under uniform refinement:
// |u - u_h|_L2 ~ h^(p+1) and |u - u_h|_H1 ~ h^p, for p = 1, 2 in 2D (plane strain) and p = 1
// in 3D. Printed: errors and observed rates.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/fem/physics/linear_elasticity.h>

#include "fem_tests.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

using namespace dealii;
using perideal::PlanarAssumption;

namespace
{
  // The linear part L x of the solution (its strain is prescribed through the boundary).
  template <int dim>
  Tensor<2, dim>
  linear_part()
  {
    Tensor<2, dim> L;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        L[i][j] = 1e-3 * (1. + i + 2. * j);
    return L;
  }

  template <int dim>
  Tensor<1, dim>
  amplitude()
  {
    Tensor<1, dim> a;
    for (unsigned int i = 0; i < dim; ++i)
      a[i] = 1e-3 * (1. - 0.4 * i);
    return a;
  }

  template <int dim>
  class ExactSolution : public Function<dim>
  {
  public:
    ExactSolution()
      : Function<dim>(dim)
    {}

    double
    value(const Point<dim> &x, const unsigned int k) const override
    {
      double phi = 1.;
      for (unsigned int d = 0; d < dim; ++d)
        phi *= std::sin(numbers::PI * x[d]);
      return amplitude<dim>()[k] * phi + linear_part<dim>()[k] * x;
    }

    Tensor<1, dim>
    gradient(const Point<dim> &x, const unsigned int k) const override
    {
      Tensor<1, dim> g;
      for (unsigned int j = 0; j < dim; ++j)
        {
          double dphi = numbers::PI;
          for (unsigned int d = 0; d < dim; ++d)
            dphi *= (d == j ? std::cos(numbers::PI * x[d]) : std::sin(numbers::PI * x[d]));
          g[j] = amplitude<dim>()[k] * dphi + linear_part<dim>()[k][j];
        }
      return g;
    }
  };

  // b_i = -C_ijkl a_k d_j d_l phi as one expression per component: d_j d_j phi = -pi^2 phi,
  // d_j d_l phi = pi^2 cos(pi x_j) cos(pi x_l) prod_(d != j, l) sin(pi x_d) for j != l.
  template <int dim>
  std::string
  body_force(const SymmetricTensor<4, dim> &C)
  {
    const char        *names[] = {"x", "y", "z"};
    std::ostringstream text;
    text.precision(17);
    for (unsigned int i = 0; i < dim; ++i)
      {
        text << (i > 0 ? "; " : "") << "0";
        for (unsigned int j = 0; j < dim; ++j)
          for (unsigned int l = 0; l < dim; ++l)
            {
              double coefficient = 0.;
              for (unsigned int k = 0; k < dim; ++k)
                coefficient -= C[i][j][k][l] * amplitude<dim>()[k];
              text << " + " << (j == l ? -1. : 1.) * coefficient << "*pi^2";
              for (unsigned int d = 0; d < dim; ++d)
                text << "*" << ((d == j) != (d == l) ? "cos" : "sin") << "(pi*" << names[d] << ")";
            }
      }
    return text.str();
  }

  // The elasticity tensor of <Finite elements/Elasticity> = @p material (plane strain in 2D).
  template <int dim>
  SymmetricTensor<4, dim>
  elasticity_tensor(const std::string &material)
  {
    perideal::LinearElasticity<dim> elasticity;
    ParameterHandler                prm;
    prm.enter_subsection("Finite elements");
    elasticity.declare_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Finite elements\n" + material + "end\n");
    prm.enter_subsection("Finite elements");
    elasticity.parse_parameters(prm,
                                dim == 2 ? PlanarAssumption::plane_strain :
                                           PlanarAssumption::three_dimensional);
    prm.leave_subsection();
    return elasticity.elasticity_tensor();
  }

  template <int dim>
  std::string
  boundary_functions()
  {
    const auto  L       = linear_part<dim>();
    const char *names[] = {"x", "y", "z"};
    std::string text;
    for (unsigned int i = 0; i < dim; ++i)
      {
        text += (i > 0 ? "; " : "");
        for (unsigned int j = 0; j < dim; ++j)
          text += (j > 0 ? " + " : "") + std::to_string(L[i][j]) + "*" + names[j];
      }
    return text;
  }

  template <int dim>
  void
  run(const unsigned int degree, const unsigned int min_level, const unsigned int max_level)
  {
    std::cout << dim << "D, FE_Q(" << degree << "), orthotropic rotated material" << std::endl;
    double previous_l2 = 0., previous_h1 = 0.;
    for (unsigned int level = min_level; level <= max_level; ++level)
      {
        const std::string material = "  subsection Elasticity\n"
                                     "    set Symmetry = orthotropic\n"
                                     "    set Young's moduli = 140e9, 10e9, 12e9\n"
                                     "    set Poisson's ratios = 0.3, 0.28, 0.4\n"
                                     "    set Shear moduli = 6e9, 5e9, 3.5e9\n"
                                     "    set Orientation = 30, 20, 10\n"
                                     "  end\n";
        const std::string text =
          fem_tests::static_problem(dim,
                                    "plane strain",
                                    body_force<dim>(elasticity_tensor<dim>(material)),
                                    "1e-12") +
          "subsection Finite elements\n"
          "  set Generator = hyper_cube\n"
          "  set Generator arguments = 0 : 1 : false\n"
          "  set Global refinements = " +
          std::to_string(level) +
          "\n"
          "  set Polynomial degree = " +
          std::to_string(degree) + "\n" + material +
          "  subsection Boundary conditions\n"
          "    set Names = clamp\n"
          "    subsection clamp\n"
          "      set Boundary ids = 0\n"
          "      set Function = " +
          boundary_functions<dim>() +
          "\n"
          "    end\n"
          "  end\n"
          "end\n";
        std::ostringstream            log;
        perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
        const auto                    solution = fem_tests::solve(problem, text);
        const auto                   &fe       = problem.fe_region();

        const ExactSolution<dim>    exact;
        dealii::Vector<float>       cellwise(fe.get_triangulation().n_active_cells());
        const QGauss<dim>           quadrature(degree + 2);
        double                      errors[2];
        const VectorTools::NormType norms[2] = {VectorTools::L2_norm, VectorTools::H1_seminorm};
        for (unsigned int k = 0; k < 2; ++k)
          {
            VectorTools::integrate_difference(fe.get_dof_handler(),
                                              solution,
                                              exact,
                                              cellwise,
                                              quadrature,
                                              norms[k]);
            errors[k] =
              VectorTools::compute_global_error(fe.get_triangulation(), cellwise, norms[k]);
          }
        char line[200];
        std::snprintf(line,
                      sizeof(line),
                      "  h = 1/%-4u dofs %7u  L2 error %.4e  rate %5.2f  H1 error %.4e  rate %5.2f",
                      1u << level,
                      static_cast<unsigned int>(fe.get_dof_handler().n_dofs()),
                      errors[0],
                      level > min_level ? std::log2(previous_l2 / errors[0]) : 0.,
                      errors[1],
                      level > min_level ? std::log2(previous_h1 / errors[1]) : 0.);
        if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << line << std::endl;
        if (level == max_level)
          std::cout << "  finest rates within 0.1 of the optimal " << degree + 1 << " and "
                    << degree << ": "
                    << (std::abs(std::log2(previous_l2 / errors[0]) - (degree + 1.)) < 0.1 &&
                            std::abs(std::log2(previous_h1 / errors[1]) - degree) < 0.1 ?
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
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  run<2>(1, 2, 6);
  run<2>(2, 1, 5);
  run<3>(1, 1, 4);
}
