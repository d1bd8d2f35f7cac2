// ---------------------------------------------------------------------
// Steady states of the FE physics 'heat' (rho c dT/dt - div(K grad T) = q) that Q1 holds
// exactly, through the problem's static path:
//  (a) the linear temperature patch test, T = T0 + b . x with 'value' conditions on the whole
//      boundary of a disc / ball mesh (non-affine cells), for an isotropic and an orthotropic
//      K in rotated axes: div(K grad T) = 0, so T_h = T at every point, and the heat flux of
//      the output, -K grad T_h, is -K b;
//  (b) a slab 0 <= x <= L (insulated faces y = 0, H) with T = T0 at x = 0 and the heat flux g
//      into the body at x = L ('flux'): T = T0 + g x / k;
//  (c) the same slab with the source q (the body force) and T = 0 at both ends:
//      T = q x (L - x) / (2 k), exact at the nodes (a 1D problem: the Galerkin solution is
//      nodally exact);
//  (d) the slab with T = T0 at x = 0 and convection h (T_inf - T) at x = L ('convection', a
//      Robin condition): T = T0 + s x with s = h (T_inf - T0) / (k + h L).
// Printed: the largest error relative to the largest temperature (below 1e-10: round-off of
// the solver tolerance 1e-13), the flux and the reactions.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/vector_tools.h>

#include <perideal/fem/physics/heat_conduction.h>

#include "fem_tests.h"

