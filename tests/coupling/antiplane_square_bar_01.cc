// ---------------------------------------------------------------------
// Short variant of the benchmark antiplane_square_bar (doc/benchmarks/antiplane_square_bar: seed
// 000, example 8.1, the square bar |x|, |y| <= 1/2 under antiplane shear, mu = 12e6, S = 12000):
// its PD file at dx = 0.02 (50 x 50 particles, six fictitious layers held at 0 beyond each
// clamped side) with the bond-based model, the state-based model with stabilization 0.1 and the
// paper's state-based model (stabilization 0). Printed: w at the top particle (0.01, 0.49)
// against the Fourier series there (antiplane_benchmarks.h) and the largest error over the
// particles at least 0.1 from the top corners (where the clamp meets the load), both relative to
// the series maximum w(0, 1/2) = 3.727434e-4. Tolerances from the benchmark's convergence table
// (README.md; the errors halve with dx), a quarter above the values measured at dx = 0.02:
// bond-based 2.01 % at the top (accepted 2.5 %) and 5.19 % away from the corners (accepted
// 6.5 %); state-based with stabilization 0.1 5.15 % (6.5 %) and 13.4 % (16.5 %); the paper's
// state-based model is wrong by more than 400 % away from the corners at every dx (its zero-energy
// modes, seed note 000 E1): accepted only above 20 %, without its numbers (the singular solve's
// oscillation is not reproducible across ranks).
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <cmath>
#include <cstdio>

#include <antiplane_benchmarks.h>
#include <tests.h>

using namespace dealii;
namespace ab = antiplane_benchmarks;

namespace
{
  // The benchmark's PD file at dx = 0.02 (six layers beyond each side, the top row) with the model
  // MODEL and stabilization ALPHA.
  const std::string pd_short = "include " SOURCE_DIR
                               "/../../doc/benchmarks/antiplane_square_bar/square_bar_pd.prm"
                               R"(
subsection Regions
  subsection left
    set Lower corner = -0.62, -0.5
  end
  subsection right
    set Upper corner = 0.62, 0.5
  end
  subsection top
    set Lower corner = -0.5, 0.48
  end
end
)" + ab::short_variant;

  // The short variant of @p model with stabilization @p alpha: accepted within @p top_tolerance
  // (the top particle) and @p tolerance (away from the corners), or, for a @p known_failure, with
  // a largest error above 20 %.
  void
  run(const std::string &model,
      const std::string &alpha,
      const double       top_tolerance,
      const double       tolerance,
      const bool         known_failure = false)
  {
    const auto measured =
      ab::measure("square_bar.prm",
                  coupling_tests::substitute(pd_short, {{"MODEL", model}, {"ALPHA", alpha}}),
                  ab::square_bar,
                  [](const Point<2> &p) {
                    return std::abs(p[0]) < 0.5 &&
                           std::hypot(0.5 - std::abs(p[0]), 0.5 - p[1]) > 0.1;
                  });
    const double      w_max = ab::square_bar(Point<2>(0., 0.5));
    const double      exact = ab::square_bar(Point<2>(0.01, 0.49));
    const double      error = measured.largest_error, top = measured.top;
    const double      top_error = (top - exact) / w_max;
    const std::string name      = model + " (stabilization " + alpha + "), dx = 0.02";
    if (known_failure)
      {
        deallog << ab::known_failure(name, " 0.1 from the top corners", "w_max", error / w_max, 0.2)
                << std::endl;
        return;
      }
    char line[300];
    std::snprintf(line,
                  sizeof(line),
                  "%s: w(0.01, 0.49) = %.4e, series %.4e, error %+.2f %% of w_max (within "
                  "%.1f %%: %s); largest error 0.1 from the top corners %.2f %% (within %.1f "
                  "%%: %s)",
                  name.c_str(),
                  top,
                  exact,
                  100. * top_error,
                  100. * top_tolerance,
                  coupling_tests::ok(std::abs(top_error) < top_tolerance),
                  100. * error / w_max,
                  100. * tolerance,
                  coupling_tests::ok(error / w_max < tolerance));
    deallog << line << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);
  deallog << "series: w(0, 1/2) = " << ab::square_bar(Point<2>(0., 0.5))
          << ", w(0.005, 0.495) = " << ab::square_bar(Point<2>(0.005, 0.495)) << std::endl;
  run("antiplane bond based", "0", 0.025, 0.065);
  run("antiplane state based", "0.1", 0.065, 0.165);
  run("antiplane state based", "0", 0., 0., true);
}
