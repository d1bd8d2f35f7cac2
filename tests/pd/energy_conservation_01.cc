// Validation: a free body (no boundary condition, no damage, no damping) keeps kinetic + strain
// energy constant under velocity Verlet: over 500 steps at safety factor 0.8 the energy error
// stays below 2 % of E0 and shows no drift (second half of the run below 1.25 x the first), and it
// is second order in the time step (halving dt divides it by 4). 2D plane-stress PMB plate and 3D
// LPS block, started from a smooth displacement and velocity field that is not in equilibrium at
// the free surfaces.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <perideal/coupling/coupled_problem.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  struct Result
  {
    unsigned int steps;
    double       max_error; // max over all steps of |energy_error| / E0
    double       early_max; // the same over the first half of the steps
    double       late_max;  // the same over the second half of the steps
  };

  // Run @p n_steps steps of Safety factor times the stable step of the body in @p body_text.
  template <int dim>
  Result
  run(const std::string &body_text,
      const std::string &region,
      const double       safety_factor,
      const unsigned int n_steps,
      const std::string &directory)
  {
    using namespace dealii;
    const auto make_text = [&](const double end_time) {
      std::ostringstream text;
      text << std::setprecision(17) << body_text << "subsection Time stepping\n"
           << "  set End time = " << end_time << "\n"
           << "  set Safety factor = " << safety_factor << "\n"
           << "end\n"
           << "subsection Output\n"
           << "  set Directory = " << directory << "\n"
           << "  set Statistics interval = 1\n"
           << "  set Write HDF5 = false\n"
           << "  set Progress = false\n"
           << "end\n";
      return text.str();
    };

    // A first set-up gives the time step (Safety factor x stable limit) of this body.
    double dt = 0.;
    {
      std::ostringstream            log;
      perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
      pd_tests::parse_problem(problem, make_text(1.), {region});
      problem.setup();
      dt = problem.time_step();
    }

    std::ostringstream            log;
    perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
    pd_tests::parse_problem(problem, make_text(n_steps * dt), {region});
    problem.setup();
    problem.run();

    Result result{0, 0., 0., 0.};
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        auto         stats = perideal_tests::read_statistics(directory + "/statistics.csv");
        const double E0    = stats["kinetic_energy"][0] + stats["strain_energy"][0];
        const auto  &error = stats["energy_error"];
        result.steps       = static_cast<unsigned int>(std::lround(stats["step"].back()));
        for (unsigned int k = 0; k < error.size(); ++k)
          {
            result.max_error = std::max(result.max_error, std::abs(error[k]) / E0);
            double &half_max = (2 * k < error.size() ? result.early_max : result.late_max);
            half_max         = std::max(half_max, std::abs(error[k]) / E0);
          }
      }
    return result;
  }

  template <int dim>
  void
  check(const std::string &name, const std::string &body_text, const std::string &region)
  {
    const Result coarse = run<dim>(body_text, region, 0.8, 500, "output_" + name + "_08");
    const Result fine   = run<dim>(body_text, region, 0.4, 1000, "output_" + name + "_04");
    const double order  = std::log2(coarse.max_error / fine.max_error);

    const bool pass = coarse.max_error < 0.02 && coarse.late_max < 1.25 * coarse.early_max &&
                      std::abs(order - 2.) < 0.2;
    std::ostringstream line;
    line << std::scientific << std::setprecision(2) << name << ": " << coarse.steps
         << " steps at safety factor 0.8: max |energy error|/E0 = " << coarse.max_error
         << " (first half of the run: " << coarse.early_max << ", second half: " << coarse.late_max
         << ")\n"
         << name << ": " << fine.steps
         << " steps at safety factor 0.4: max |energy error|/E0 = " << fine.max_error << "\n"
         << std::fixed << name << ": observed order in dt = " << order << "\n"
         << name << ": bounded below 2 %, no drift, second order: " << (pass ? "ok" : "FAILED");
    std::istringstream lines(line.str());
    for (std::string text; std::getline(lines, text);)
      dealii::deallog << text << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  // 20 mm x 20 mm x 1 mm steel plate, 40 x 40 particles, delta = 3.015 dx.
  check<2>(
    "pmb_2d",
    "subsection Discretization\n"
    "  set Lattice spacing = 5e-4\n"
    "  set Horizon factor = 3.015\n"
    "  set Thickness = 1e-3\n"
    "  set Body = plate\n"
    "end\n"
    "subsection Regions\n"
    "  set Names = plate\n"
    "  subsection plate\n"
    "    set Lower corner = 0, 0\n"
    "    set Upper corner = 0.02, 0.02\n"
    "  end\n"
    "end\n"
    "subsection Material\n"
    "  set Model = bond based\n"
    "  set Density = 7800\n"
    "  subsection bond based\n"
    "    set Young's modulus = 192e9\n"
    "  end\n"
    "end\n"
    "subsection Initial conditions\n"
    "  set Displacement = 1e-6*sin(3.141592653589793*x/0.02)*cos(3.141592653589793*y/0.02); 0\n"
    "  set Velocity = 0; cos(3.141592653589793*x/0.02)*cos(2*3.141592653589793*y/0.02)\n"
    "end\n",
    "plate");

  // 12 mm steel cube, 12 x 12 x 12 particles, delta = 3.015 dx, nu = 0.3.
  check<3>("lps_3d",
           "subsection Discretization\n"
           "  set Lattice spacing = 1e-3\n"
           "  set Horizon factor = 3.015\n"
           "  set Body = block\n"
           "end\n"
           "subsection Regions\n"
           "  set Names = block\n"
           "  subsection block\n"
           "    set Lower corner = 0, 0, 0\n"
           "    set Upper corner = 0.012, 0.012, 0.012\n"
           "  end\n"
           "end\n"
           "subsection Material\n"
           "  set Model = linear peridynamic solid\n"
           "  set Density = 7800\n"
           "  subsection linear peridynamic solid\n"
           "    set Young's modulus = 192e9\n"
           "    set Poisson's ratio = 0.3\n"
           "  end\n"
           "end\n"
           "subsection Initial conditions\n"
           "  set Displacement = 0; 0; "
           "1e-6*sin(3.141592653589793*z/0.012)*cos(3.141592653589793*x/0.012)\n"
           "  set Velocity = cos(3.141592653589793*x/0.012); "
           "cos(3.141592653589793*y/0.012)*cos(3.141592653589793*z/0.012); 0\n"
           "end\n",
           "block");
}