#include <cmath>
#include <functional>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  using fem_tests::number;

  const double L = 0.2, H = 0.05, t = 0.01, k = 45., T0 = 300.;

  // The temperature as a deal.II function.
  template <int dim>
  class Exact : public Function<dim>
  {
  public:
    explicit Exact(const std::function<double(const Point<dim> &)> &f)
      : f(f)
    {}

    double
    value(const Point<dim> &x, const unsigned int = 0) const override
    {
      return f(x);
    }

  private:
    std::function<double(const Point<dim> &)> f;
  };

  // The largest |T_h - T| at the quadrature points of Q(3) relative to max |T|.
  template <int dim>
  double
  relative_error(const perideal::CoupledProblem<dim>              &problem,
                 const LinearAlgebra::distributed::Vector<double> &solution,
                 const std::function<double(const Point<dim> &)>  &exact,
                 const double                                      scale)
  {
    const auto           &fe = problem.fe_region();
    dealii::Vector<float> cellwise(fe.get_triangulation().n_active_cells());
    VectorTools::integrate_difference(fe.get_dof_handler(),
                                      solution,
                                      Exact<dim>(exact),
                                      cellwise,
                                      QGauss<dim>(3),
                                      VectorTools::Linfty_norm);
    return VectorTools::compute_global_error(fe.get_triangulation(),
                                             cellwise,
                                             VectorTools::Linfty_norm) /
           scale;
  }

  void
  verdict(const std::string &what, const double error)
  {
    deallog << what << " relative error below 1e-10: " << (error < 1e-10 ? "ok" : "FAILED")
            << std::endl;
  }

  // (a) The patch test on a disc / ball.
  template <int dim>
  void
  patch_test(const std::string &conductivity)
  {
    const double b[3]   = {120., -80., 40.};
    std::string  linear = number(T0);
    for (unsigned int d = 0; d < dim; ++d)
      linear += " + " + number(b[d]) + "*" + "xyz"[d];
    const std::string text = fem_tests::static_problem(dim, "plane stress", "0", "1e-13") +
                             "subsection Finite elements\n"
                             "  set Physics = heat\n"
                             "  set Generator = hyper_ball\n"
                             "  set Generator arguments = " +
                             std::string(dim == 2 ? "0, 0" : "0, 0, 0") +
                             " : 0.1 : false\n"
                             "  set Global refinements = " +
                             std::to_string(dim == 2 ? 3 : 2) +
                             "\n"
                             "  subsection heat\n" +
                             conductivity +
                             "  end\n"
                             "  subsection Boundary conditions\n"
                             "    set Names = held\n"
                             "    subsection held\n"
                             "      set Boundary ids = 0\n"
                             "      set Function = " +
                             linear +
                             "\n"
                             "    end\n"
                             "  end\n"
                             "end\n";
    std::ostringstream            log;
    perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
    const auto                    solution = fem_tests::solve(problem, text);
    const auto                    exact    = [&](const Point<dim> &x) {
      double T = T0;
      for (unsigned int d = 0; d < dim; ++d)
        T += b[d] * x[d];
      return T;
    };
    deallog << dim << "D patch test, " << problem.fe_region().physics().summary() << std::endl;
    verdict("  T", relative_error<dim>(problem, solution, exact, T0));

    // The output's heat flux -K grad T_h at the cell centres of the owned cells against -K b.
    const auto &physics =
      dynamic_cast<const perideal::HeatConduction<dim> &>(problem.fe_region().physics());
    Tensor<1, dim> gradient;
    for (unsigned int d = 0; d < dim; ++d)
      gradient[d] = b[d];
    const Tensor<1, dim> expected = -(physics.conductivity() * gradient);
    const double         largest  = fem_tests::output_error(
      problem.fe_region(),
      solution,
      QGauss<dim>(1),
      [](const auto &) { return true; },
      expected);
    deallog << "  heat flux -K b = (";
    for (unsigned int d = 0; d < dim; ++d)
      deallog << (d > 0 ? ", " : "") << std::fixed << std::setprecision(4) << expected[d];
    deallog << ") W/m^2" << std::endl;
    verdict("  output heat flux", largest / expected.norm());
  }

  // The slab of (b), (c), (d): 2D, 8 x 2 cells, ids 0 (x = 0), 1 (x = L), 2, 3 (insulated).
  std::string
  slab(const std::string &source, const std::string &conditions)
  {
    return fem_tests::static_problem(2, "plane stress", source, "1e-13") +
           "subsection Discretization\n"
           "  set Thickness = " +
           number(t) +
           "\n"
           "end\n"
           "subsection Finite elements\n"
           "  set Physics = heat\n"
           "  set Generator = subdivided_hyper_rectangle\n"
           "  set Generator arguments = 8, 2 : 0, 0 : " +
           number(L) + ", " + number(H) +
           " : true\n"
           "  subsection heat\n"
           "    set Conductivity = " +
           number(k) +
           "\n"
           "  end\n"
           "  subsection Boundary conditions\n" +
           conditions +
           "  end\n"
           "end\n";
  }

  void
  slab_flux()
  {
    const double                g = 5e4;
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    const auto                  solution = fem_tests::solve(problem,
                                           slab("0",
                                                "    set Names = held, heated\n"
                                                                 "    subsection held\n"
                                                                 "      set Boundary ids = 0\n"
                                                                 "      set Function = " +
                                                  number(T0) +
                                                  "\n"
                                                                   "    end\n"
                                                                   "    subsection heated\n"
                                                                   "      set Boundary ids = 1\n"
                                                                   "      set Type = flux\n"
                                                                   "      set Function = " +
                                                  number(g) +
                                                  "\n"
                                                                   "    end\n"));
    deallog << "slab, flux g = " << g << " W/m^2 at x = L: T(L) = T0 + g L / k = " << T0 + g * L / k
            << " K" << std::endl;
    verdict("  T",
            relative_error<2>(
              problem,
              solution,
              [&](const Point<2> &x) { return T0 + g * x[0] / k; },
              T0 + g * L / k));
  }

  void
  slab_source()
  {
    const double                q = 2e6;
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    const auto                  solution = fem_tests::solve(problem,
                                           slab(number(q),
                                                "    set Names = ends\n"
                                                                 "    subsection ends\n"
                                                                 "      set Boundary ids = 0, 1\n"
                                                                 "    end\n"));
    deallog << "slab, source q = " << q
            << " W/m^3: T(L/2) = q L^2 / (8 k) = " << q * L * L / (8. * k) << " K" << std::endl;
    // The nodes of the uniform mesh: x = L i / 8.
    const auto &fe    = problem.fe_region();
    const auto  exact = [&](const Point<2> &x) { return q * x[0] * (L - x[0]) / (2. * k); };
    LinearAlgebra::distributed::Vector<double> interpolated;
    fe.initialize_vector(interpolated);
    fe.interpolate(Exact<2>(exact), interpolated);
    double largest = 0.;
    for (unsigned int i = 0; i < interpolated.locally_owned_size(); ++i)
      largest =
        std::max(largest, std::abs(interpolated.local_element(i) - solution.local_element(i)));
    largest = Utilities::MPI::max(largest, MPI_COMM_WORLD);
    verdict("  nodal T", largest / (q * L * L / (8. * k)));
  }

  void
  slab_convection()
  {
    const double                h = 800., T_inf = 350.;
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    const auto                  solution = fem_tests::solve(problem,
                                           slab("0",
                                                "    set Names = held, cooled\n"
                                                                 "    subsection held\n"
                                                                 "      set Boundary ids = 0\n"
                                                                 "      set Function = " +
                                                  number(T0) +
                                                  "\n"
                                                                   "    end\n"
                                                                   "    subsection cooled\n"
                                                                   "      set Boundary ids = 1\n"
                                                                   "      set Type = convection\n"
                                                                   "      set Heat transfer coefficient = " +
                                                  number(h) +
                                                  "\n"
                                                                   "      set Ambient temperature = " +
                                                  number(T_inf) +
                                                  "\n"
                                                                   "    end\n"));
    const double                s        = h * (T_inf - T0) / (k + h * L);
    deallog << "slab, convection h = " << h << " W/(m^2 K), T_inf = " << T_inf
            << " K at x = L: T(L) = " << T0 + s * L << " K" << std::endl;
    verdict("  T",
            relative_error<2>(
              problem,
              solution,
              [&](const Point<2> &x) { return T0 + s * x[0]; },
              T0 + s * L));
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no CG iteration lines
  const std::string isotropic = "    set Conductivity = 45\n";
  const std::string rotated   = "    set Symmetry = orthotropic\n"
                                "    set Conductivities = 40, 5, 12\n"
                                "    set Orientation = 30, 50, -20\n";
  patch_test<2>(isotropic);
  patch_test<2>(rotated);
  patch_test<3>(isotropic);
  patch_test<3>(rotated);
  slab_flux();
  slab_source();
  slab_convection();
}
