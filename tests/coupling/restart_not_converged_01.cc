// ---------------------------------------------------------------------
// A quasi-static run that stops without convergence writes its last iterate for inspection and
// the checkpoint of its last converged load step, from which a restart with other solver
// settings continues (LoadStepping, Checkpoint::keep() and write_kept()). The ADR plate of
// app-solid/cracked_plate_adr (PMB, a pre-crack, critical stretch 1e-3, 6 load steps; 210 bonds
// broken after load step 1, the crack grows in load step 2) with <Solver/Maximum iterations> =
// 170: load step 1 needs between 131 and 140 relaxation iterations, a solve of load step 2
// between 201 and 210 (measured with the pre-crack rule of doc/theory/models.md), so the run
// stops in load step 2 with ExcNotConverged. Then:
//  - its last iterate is in particles_not_converged.xdmf (+ .h5, output index 2, time = the load
//    factor 2/6), and statistics.csv ends at load step 1 (header, rows of load steps 0 and 1);
//  - a restart with other <Solver/Load steps> is refused, naming the solver line of the
//    checkpoint's fingerprint, and leaves statistics.csv as it was;
//  - the restart with the default <Solver/Maximum iterations> (100000) continues from load
//    step 1 and must end with the numbers of the run that had 100000 from the start, bit for bit
//    (same number of ranks): the final particle displacements equal, statistics.csv and
//    particles.xdmf the same files.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>

#include <perideal/base/problem_settings.h>
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  const std::string max_iterations_failing = "170";

  std::size_t
  n_lines(const std::string &file)
  {
    const std::string text = coupling_tests::read_text(file);
    return std::count(text.begin(), text.end(), '\n');
  }

  // The plate with @p solver (lines of <Solver>), its output in @p directory.
  std::string
  plate(const std::string &solver, const std::string &directory)
  {
    return "include " SOURCE_DIR "/../app-solid/cracked_plate_adr.prm\n"
           "subsection Solver\n" +
           solver +
           "end\n"
           "subsection Output\n  set Directory = " +
           directory + "\n  set Write HDF5 = true\n  set Progress = false\nend\n";
  }

  struct Outcome
  {
    std::vector<double> u;
    std::string         log, error;
  };

  // Run @p text (restarted if @p restart); the message of an ExcNotConverged or of another
  // refusal is kept in error.
  Outcome
  run(const std::string &text, const std::string &file, const bool restart)
  {
    Outcome outcome;
    coupling_tests::write_file(file, text);
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    coupling_tests::parse(problem, file);
    problem.setup();
    if (restart)
      problem.restart_from_checkpoint();
    try
      {
        problem.run();
        const auto &u = problem.particle_displacement();
        outcome.u.assign(u.begin(), u.begin() + u.locally_owned_size());
      }
    catch (const perideal::ExcNotConverged &exc)
      {
        outcome.error = "ExcNotConverged: " + perideal_tests::exception_text(exc);
      }
    catch (const ExceptionBase &exc)
      {
        outcome.error = perideal_tests::exception_text(exc);
      }
    outcome.log = log.str();
    MPI_Barrier(MPI_COMM_WORLD);
    return outcome;
  }

  // The lines of @p text that start with one of @p keys.
  void
  print_lines(const std::string &text, const std::vector<std::string> &keys)
  {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      for (const auto &key : keys)
        if (line.rfind(key, 0) == 0)
          {
            // Not the broken bonds at the last iterate: how many solves of the step converge
            // before the one that does not depends on round-off (1 or 2 ranks).
            const auto open = line.find(" (");
            if (line.find("at its last iterate)") != std::string::npos)
              line.erase(open, line.find(')', open) + 1 - open);
            deallog << "  " << line << std::endl;
            break;
          }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  // The directory listing below must not see files of an earlier run of the test.
  if (root)
    for (const char *directory : {"full", "stopped"})
      std::filesystem::remove_all(directory);
  MPI_Barrier(MPI_COMM_WORLD);

  // The reference: enough iterations from the start.
  const Outcome full = run(plate("", "full"), "full.prm", false);
  deallog << "full run: " << (full.error.empty() ? "converged" : full.error) << std::endl;

  // Too few iterations for load step 2.
  const Outcome failed =
    run(plate("  set Maximum iterations = " + max_iterations_failing + "\n", "stopped"),
        "stopped.prm",
        false);
  deallog << "run with Maximum iterations = " << max_iterations_failing << ":" << std::endl;
  print_lines(failed.log, {"Load step", "Checkpoint"});
  // The solver's message (its residual history is left out: round-off between rank counts),
  // then what the load stepping adds.
  if (root)
    {
      std::istringstream lines(failed.error);
      std::string        line;
      std::getline(lines, line);
      deallog << "  " << line.substr(0, line.find(':', line.find(':') + 1)) << std::endl;
      for (; std::getline(lines, line);)
        if (line.rfind("Load step", 0) == 0)
          deallog << "  " << line << std::endl;
      std::set<std::string> written;
      for (const auto &entry : std::filesystem::directory_iterator("stopped"))
        written.insert(entry.path().filename().string());
      deallog << "  files:";
      for (const auto &name : written)
        deallog << ' ' << name;
      deallog << std::endl;
      const std::string xdmf = coupling_tests::read_text("stopped/particles_not_converged.xdmf");
      const auto        time = xdmf.find("<Time Value=\"");
      deallog << "  particles_not_converged.xdmf: "
              << (time == std::string::npos ?
                    std::string("no time") :
                    xdmf.substr(time + 13, xdmf.find('"', time + 13) - time - 13))
              << " (load factor 2/6); statistics.csv: " << n_lines("stopped/statistics.csv")
              << " lines (header, load steps 0 and 1)" << std::endl;
    }
  MPI_Barrier(MPI_COMM_WORLD);

  // Another number of load steps: another problem for the checkpoint.
  const std::string statistics_before = coupling_tests::read_text("stopped/statistics.csv");
  const Outcome     other_steps = run(plate("  set Load steps = 7\n", "stopped"), "7.prm", true);
  deallog << "restart with Load steps = 7: " << other_steps.error << std::endl;
  deallog << "  statistics.csv unchanged: "
          << coupling_tests::ok(coupling_tests::read_text("stopped/statistics.csv") ==
                                statistics_before)
          << std::endl;

  // The restart with enough iterations.
  const Outcome restarted = run(plate("", "stopped"), "restart.prm", true);
  deallog << "restart with Maximum iterations = 100000: "
          << (restarted.error.empty() ? "converged" : restarted.error) << std::endl;
  print_lines(restarted.log, {"Restart", "Load step"});
  double difference = full.u.size() == restarted.u.size() ? 0. : HUGE_VAL;
  for (std::size_t k = 0; k < full.u.size() && k < restarted.u.size(); ++k)
    difference = std::max(difference, std::abs(full.u[k] - restarted.u[k]));
  difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
  if (root)
    {
      deallog << "  largest difference of the final particle displacements to the full run: "
              << difference << ": " << coupling_tests::ok(difference == 0.) << std::endl;
      for (const std::string file : {"statistics.csv", "particles.xdmf"})
        deallog << "  " << file << " the same file as the full run's: "
                << coupling_tests::ok(coupling_tests::read_text("full/" + file) ==
                                      coupling_tests::read_text("stopped/" + file))
                << std::endl;
    }
}
