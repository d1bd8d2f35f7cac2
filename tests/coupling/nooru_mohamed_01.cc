// ---------------------------------------------------------------------
// The Nooru-Mohamed benchmark (doc/benchmarks/nooru_mohamed; seed 003, sec. 3.2; seed note 003,
// T003-12): double-edge-notched concrete with softening Timoshenko-beam bonds, the lateral force
// of 10 kN applied and held, then the normal platens moved apart until the specimen separates
// (explicit dynamics, 2 ms). The benchmark's own files at its resolution (dx = 2 mm), all-PD
// (full_pd.prm) and coupled (coupled.prm: PD in the band of the cracks, FE elsewhere), without
// field output. The files name their includes and meshes relative to the repository's top
// directory, which the test links into its working directory ('doc', 'meshes').
// Checked for each run (the note's qualitative checks, the regression baseline it asks for):
//  - the cracks start at both notch tips: a crack particle (damage >= 0.3) within one horizon;
//  - the final pattern is point-symmetric about the centre within one dx (the Hausdorff distance
//    of the crack set and its image turned by 180 degrees);
//  - the normal force (reaction of the top platen) peaks and softens below 0.8 of its peak;
// and between them: the coupled peak within 1 % of the all-PD one (measured: 0.997), the crack
// sets within one horizon of each other (measured: 2 mm). The same numbers on 1 and 2 ranks.
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
  constexpr double dx = 2e-3, horizon = 3 * dx;

  struct Result
  {
    std::vector<Point<2>> cracks;
    double                peak = 0., last = 0.;
  };

  /// Run the benchmark's file @p name; its crack particles and normal force.
  Result
  run(const std::string &name)
  {
    Result              result;
    std::vector<double> points;
    coupling_tests::run(name + ".prm",
                        "include doc/benchmarks/nooru_mohamed/" + name +
                          ".prm\n"
                          "subsection Output\n"
                          "  set Directory  = " +
                          name +
                          "\n"
                          "  set Write HDF5 = false\n"
                          "end\n",
                        [&](const auto &problem) {
                          points = coupling_tests::gather_damage(problem);
                        });
    for (std::size_t k = 0; k + 3 <= points.size(); k += 3)
      if (points[k + 2] >= 0.3)
        result.cracks.emplace_back(points[k], points[k + 1]);
    const auto force =
      perideal_tests::read_statistics(name + "/statistics.csv").at("reaction_top_y");
    result.peak = *std::max_element(force.begin(), force.end());
    result.last = force.back();
    return result;
  }

  void
  check(const std::string &name, const Result &r)
  {
    const Point<2>        centre(0.1, 0.1);
    std::vector<Point<2>> turned;
    for (const auto &p : r.cracks)
      turned.push_back(Point<2>(2. * centre[0] - p[0], 2. * centre[1] - p[1]));
    const double left     = coupling_tests::nearest_distance(Point<2>(0.025, 0.1), r.cracks);
    const double right    = coupling_tests::nearest_distance(Point<2>(0.175, 0.1), r.cracks);
    const double symmetry = coupling_tests::hausdorff(r.cracks, turned);
    std::cout << name << ": " << r.cracks.size() << " crack particles; peak normal force "
              << r.peak / 1e3 << " kN" << std::endl;
    std::cout << "  cracks at both notch tips (nearest " << 1e3 * left << ", " << 1e3 * right
              << " mm): " << coupling_tests::ok(left <= horizon && right <= horizon) << std::endl;
    std::cout << "  point-symmetric within one dx (" << 1e3 * symmetry
              << " mm): " << coupling_tests::ok(symmetry <= dx * (1. + 1e-9)) << std::endl;
    std::cout << "  peaks and softens below 0.8: " << coupling_tests::ok(r.last < 0.8 * r.peak)
              << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  coupling_tests::link_top_directories();

  std::cout << std::setprecision(3);
  const Result all_pd = run("full_pd"), coupled = run("coupled");
  check("all-PD", all_pd);
  check("coupled", coupled);
  const double ratio    = coupled.peak / all_pd.peak,
               distance = coupling_tests::hausdorff(coupled.cracks, all_pd.cracks);
  std::cout << "coupled / all-PD peak " << ratio
            << " (within 1 %): " << coupling_tests::ok(std::abs(ratio - 1.) < 0.01)
            << "; crack sets " << 1e3 * distance
            << " mm apart (within one horizon): " << coupling_tests::ok(distance <= horizon)
            << std::endl;
}
