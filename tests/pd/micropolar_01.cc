// A micropolar field layout (x, y, rz: translations and a rotation per particle) end to end,
// with a material model registered outside the library, "rotational springs"
// (tests/rotational_springs.h).
// Checks: a rigid rotation stores no energy and gives no force or moment; the linearization
// (three rows per bond) gives the model's forces; rotational inertia enters the stable time
// step; through the driver (perideal's CoupledProblem with particles only), a static run with
// a moment condition reports the moment reaction and closes the energy balance, and an
// explicit run with an initial rotation field conserves energy, translations and rotation
// clamped by one condition of the default type 'value'. 1 and 2 ranks.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>

#include "../rotational_springs.h"
#include "../tests.h"
#include "pd_tests.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using dealii::deallog;
  using pd_tests::ok;
  const MPI_Comm comm = MPI_COMM_WORLD;
  using pd_tests::Body;
  using perideal_tests::RotationalSprings;

  // 1. and 2. on a 12 x 12 lattice: rigid rotation, linearization.
  void
  check_model()
  {
    Body<2>              body(12, 1e-3, 3.015, perideal::PartialVolume::book, 1e-3);
    RotationalSprings<2> model;
    pd_tests::parse_model(model, {});
    model.initialize(body.ps, {});
    const auto              &ps = body.ps;
    perideal::ParticleVector u, f;
    ps.reinit_vector(u, 3);
    ps.reinit_vector(f, 3);
    std::vector<double> energy;
    const auto          total = [&]() {
      double sum = 0.;
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        sum += energy[i] * ps.volumes()[i];
      return dealii::Utilities::MPI::sum(sum, comm);
    };
    const auto largest = [&](const perideal::ParticleVector &v) {
      return dealii::Utilities::MPI::max(v.linfty_norm(), comm);
    };

    // Rigid rotation phi: u = phi (-y, x), theta = phi; against the same displacement with
    // theta = 0 (a rotation of the lattice that the particles do not follow).
    const double phi              = 1e-3;
    double       reference_energy = 0., reference_force = 0.;
    for (const bool follow : {false, true})
      {
        for (unsigned int i = 0; i < ps.n_local(); ++i)
          {
            u.local_element(3 * i)     = -phi * ps.positions()[i][1];
            u.local_element(3 * i + 1) = phi * ps.positions()[i][0];
            u.local_element(3 * i + 2) = follow ? phi : 0.;
          }
        model.compute_forces(body.ps, u, f, &energy, 0.);
        if (!follow)
          {
            reference_energy = total();
            reference_force  = largest(f);
          }
      }
    deallog << "rigid rotation: energy / energy without the particle rotations < 1e-24 "
            << ok(std::abs(total()) < 1e-24 * reference_energy)
            << ", largest force or moment density / that without < 1e-12 "
            << ok(largest(f) < 1e-12 * reference_force) << std::endl;

    // Linearization: f = -(1/V) G^T diag(w) G u for a random u.
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      for (unsigned int c = 0; c < 3; ++c)
        u.local_element(3 * i + c) =
          (c == 2 ? 1e-3 : 1e-6) * pd_tests::random_number(3 * body.lattice_index(i) + c);
    model.compute_forces(body.ps, u, f, &energy, 0.);
    perideal::LinearizedModel linearized;
    model.linearize(ps, linearized);
    perideal::ParticleVector f_linear;
    const double energy_linear = pd_tests::linearized_forces(ps, linearized, u, f_linear);
    f_linear -= f;
    deallog << "linearization: 3 components " << ok(linearized.n_components() == 3)
            << ", max |f_G - f| / max |f| < 1e-12 " << ok(largest(f_linear) < 1e-12 * largest(f))
            << ", |E_G / E - 1| < 1e-12 " << ok(std::abs(energy_linear / total() - 1.) < 1e-12)
            << std::endl;
  }

  const std::string input = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 5e-4
  set Horizon factor  = 3.015
  set Thickness       = 1e-3
  set Body            = body
end
subsection Regions
  set Names = body, left, right
  subsection body
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.02, 0.004
  end
  subsection left
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.0015, 0.004
  end
  subsection right
    set Shape        = box
    set Lower corner = 0.0185, 0
    set Upper corner = 0.02, 0.004
  end
end
subsection Material
  set Model   = rotational springs
  set Density = 7800
  subsection rotational springs
    set Radius of gyration = RADIUS
  end
