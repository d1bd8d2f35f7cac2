// ---------------------------------------------------------------------
// Restarts of a problem with several physics (<Physics/List> = heat; doc/architecture/
// 09_checkpoints.md, 16_multiphysics.md) on another number of ranks, and after a load step that
// did not converge. The plate of multiphysics_01 (20 mm x 10 mm, dx = 1 mm, PMB with a critical
// stretch of 1e-3, the bond based conduction from 100 K in the left half and 0 in the right
// one, the left 3 mm held at 200 K so that heat comes in). The harness of restart_tests.h:
// a run stopped after the checkpoint of step K and restarted from it ends with the numbers of
// the run that did not stop, bit for bit on the same number of ranks (the mechanics' particle
// and FE displacements, the heat's particle and FE temperatures, statistics.csv with its heat.
// columns and the XDMF records of both physics); on 2 ranks also stopped on 1 rank and
// restarted on 2, and the reverse, where both physics' fields agree with the uninterrupted run
// on the ranks of the restart to 1e-10 of their largest value and each statistics column to
// round-off (the sums of the checkpoint are added on rank 0 and the solves sum in another
// order, so the runs differ in the last bits). Cases:
//  - explicit mechanics whose halves move apart (the bonds across the middle break in the first
//    step), the heat sub-cycled explicitly (2 us, 13 steps; K = 6);
//  - quasi-static mechanics (4 static load steps pulling the right end) with the heat implicit
//    (one theta step per load step; K = 2);
//  - coupled (blended): the explicit run with an FE part of both physics (2 mm cells, the
//    particles blended out from x = 12 mm to 16 mm; K = 6).
// Then a quasi-static run that does not converge: adaptive dynamic relaxation with <Solver/
// Maximum iterations> = 50 and the pull as a time history (<Solver/Control/Load history> =
// time) that is 0 in load steps 1 and 2 of 4 and 3 um, 4 um in load steps 3 and 4 (which need
// more relaxation iterations), so load step 3 stops with ExcNotConverged and writes
// the checkpoint of load step 2 for both physics (kept before the heat advanced to load step 3's
// time, Checkpoint::write_kept()). A restart with the default 100000 iterations continues from
// load step 2 and ends, bit for bit, with the run that had them from the start: both physics'
// fields, statistics.csv and the XDMF records.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>

#include <perideal/coupling/coupled_problem.h>

#include "restart_tests.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  // The heat of the plate, <Heat/Solver/Type> = @p solver, with an FE part if @p coupled.
  std::string
  heat(const std::string &solver, const bool coupled)
  {
    return coupling_tests::with_heat(coupling_tests::multiphysics_conduction() +
                                     coupling_tests::multiphysics_heat_start() +
                                     "subsection Solver\n  set Type = " + solver + "\nend\n" +
                                     (coupled ? coupling_tests::multiphysics_fe(true) : ""));
  }

  // The plate's mechanics: explicit, its halves moving apart (with an FE part if @p coupled).
  std::string
  explicit_plate(const bool coupled)
  {
    return coupling_tests::multiphysics_plate() + coupling_tests::multiphysics_mechanics(true) +
           R"(
subsection Initial conditions
  set Velocity = if(x < 0.01, -20, 20); 0
end
subsection Time stepping
  set End time = 2e-6
end
)" + (coupled ? coupling_tests::multiphysics_fe(false) : "");
  }

  // The plate's mechanics pulled at its right end by @p pull [m] (a function of the time with
  // @p time_history) in 4 load steps of <Solver/Type> = @p type.
  std::string
  static_plate(const std::string &pull, const bool time_history, const std::string &type)
  {
    return coupling_tests::multiphysics_plate() + coupling_tests::multiphysics_mechanics(true) +
           R"(
subsection Boundary conditions
  set Names = hold, pull
  subsection hold
    set Region = left
    set Type   = displacement
  end
  subsection pull
    set Region     = right
    set Type       = displacement
    set Components = x
    set Function   = )" +
           pull + R"(
  end
end
subsection Time stepping
  set End time = 2e-6
