// PMB stable time step (thesis value) and a two-particle oscillator under the velocity-Verlet
// time stepping of the driver (CoupledProblem, particles only).

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
  using dealii::deallog;
  const double pi  = dealii::numbers::PI;
  const double E   = 192e9;
  const double rho = 7800.;
  const double dx  = 1e-4;

  template <int dim>
  void
  make_model(perideal::BondBased<dim>        &model,
             perideal::ParticleSystem<dim>   &ps,
             const perideal::PlanarAssumption planar)
  {
    pd_tests::parse_model(model, {{"Young's modulus", std::to_string(E)}});
    model.initialize(
      ps,
      pd_tests::model_context(ps.settings().horizon, ps.settings().thickness, planar, false));
  }

  // The thesis plate (seed note 002, sec. 5.3): E = 192 GPa, rho = 7800 kg/m^3,
  // dx = h = 1e-4 m, delta = 4 dx, |xi| <= delta, no corrections: dt = 2.94685e-8 s from the
  // Silling-Askari bound at an interior particle (48 neighbours; the most stiffness, so the
  // minimum over the body).
  void
  check_stable_time_step()
  {
    perideal::ParticleSystem<2>           ps(MPI_COMM_WORLD);
    perideal::ParticleSystem<2>::Settings s;
    s.spacing        = dx;
    s.horizon        = 4. * dx;
    s.thickness      = 1e-4;
    s.partial_volume = perideal::PartialVolume::none;
    pd_tests::generate_box<2>(ps, s, dealii::Point<2>(), dealii::Point<2>(11 * dx, 11 * dx));
    perideal::BondBased<2> model;
    make_model(model, ps, perideal::PlanarAssumption::plane_stress);
    const double dt = model.stable_time_step(ps, rho);

    // Independently: sqrt(2 rho / sum_j c V / |xi|) over the 48 lattice offsets.
    double sum = 0.;
    for (int a = -4; a <= 4; ++a)
      for (int b = -4; b <= 4; ++b)
        if (a * a + b * b > 0 && a * a + b * b <= 16)
          sum += model.micromodulus() * dx * dx * s.thickness / (dx * std::sqrt(a * a + b * b));
    const double expected = std::sqrt(2. * rho / sum);
    deallog << "stable time step " << dt << " s: lattice sum (< 1e-12) "
            << (std::abs(dt / expected - 1.) < 1e-12 ? "ok" : "FAILED")
            << ", thesis 2.94685e-8 s (< 1e-4) "
            << (std::abs(dt / 2.94685e-8 - 1.) < 1e-4 ? "ok" : "FAILED") << std::endl;
  }

  // Two particles one dx apart on x with delta = 1.5 dx share one bond, a linear spring in 1D:
  // the force on particle 1 is f V = c (q / |xi|) V V with q = u2 - u1, each mass is rho V, so
  // rho V q'' = -2 c V^2 q / |xi| and omega^2 = 2 c V / (rho |xi|).
  void
  check_oscillator()
  {
    perideal::ParticleSystem<3>           ps(MPI_COMM_WORLD);
    perideal::ParticleSystem<3>::Settings s;
    s.spacing        = dx;
    s.horizon        = 1.5 * dx;
    s.partial_volume = perideal::PartialVolume::none;
    pd_tests::generate_box<3>(ps, s, dealii::Point<3>(), dealii::Point<3>(2 * dx, dx, dx));
    perideal::BondBased<3> model;
    make_model(model, ps, perideal::PlanarAssumption::three_dimensional);
    deallog << "oscillator: " << ps.n_global() << " particles, " << ps.n_global_bonds() << " bond"
            << std::endl;

    const double V      = dx * dx * dx;
    const double omega  = std::sqrt(2. * model.micromodulus() * V / (rho * dx));
    const double period = 2. * pi / omega;
    const double dt     = period / 200.;
    // Velocity Verlet on a linear oscillator gives q_n = q_0 cos(omega_h n dt) exactly, with
    // cos(omega_h dt) = 1 - (omega dt)^2 / 2: the period is shorter by (omega dt)^2 / 24.
    const double period_verlet = 2. * pi * dt / std::acos(1. - 0.5 * std::pow(omega * dt, 2));

    // The same two particles through the driver: u_x = -+amplitude, 2000 steps of dt, a
    // statistics row per step (energies; |u| of each particle is |q| / 2).
    const double       amplitude = 1e-3 * dx;
    const unsigned int n_steps   = 2000;
    std::ostringstream text;
    text << std::setprecision(17) << "set Dimension = 3\n"
         << "subsection Discretization\n"
         << "  set Lattice spacing = " << dx << "\n"
         << "  set Horizon factor = 1.5\n"
         << "  set Partial volume correction = none\n"
         << "  set Surface correction = false\n"
         << "  set Body = pair\n"
         << "end\n"
         << "subsection Regions\n"
         << "  set Names = pair\n"
         << "  subsection pair\n"
         << "    set Lower corner = 0, 0, 0\n"
         << "    set Upper corner = " << 2 * dx << ", " << dx << ", " << dx << "\n"
         << "  end\n"
         << "end\n"
         << "subsection Material\n"
         << "  set Density = " << rho << "\n"
         << "  subsection bond based\n"
         << "    set Young's modulus = " << E << "\n"
         << "  end\n"
         << "end\n"
         << "subsection Initial conditions\n"
         << "  set Displacement = if(x > " << dx << ", " << amplitude << ", " << -amplitude
         << "); 0; 0\n"
         << "end\n"
         << "subsection Time stepping\n"
         << "  set Time step = " << dt << "\n"
         << "  set End time = " << n_steps * dt << "\n"
         << "end\n"
         << "subsection Output\n"
         << "  set Directory = oscillator\n"
         << "  set Statistics interval = 1\n"
         << "  set Write HDF5 = false\n"
         << "  set Progress = false\n"
         << "end\n";
    {
      std::ostringstream          log;
      perideal::CoupledProblem<3> problem(MPI_COMM_WORLD, log);
      pd_tests::parse_problem(problem, text.str(), {"pair"});
      problem.setup();
      problem.run();
    }
    MPI_Barrier(MPI_COMM_WORLD);
    auto        stats     = perideal_tests::read_statistics("oscillator/statistics.csv");
    const auto &magnitude = stats["max_particle_displacement"];
    const auto &times     = stats["time"];
    deallog << "  " << times.size() - 1 << " steps of the driver" << std::endl;
    std::cerr << std::setprecision(12) << times[1] << " " << dt << std::endl;

    // q = u2 - u1 = 2 |u| up to its sign, which flips at each minimum of |q|: near a zero
    // crossing q is linear, so the crossing lies after the minimum m if |q_(m-1)| > |q_(m+1)|
    // (q_m still has the old sign), before it otherwise.
    std::vector<double> q(magnitude.size());
    double              sign = 1.;
    for (unsigned int n = 0; n < magnitude.size(); ++n)
      {
        q[n] = sign * 2. * magnitude[n];
        if (n > 0 && n + 1 < magnitude.size() && magnitude[n] < magnitude[n - 1] &&
            magnitude[n] <= magnitude[n + 1])
          {
            if (magnitude[n - 1] <= magnitude[n + 1])
              q[n] = -q[n];
            sign = -sign;
          }
      }
    std::vector<double> crossings;
    double              energy_error = 0.;
    const double        energy_0     = stats["kinetic_energy"][0] + stats["strain_energy"][0];
    for (unsigned int n = 1; n < q.size(); ++n)
      {
        if ((q[n - 1] > 0.) != (q[n] > 0.))
          crossings.push_back(times[n] - (times[n] - times[n - 1]) * q[n] / (q[n] - q[n - 1]));
        energy_error =
          std::max(energy_error,
                   std::abs((stats["kinetic_energy"][n] + stats["strain_energy"][n]) / energy_0 -
                            1.));
      }
    const double measured = 2. * (crossings.back() - crossings.front()) / (crossings.size() - 1);

    deallog << "  " << crossings.size()
            << " zero crossings in 10 periods; measured/exact period - 1 = " << std::setprecision(2)
            << measured / period - 1. << std::setprecision(6)
            << ", theory -(omega dt)^2/24 = " << std::setprecision(2)
            << -std::pow(omega * dt, 2) / 24. << std::setprecision(6) << std::endl;
    // Tolerances: the Verlet period error (omega dt)^2/24 = 4.1e-5 must be reproduced to 1e-6
    // (the secant zero crossings err by O((omega dt)^3) per crossing, averaged over 20); the
    // period itself is right to 1e-4.
    deallog << "  period within 1e-4 of 2 pi / omega "
            << (std::abs(measured / period - 1.) < 1e-4 ? "ok" : "FAILED")
            << ", within 1e-6 of the Verlet period "
            << (std::abs(measured / period_verlet - 1.) < 1e-6 ? "ok" : "FAILED") << std::endl;
    // The Verlet energy of a linear oscillator oscillates between E0 (1 - (omega dt)^2/4) and
    // E0 without drift (the modified energy v^2/2 / (1 - (omega dt / 2)^2) + omega^2 q^2 / 2 is
    // conserved exactly). The energies come from statistics.csv, written with 10 significant
    // digits: E / E0 carries up to 1e-9 of rounding (two terms of at most E0 each), allowed on
    // top of the bound.
    const double bound = 0.25 * std::pow(omega * dt, 2);
    deallog << "  max |E/E0 - 1| over 10 periods = " << std::setprecision(3) << energy_error
            << std::setprecision(6) << ", bound (omega dt)^2/4 = " << std::setprecision(3) << bound
            << std::setprecision(6) << ": " << (energy_error <= bound + 1e-9 ? "ok" : "FAILED")
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  check_stable_time_step();
  check_oscillator();
}
