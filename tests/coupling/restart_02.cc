// ---------------------------------------------------------------------
// Checkpoints by simulated time (<Output/Checkpoint time interval>): a checkpoint after the first
// step that reaches each multiple k T of the interval (before the last step), and the restart
// from the newest one ends with the numbers of the run that did not stop, bit for bit on the
// same number of ranks. Two runs:
//  - explicit dynamics: the PMB plate of app-solid/plate_2d_pmb to 1e-6 s (20 steps of 5e-8 s)
//    with T = 0.27e-6 s = 5.4 dt: the checkpoint steps must be ceil(k T / dt) = 6, 11, 17;
//  - quasi-static (adaptive dynamic relaxation with bond breaking): app-solid/cracked_plate_adr
//    in 6 load steps with T = 0.25 of the load factor: load steps 2, 3 and 5 (factors 1/3, 1/2,
//    5/6 reach 0.25, 0.5, 0.75), none after the last.
// Then each run restarts from the checkpoint it left (the newest) and must end with the same
// particle displacements, statistics.csv and particles.xdmf as the run itself.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  struct Outcome
  {
    std::vector<double> u;
    std::string         log;
  };

  Outcome
  run(const std::string &text, const std::string &directory, const bool restart)
  {
    coupling_tests::write_file(directory + ".prm",
                               text + "subsection Output\n  set Directory = " + directory +
                                 "\n  set Write HDF5 = true\n  set Progress = false\nend\n");
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    coupling_tests::parse(problem, directory + ".prm");
    problem.setup();
    if (restart)
      problem.restart_from_checkpoint();
    problem.run();
    const auto &u = problem.particle_displacement();
    Outcome     outcome;
    outcome.u.assign(u.begin(), u.begin() + u.locally_owned_size());
    outcome.log = log.str();
    MPI_Barrier(MPI_COMM_WORLD);
    return outcome;
  }

  // The steps of the lines "Checkpoint of step N: ..." of @p log.
  std::vector<unsigned int>
  checkpoint_steps(const std::string &log)
  {
    std::vector<unsigned int> steps;
    std::istringstream        lines(log);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("Checkpoint of step ", 0) == 0)
        steps.push_back(std::stoul(line.substr(19)));
    return steps;
  }

  // Run @p text, restart it from its newest checkpoint, compare; @p expected gives the
  // checkpoint steps from the log of the run.
  void
  check(const std::string                                                   &name,
        const std::string                                                   &text,
        const std::function<std::vector<unsigned int>(const std::string &)> &expected_steps)
  {
    const Outcome full      = run(text, name, false);
    const auto    steps     = checkpoint_steps(full.log);
    const auto    expected  = expected_steps(full.log);
    const auto    statistic = coupling_tests::read_text(name + "/statistics.csv");
    const auto    xdmf      = coupling_tests::read_text(name + "/particles.xdmf");
    const Outcome restarted = run(text, name, true);
    double        difference =
      full.u.size() == restarted.u.size() ? 0. : std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < full.u.size() && k < restarted.u.size(); ++k)
      difference = std::max(difference, std::abs(full.u[k] - restarted.u[k]));
    difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    deallog << name << ": checkpoints after steps";
    for (const auto step : steps)
      deallog << ' ' << step;
    deallog << " (expected";
    for (const auto step : expected)
      deallog << ' ' << step;
    deallog << "): " << coupling_tests::ok(steps == expected) << std::endl;
    std::istringstream lines(restarted.log);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("Restart", 0) == 0)
        deallog << "  " << line << std::endl;
    deallog << "  largest difference of the final particle displacements: " << difference << ": "
            << coupling_tests::ok(difference == 0.) << std::endl;
    deallog << "  statistics.csv the same file: "
            << coupling_tests::ok(coupling_tests::read_text(name + "/statistics.csv") == statistic)
            << std::endl;
    deallog << "  particles.xdmf the same file: "
            << coupling_tests::ok(coupling_tests::read_text(name + "/particles.xdmf") == xdmf)
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const std::string app = SOURCE_DIR "/../app-solid/";

  // Explicit: the expected steps from the run's time step (its log: "Time step: dt s, steps:
  // N"): the first step n with n dt >= k T.
  check("explicit",
        "include " + app +
          "plate_2d_pmb.prm\n"
          "subsection Time stepping\n  set End time = 1e-6\nend\n"
          "subsection Output\n  set Probe points =\n  set Output interval = 10\n"
          "  set Checkpoint time interval = 0.27e-6\nend\n",
        [](const std::string &log) {
          const auto         numbers = coupling_tests::numbers_of(log, "Time step:");
          const double       dt      = numbers[0];
          const unsigned int n_steps = std::lround(numbers.back());
          deallog << "explicit: " << n_steps << " steps of " << dt << " s" << std::endl;
          std::vector<unsigned int> expected;
          for (unsigned int k = 1; std::ceil(k * 0.27e-6 / dt - 1e-6) < n_steps; ++k)
            expected.push_back(std::ceil(k * 0.27e-6 / dt - 1e-6));
          return expected;
        });

  check("quasi_static",
        "include " + app +
          "cracked_plate_adr.prm\n"
          "subsection Output\n  set Checkpoint time interval = 0.25\nend\n",
        [](const std::string &) {
          return std::vector<unsigned int>{2, 3, 5};
        });
}
