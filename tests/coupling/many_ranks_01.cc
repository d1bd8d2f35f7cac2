// ---------------------------------------------------------------------
// The many-rank check of issue #41 (part 3): the 3D Kalthoff-Winkler-like plate of
// doc/benchmarks/many_ranks/kalthoff_plate_3d.prm (FE everywhere, PMB in a cylinder through the
// thickness at each notch tip, 16 m/s impact, 35 us, dx = 1.25 mm, 12 336 particles) must give
// the same numbers on every rank count: this test runs on 1, 2 and 4 ranks against one golden
// (the three .output files are copies of each other; 8 ranks are checked by
// doc/benchmarks/many_ranks/run.sh). Then the same plate with an adaptive PD region
// (kalthoff_plate_3d_adaptive.prm: balls at the tips that grow with the damage, 50 us), whose
// conversions rebuild particles, bonds and transfer operators on every rank. Last the fixed-region
// plate at dx = 2 mm, whose lattice rows y = +-25 mm lie on the notch planes, the slits of the
// mesh (two faces with nodes of their own): such a particle lies in a cell on each side; the
// transfer operator gives it to the side a fixed direction with v_y > 0 points into, the upper
// one, the same on every partition (before, the side depended on the rank count and 8 ranks
// stopped). Printed for each:
//  - the broken bonds as a set: every broken bond as the pair of its particles' rank-invariant
//    indices (ParticleSystem::invariant_index(): the lattice bins do not depend on the rank
//    count), gathered, sorted and hashed (FNV-1a, 64 bit): the hash is equal only if the very
//    same bonds broke; and how many of them cross no notch (broken by the run, not pre-cracks);
//  - the summary of the run (energies, reactions, 7 digits) and the 2-norms of the particle and
//    FE displacements to 12 digits (the comparison's relative tolerance is 1e-8: round-off, not
//    a different bond, passes).
// Expected from the physics: bonds break at the notch tips (the stress wave reaches them after
// about 10 us, 50 mm at the 5.3 km/s P-wave), the impact reaction in y is zero (the plate is
// symmetric about y = 0) and as many bonds break above as below the plate's mid-plane y = 0
// (exactly with the fixed PD region; 9570 and 9573 in the adaptive run, where the round-off of
// the sums decides in which step a bond at its critical stretch breaks). Not at dx = 2 mm: the
// particles on both notch planes follow the FE side above them, outside the moving segment at
// y = 25 mm and inside it at y = -25 mm, so the model is not symmetric about y = 0 (printed, not
// checked).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  /// Run the file @p name of doc/benchmarks/many_ranks (with @p overrides) and print what must
  /// not depend on the rank count; @p symmetric: check the halves above and below y = 0.
  void
  report(const std::string &name, const std::string &overrides = "", const bool symmetric = true)
  {
    // Every broken bond (i, j) once: an owned-owned bond is stored once, a bond to a ghost on
    // both ranks (kept where the owned end has the smaller invariant index). Beside the pair: 1
    // if the bond crosses a notch (y = +-25 mm, x < 50 mm), and whether its midpoint has y > 0.
    std::vector<std::uint64_t> pairs;
    double                     displacement_norm = 0., fe_norm = 0.;
    unsigned int               n_particles = 0, n_on_notches = 0;
    const std::string          log = coupling_tests::run<3>(
      name,
      "include " SOURCE_DIR "/../../doc/benchmarks/many_ranks/" + name +
        "\n"
                 "subsection Finite elements\n"
                 "  set Mesh file = " SOURCE_DIR "/../../meshes/kalthoff_plate_coarse_3d.msh\n"
                 "end\n"
                 "subsection Output\n"
                 "  set Directory  = results\n"
                 "  set Write HDF5 = false\n"
                 "  set Progress   = false\n"
                 "end\n" +
        overrides,
      [&](const perideal::CoupledProblem<3> &problem) {
        const auto                &ps    = problem.particles();
        const auto                &bonds = ps.bonds();
        const auto                &x     = ps.positions();
        std::vector<std::uint64_t> local;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            {
              if (bonds.intact[b] != 0)
                continue;
              const unsigned int  j  = bonds.neighbor[b];
              const std::uint64_t ki = ps.invariant_index(i), kj = ps.invariant_index(j);
              if (j >= ps.n_owned() && ki > kj)
                continue;
              bool crosses_notch = false;
              for (const double notch : {0.025, -0.025})
                {
                  // An end on the notch plane counts (the pre-cracks cut such a bond too).
                  const double yi = x[i][1] - notch, yj = x[j][1] - notch;
                  if (yi * yj <= 0. && (yi != 0. || yj != 0.) && x[i][0] + x[j][0] < 0.1)
                    crosses_notch = true;
                }
              local.insert(local.end(),
                           {std::min(ki, kj),
                            std::max(ki, kj),
                            std::uint64_t(crosses_notch),
                            std::uint64_t(x[i][1] + x[j][1] > 0.)});
            }
        for (const auto &part : Utilities::MPI::gather(MPI_COMM_WORLD, local))
          pairs.insert(pairs.end(), part.begin(), part.end());
        // The particles on a notch plane (y = +-25 mm exactly, x < 50 mm): on a slit.
        unsigned int on_notches = 0;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          if (std::abs(std::abs(x[i][1]) - 0.025) < 1e-12 && x[i][0] < 0.05)
            ++on_notches;
        n_on_notches      = Utilities::MPI::sum(on_notches, MPI_COMM_WORLD);
        n_particles       = problem.particles().n_global();
        displacement_norm = problem.particle_displacement().l2_norm();
        fe_norm           = problem.fe_displacement().l2_norm();
      });

    // Sort the bonds (4 numbers each) and hash them.
    std::vector<std::array<std::uint64_t, 4>> sorted(pairs.size() / 4);
    for (std::size_t k = 0; k < sorted.size(); ++k)
      sorted[k] = {{pairs[4 * k], pairs[4 * k + 1], pairs[4 * k + 2], pairs[4 * k + 3]}};
    std::sort(sorted.begin(), sorted.end());
    std::uint64_t hash   = 14695981039346656037ull;
    unsigned int  by_run = 0, by_run_above = 0;
    for (const auto &bond : sorted)
      {
        for (const std::uint64_t value : bond)
          for (unsigned int byte = 0; byte < 8; ++byte)
            hash = (hash ^ ((value >> (8 * byte)) & 0xff)) * 1099511628211ull;
        if (bond[2] == 0)
          {
            ++by_run;
            by_run_above += bond[3];
          }
      }
    std::cout << name << (overrides.empty() ? "" : " at dx = 2 mm") << std::endl;
    std::cout << "particles on the notch planes (slits): " << n_on_notches << std::endl;
    std::cout << "broken bonds: " << sorted.size() << ", " << by_run
              << " of them by the run (crossing no notch), " << by_run_above << " with y > 0"
              << std::endl;
    std::cout << "hash of the broken bonds' invariant index pairs: " << std::hex << hash << std::dec
              << std::endl;
    std::cout << "  bonds broke at the tips: " << coupling_tests::ok(by_run > 0) << std::endl;
    // The plate is symmetric about y = 0; round-off that decides whether a bond at its critical
    // stretch breaks in this step or the next makes the two halves differ slightly.
    if (symmetric)
      std::cout << "  as many above as below y = 0 (within 1 %): "
                << coupling_tests::ok(std::abs(2. * by_run_above - by_run) <= 0.01 * by_run)
                << std::endl;
    std::cout << "conversions: " << coupling_tests::count_lines(log, "the PD region grew by")
              << ", particles at the end: " << n_particles << std::endl;
    const std::string text = "\n" + log;
    for (const std::string key : {"Particles:",
                                  "Bonds:",
                                  "Coupling:",
                                  "Time step:",
                                  "Kinetic energy:",
                                  "Strain energy:",
                                  "External work:",
                                  "Dissipated energy:",
                                  "Energy change of the conversions:",
                                  "Energy error:",
                                  "Broken bonds:",
                                  "Reaction impact:"})
      {
        const auto begin = text.find("\n" + key);
        if (begin != std::string::npos)
          std::cout << text.substr(begin + 1, text.find('\n', begin + 1) - begin - 1) << std::endl;
      }
    std::cout << std::setprecision(12)
              << "2-norm of the particle displacements: " << displacement_norm << " m" << std::endl;
    std::cout << "2-norm of the FE displacements: " << fe_norm << " m" << std::setprecision(6)
              << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  report("kalthoff_plate_3d.prm");
  report("kalthoff_plate_3d_adaptive.prm");
  report("kalthoff_plate_3d.prm",
         "subsection Discretization\n"
         "  set Lattice spacing = 2e-3\n"
         "end\n",
         /*symmetric=*/false);
}
