// ---------------------------------------------------------------------
// The Nooru-Mohamed benchmark (doc/benchmarks/nooru_mohamed; seed 003, sec. 3.2; seed note 003,
// T003-12; issue #40, part 3): double-edge-notched concrete with softening Timoshenko-beam bonds
// whose elastic limit is the tensile strength (3 MPa), the lateral force of 10 kN applied and
// held, then the normal platens moved apart (explicit dynamics, 3 ms). The benchmark's own files
// at its resolution (dx = 2 mm), all-PD (full_pd.prm) and coupled (coupled.prm: PD in the band
// of the cracks, FE elsewhere), without field output. The files name their includes and meshes
// relative to the repository's top directory, which the test links into its working directory
// ('doc', 'meshes').
// Crack particles: the damage index of seed note 003, A14, with the axial softening factor of
// each bond at the final displacement >= 0.3 (postprocess.py's measure; the code's own index
// counts removed bonds only, and these bonds are removed at 1e-6 of their peak force, beyond
// the end of the run). Checked for each run:
//  - the cracks start at both notch tips: a crack particle within one horizon;
//  - against the reference (issue #40), all-PD: the nominal ligament stress at the peak, normal
//    force over 150 mm x 50 mm, within what a notched specimen of sigma_t = 3 MPa concrete
//    carries, 2 ... 4 MPa (measured: 3.9 MPa; the coupled run's is printed);
//  - the normal force (reaction of the top platen) peaks and softens below 0.8 of its peak;
// and between them the coupled peak within 5 % of the all-PD one (measured: 1.033; the FE part
// cannot soften, and near the peak the whole body's stress reaches sigma_t, README.md). The
// point symmetry of the final pattern is no longer checked: the two curved cracks race after
// the peak (README.md). The same numbers on 1 and 2 ranks.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/pd/timoshenko_bond_based.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
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

  /// The crack particles of the gathered positions and displacements @p points (x, y, u_x,
  /// u_y per particle): phi_i = 1 - sum_j mu(x_ij) / (number of bonds), x the bond's stretch
  /// over its limit (s_0 in tension, s_c in compression), mu = e^(-k (x - 1)) / x beyond 1.
  std::vector<Point<2>>
  crack_particles(const std::vector<double> &points, const double k)
  {
    const double                                              s0 = 3e6 / 32e9, sc = 38.4e6 / 32e9;
    const auto                                                n = points.size() / 4;
    std::map<std::pair<long, long>, std::vector<std::size_t>> cells;
    const auto cell = [&](const std::size_t i, const long a, const long b) {
      return std::make_pair(std::lround(std::floor(points[4 * i] / horizon)) + a,
                            std::lround(std::floor(points[4 * i + 1] / horizon)) + b);
    };
    for (std::size_t i = 0; i < n; ++i)
      cells[cell(i, 0, 0)].push_back(i);
    std::vector<Point<2>> cracks;
    for (std::size_t i = 0; i < n; ++i)
      {
        double bonds = 0., kept = 0.;
        for (long a = -1; a <= 1; ++a)
          for (long b = -1; b <= 1; ++b)
            {
              const auto found = cells.find(cell(i, a, b));
              if (found == cells.end())
                continue;
              for (const std::size_t j : found->second)
                {
                  const double xi[2]  = {points[4 * j] - points[4 * i],
                                         points[4 * j + 1] - points[4 * i + 1]};
                  const double eta[2] = {points[4 * j + 2] - points[4 * i + 2],
                                         points[4 * j + 3] - points[4 * i + 3]};
                  const double r2     = xi[0] * xi[0] + xi[1] * xi[1];
                  if (j == i || r2 > horizon * horizon * (1. + 1e-9))
                    continue;
                  const double s = (xi[0] * eta[0] + xi[1] * eta[1]) / r2;
                  const double x = s >= 0. ? s / s0 : -s / sc;
                  bonds += 1.;
                  kept += perideal::Timoshenko::softening_factor(x, k);
                }
            }
        if (bonds > 0. && 1. - kept / bonds >= 0.3)
          cracks.emplace_back(points[4 * i], points[4 * i + 1]);
      }
    return cracks;
  }

  /// Run the benchmark's file @p name; its crack particles and normal force.
  Result
  run(const std::string &name)
  {
    Result              result;
    std::vector<double> points;
    double              k = 0.;
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
                          const auto &ps = problem.particles();
                          const auto &u  = problem.particle_displacement();
                          k              = dynamic_cast<const perideal::TimoshenkoBondBased<2> &>(
                                problem.material())
                                .softening_parameter();
                          std::vector<double> local;
                          for (unsigned int i = 0; i < ps.n_owned(); ++i)
                            for (const double value : {ps.positions()[i][0],
                                                       ps.positions()[i][1],
                                                       u.local_element(3 * i),
                                                       u.local_element(3 * i + 1)})
                              local.push_back(value);
                          for (const auto &part : Utilities::MPI::gather(MPI_COMM_WORLD, local))
                            points.insert(points.end(), part.begin(), part.end());
                        });
    result.cracks = crack_particles(points, k);
    const auto force =
      perideal_tests::read_statistics(name + "/statistics.csv").at("reaction_top_y");
    result.peak = *std::max_element(force.begin(), force.end());
    result.last = force.back();
    return result;
  }

  void
  check(const std::string &name, const Result &r, const bool against_reference)
  {
    const double left    = coupling_tests::nearest_distance(Point<2>(0.025, 0.1), r.cracks);
    const double right   = coupling_tests::nearest_distance(Point<2>(0.175, 0.1), r.cracks);
    const double nominal = r.peak / (0.15 * 0.05);
    std::cout << name << ": peak normal force " << r.peak / 1e3 << " kN" << std::endl;
    std::cout << "  cracks at both notch tips: "
              << coupling_tests::ok(left <= horizon && right <= horizon) << std::endl;
    std::cout << "  nominal ligament stress at the peak " << nominal / 1e6 << " MPa";
    if (against_reference)
      std::cout << " (2 ... 4 MPa): " << coupling_tests::ok(nominal >= 2e6 && nominal <= 4e6);
    std::cout << std::endl;
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
  check("all-PD", all_pd, true);
  check("coupled", coupled, false);
  const double ratio = coupled.peak / all_pd.peak;
  std::cout << "coupled / all-PD peak " << ratio
            << " (within 5 %): " << coupling_tests::ok(std::abs(ratio - 1.) < 0.05) << std::endl;
}
