// ---------------------------------------------------------------------
// The Nooru-Mohamed benchmark (doc/benchmarks/nooru_mohamed; seed 003, sec. 3.2; seed note 003,
// T003-12; issue #40, part 3): double-edge-notched concrete with softening Timoshenko-beam bonds
// whose elastic limit is the tensile strength (3 MPa), the lateral force of 10 kN applied and
// held, then the normal platens moved apart (explicit dynamics, 3 ms). The benchmark's own three
// runs at its resolution (dx = 2 mm) and full length, without field output (nooru_mohamed_tests.h):
// all-PD (full_pd.prm), coupled with the fixed band (coupled.prm: PD in the band of the cracks,
// FE elsewhere) and coupled with the adaptive PD region (coupled_adaptive.prm). Checked for each
// run:
//  - the cracks start at both notch tips: a crack particle (damage index >= 0.3) within one
//    horizon;
//  - against the reference (issue #40), all-PD and adaptive: the nominal ligament stress at the
//    peak, normal force over 150 mm x 50 mm, within what a notched specimen of sigma_t = 3 MPa
//    concrete carries, 2 ... 4 MPa (measured: 3.92 MPa in both; the fixed band's 4.05 MPa is
//    printed);
//  - the normal force (reaction of the top platen) peaks and softens below 0.8 of its peak;
// and against all-PD the fixed band's peak within 5 % (measured: 1.033; its FE part cannot
// soften, and near the peak the whole body's stress reaches sigma_t, README.md) and the adaptive
// run's within 2 % (issue #40; measured: 1.002). The point symmetry of the final pattern is no
// longer checked: the two curved cracks race after the peak (README.md). The default set's
// nooru_mohamed_short checks the same on a lattice twice as coarse, stopped at 1.4 ms. The same
// numbers on 1 and 2 ranks.
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

  const auto all_pd   = nooru_mohamed_tests::run("full_pd");
  const auto coupled  = nooru_mohamed_tests::run("coupled");
  const auto adaptive = nooru_mohamed_tests::run("coupled_adaptive");
  std::cout << std::setprecision(3);
  nooru_mohamed_tests::check("all-PD", all_pd, true);
  nooru_mohamed_tests::check("coupled", coupled, false);
  nooru_mohamed_tests::check("coupled, adaptive", adaptive, true);
  const double ratio = coupled.peak / all_pd.peak;
  std::cout << "coupled / all-PD peak " << ratio
            << " (within 5 %): " << coupling_tests::ok(std::abs(ratio - 1.) < 0.05) << std::endl;
  const double adaptive_ratio = adaptive.peak / all_pd.peak;
  std::cout << "adaptive / all-PD peak " << std::fixed << std::setprecision(4) << adaptive_ratio
            << " (within 2 %): " << coupling_tests::ok(std::abs(adaptive_ratio - 1.) < 0.02)
            << std::endl;
}
