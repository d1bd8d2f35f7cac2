// ---------------------------------------------------------------------
// Coupled torsion, a patch-type check (doc/benchmarks/torsion_rectangle/torsion_coupled.prm: the
// 1 x 2 bar of seed 000, example 8.4, mu = psi = 1): PD (the bond-based and the state-based
// antiplane model, twisted bond slope, dx = 0.05) in the band |y| <= 0.2 across the section,
// linear ramps to |y| = 0.4 (wider than the horizon 0.15), FE Q2 (h = 1/8) elsewhere, blended
// (FE energy weighted by 1 - beta, its twist a volume load; the particles' by beta), run through
// perideal-solid's driver by adaptive dynamic relaxation. Printed: the torque of the body
// T = fe_torque + pd_torque (columns total_*) against the Saint-Venant series, T = 0.457363, with
// both parts, and T psi / (2E) - 1. The coupled torque must lie within the accuracy of its
// parts: FE Q2 at h = 1/8 is within 0.01 % (torsion_rectangle README), the all-PD torques at
// dx = 0.05 are -0.67 % (bond-based) and -2.0 % (state-based, torsion_rectangle_01); accepted
// |error| < 1 % and < 2 %, below the all-PD errors' bounds (the band carries only a part of the
// torque). With the twist as the FE boundary load (unweighted by the blending) the torque is off
// by far more. T psi / (2E) - 1 within 2 % (its PD part's discretization error, as for all-PD).
// Then the bond-based model in a band away from the twist axis (0, 0): beta = 1 for
// |y - 0.6| <= 0.1, ramps 0.2 wide, so the particles (beta > 0 and a horizon) fill 0.15 <= y <= 1
// and their section does not contain the axis; the twist is defined for the whole section, so
// the run is accepted (the axis lies in the body: the FE mesh) and its torque meets the same
// bounds.
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
  run(const std::string &model, const double tolerance, const std::string &band = "")
  {
    const auto integrals = coupling_tests::run_torsion(
      "torsion_rectangle/torsion_coupled.prm",
      "subsection Discretization\n  set Lattice spacing = 0.05\nend\n"
      "subsection Finite elements\n  set Global refinements = 3\nend\n" +
        coupling_tests::torsion_material(model) +
        (band.empty() ? std::string() :
                        "subsection Coupling\n  set Blending function = " + band + "\nend\n"));
    const auto   columns   = perideal_tests::read_statistics("results/statistics.csv");
    const double T         = integrals.torque;
    const double error     = T / saint_venant::torque(0.5, 1.) - 1.;
    const double clapeyron = T / (2. * integrals.energy) - 1.;
    char         line[400];
    std::snprintf(line,
                  sizeof(line),
                  "%s%s: T/(mu psi) = %.5f (FE %.5f + PD %.5f), error %+.2f %% (within %.0f %%: "
                  "%s), T psi/(2E) - 1 = %+.2e (within 2e-02: %s)",
                  model.c_str(),
                  band.empty() ? "" : ", band 0.3 <= y <= 0.9 off the axis",
                  T,
                  columns.at("fe_torque").back(),
                  columns.at("pd_torque").back(),
                  100. * error,
                  100. * tolerance,
                  coupling_tests::ok(std::abs(error) < tolerance),
                  clapeyron,
                  coupling_tests::ok(std::abs(clapeyron) < 0.02));
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
  run("antiplane bond based", 0.01);
  run("antiplane state based", 0.02);
  run("antiplane bond based", 0.01, "min(1, max(0, (0.3 - abs(y - 0.6)) / 0.2))");
}
