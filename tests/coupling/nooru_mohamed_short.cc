// ---------------------------------------------------------------------
// Short variant of the Nooru-Mohamed benchmark (doc/benchmarks/nooru_mohamed; seed 003, sec. 3.2;
// issue #40, part 3): double-edge-notched concrete with softening Timoshenko-beam bonds whose
// elastic limit is the tensile strength (3 MPa), the lateral force of 10 kN applied and held,
// then the normal platens moved apart (explicit dynamics). The benchmark's own files, all-PD
// (full_pd.prm) and coupled with the adaptive PD region (coupled_adaptive.prm), on a lattice
// twice as coarse (dx = 4 mm, delta = 12 mm: 2476 particles all-PD; the platens still one row
// of particles, the slots 24 x 8 mm) and stopped at 1.4 ms instead of 3 ms (the peak is at
// 1.08 ms, the normal force below 0.8 of it from 1.28 ms). The coupled ramps (band and disks)
// are widened from 10 to 16 mm, a horizon plus an FE cell as in the benchmark, and the disks'
// seeds kept 30 mm (their reach and 2 mm) from the FE boundary conditions. Checked for each run
// (nooru_mohamed_tests.h):
//  - the cracks start at both notch tips (damage index of seed note 003, A14, >= 0.3 within one
//    horizon);
//  - against the reference (issue #40): the nominal ligament stress at the peak, normal force
//    over 150 mm x 50 mm, within what a notched specimen of sigma_t = 3 MPa concrete carries,
//    2 ... 4 MPa (measured: 3.86 MPa all-PD, 3.87 MPa adaptive; the benchmark at dx = 2 mm
//    3.92 MPa in both);
//  - the normal force peaks and has fallen below 0.8 of its peak at 1.4 ms (measured: 0.36 and
//    0.35);
// the adaptive run's PD region grew (measured: 20 conversions, 1476 -> 2448 particles), and its
// peak within 1 % of all-PD's. Measured: 1.0024; at this spacing the Strain fraction 0.7 and 1.0
// give 1.0023 and 1.0032, the benchmark at dx = 2 mm 1.0017 ... 1.0022, and the fixed band (the
// adaptive region off, coupled.prm with the 16 mm ramp) 1.027 (1.033 at dx = 2 mm): 1 % is three
// times the largest spread of the adaptive run and a third of the fixed band's excess (README.md).
// With three times the tensile strength the nominal stress is 7.1 MPa, with the former limits
// from G0 alone (k = 2) 8.1 MPa: both fail. The same numbers on 1 and 2 ranks.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "nooru_mohamed_tests.h"

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  coupling_tests::link_top_directories();

  // dx = 4 mm: the platens and lateral platens one row of particles as in the benchmark, the
  // slots 24 x 8 mm in particle volumes (the ligament box keeps the rows at y = 98 and 102 mm).
  const std::string coarse = "subsection Discretization\n"
                             "  set Lattice spacing = 0.004\n"
                             "end\n"
                             "subsection Regions\n"
                             "  subsection bottom\n"
                             "    set Upper corner = 0.2, 0.004\n"
                             "  end\n"
                             "  subsection top\n"
                             "    set Lower corner = 0, 0.196\n"
                             "  end\n"
                             "  subsection left upper\n"
                             "    set Upper corner = 0.004, 0.2\n"
                             "  end\n"
                             "  subsection right lower\n"
                             "    set Lower corner = 0.196, 0\n"
                             "  end\n"
                             "end\n"
                             "subsection Time stepping\n"
                             "  set End time = 1.4e-3\n"
                             "end\n";
  const auto        all_pd = nooru_mohamed_tests::run("full_pd",
                                               coarse + "subsection Boundary conditions\n"
                                                               "  subsection shear\n"
                                                               "    set Layer thickness = 0.004\n"
                                                               "  end\n"
                                                               "end\n",
                                               4e-3);
  // The ramps a horizon (12 mm) plus an FE cell (4 mm) wide, the seeds 30 mm (a disk's reach of
  // 28 mm and 2 mm) from the FE boundary conditions.
  const auto adaptive = nooru_mohamed_tests::run(
    "coupled_adaptive",
    coarse + "subsection Coupling\n"
             "  set Blending function = min(1, max(0, (0.046 - abs(y - 0.1)) / 0.016))\n"
             "  subsection Adaptive region\n"
             "    set Ramp width    = 0.016\n"
             "    set Strain region = min(0.070 - abs(y - 0.1), max(x - 0.030, 0.110 - y), "
             "max(0.170 - x, y - 0.090))\n"
             "  end\n"
             "end\n",
    4e-3);

  std::cout << std::setprecision(3);
  for (const auto &[name, r] :
       {std::make_pair("all-PD", all_pd), std::make_pair("coupled, adaptive", adaptive)})
    {
      nooru_mohamed_tests::check(name, r, true);
      std::cout << "  peak " << std::fixed << std::setprecision(2) << r.peak / 1e3 << " kN at "
                << r.peak_time * 1e3 << " ms, normal force at 1.4 ms " << r.last / r.peak
                << " of the peak" << std::defaultfloat << std::setprecision(3) << std::endl;
    }
  std::cout << "adaptive: " << adaptive.conversions << " conversions, particles "
            << adaptive.n_start << " -> " << adaptive.n_particles << " (all-PD "
            << all_pd.n_particles << "): the PD region grew: "
            << coupling_tests::ok(adaptive.conversions > 0 &&
                                  adaptive.n_particles > adaptive.n_start)
            << std::endl;
  const double ratio = adaptive.peak / all_pd.peak;
  std::cout << "adaptive / all-PD peak " << std::fixed << std::setprecision(4) << ratio
            << " (within 1 %): " << coupling_tests::ok(std::abs(ratio - 1.) < 0.01) << std::endl;
}