end
subsection Solver
  set Type          = )" +
           type + R"(
  set Load steps    = 4
  set Linear solver = direct
)" + (time_history ? "  subsection Control\n    set Load history = time\n  end\n" : "") +
           "end\n";
  }

  const std::string every_step = "subsection Output\n  set Statistics interval = 1\n"
                                 "  set Output interval = 4\n  set Write HDF5 = true\nend\n";

  struct Outcome
  {
    std::vector<double> u, T;
    std::string         error;
  };

  // Run @p text in @p directory (restarted if @p restart); the message of an ExcNotConverged
  // is kept in error.
  Outcome
  run(const std::string &text, const std::string &directory, const bool restart)
  {
    Outcome outcome;
    coupling_tests::write_file(directory + ".prm",
                               text + every_step + "subsection Output\n  set Directory = " +
                                 directory + "\n  set Progress = false\nend\n");
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    coupling_tests::parse(problem, directory + ".prm");
    // Not the lines of the solver controls.
    deallog.push("run");
    problem.setup();
    if (restart)
      problem.restart_from_checkpoint();
    try
      {
        problem.run();
      }
    catch (const perideal::ExcNotConverged &exc)
      {
        outcome.error = perideal_tests::exception_text(exc);
      }
    deallog.pop();
    const auto &physics = problem.get_physics();
    for (const auto *field : {&physics[0]->state().u, &physics[0]->state().U})
      outcome.u.insert(outcome.u.end(),
                       field->begin(),
                       field->begin() + field->locally_owned_size());
    for (const auto *field : {&physics[1]->state().u, &physics[1]->state().U})
      outcome.T.insert(outcome.T.end(),
                       field->begin(),
                       field->begin() + field->locally_owned_size());
    MPI_Barrier(MPI_COMM_WORLD);
    return outcome;
  }

  // Whether @p a and @p b are equal bit for bit on every rank.
  bool
  equal(const std::vector<double> &a, const std::vector<double> &b)
  {
    return Utilities::MPI::min(static_cast<int>(a == b), MPI_COMM_WORLD) == 1;
  }

  void
  not_converged()
  {
    const std::string pull = "if(t < 1.1e-6, 0, 4e-6 * t / 2e-6)";
    const std::string text =
      static_plate(pull, true, "adaptive dynamic relaxation") + heat("explicit", false);
    const Outcome full = run(text, "not_converged_full", false);
    const Outcome stops =
      run(text + "subsection Solver\n  set Maximum iterations = 50\nend\n", "not_converged", false);
    deallog << "converged with 100000 iterations: " << coupling_tests::ok(full.error.empty())
            << std::endl;
    deallog << "with 50 iterations: " << (stops.error.empty() ? "converged (FAILED)" : "")
            << std::endl;
    std::istringstream lines(stops.error);
    for (std::string line; std::getline(lines, line);)
      if (line.find("did not converge") != std::string::npos)
        deallog << "  " << line.substr(0, std::min(line.find(". "), line.find(" (<"))) << std::endl;
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    if (root)
      {
        const auto statistics =
          perideal_tests::read_statistics("not_converged/statistics.csv").at("step");
        deallog << "  statistics.csv ends at load step " << statistics.back() << std::endl;
      }
    const Outcome restarted = run(text, "not_converged", true);
    deallog << "  restarted with 100000 iterations: "
            << (restarted.error.empty() ? "converged" : restarted.error) << std::endl;
    deallog << "  mechanics equal to the run that converged, bit for bit: "
            << coupling_tests::ok(equal(full.u, restarted.u)) << std::endl;
    deallog << "  temperatures equal, bit for bit: "
            << coupling_tests::ok(!full.T.empty() && equal(full.T, restarted.T)) << std::endl;
    for (const std::string file : {"statistics.csv", "particles.xdmf", "particles_heat.xdmf"})
      {
        bool same = true;
        if (root)
          same = coupling_tests::read_text("not_converged_full/" + file) ==
                 coupling_tests::read_text("not_converged/" + file);
        deallog << "  " << file << " the same: "
                << coupling_tests::ok(Utilities::MPI::broadcast(MPI_COMM_WORLD, same, 0))
                << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);

  restart_tests::check(
    {"explicit_heat", explicit_plate(false) + every_step + heat("explicit", false), 0.5});
  restart_tests::check(
    {"quasi_static_implicit_heat",
     static_plate("4e-6", false, "static") + every_step + heat("implicit", false),
     0.5});
  restart_tests::check(
    {"coupled_heat", explicit_plate(true) + every_step + heat("explicit", true), 0.5});
  not_converged();
}
