// ---------------------------------------------------------------------
// Several physics in one problem (<Physics/List> = heat; doc/architecture/16_multiphysics.md):
// a 20 mm x 10 mm plane-stress plate (dx = 1 mm, 200 particles) whose halves move apart at
// 20 m/s (initial velocity -20 m/s for x < 10 mm, +20 m/s beyond), PMB mechanics; its heat a
// bond based conduction (k = 50 W/(m K)) from T = 100 K in the left half and
// 0 in the right one, insulated. Explicit, 2 us; the heat is sub-cycled in the mechanical
// steps. Its heat capacity rho c = 1 J/(m^3 K) (density 1, specific heat 1) makes the heat
// diffuse across the plate in the 2 us of the mechanics (diffusivity 50 m^2/s). Checked, on 1
// and 2 ranks:
//  - no exchange effect (no damage): the mechanics equal the mechanics run alone bit for bit,
//    the temperatures those of the heat run alone with the sub-step as its time step, to
//    1e-12 of the largest (the times of the sub-steps differ in the last bit);
//  - the same with the heat implicit (<Heat/Solver/Type> = implicit: one backward-Euler step
//    per mechanical step) against the heat run alone, implicit, with the mechanical step;
//  - quasi-static mechanics (2 static load steps of a pull, equal to the mechanics alone bit
//    for bit) with the heat advanced explicitly to each load step's time before its solve
//    (equal to the heat alone to 1e-12);
//  - the exchange publishes the heat's temperature at the particles;
//  - a mechanical crack insulates: with a critical stretch of 1e-3 the bonds across x = 10 mm
//    break in the first step (the halves separate at 40 m/s); the heat in the right half, which
//    only the flow across the crack line can change, is then the same at 1 us and at 2 us to
//    round-off (1e-12 of the heat in the plate), while without damage it grows.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  enum class Fields
  {
    mechanics,
    heat,
    both
  };

  std::string
  number(const double x)
  {
    std::ostringstream text;
    text << std::setprecision(17) << x;
    return text.str();
  }

  // The plate: the mechanics in the top-level sections, the heat in them (alone) or in
  // <Heat> (both).
  std::string
  input(const Fields       fields,
        const bool         damage,
        const double       end_time,
        const double       heat_step,
        const std::string &heat_solver,
        const bool         quasi_static)
  {
    const std::string mechanics = coupling_tests::multiphysics_mechanics(damage) + R"(
subsection Initial conditions
  set Velocity = if(x < 0.01, -20, 20); 0
end
)" +
                                  std::string(quasi_static ? R"(
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
    set Function   = 2e-6 * t / 2e-6
  end
end
subsection Solver
  set Type        = static
  set Load steps  = 2
  set Linear solver = direct
end
)" :
                                                             "");
    const std::string heat = coupling_tests::multiphysics_conduction() + R"(
subsection Initial conditions
  set Displacement = if(x < 0.01, 100, 0)
end
subsection Solver
  set Type = )" + heat_solver +
                             R"(
end
)";
    std::string text =
      coupling_tests::multiphysics_plate() + R"(
subsection Time stepping
  set End time = )" +
      number(end_time) + "\n" +
      (fields == Fields::heat ? "  set Time step = " + number(heat_step) + "\n" : "") +
      R"(end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
  set Statistics interval = 1000
