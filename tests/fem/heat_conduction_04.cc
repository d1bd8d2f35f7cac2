// ---------------------------------------------------------------------
// Convective cooling of a plate with the FE physics 'heat': a plate of thickness 2 L (L = 0.02
// m) at T_i = 500 K cooled on both faces by convection (h, T_inf = 300 K), modelled as its half
// 0 <= x <= L (x = 0 the insulated mid-plane, the face x = L a 'convection' condition; a 2D strip
// of n x 1 cells with insulated long sides), k = 20 W/(m K), rho c = 8000 * 500 J/(m^3 K), Biot
// number Bi = h L / k = 1. The series solution (Carslaw & Jaeger, Conduction of Heat in Solids,
// 1959, Sect. 3.11; Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, eq. 5.42):
//   (T - T_inf) / (T_i - T_inf) = sum_n C_n exp(-zeta_n^2 Fo) cos(zeta_n x / L),
//   zeta_n tan zeta_n = Bi, C_n = 4 sin zeta_n / (2 zeta_n + sin 2 zeta_n), Fo = alpha t / L^2,
// summed here over 50 terms (the roots by bisection in ((n - 1) pi, (n - 1/2) pi)).
// Checked at Fo = 0.5 (t = 40 s) at the mid-plane and the face: the errors relative to
// T_i - T_inf with the implicit Crank-Nicolson scheme fall like h^2 + dt^2 when both halve, and
// with explicit forward Euler at 0.8 of the FE region's stable step (2 / Gershgorin bound, so
// dt ~ h^2) like h^2.
// ---------------------------------------------------------------------
#include <deal.II/base/function.h>

#include "fem_tests.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  using fem_tests::number;

  const double L = 0.02, k = 20., rho = 8000., c = 500., h = 1000., T_i = 500., T_inf = 300.;
  const double alpha = k / (rho * c), Bi = h * L / k, end_time = 0.5 * L * L / alpha;

  // The series solution at x / L = @p xi and Fourier number @p Fo.
  double
  series(const double xi, const double Fo)
  {
    double theta = 0.;
    for (unsigned int n = 1; n <= 50; ++n)
      {
        // zeta tan zeta - Bi rises from -Bi to +infinity on the interval: bisection.
        double low = (n - 1.) * numbers::PI, high = (n - 0.5) * numbers::PI;
        for (unsigned int it = 0; it < 100; ++it)
          {
            const double middle                           = 0.5 * (low + high);
            (middle * std::tan(middle) < Bi ? low : high) = middle;
          }
        const double zeta = 0.5 * (low + high);
        const double C    = 4. * std::sin(zeta) / (2. * zeta + std::sin(2. * zeta));
        theta += C * std::exp(-zeta * zeta * Fo) * std::cos(zeta * xi);
      }
    return T_inf + (T_i - T_inf) * theta;
  }

  // The temperature of the FE solution @p T at x (any y): the owned nodal value there.
  double
  temperature_at(const perideal::FERegion<2>                      &fe,
                 const LinearAlgebra::distributed::Vector<double> &T,
                 const double                                      x)
  {
    double value = -1e300;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          if (std::abs(cell->vertex(v)[0] - x) < 1e-12 * L)
            value = std::max(value, T(cell->vertex_dof_index(v, 0, 0)));
    return Utilities::MPI::max(value, MPI_COMM_WORLD);
  }

  std::pair<double, double>
  run(const std::string &solver, const unsigned int n, const double dt)
  {
    const std::string text =
      fem_tests::heat_strip(solver,
                            n,
                            L,
                            number(T_i),
                            end_time,
                            dt,
                            0.5,
                            k,
                            rho,
                            c,
                            "    set Names = cooled\n"
                            "    subsection cooled\n"
                            "      set Boundary ids = 1\n"
                            "      set Type = convection\n"
                            "      set Heat transfer coefficient = " +
                              number(h) + "\n      set Ambient temperature = " + number(T_inf) +
                              "\n    end\n");
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    const auto                  T  = fem_tests::solve(problem, text);
    const auto                 &fe = problem.fe_region();
    return {temperature_at(fe, T, 0.), temperature_at(fe, T, L)};
  }

  void
  cooling(const std::string &solver, const std::vector<std::pair<unsigned int, double>> &runs)
  {
    const double mid = series(0., 0.5), face = series(1., 0.5);
    char         line[200];
    double       previous = 0., rate = 0.;
    for (const auto &[n, dt] : runs)
      {
        const auto [T_mid, T_face] = run(solver, n, dt);
        const double error =
          std::max(std::abs(T_mid - mid), std::abs(T_face - face)) / (T_i - T_inf);
        rate = previous > 0. ? std::log2(previous / error) : 0.;
        std::snprintf(line,
                      sizeof(line),
                      "%s, %2u cells, dt = %s: T(0) = %.3f K, T(L) = %.3f K, error %.3e, "
                      "rate %.2f",
                      solver.c_str(),
                      n,
                      (dt > 0. ? number(dt) + " s" : std::string("automatic")).c_str(),
                      T_mid,
                      T_face,
                      error,
                      rate);
        deallog << line << std::endl;
        previous = error;
      }
    deallog << "  rate within 0.2 of 2: " << (std::abs(rate - 2.) < 0.2 ? "ok" : "FAILED")
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);
  char line[200];
  std::snprintf(line,
                sizeof(line),
                "Bi = %.2f, Fo = 0.5 at t = %.1f s: series T(0) = %.3f K, T(L) = %.3f K",
                Bi,
                end_time,
                series(0., 0.5),
                series(1., 0.5));
  deallog << line << std::endl;
  cooling("implicit", {{10, 2.}, {20, 1.}, {40, 0.5}});
  cooling("explicit", {{10, 0.}, {20, 0.}, {40, 0.}});
}
