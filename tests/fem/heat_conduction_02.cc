// ---------------------------------------------------------------------
// An orthotropic conductivity in rotated material axes, FE physics 'heat', through the
// problem's static path: K = R diag(k1, k2, k3) R^T with R the z-x-z Euler rotation
// R_z(phi) R_x(theta) R_z(psi) (formed here from the closed-form elementary rotations; in 2D
// the in-plane block), the quadratic temperature T = x . A x + b . x with an A that has
// off-diagonal terms, so that the source is q = -div(K grad T) = -2 K : A (the body force) and
// every entry of K enters, and 'value' conditions T on the whole boundary of the unit square /
// cube. Q2 holds a quadratic exactly on the affine mesh: T_h = T to the solver tolerance (and
// only with the right K: the source and the boundary values are consistent for that K alone).
// A second run with phi + 90 degrees and k1, k2 exchanged is the same tensor. Printed: K, the
// largest error relative to the largest temperature (below 1e-10), and the heat flux -K grad T_h
// of the output at the cube's centre against the closed form.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/fem/physics/heat_conduction.h>

#include "fem_tests.h"

#include <cmath>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  using fem_tests::number;

  const double A[3][3] = {{30., 12., -8.}, {12., -10., 6.}, {-8., 6., 15.}};
  const double b[3]    = {4., -3., 2.};

  // The rotation by @p degrees about the axis @p axis.
  Tensor<2, 3>
  about(const unsigned int axis, const double degrees)
  {
    const double c = std::cos(degrees * numbers::PI / 180.),
                 s = std::sin(degrees * numbers::PI / 180.);
    Tensor<2, 3> R;
    if (axis == 2)
      {
        R[0][0] = c, R[0][1] = -s, R[1][0] = s, R[1][1] = c, R[2][2] = 1.;
      }
    else
      {
        R[1][1] = c, R[1][2] = -s, R[2][1] = s, R[2][2] = c, R[0][0] = 1.;
      }
    return R;
  }

  template <int dim>
  class Exact : public Function<dim>
  {
  public:
    double
    value(const Point<dim> &x, const unsigned int = 0) const override
    {
      double T = 0.;
      for (unsigned int i = 0; i < dim; ++i)
        {
          T += b[i] * x[i];
          for (unsigned int j = 0; j < dim; ++j)
            T += A[i][j] * x[i] * x[j];
        }
      return T;
    }

    Tensor<1, dim>
    gradient(const Point<dim> &x, const unsigned int = 0) const override
    {
      Tensor<1, dim> g;
      for (unsigned int i = 0; i < dim; ++i)
        {
          g[i] = b[i];
          for (unsigned int j = 0; j < dim; ++j)
            g[i] += 2. * A[i][j] * x[j];
        }
      return g;
    }
  };

  template <int dim>
  void
  run(const double k[3], const double angles[3])
  {
    // The closed form of K.
    const Tensor<2, 3> R = about(2, angles[0]) * about(0, angles[1]) * about(2, angles[2]);
    Tensor<2, dim>     K;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int a = 0; a < 3; ++a)
          K[i][j] += R[i][a] * k[a] * R[j][a];
    double source = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        source -= 2. * K[i][j] * A[i][j];
    const char *x = "xyz";
    std::string T;
    for (unsigned int i = 0; i < dim; ++i)
      {
        T += (i > 0 ? " + " : "") + number(b[i]) + "*" + x[i];
        for (unsigned int j = 0; j < dim; ++j)
          T += " + " + number(A[i][j]) + "*" + x[i] + "*" + x[j];
      }
    const std::string text =
      fem_tests::static_problem(dim, "plane stress", number(source), "1e-13") +
      "subsection Finite elements\n"
      "  set Physics = heat\n"
      "  set Generator = hyper_cube\n"
      "  set Generator arguments = 0 : 1 : false\n"
      "  set Global refinements = 2\n"
      "  set Polynomial degree = 2\n"
      "  subsection heat\n"
      "    set Symmetry = orthotropic\n"
      "    set Conductivities = " +
      number(k[0]) + ", " + number(k[1]) + ", " + number(k[2]) +
      "\n"
      "    set Orientation = " +
      number(angles[0]) + ", " + number(angles[1]) + ", " + number(angles[2]) +
      "\n"
      "  end\n"
      "  subsection Boundary conditions\n"
      "    set Names = boundary\n"
      "    subsection boundary\n"
      "      set Boundary ids = 0\n"
      "      set Function = " +
      T +
      "\n"
      "    end\n"
      "  end\n"
      "end\n";
    std::ostringstream            log;
    perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
    const auto                    solution = fem_tests::solve(problem, text);
    const auto                   &fe       = problem.fe_region();
    const auto &physics = dynamic_cast<const perideal::HeatConduction<dim> &>(fe.physics());
    deallog << dim << "D, " << physics.summary() << std::endl << "  K =";
    double K_error = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          deallog << " " << std::fixed << std::setprecision(4) << K[i][j];
          K_error = std::max(K_error, std::abs(physics.conductivity()[i][j] - K[i][j]));
        }
    deallog << " W/(m K)" << std::endl;
    deallog << "  the physics' K equals the closed form: " << (K_error < 1e-12 ? "ok" : "FAILED")
            << std::endl;

    const Exact<dim>      exact;
    dealii::Vector<float> cellwise(fe.get_triangulation().n_active_cells());
    VectorTools::integrate_difference(fe.get_dof_handler(),
                                      solution,
                                      exact,
                                      cellwise,
                                      QGauss<dim>(4),
                                      VectorTools::Linfty_norm);
    const double error =
      VectorTools::compute_global_error(fe.get_triangulation(), cellwise, VectorTools::Linfty_norm);
    double scale = 0.;
    for (unsigned int i = 0; i < dim; ++i)
      {
        scale += std::abs(b[i]);
        for (unsigned int j = 0; j < dim; ++j)
          scale += std::abs(A[i][j]);
      }
    deallog << "  T relative error below 1e-10: " << (error / scale < 1e-10 ? "ok" : "FAILED")
            << std::endl;

    // The output's flux at the centre, from a cell that holds it (a corner of 2^dim cells).
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    const Tensor<1, dim> expected = -(K * exact.gradient(centre));
    const double         largest  = fem_tests::output_error(
      fe,
      solution,
      Quadrature<dim>(std::vector<Point<dim>>{Point<dim>()}),
      [&](const auto &cell) { return cell->vertex(0).distance(centre) < 1e-12; },
      expected);
    deallog << "  heat flux at the centre -K grad T = (";
    for (unsigned int d = 0; d < dim; ++d)
      deallog << (d > 0 ? ", " : "") << expected[d];
    deallog << ") W/m^2, output within 1e-10 relative: "
            << (largest / expected.norm() < 1e-10 ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no CG iteration lines
  const double k[3] = {40., 5., 12.}, swapped[3] = {5., 40., 12.};
  const double in_plane[3] = {30., 0., 0.}, turned[3] = {120., 0., 0.};
  const double tilted[3] = {30., 50., -20.};
  run<2>(k, in_plane);
  run<2>(swapped, turned);
  run<3>(k, tilted);
}
