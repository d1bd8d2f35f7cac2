// ---------------------------------------------------------------------
// Bad input of checkpoint and restart: each case stops with a message naming the entry or the
// file, and a refused restart leaves the results of the run it would continue as they were
// (statistics.csv unchanged). Cases: <Output/Checkpoint interval> <= 0 or not an integer and
// <Output/Checkpoint time interval> <= 0 or not a number (when the file is read; "off" is the
// default);
// a restart without a checkpoint; a restart with the checkpoint of another problem (another
// material model; another horizon, so other bonds); a truncated checkpoint; a file that is not a
// checkpoint; a checkpoint of the first format (PERIDEAL-CKPT-01). The good checkpoint is then
// accepted.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  const std::string plate = "include " SOURCE_DIR "/../app-solid/plate_2d_pmb.prm\n"
                            "subsection Time stepping\n  set End time = 1e-6\nend\n"
                            "subsection Output\n  set Probe points =\n  set Progress = false\n";

  // The message with the sizes of a truncated checkpoint, "(N bytes, its header gives M)",
  // replaced by their difference: the test cuts 100 bytes off, but the size itself depends on
  // the statistics the checkpoint holds, whose round-off digits differ between machines.
  std::string
  without_sizes(const std::string &text)
  {
    const std::regex size(R"(\((\d+) bytes, its header gives (\d+)\))");
    std::smatch      match;
    if (!std::regex_search(text, match, size))
      return text;
    const long missing = std::stol(match[2].str()) - std::stol(match[1].str());
    return match.prefix().str() + "(" + std::to_string(missing) +
           " bytes fewer than its header gives)" + match.suffix().str();
  }

  // Run @p text (output in @p directory), stopped after step @p stop or restarted; print the
  // message if it stops with one.
  void
  run(const std::string &text,
      const std::string &directory,
      const unsigned int stop,
      const bool         restart)
  {
    coupling_tests::write_file(directory + ".prm",
                               text + "  set Directory = " + directory + "\nend\n");
    try
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        coupling_tests::parse(problem, directory + ".prm");
        problem.setup();
        if (restart)
          problem.restart_from_checkpoint();
        if (stop > 0)
          problem.stop_after_step(stop);
        problem.run();
        deallog << directory << ": ran" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        deallog << directory << ": " << without_sizes(perideal_tests::exception_text(exc))
                << std::endl;
      }
    MPI_Barrier(MPI_COMM_WORLD);
  }

  // Restart @p text from the checkpoint in @p directory and state whether statistics.csv is
  // unchanged.
  void
  refused_restart(const std::string &text, const std::string &directory)
  {
    const std::string statistics = directory + "/statistics.csv";
    const std::string before     = coupling_tests::read_text(statistics);
    run(text, directory, 0, true);
    deallog << "  statistics.csv unchanged: "
            << coupling_tests::ok(coupling_tests::read_text(statistics) == before) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  run(plate + "  set Checkpoint interval = -1\n", "negative_interval", 0, false);
  run(plate + "  set Checkpoint interval = 0\n", "zero_interval", 0, false);
  run(plate + "  set Checkpoint interval = 2.5\n", "fractional_interval", 0, false);
  run(plate + "  set Checkpoint time interval = -1e-7\n", "negative_time_interval", 0, false);
  run(plate + "  set Checkpoint time interval = 0\n", "zero_time_interval", 0, false);
  run(plate + "  set Checkpoint time interval = never\n", "word_time_interval", 0, false);

  run(plate, "no_checkpoint", 0, true);
  deallog << "  output directory created: " << std::filesystem::exists("no_checkpoint")
          << std::endl;

  // A checkpoint after step 5, then restarts by other problems.
  run(plate, "other", 5, false);
  refused_restart("include " SOURCE_DIR "/../app-solid/plate_2d_pmb.prm\n"
                  "subsection Material\n  set Model = linear peridynamic solid\n"
                  "  subsection linear peridynamic solid\n    set Young's modulus = 192e9\n"
                  "  end\nend\n" +
                    plate.substr(plate.find("subsection Time")),
                  "other");
  refused_restart(plate + "end\nsubsection Discretization\n  set Horizon factor = 3\nend\n"
                          "subsection Output\n",
                  "other");

  // The checkpoint cut short, and a file that is not a checkpoint.
  if (root)
    {
      std::filesystem::create_directories("truncated");
      std::filesystem::copy_file("other/statistics.csv",
                                 "truncated/statistics.csv",
                                 std::filesystem::copy_options::overwrite_existing);
      std::filesystem::copy_file("other/checkpoint",
                                 "truncated/checkpoint",
                                 std::filesystem::copy_options::overwrite_existing);
      std::filesystem::resize_file("truncated/checkpoint",
                                   std::filesystem::file_size("other/checkpoint") - 100);
      std::filesystem::create_directories("not_a_checkpoint");
      std::filesystem::copy_file("other/statistics.csv",
                                 "not_a_checkpoint/statistics.csv",
                                 std::filesystem::copy_options::overwrite_existing);
      std::ofstream("not_a_checkpoint/checkpoint") << std::ifstream("other/statistics.csv").rdbuf();
      // A checkpoint of the first format (before the regions wrote their own sections): its
      // mark, then what followed it.
      std::filesystem::create_directories("old_format");
      std::filesystem::copy_file("other/statistics.csv",
                                 "old_format/statistics.csv",
                                 std::filesystem::copy_options::overwrite_existing);
      std::ofstream old("old_format/checkpoint");
      old << "PERIDEAL-CKPT-01";
      std::ifstream current("other/checkpoint");
      current.seekg(16);
      old << current.rdbuf();
    }
  MPI_Barrier(MPI_COMM_WORLD);
  refused_restart(plate, "truncated");
  refused_restart(plate, "not_a_checkpoint");
  refused_restart(plate, "old_format");

  // The checkpoint itself is good: the run continues from it.
  run(plate, "other", 0, true);
}
