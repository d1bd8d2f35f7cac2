// ---------------------------------------------------------------------
// Checkpoint and restart of a problem with several physics (<Physics/List> = heat;
// doc/architecture/09_checkpoints.md, 16_multiphysics.md): the plate of multiphysics_01 (20 mm x
// 10 mm, dx = 1 mm, PMB mechanics whose halves move apart, a bond based conduction from 100 K in
// the left half and 0 in the right one, the left 3 mm held at 200 K so that heat comes in) with
// a critical stretch of 1e-3, so the bonds across the middle break in the first step and the
// crack insulates. A run stopped after the checkpoint of
// step K and restarted from it must end with the numbers of the run that did not stop, on the
// same number of ranks bit for bit: the mechanics' displacements, the heat's temperatures, and
// the files statistics.csv (with its heat. columns: the heat in and the stored heat, whose sums
// the checkpoint holds) and the XDMF records of both physics. Cases:
//  - explicit mechanics, the heat sub-cycled explicitly (2 us, 13 steps; K = 6);
//  - explicit mechanics, the heat implicit (one backward-Euler step per mechanical step; K = 6);
//  - quasi-static mechanics (4 static load steps pulling the right end) with the heat advanced
//    explicitly to each load step's time before its solve (K = 2);
//  - coupled: the same explicit run with an FE part of both physics (an elasticity and a heat
//    mesh of 2 mm cells, blended from x = 12 mm to 16 mm), so the checkpoint holds the FE
//    dof values of both (K = 6);
//  - two way: the coupled run with a thermal expansion of 1e-8 /K on both sides and the
//    thermoelastic heating (<Temperature/Coupling> = two way, T_0 = 300 K: with this plate's
//    rho c of 1 J/(m^3 K) a coupling number T_0 beta : alpha / (rho c) of 0.018, which lowers
//    the stable step by 2 sqrt(1.018); thermoelastic_02 runs alpha = 1e-5), so the checkpoint
//    also holds the measure the next step heats from, the heat so far and the temperature the
//    mechanics' last force evaluation saw (K = 6).
// A checkpoint of the mechanics alone read by the problem with the heat, and the reverse, is
// refused naming <Physics/List>, before anything is written.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  enum class Kind
  {
    explicit_heat,
    implicit_heat,
    quasi_static,
    coupled,
    two_way
  };

  // The plate with its heat (@p with_heat) for the case @p kind.
  std::string
  input(const Kind kind, const bool with_heat)
  {
    const bool        coupled   = kind == Kind::coupled || kind == Kind::two_way;
    const std::string mechanics = coupling_tests::multiphysics_mechanics(true) + R"(
subsection Initial conditions
  set Velocity = if(x < 0.01, -20, 20); 0
end
)" +
                                  std::string(kind == Kind::quasi_static ? R"(
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
    set Function   = 4e-6 * t / 2e-6
  end
end
subsection Solver
  set Type        = static
  set Load steps  = 4
  set Linear solver = direct
end
)" :
                                                                           "") +
                                  (coupled ? coupling_tests::multiphysics_fe(false) : "");
    const std::string heat = coupling_tests::multiphysics_conduction() +
                             coupling_tests::multiphysics_heat_start() + R"(
subsection Solver
  set Type = )" + std::string(kind == Kind::implicit_heat ? "implicit" : "explicit") +
                             R"(
end
)" + (coupled ? coupling_tests::multiphysics_fe(true) : "");
    std::string text = coupling_tests::multiphysics_plate() + R"(
subsection Time stepping
  set End time = 2e-6
end
)";
    text += mechanics;
    if (kind == Kind::two_way)
      text += R"(
subsection Material
  subsection bond based
    set Thermal expansion = 1e-8
  end
end
subsection Finite elements
  subsection Elasticity
    set Thermal expansion = 1e-8
  end
end
subsection Temperature
  set Source                         = heat
  set Reference temperature          = 0
  set Coupling                       = two way
  set Absolute reference temperature = 300
