// The harness of the Nooru-Mohamed tests (nooru_mohamed_01: the benchmark's runs at full length,
// nooru_mohamed_short: all-PD and the adaptive coupled run at dx = 4 mm, stopped soon after the
// peak): run one of the benchmark's files (doc/benchmarks/nooru_mohamed) with overrides, without
// field output, and measure what its postprocess.py checks. The files name their includes and
// meshes relative to the repository's top directory, which the tests link into their working
// directory (coupling_tests::link_top_directories()).
// Crack particles: the damage index of seed note 003, A14, with the axial softening factor of
// each bond at the final displacement >= 0.3 (postprocess.py's measure; the code's own index
// counts removed bonds only, and these bonds are removed at 1e-6 of their peak force, beyond
// the end of the runs).
#ifndef perideal_nooru_mohamed_tests_h
#define perideal_nooru_mohamed_tests_h

#include <deal.II/base/mpi.h>

#include <perideal/pd/timoshenko_bond_based.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace nooru_mohamed_tests
{
  /// What a run of the benchmark gives.
  struct Result
  {
    /// The crack particles at the end (damage index >= 0.3).
    std::vector<dealii::Point<2>> cracks;
    /// The largest normal force (reaction of the top platen) [N] and its time [s].
    double peak = 0., peak_time = 0.;
    /// The normal force at the end [N].
    double last = 0.;
    /// The particles at the start and at the end.
    unsigned int n_start = 0, n_particles = 0;
    /// The conversions of an adaptive run (lines "the PD region grew" of its log).
    unsigned int conversions = 0;
    /// The horizon of the run [m].
    double horizon = 0.;
  };

  /// The crack particles of the gathered positions and displacements @p points (x, y, u_x,
  /// u_y per particle), whose bonds reach @p horizon: phi_i = 1 - sum_j mu(x_ij) / (number of
  /// bonds), x the bond's stretch over its limit (s_0 in tension, s_c in compression), mu = e^(-k
  /// (x - 1)) / x beyond 1.
  inline std::vector<dealii::Point<2>>
  crack_particles(const std::vector<double> &points, const double k, const double horizon)
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
    std::vector<dealii::Point<2>> cracks;
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

  /// Run the benchmark's file @p name (full_pd, coupled or coupled_adaptive) with the
  /// @p overrides (sections of a parameter file) into the directory @p name, on the lattice of
  /// spacing @p dx that the file and the overrides set (the horizon is 3 dx); what it gives.
  inline Result
  run(const std::string &name, const std::string &overrides = "", const double dx = 2e-3)
  {
    Result result;
    result.horizon = 3 * dx;
    std::vector<double> points;
    double              k   = 0.;
    const std::string   log = coupling_tests::run(
      name + ".prm",
      "include doc/benchmarks/nooru_mohamed/" + name + ".prm\n" + overrides +
        "subsection Output\n"
          "  set Directory  = " +
        name +
        "\n"
          "  set Write HDF5 = false\n"
          "end\n",
      [&](const auto &problem) {
        const auto &ps     = problem.particles();
        const auto &u      = problem.particle_displacement();
        result.n_particles = ps.n_global();
        k = dynamic_cast<const perideal::TimoshenkoBondBased<2> &>(problem.material())
              .softening_parameter();
        std::vector<double> local;
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          for (const double value : {ps.positions()[i][0],
                                     ps.positions()[i][1],
                                     u.local_element(3 * i),
                                     u.local_element(3 * i + 1)})
            local.push_back(value);
        for (const auto &part : dealii::Utilities::MPI::gather(MPI_COMM_WORLD, local))
          points.insert(points.end(), part.begin(), part.end());
      });
    result.cracks = crack_particles(points, k, result.horizon);
    // The log is rank 0's: "Particles: N" at the start, a line per conversion.
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        result.conversions = coupling_tests::count_lines(log, "the PD region grew");
        result.n_start     = std::lround(coupling_tests::numbers_of(log, "Particles:")[0]);
      }
    const auto  statistics = perideal_tests::read_statistics(name + "/statistics.csv");
    const auto &force      = statistics.at("reaction_top_y");
    const auto  peak       = std::max_element(force.begin(), force.end());
    result.peak            = *peak;
    result.peak_time       = statistics.at("time")[peak - force.begin()];
    result.last            = force.back();
    return result;
  }

  /// Print the checks of the run @p name: cracks at both notch tips, the nominal ligament stress
  /// at the peak (normal force over 150 mm x 50 mm; checked against 2 ... 4 MPa if
  /// @p against_reference), the normal force at the end below 0.8 of the peak. 3 digits.
  inline void
  check(const std::string &name, const Result &r, const bool against_reference)
  {
    const double left    = coupling_tests::nearest_distance(dealii::Point<2>(0.025, 0.1), r.cracks);
    const double right   = coupling_tests::nearest_distance(dealii::Point<2>(0.175, 0.1), r.cracks);
    const double nominal = r.peak / (0.15 * 0.05);
    std::cout << name << ": peak normal force " << r.peak / 1e3 << " kN" << std::endl;
    std::cout << "  cracks at both notch tips: "
              << coupling_tests::ok(left <= r.horizon && right <= r.horizon) << std::endl;
    std::cout << "  nominal ligament stress at the peak " << nominal / 1e6 << " MPa";
    if (against_reference)
      std::cout << " (2 ... 4 MPa): " << coupling_tests::ok(nominal >= 2e6 && nominal <= 4e6);
    std::cout << std::endl;
    std::cout << "  peaks and softens below 0.8: " << coupling_tests::ok(r.last < 0.8 * r.peak)
              << std::endl;
  }
} // namespace nooru_mohamed_tests

#endif