end
subsection Boundary conditions
  set Names = clamp, twist
  subsection clamp
    set Region = left
  end
  subsection twist
    set Region          = right
    set Type            = moment
    set Function        = MOMENT
    set Layer thickness = 0.0015
  end
end
subsection Initial conditions
  set Displacement = 0; 0; ROTATION
end
subsection Solver
  set Type          = SOLVER
  set Linear solver = direct
end
subsection Time stepping
  set End time = END_TIME
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  // The log of the driver on @p input with the placeholders replaced.
  std::string
  run(const std::vector<std::pair<std::string, std::string>> &values)
  {
    std::string text = input;
    for (const auto &[key, value] : values)
      text.replace(text.find(key), key.size(), value);
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(comm, log);
    pd_tests::parse_problem(problem, text, {"body", "left", "right"}, {"clamp", "twist"});
    problem.setup();
    problem.run();
    return log.str();
  }

  // The lines of @p log that start with one of @p keys, indented.
  void
  print_lines(const std::string &log, const std::vector<std::string> &keys)
  {
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
      for (const auto &key : keys)
        if (line.rfind(key, 0) == 0)
          deallog << "  " << line << std::endl;
  }

  // The first number after @p key in @p log.
  double
  number_after(const std::string &log, const std::string &key)
  {
    const auto at = log.find(key);
    return at == std::string::npos ? std::nan("") : std::stod(log.substr(at + key.size()));
  }

  // 3. and 4. through the driver.
  void
  check_driver()
  {
    // Static: a moment of 1 N m/m^2 on the right end; the clamp takes it.
    const std::string statics = run({{"RADIUS", "5e-4"},
                                     {"MOMENT", "1"},
                                     {"ROTATION", "0"},
                                     {"SOLVER", "static"},
                                     {"END_TIME", "0"}});
    deallog << "static, moment 1 N m/m^2 on the right end (4e-6 N m):" << std::endl;
    print_lines(statics, {"Strain energy", "External work"});
    {
      // "Reaction clamp: f_x f_y m_z N (N m for rotations)": a pure moment, no net force.
      // (The log is written on rank 0 only.)
      const auto         at = statics.find("Reaction clamp: ");
      std::istringstream reaction(at == std::string::npos ? "" : statics.substr(at + 16));
      double             f_x = 0., f_y = 0., m_z = 0.;
      reaction >> f_x >> f_y >> m_z;
      deallog << "  Reaction clamp: moment " << m_z << " N m, forces below 1e-12 N "
              << ok(std::abs(f_x) < 1e-12 && std::abs(f_y) < 1e-12) << std::endl;
    }
    std::string header;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      std::getline(std::ifstream("results/statistics.csv"), header);
    header = dealii::Utilities::MPI::broadcast(comm, header, 0);
    deallog << "  the moment does work on the rotations: relative energy error < 1e-10 "
            << ok(number_after(statics, "(relative ") < 1e-10)
            << "; the clamp (Type 'value', the default: x, y and rz) reports forces and the "
               "moment as statistics columns "
            << ok(header.find(",reaction_clamp_x,reaction_clamp_y,reaction_clamp_rz") !=
                  std::string::npos)
            << std::endl;

    // Explicit: an initial rotation field, no load; rotational inertia rho r^2 in the stable
    // step (r and r / 10).
    std::vector<double> steps;
    for (const std::string radius : {"5e-4", "5e-5"})
      {
        const std::string dynamics = run({{"RADIUS", radius},
                                          {"MOMENT", "0"},
                                          {"ROTATION", "1e-4 * sin(3.14159265 * x / 0.02)"},
                                          {"SOLVER", "explicit"},
                                          {"END_TIME", "2e-5"}});
        deallog << "explicit, radius of gyration " << radius << " m:" << std::endl;
        print_lines(dynamics,
                    {"Stable time step", "Kinetic energy", "Strain energy", "Energy error"});
        steps.push_back(number_after(dynamics, "Stable time step: PD "));
        const double energy =
          number_after(dynamics, "Kinetic energy: ") + number_after(dynamics, "Strain energy: ");
        deallog << "  |energy error| / energy < 1e-3 "
                << ok(std::abs(number_after(dynamics, "Energy error: ")) < 1e-3 * energy)
                << std::endl;
      }
    deallog << "stable step with r / 10 over that with r = " << steps[1] / steps[0] << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no iteration lines of the linear solver
  check_model();
  check_driver();
}
