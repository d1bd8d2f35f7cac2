// ---------------------------------------------------------------------
// Short variant of the adaptive alumina quench (doc/benchmarks/thermal_shock/quench_adaptive.prm:
// the water quench of quench.prm, blended for the mechanics and the heat, PD starting in a frame
// 1.25 mm deep along the quenched edges (overlap to 2.05 mm), growing by disks of 2 mm where a
// particle damaged by the run (>= 0.3) comes within 0.75 mm of the edge of the PD-only zone,
// checked after every converged quasi-static load step): a 10 x 10 mm segment (the plate's
// 10 mm width, which sets the cooling; 20 mm long until the default tier's budget of 120 s
// per case asked for half), T0 = 600 degrees C, the first 20 ms in 2 load steps (cut
// above 500 broken bonds, as in the benchmark), without output files. The benchmark's file is
// named relative to the repository's top directory, which the test links into its working
// directory ('doc'). Checked:
//  - bonds break and the PD region grows: the load steps convert (LoadStepping::convert_regions():
//    "the PD region grew" in the log), the particles are more at the end than at the start;
//  - every particle with damage >= 0.3 (the criterion's threshold, the crack measure of
//    cracks.py) is PD only (beta = 1), so no crack runs into the overlap or the FE core;
//  - the cracks start at the quenched edges: the damaged particles lie within 2 mm of an edge
//    and none in the core deeper than L/2 = 2.5 mm, which the cooling puts in compression (PMB
//    breaks in tension only); the deepest is reported;
//  - the broken bonds within 5 % of the same segment all-PD (quench.prm): the cracks do not
//    depend on where the PD region is while they stay in it. (Before CoupledProblem::
//    convert_regions() shared the bonds the mechanics broke in the last load step, by their old
//    indices, with the heat before the rebuild, the heat's later share broke other bonds of the
//    renumbered list: 2772 broken bonds against 2256 all-PD, damage in the FE core.)
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

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  coupling_tests::link_top_directories();

  constexpr double length = 0.01, width = 0.01;
  // The segment and the run, for the benchmark file @p file, output in @p directory.
  const auto segment = [](const std::string &file, const std::string &directory) {
    return "include doc/benchmarks/thermal_shock/" + file +
           "\n"
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
           "    set Lower corner = 0.004775, 0.000525\n"
           "    set Upper corner = 0.004975, 0.000725\n"
           "  end\n"
           "  subsection end\n"
           "    set Lower corner = 0.009775, 0.004775\n"
           "    set Upper corner = 0.009975, 0.004975\n"
           "  end\n"
           "end\n"
           "subsection Temperature\n"
           "  set Reference temperature = 600\n"
           "end\n"
           "subsection Heat\n"
           "  subsection Initial conditions\n"
           "    set Displacement = 600\n"
           "  end\n"
           "end\n"
           "subsection Solver\n"
           "  set Load steps = 2\n"
           "end\n"
           "subsection Time stepping\n"
           "  set End time = 0.02\n"
           "end\n"
           "subsection Output\n"
           "  set Directory  = " +
           directory +
           "\n"
           "  set Write HDF5 = false\n"
           "  set Progress   = false\n"
           "end\n";
  };
  std::vector<double> points, betas;
  const std::string   log = coupling_tests::run(
    "quench_adaptive.prm",
    segment("quench_adaptive.prm", "quench_adaptive") +
      "subsection Finite elements\n"
        "  set Generator arguments = 20, 20 : 0, 0 : 0.01, 0.01 : true\n"
        "end\n"
        "subsection Coupling\n"
        "  set Blending function = min(1, max(0, (0.00205 - min(min(x, 0.01 - x), min(y, 0.01 - "
        "y))) / 0.0008))\n"
        "end\n",
    [&](const auto &problem) {
      points = coupling_tests::gather_damage(problem);
      for (std::size_t k = 0; k + 3 <= points.size(); k += 3)
        betas.push_back(problem.blending(Point<2>(points[k], points[k + 1])));
    });
  // The same segment all-PD (quench.prm).
  coupling_tests::run("quench_pd.prm", segment("quench.prm", "quench_pd"));
  const double broken_pd =
    perideal_tests::read_statistics("quench_pd/statistics.csv").at("broken_bonds").back();
  const unsigned int conversions = coupling_tests::count_lines(log, "the PD region grew");
  const double       first       = coupling_tests::numbers_of(log, "Particles:").at(0);
  const auto         broken =
    perideal_tests::read_statistics("quench_adaptive/statistics.csv").at("broken_bonds").back();

  unsigned int n_particles = 0, damaged = 0, damaged_not_pd = 0, core = 0;
  double       deepest = 0.;
  for (std::size_t k = 0, p = 0; k + 3 <= points.size(); k += 3, ++p)
    {
      ++n_particles;
      const double x = points[k], y = points[k + 1], damage = points[k + 2];
      const double depth = std::min({x, length - x, y, width - y});
      if (damage >= 0.3)
        {
          ++damaged;
          if (betas[p] < 1.)
            ++damaged_not_pd;
        }
      if (damage > 0.)
        {
          deepest = std::max(deepest, depth);
          if (depth > 0.5 * width / 2.)
            ++core;
        }
    }
  std::cout << "T0 = 600 C, 20 ms: broken bonds " << broken << ", conversions " << conversions
            << ", particles " << first << " -> " << n_particles << ", damaged particles (>= 0.3) "
            << damaged << ", of them not PD only " << damaged_not_pd
            << ", deepest damaged particle " << std::fixed << std::setprecision(3) << 1e3 * deepest
            << " mm" << std::defaultfloat << std::endl;
  std::cout << "all-PD: broken bonds " << static_cast<unsigned int>(broken_pd)
            << ", adaptive/all-PD " << std::setprecision(3) << broken / broken_pd
            << std::defaultfloat << std::endl;
  std::cout << "bonds break: " << coupling_tests::ok(broken > 0) << std::endl;
  std::cout << "broken bonds within 5 % of all-PD: "
            << coupling_tests::ok(std::abs(broken / broken_pd - 1.) < 0.05) << std::endl;
  std::cout << "the PD region grew: " << coupling_tests::ok(conversions > 0 && n_particles > first)
            << std::endl;
  std::cout << "every damaged particle is PD only: "
            << coupling_tests::ok(damaged > 0 && damaged_not_pd == 0) << std::endl;
  std::cout << "damage within 2 mm of the edges: " << coupling_tests::ok(deepest <= 2e-3)
            << std::endl;
  std::cout << "no damage in the core (deeper than 2.5 mm): " << coupling_tests::ok(core == 0)
            << std::endl;
}
