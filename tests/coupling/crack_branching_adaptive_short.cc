// ---------------------------------------------------------------------
// Short variant of the adaptive crack-branching run (doc/benchmarks/crack_branching/
// branching_adaptive.prm: FE everywhere but a PD disk at the notch tip and PD strips along the
// loaded edges; the PD region grows where the run damages particles near its edge): the
// benchmark's file at dx = 0.5 mm, delta = 2 mm (instead of 0.25 and 1 mm; the ramp of 2 mm
// needs delta <= 2 mm), the whole 46 us, without output files. A crack particle has a damage
// index of at least 0.35 and lies beyond the notch tip (50, 0) mm by more than a horizon.
// Measured: the conversions, the particles at the end against the plate's lattice (what
// all-PD carries), the energy change of the conversions against the external work, and the
// crack: its farthest particle in x and its largest distance from the notch line y = 0.
// Expected (the benchmark's README): the run reaches 46 us (a crack outside the PD-only zone at a
// check would stop it), the crack reaches the right edge (beyond x = 95 mm; all-PD: the branch
// tips at x = 99.8 mm) and a branch leaves the notch line by more than 8 mm (all-PD: 12.8 mm;
// the adaptive benchmark at dx = 0.5 mm: 15.2 mm), so the PD region followed the crack and a
// branch; fewer particles than the plate's lattice (0.65 measured: the strips along the edges
// and the branches' disks); conversion energy within 1 % of the work. The same numbers on 1 and
// 2 ranks.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

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

  constexpr double    dx = 5e-4, horizon = 4. * dx;
  std::vector<double> points; // rank 0: x, y, damage of every particle at the end
  unsigned int        n_particles = 0;
  const std::string   log =
    coupling_tests::run("branching_adaptive.prm",
                        "include " SOURCE_DIR
                        "/../../doc/benchmarks/crack_branching/branching_adaptive.prm\n"
                        "subsection Discretization\n"
                        "  set Lattice spacing = 5e-4\n"
                        "end\n"
                        "subsection Finite elements\n"
                        "  set Mesh file = " SOURCE_DIR "/../../meshes/crack_branching_2d.msh\n"
                        "end\n"
                        "subsection Output\n"
                        "  set Directory  = results\n"
                        "  set Write HDF5 = false\n"
                        "  set Progress   = false\n"
                        "end\n",
                        [&](const auto &problem) {
                          points      = coupling_tests::gather_damage(problem);
                          n_particles = problem.particles().n_global();
                        });
  const double plate_points = 0.1 * 0.04 / (dx * dx);
  const double change       = coupling_tests::print_conversions(log, n_particles, plate_points);
  std::cout << "  fewer particles than the plate's lattice: "
            << coupling_tests::ok(n_particles < plate_points) << std::endl;
  std::cout << "  conversion energy within 1 % of the work: "
            << coupling_tests::ok(std::abs(change) < 0.01) << std::endl;

  double       reach = 0., off_axis = 0.;
  unsigned int n_crack = 0;
  for (std::size_t k = 0; k + 3 <= points.size(); k += 3)
    if (points[k + 2] >= 0.35 && points[k] > 0.05 + horizon)
      {
        reach    = std::max(reach, points[k]);
        off_axis = std::max(off_axis, std::abs(points[k + 1]));
        ++n_crack;
      }
  std::cout << std::fixed << std::setprecision(1) << "crack: " << n_crack
            << " particles, farthest at x = " << reach * 1e3 << " mm, largest |y| "
            << off_axis * 1e3 << " mm" << std::endl;
  std::cout << "  reaches the right edge (x > 95 mm): " << coupling_tests::ok(reach > 0.095)
            << std::endl;
  std::cout << "  a branch leaves the notch line by more than 8 mm: "
            << coupling_tests::ok(off_axis > 0.008) << std::endl;
}
