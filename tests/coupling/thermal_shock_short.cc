// ---------------------------------------------------------------------
// Short variant of the alumina quench (doc/benchmarks/thermal_shock: quench.prm, all-PD bond-based
// PMB on its perturbed lattice, dx = 0.25 mm, delta = 3.015 dx, convection h = 5e4 W/(m^2 K) to
// water at 20 degrees C on all edges): a 10 x 10 mm segment (the plate's 10 mm width, which sets
// the cooling; its cooled skin is 0.3 mm deep at 10 ms), the first 10 ms of the cooling in 4 load
// steps (cut above 500 broken bonds, as in the benchmark), from T0 = 300 and 600 degrees C, without
// output files. The benchmark's file is named relative to the repository's top directory, which the
// test links into its working directory ('doc'). Checked (the thermal_shock_subcritical /
// _supercritical app tests check the critical dT itself):
//  - bonds break at both T0 (dT = 280 and 580 K, far above dT_c = 83.2 K);
//  - more at the higher T0 (measured: 336 and 858), the damaged skin along the edges longer;
//  - the damage stays at the quenched edges: every particle with a damage index > 0 lies within
//    one horizon and one spacing (1.0 mm) of an edge (the cooled skin is sqrt(kappa t) = 0.3 mm
//    deep at 10 ms, a bond reaches one horizon beyond it), the hot core (deeper than two
//    horizons) has none: its compression breaks nothing (PMB breaks in tension only).
// The same numbers on 1 and 2 ranks.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  constexpr double dx = 2.5e-4, horizon = 3.015 * dx, length = 0.01, width = 0.01;

  struct Result
  {
    unsigned int broken = 0;
    /// Particles along the top and bottom edges (their first particle row) with a damage index
    /// > 0.3.
    unsigned int skin = 0;
    /// The deepest damaged particle (distance to its nearest edge) and the damaged particles
    /// deeper than two horizons.
    double       deepest = 0.;
    unsigned int core    = 0;
  };

  Result
  run(const unsigned int t0)
  {
    const std::string   name = "quench_" + std::to_string(t0);
    const std::string   T    = std::to_string(t0);
    Result              result;
    std::vector<double> points;
    coupling_tests::run(name + ".prm",
                        "include doc/benchmarks/thermal_shock/quench.prm\n"
                        "subsection Regions\n"
                        "  subsection plate\n"
                        "    set Upper corner = 0.01, 0.01\n"
                        "  end\n"
                        "  subsection top\n"
                        "    set Upper corner = 0.01, 0.01\n"
                        "  end\n"
                        "  subsection bottom\n"
                        "    set Upper corner = 0.01, 0.00025\n"
                        "  end\n"
                        "  subsection right\n"
                        "    set Lower corner = 0.00975, 0\n"
                        "    set Upper corner = 0.01, 0.01\n"
                        "  end\n"
                        "  subsection centre\n"
                        "    set Lower corner = 0.004775, 0.004775\n"
                        "    set Upper corner = 0.004975, 0.004975\n"
                        "  end\n"
                        "  subsection end\n"
                        "    set Lower corner = 0.009775, 0.004775\n"
                        "    set Upper corner = 0.009975, 0.004975\n"
                        "  end\n"
                        "end\n"
                        "subsection Temperature\n"
                        "  set Reference temperature = " +
                          T +
                          "\n"
                          "end\n"
                          "subsection Heat\n"
                          "  subsection Initial conditions\n"
                          "    set Displacement = " +
                          T +
                          "\n"
                          "  end\n"
                          "end\n"
                          "subsection Solver\n"
                          "  set Load steps = 4\n"
                          "end\n"
                          "subsection Time stepping\n"
                          "  set End time = 0.01\n"
                          "end\n"
                          "subsection Output\n"
                          "  set Directory  = " +
                          name +
                          "\n"
                          "  set Write HDF5 = false\n"
                          "  set Progress   = false\n"
                          "end\n",
                        [&](const auto &problem) {
                          points = coupling_tests::gather_damage(problem);
                        });
    result.broken = static_cast<unsigned int>(
      perideal_tests::read_statistics(name + "/statistics.csv").at("broken_bonds").back());
    for (std::size_t k = 0; k + 3 <= points.size(); k += 3)
      {
        const double x = points[k], y = points[k + 1], damage = points[k + 2];
        const double depth = std::min({x, length - x, y, width - y});
        if (damage > 0.)
          {
            result.deepest = std::max(result.deepest, depth);
            if (depth > 2. * horizon)
              ++result.core;
          }
        if (damage > 0.3 && std::min(y, width - y) < dx)
          ++result.skin;
      }
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  coupling_tests::link_top_directories();

  const Result low = run(300), high = run(600);
  for (const auto &[t0, r] : {std::make_pair(300, low), std::make_pair(600, high)})
    {
      std::cout << "T0 = " << t0 << " C: broken bonds " << r.broken
                << ", damaged particles (> 0.3) in the top and bottom edges' first row " << r.skin
                << ", deepest damaged particle " << std::fixed << std::setprecision(3)
                << 1e3 * r.deepest << " mm" << std::defaultfloat << std::endl;
      std::cout << "  bonds break: " << coupling_tests::ok(r.broken > 0) << std::endl;
      std::cout << "  damage within a horizon and a spacing of the edges: "
                << coupling_tests::ok(r.deepest <= horizon + dx) << std::endl;
      std::cout << "  no damage in the core (deeper than two horizons): "
                << coupling_tests::ok(r.core == 0) << std::endl;
    }
  std::cout << "more broken bonds at T0 = 600 C: " << coupling_tests::ok(high.broken > low.broken)
            << std::endl;
  std::cout << "longer damaged skin at T0 = 600 C: " << coupling_tests::ok(high.skin > low.skin)
            << std::endl;
}
