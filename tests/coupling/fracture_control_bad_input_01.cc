// ---------------------------------------------------------------------
// Bad input of the quasi-static fracture control (<Solver/Control>, issue #16 part 3), on the
// all-PD compact-tension file of doc/benchmarks/compact_tension: each case stops with a message
// that names the entry (and the accepted values) before any work, or, for a solve that does not
// converge, with its last iterate written. The reference case runs to separation.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>

#include "coupling_tests.h"

#include <filesystem>
#include <string>

#include <tests.h>

using namespace dealii;

namespace
{
  void
  run_case(const std::string &title, const std::string &overrides)
  {
    deallog << title << ":" << std::endl;
    const std::string directory = "results_bad_input";
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::remove_all(directory);
    MPI_Barrier(MPI_COMM_WORLD);
    try
      {
        const std::string log =
          coupling_tests::run("bad_input.prm",
                              "include " SOURCE_DIR
                              "/../../doc/benchmarks/compact_tension/full_pd.prm\n" +
                                overrides + "subsection Output\n  set Directory = " + directory +
                                "\n  set Write HDF5 = true\nend\n");
        std::istringstream lines(log);
        for (std::string line; std::getline(lines, line);)
          if (line.rfind("Sequentially linear control", 0) == 0)
            deallog << "  " << line.substr(0, line.find(',')) << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        // A solve that did not converge: the lines of the control (the linear solver's own
        // message before them holds round-off that differs between rank counts); else all.
        const std::string text = perideal_tests::exception_text(exc);
        if (text.find("did not converge") == std::string::npos)
          deallog << "  " << text << std::endl;
        else
          {
            std::istringstream lines(text);
            for (std::string line; std::getline(lines, line);)
              if (line.rfind("The solve of event", 0) == 0 || line.rfind("Load step", 0) == 0)
                deallog << "  " << line << std::endl;
          }
      }
    deallog << "  output directory created: " << (std::filesystem::exists(directory) ? "yes" : "no")
            << std::endl;
  }

  std::string
  control(const std::string &entries)
  {
    return "subsection Solver\n  subsection Control\n" + entries + "  end\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  run_case("valid input", "");
  run_case("load point that names no condition", control("    set Load point = pin\n"));
  run_case("load point without a load component", control("    set Load component = \n"));
  run_case("load component the load point does not prescribe",
           control("    set Load component = x\n"));
  run_case("load point on a region without particles",
           "subsection Regions\n  subsection anchor\n    set Lower corner = 0.1, 0.1\n"
           "    set Upper corner = 0.2, 0.2\n  end\nend\n" +
             control("    set Load point = anchor\n    set Load component = x\n"));
  run_case("sequentially linear without a load point", control("    set Load point = \n"));
  run_case("event tolerance out of range", control("    set Event tolerance = 0.5\n"));
  run_case("separation load fraction out of range",
           control("    set Separation load fraction = 1\n"));
  run_case("maximum events out of range", control("    set Maximum events = 0\n"));
  run_case("sequentially linear with relaxation",
           "subsection Solver\n  set Type = adaptive dynamic relaxation\nend\n");
  run_case("sequentially linear without a damage model",
           "subsection Material\n  set Damage model = none\nend\n");
  run_case("sequentially linear with checkpoints",
           "subsection Output\n  set Checkpoint interval = 10\nend\n");
  run_case("cut threshold out of range", control("    set Cut above broken bonds = -1\n"));
  run_case("maximum step cuts out of range", control("    set Maximum step cuts = 51\n"));
  run_case("cut load steps with checkpoints",
           control("    set Method = load steps\n    set Cut above broken bonds = 5\n") +
             "subsection Output\n  set Checkpoint interval = 1\nend\n");
  run_case("a solve that does not converge",
           "subsection Solver\n  set Linear solver = cg amg\n  set Maximum iterations = 1\nend\n");
  run_case(
    "a cut load step that does not converge after the allowed cuts",
    control("    set Method = load steps\n    set Cut above broken bonds = 5\n"
            "    set Maximum step cuts = 2\n") +
      "subsection Solver\n  set Linear solver = cg amg\n  set Maximum iterations = 1\nend\n");
  run_case("maximum events reached", control("    set Maximum events = 3\n"));
}
