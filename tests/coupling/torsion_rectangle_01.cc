// ---------------------------------------------------------------------
// Short variant of the benchmark torsion_rectangle (doc/benchmarks/torsion_rectangle: seed 000,
// example 8.4, the 1 x 2 bar, mu = psi = 1): its FE file with Q1 at h = 1/8 and its PD file
// (bond-based antiplane model, twisted bond slope) at dx = 0.05, each run through perideal-solid's
// driver. Printed: the torque T/(mu psi) of each against the Saint-Venant series (T = 0.457363)
// and T psi / (2E), with verdicts whose tolerances come from the benchmark's convergence table
// (README.md): the FE torque converges from above like h^2 (the Galerkin solution is too stiff:
// +2.3 % at h = 1/4, +0.59 % at 1/8, +0.15 % at 1/16; accepted |error| < 1 %) and T psi = 2E
// holds to round-off (exact for the Galerkin solution; accepted 1e-8); the PD torque stays within
// 0.8 % of the series for every dx of the table (-0.76 % at dx = 0.1, -0.67 % at 0.05, -0.08 % at
// 0.02, +0.03 % at 0.01; accepted |error| < 1 %), and T psi / (2E) - 1, which falls like dx
// (-1.7 % at 0.05, -1.2 % at 0.02, -0.7 % at 0.01: the energy of the boundary layer), within 3 %.
// The same PD file with the state-based antiplane model (twisted slopes in its shear angles):
// torque -2.0 % at dx = 0.05, -0.70 % at 0.025, -0.48 % at 0.02, -0.14 % at 0.01 (accepted
// |error| < 3 %), T psi / (2E) - 1 = +0.78 % at 0.05, +0.04 % at 0.02 (accepted 2 %).
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <cmath>
#include <cstdio>

#include <saint_venant.h>
#include <tests.h>

using namespace dealii;

namespace
{
  void
  run(const std::string &label,
      const std::string &name,
      const std::string &overrides,
      const double       tolerance,
      const double       energy_tolerance)
  {
    const auto   integrals = coupling_tests::run_torsion("torsion_rectangle/" + name, overrides);
    const double T         = integrals.torque;
    const double E         = integrals.energy;
    const double error     = T / saint_venant::torque(0.5, 1.) - 1.;
    const double clapeyron = T / (2. * E) - 1.;
    char         line[300];
    std::snprintf(line,
                  sizeof(line),
                  "%s: T/(mu psi) = %.5f, error %+.2f %% (within %.0f %%: %s), T psi/(2E) - 1 = "
                  "%+.2e (within %.0e: %s)",
                  label.c_str(),
                  T,
                  100. * error,
                  100. * tolerance,
                  std::abs(error) < tolerance ? "yes" : "NO",
                  std::abs(clapeyron) < 1e-8 ? 0. : clapeyron,
                  energy_tolerance,
                  std::abs(clapeyron) < energy_tolerance ? "yes" : "NO");
    deallog << line << std::endl;
    MPI_Barrier(MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no CG iteration lines
  deallog << "Saint-Venant: T/(mu psi) = " << saint_venant::torque(0.5, 1.) << std::endl;
  run("torsion_fe.prm",
      "torsion_fe.prm",
      "subsection Finite elements\n  set Global refinements = 3\nend\n",
      0.01,
      1e-8);
  run("torsion_pd.prm",
      "torsion_pd.prm",
      coupling_tests::torsion_pd_overrides(0.05, "antiplane bond based"),
      0.01,
      0.03);
  run("torsion_pd.prm, antiplane state based",
      "torsion_pd.prm",
      coupling_tests::torsion_pd_overrides(0.05, "antiplane state based"),
      0.03,
      0.02);
}