end
)";
    if (fields == Fields::mechanics)
      return text + mechanics;
    if (fields == Fields::heat)
      return text + heat;
    return text + mechanics + coupling_tests::with_heat(heat);
  }

  struct Result
  {
    // Owned entries: the displacement, the temperature.
    std::vector<double> u, T;
    // The temperature as the exchange publishes it (owned particles).
    std::vector<double> published;
    // The heat sum V T (rho c = 1) over the particles with x > 10 mm, and over all [J].
    double right_heat = 0., heat = 0.;
    // The heat's sub-step and the mechanics' step [s].
    double heat_step = 0., step = 0.;
  };

  Result
  run(const Fields       fields,
      const bool         damage,
      const double       end_time,
      const double       heat_step    = 0.,
      const std::string &heat_solver  = "explicit",
      const bool         quasi_static = false)
  {
    std::ostringstream                   log;
    perideal::CoupledProblem<2>          problem(MPI_COMM_WORLD, log);
    ParameterHandler                     prm;
    perideal::Physics<2>::ConditionNames none;
    perideal::CoupledProblem<2>::declare_parameters(prm,
                                                    {"plate", "left", "right"},
                                                    {"hold", "pull"},
                                                    {},
                                                    {{"heat", none}});
    prm.parse_input_from_string(
      input(fields, damage, end_time, heat_step, heat_solver, quasi_static));
    problem.parse_parameters(prm);
    // Not the iterations of the solves.
    deallog.push("run");
    problem.setup();
    problem.run();
    deallog.pop();
    Result                          result;
    const auto                     &ps      = problem.particles();
    const auto                     &physics = problem.get_physics();
    const perideal::ParticleVector *temperature =
      fields == Fields::both ? &physics[1]->state().u :
      fields == Fields::heat ? &problem.particle_displacement() :
                               nullptr;
    const unsigned int nc = fields == Fields::heat ? 1 : 2;
    for (unsigned int k = 0; k < ps.n_owned() * nc; ++k)
      if (fields != Fields::heat)
        result.u.push_back(problem.particle_displacement().local_element(k));
    const double rho_c = 1.;
    if (temperature != nullptr)
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        {
          const double T = temperature->local_element(i);
          result.T.push_back(T);
          result.heat += rho_c * ps.volumes()[i] * T;
          if (ps.positions()[i][0] > 0.01)
            result.right_heat += rho_c * ps.volumes()[i] * T;
          if (fields == Fields::both)
            result.published.push_back(problem.get_exchange().particle_value("temperature", i));
        }
    result.right_heat = Utilities::MPI::sum(result.right_heat, MPI_COMM_WORLD);
    result.heat       = Utilities::MPI::sum(result.heat, MPI_COMM_WORLD);
    if (fields == Fields::both)
      {
        result.heat_step = physics[1]->state().time_step;
        result.step      = physics[0]->state().time_step;
      }
    return result;
  }

  // The largest difference of @p a and @p b over the ranks relative to @p scale.
  double
  difference(const std::vector<double> &a, const std::vector<double> &b, const double scale)
  {
    AssertThrow(a.size() == b.size(), ExcInternalError());
    double largest = 0.;
    for (std::size_t k = 0; k < a.size(); ++k)
      largest = std::max(largest, std::abs(a[k] - b[k]));
    return Utilities::MPI::max(largest, MPI_COMM_WORLD) / scale;
  }

  void
  verdict(const std::string &what, const bool ok)
  {
    deallog << what << ": " << (ok ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);

  // No exchange effect: each physics as alone.
  const Result both      = run(Fields::both, false, 2e-6);
  const Result mechanics = run(Fields::mechanics, false, 2e-6);
  const Result heat      = run(Fields::heat, false, 2e-6, both.heat_step);
  deallog << "heat sub-step: " << both.heat_step << " s" << std::endl;
  verdict("mechanics equal to the mechanics alone, bit for bit",
          difference(both.u, mechanics.u, 1.) == 0.);
  const double heat_difference = difference(both.T, heat.T, 100.);
  verdict("temperature equal to the heat alone to 1e-12", heat_difference <= 1e-12);
  verdict("the exchange publishes the temperature", difference(both.published, both.T, 1.) == 0.);

  // The heat implicit, one theta step (backward Euler) per mechanical step, as alone.
  const Result implicit_both = run(Fields::both, false, 2e-6, 0., "implicit");
  const Result implicit_heat = run(Fields::heat, false, 2e-6, implicit_both.step, "implicit");
  deallog << "implicit heat step: " << implicit_both.heat_step << " s" << std::endl;
  verdict("implicit heat step equal to the mechanical step",
          implicit_both.heat_step == implicit_both.step);
  verdict("implicit temperature equal to the heat alone to 1e-12",
          difference(implicit_both.T, implicit_heat.T, 100.) <= 1e-12);

  // Quasi-static mechanics (2 static load steps, the right end pulled by 1 um per step) and
  // the heat advanced explicitly to each load step's time (k/2 of 2 us) before its solve.
  const Result static_both      = run(Fields::both, false, 2e-6, 0., "explicit", true);
  const Result static_mechanics = run(Fields::mechanics, false, 2e-6, 0., "explicit", true);
  const Result static_heat      = run(Fields::heat, false, 2e-6, static_both.heat_step);
  double       largest          = 0.;
  for (const double u : static_both.u)
    largest = std::max(largest, std::abs(u));
  deallog << "quasi-static: heat sub-step " << static_both.heat_step << " s, largest displacement "
          << Utilities::MPI::max(largest, MPI_COMM_WORLD) << " m" << std::endl;
  verdict("quasi-static mechanics equal to the mechanics alone, bit for bit",
          difference(static_both.u, static_mechanics.u, 1.) == 0.);
  verdict("quasi-static: temperature equal to the heat alone to 1e-12",
          difference(static_both.T, static_heat.T, 100.) <= 1e-12);

  // A mechanical crack insulates.
  const Result cracked_1 = run(Fields::both, true, 1e-6), cracked_2 = run(Fields::both, true, 2e-6);
  const Result intact_1 = run(Fields::both, false, 1e-6);
  const double change   = std::abs(cracked_2.right_heat - cracked_1.right_heat) / cracked_2.heat;
  deallog << "heat of the right half, cracked: " << cracked_1.right_heat << " J at 1 us, "
          << cracked_2.right_heat << " J at 2 us; intact: " << intact_1.right_heat << " J at 1 us, "
          << both.right_heat << " J at 2 us" << std::endl;
  verdict("no heat crosses the crack after it opened (1e-12 of the heat)", change <= 1e-12);
  verdict("heat crosses the intact plate",
          both.right_heat - intact_1.right_heat > 1e-3 * both.heat);
}
