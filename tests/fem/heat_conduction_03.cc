// ---------------------------------------------------------------------
// Transient conduction in a bar with the FE physics 'heat' and the implicit theta scheme
// (<Solver/Type> = implicit): 0 <= x <= L = 0.1 m as a 2D strip (n x 1 cells, insulated long
// sides), T = 0 at both ends, T(x, 0) = T0 sin(pi x / L) with T0 = 100 K, alpha = k / (rho c) =
// 50 / (7800 * 500) m^2/s. The classical series has one term, T = T0 sin(pi x / L)
// exp(-lambda t), lambda = alpha pi^2 / L^2 (Carslaw & Jaeger, Conduction of Heat in Solids,
// 1959, Sect. 3.3). On the uniform mesh the nodal sine is an eigenvector of the lumped capacity
// and the stiffness (the strip's y direction drops out), with lambda_h = 4 alpha / h^2
// sin^2(pi h / (2 L)), so the scheme gives exactly T0 sin(pi x_i / L) g^n with the
// amplification g = (1 - (1 - theta) dt lambda_h) / (1 + theta dt lambda_h). Checked:
//  (a) every run against that closed form (the scheme itself, to the solver tolerance);
//  (b) time steps far above the explicit limit h^2 / (2 alpha) of forward Euler: the error
//      against exp(-lambda_h t) (the semi-discrete solution) falls like dt^2 at theta = 1/2
//      and like dt at theta = 1;
//  (c) the error against the classical series at fixed small dt falls like h^2;
//  (d) the FE region's stable step of forward Euler, 2 / (Gershgorin bound of C^-1 K), lies
//      below the limit h^2 / (2 alpha) of the strip's x modes (the bound exceeds lambda_max).
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

  const double L = 0.1, k = 50., rho = 7800., c = 500., T0 = 100., end_time = 40.;
  const double alpha = k / (rho * c), lambda = alpha * numbers::PI * numbers::PI / (L * L);

  class Sine : public Function<2>
  {
  public:
    explicit Sine(const double amplitude)
      : amplitude(amplitude)
    {}

    double
    value(const Point<2> &x, const unsigned int = 0) const override
    {
      return amplitude * std::sin(numbers::PI * x[0] / L);
    }

  private:
    double amplitude;
  };

  // The largest nodal |T_h - a sin(pi x / L)| over T0.
  double
  nodal_error(const perideal::FERegion<2>                      &fe,
              const LinearAlgebra::distributed::Vector<double> &T,
              const double                                      amplitude)
  {
    LinearAlgebra::distributed::Vector<double> exact;
    fe.initialize_vector(exact);
    fe.interpolate(Sine(amplitude), exact);
    double largest = 0.;
    for (unsigned int i = 0; i < exact.locally_owned_size(); ++i)
      largest = std::max(largest, std::abs(exact.local_element(i) - T.local_element(i)));
    return Utilities::MPI::max(largest, MPI_COMM_WORLD) / T0;
  }

  struct Result
  {
    double scheme_error, semi_discrete_error, classical_error, stable_step;
  };

  Result
  run(const unsigned int n, const double dt, const double theta)
  {
    const std::string           text = fem_tests::heat_strip("implicit",
                                                   n,
                                                   L,
                                                   number(T0) + "*sin(pi*x/" + number(L) + ")",
                                                   end_time,
                                                   dt,
                                                   theta,
                                                   k,
                                                   rho,
                                                   c,
                                                   "    set Names = ends\n"
                                                             "    subsection ends\n"
                                                             "      set Boundary ids = 0, 1\n"
                                                             "    end\n");
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    const auto                  T        = fem_tests::solve(problem, text);
    const auto                 &fe       = problem.fe_region();
    const double                h        = L / n;
    const double                s        = std::sin(numbers::PI * h / (2. * L));
    const double                lambda_h = 4. * alpha / (h * h) * s * s;
    const double                n_steps  = std::round(end_time / dt);
    const double g = (1. - (1. - theta) * dt * lambda_h) / (1. + theta * dt * lambda_h);
    return {nodal_error(fe, T, T0 * std::pow(g, n_steps)),
            nodal_error(fe, T, T0 * std::exp(-lambda_h * end_time)),
            nodal_error(fe, T, T0 * std::exp(-lambda * end_time)),
            fe.stable_time_step()};
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
                "alpha = %.4e m^2/s, T(L/2, %g s) = %.6f K (classical series)",
                alpha,
                end_time,
                T0 * std::exp(-lambda * end_time));
  deallog << line << std::endl;

  // (b) Time steps above the explicit limit on 40 cells.
  const unsigned int n             = 40;
  const double       explicit_step = (L / n) * (L / n) / (2. * alpha);
  bool               scheme_ok     = true;
  for (const double theta : {0.5, 1.})
    {
      double previous = 0.;
      for (const double dt : {8., 4., 2.})
        {
          const Result r    = run(n, dt, theta);
          scheme_ok         = scheme_ok && r.scheme_error < 1e-9;
          const double rate = previous > 0. ? std::log2(previous / r.semi_discrete_error) : 0.;
          std::snprintf(line,
                        sizeof(line),
                        "theta = %.1f, %u cells, dt = %g s (%.0f x the explicit limit): error "
                        "against exp(-lambda_h t) %.3e, rate %.2f",
                        theta,
                        n,
                        dt,
                        dt / explicit_step,
                        r.semi_discrete_error,
                        rate);
          deallog << line << std::endl;
          if (dt == 2.)
            deallog << "  rate within 0.1 of " << (theta == 0.5 ? 2 : 1) << ": "
                    << (std::abs(rate - (theta == 0.5 ? 2. : 1.)) < 0.1 ? "ok" : "FAILED")
                    << std::endl;
          previous = r.semi_discrete_error;
          if (theta == 0.5 && dt == 8.)
            {
              std::snprintf(line,
                            sizeof(line),
                            "  the FE region's forward-Euler step 2 / (Gershgorin bound of "
                            "C^-1 K) = %.4f s, at most h^2 / (2 alpha) = %.4f s: %s",
                            r.stable_step,
                            explicit_step,
                            r.stable_step <= explicit_step ? "ok" : "FAILED");
              deallog << line << std::endl;
            }
        }
    }

  // (c) Convergence in h at theta = 1/2 and dt = 0.25 s.
  double previous = 0., rate = 0.;
  for (const unsigned int cells : {10u, 20u, 40u})
    {
      const Result r = run(cells, 0.25, 0.5);
      scheme_ok      = scheme_ok && r.scheme_error < 1e-9;
      rate           = previous > 0. ? std::log2(previous / r.classical_error) : 0.;
      std::snprintf(line,
                    sizeof(line),
                    "theta = 0.5, dt = 0.25 s, %2u cells: error against the classical series "
                    "%.3e, rate %.2f",
                    cells,
                    r.classical_error,
                    rate);
      deallog << line << std::endl;
      previous = r.classical_error;
    }
  deallog << "  rate within 0.1 of 2: " << (std::abs(rate - 2.) < 0.1 ? "ok" : "FAILED")
          << std::endl;
  deallog << "(a) every run equals the scheme's closed form to 1e-9 T0: "
          << (scheme_ok ? "ok" : "FAILED") << std::endl;
}