end
)";
    if (with_heat)
      text += coupling_tests::with_heat(heat);
    return text;
  }

  struct Result
  {
    // Owned entries: the mechanics' particle and FE displacements, the heat's particle and FE
    // temperatures.
    std::vector<double> u, U, T, FE_T;
    // The log of the run.
    std::string log;
  };

  // Run @p text with its output in @p directory: stopped after step @p stop (0: not), or
  // restarted from the checkpoint there.
  Result
  run(const std::string &text,
      const std::string &directory,
      const unsigned int stop,
      const bool         restart)
  {
    std::ostringstream                   log;
    perideal::CoupledProblem<2>          problem(MPI_COMM_WORLD, log);
    ParameterHandler                     prm;
    perideal::Physics<2>::ConditionNames heat;
    heat.particles = {"hot"};
    perideal::CoupledProblem<2>::declare_parameters(prm,
                                                    {"plate", "left", "right"},
                                                    {"hold", "pull"},
                                                    {},
                                                    {{"heat", heat}});
    prm.parse_input_from_string(
      text + "subsection Output\n  set Directory = " + directory +
      "\n  set Write HDF5 = true\n  set Progress = false\n  set Statistics interval "
      "= 1\n  set Output interval = 4\nend\n");
    problem.parse_parameters(prm);
    // Not the iterations of the solves.
    deallog.push("run");
    problem.setup();
    if (restart)
      problem.restart_from_checkpoint();
    if (stop > 0)
      problem.stop_after_step(stop);
    problem.run();
    deallog.pop();
    Result      result;
    const auto &physics = problem.get_physics();
    const auto  owned   = [](const perideal::FEVector &v) {
      return std::vector<double>(v.begin(), v.begin() + v.locally_owned_size());
    };
    result.u = owned(physics[0]->state().u);
    result.U = owned(physics[0]->state().U);
    if (physics.size() > 1)
      {
        result.T    = owned(physics[1]->state().u);
        result.FE_T = owned(physics[1]->state().U);
      }
    result.log = log.str();
    MPI_Barrier(MPI_COMM_WORLD);
    return result;
  }

  // Whether @p a and @p b are equal bit for bit on every rank.
  bool
  equal(const std::vector<double> &a, const std::vector<double> &b)
  {
    return Utilities::MPI::min(static_cast<int>(a == b), MPI_COMM_WORLD) == 1;
  }

  // Whether the files of @p name in the directories @p a and @p b are the same (rank 0 reads).
  bool
  same_file(const std::string &a, const std::string &b, const std::string &name)
  {
    bool same = true;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      same = std::filesystem::exists(a + "/" + name) &&
             coupling_tests::read_text(a + "/" + name) == coupling_tests::read_text(b + "/" + name);
    return Utilities::MPI::broadcast(MPI_COMM_WORLD, same, 0);
  }

  void
  verdict(const std::string &what, const bool ok)
  {
    deallog << what << ": " << (ok ? "ok" : "FAILED") << std::endl;
  }

  void
  check(const std::string &name, const Kind kind, const unsigned int stop)
  {
    const std::string text      = input(kind, true);
    const Result      full      = run(text, name + "_full", 0, false);
    const Result      stopped   = run(text, name + "_restarted", stop, false);
    const Result      restarted = run(text, name + "_restarted", 0, true);
    (void)stopped;
    deallog << name << ": stopped after step " << stop << std::endl;
    verdict("  mechanics equal, bit for bit",
            equal(full.u, restarted.u) && equal(full.U, restarted.U));
    verdict("  temperatures equal, bit for bit",
            !full.T.empty() && equal(full.T, restarted.T) && equal(full.FE_T, restarted.FE_T));
    const std::vector<std::string> files =
      kind == Kind::coupled || kind == Kind::two_way ?
        std::vector<std::string>{"statistics.csv",
                                 "particles.xdmf",
                                 "particles_heat.xdmf",
                                 "solution.xdmf",
                                 "solution_heat.xdmf"} :
        std::vector<std::string>{"statistics.csv", "particles.xdmf", "particles_heat.xdmf"};
    for (const auto &file : files)
      verdict("  " + file + " the same", same_file(name + "_full", name + "_restarted", file));
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        const auto statistics = perideal_tests::read_statistics(name + "_full/statistics.csv");
        deallog << "  rows: " << statistics.at("step").size() << ", heat in at the end > 0: "
                << (statistics.at("heat.heat_in").back() > 0. ? "yes" : "no") << std::endl;
      }
  }

  // A restart of @p text from the checkpoint another problem @p other wrote: the message.
  void
  refused(const std::string &name, const std::string &other, const std::string &text)
  {
    run(other, name, 5, false);
    const std::string before = coupling_tests::read_text(name + "/statistics.csv");
    try
      {
        run(text, name, 0, true);
        deallog << name << ": not refused" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        deallog.pop();
        deallog << name << ": " << perideal_tests::exception_text(exc) << std::endl;
      }
    verdict("  statistics.csv unchanged",
            coupling_tests::read_text(name + "/statistics.csv") == before);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);

  check("explicit", Kind::explicit_heat, 6);
  check("implicit", Kind::implicit_heat, 6);
  check("quasi_static", Kind::quasi_static, 2);
  check("coupled", Kind::coupled, 6);
  check("two_way", Kind::two_way, 6);

  refused("heat_from_mechanics",
          input(Kind::explicit_heat, false),
          input(Kind::explicit_heat, true));
  refused("mechanics_from_heat",
          input(Kind::explicit_heat, true),
          input(Kind::explicit_heat, false));
}
