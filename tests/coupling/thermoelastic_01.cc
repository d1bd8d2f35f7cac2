// ---------------------------------------------------------------------
// Test (#39): the two-way thermoelastic coupling (<Temperature/Coupling> = two way,
// doc/theory/thermoelasticity.md) on a bar in uniaxial strain: 0 < x < L = 0.1 m, 10 mm high,
// plane strain, u_y = 0 everywhere, u_x = 0 at both ends, insulated, starting from rest in the
// mode u_x = U_0 sin(q x), q = pi / L, at T = T_0. Linear thermoelasticity keeps the mode:
// u_x = U(t) sin(q x), T - T_0 = Theta(t) cos(q x) with
//   rho U'' = -M q^2 U + beta q Theta,  rho c Theta' = -k q^2 Theta - T_0 beta q U',
// M = lambda + 2 mu, beta = (3 lambda + 2 mu) alpha; its roots s solve the cubic
// (rho s^2 + M q^2)(rho c s + k q^2) + T_0 beta^2 q^2 s = 0 (Zener's thermoelastic damping of a
// plane wave; Chadwick 1960). Here the coupling T_0 beta^2 / (rho c M) = 0.25 and the thermal
// relaxation k q^2 / (rho c) at the frequency (omega tau = 1.1: Zener's peak), so that the
// vibration loses most of its amplitude in two periods.
//
// For the particles alone (PMB, nu = 1/4, the bond based conduction; the ends held in layers
// of a horizon beyond x = 0 and L), the FE region alone (Q1 elasticity and FE heat) and both
// blended (PD in the middle, FE at the ends), each on 1 and 2 ranks, the test checks:
//  - adiabatic (k = 1e-6, one period): the heat each free particle gains is -T_0 times the gain
//    of its thermoelastic measure (to 1e-8: the conduction left); the energy of linear
//    thermoelasticity, kinetic + 1/2 eps : C : eps + C_i (T - T_0)^2 / (2 T_0), kept to the
//    integration error, second order in the step (the adiabatic split: the heating's temperature
//    change reaches the mechanics' forces within the step, ThermoelasticHeating::heat_step());
//  - conducting (two periods): the mode's amplitude (the projection of u_x on sin(q x)) against
//    the exact solution of the mode's equations, with the modulus of the run's own period
//    without the coupling (the particles' discrete stiffness), to 1 % of U_0 for FE and blended
//    and 6 % for the particles alone, whose clamp layers also conduct and heat: their error is
//    first order in delta / L (4.7 % at L = 0.1 m, 2.1 % at 0.2 m, measured with the same
//    parameters and k doubled to keep omega tau); the coupling changes the amplitude by more than
//    ten times the error.
// ---------------------------------------------------------------------
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <perideal/base/parameter_utilities.h>

#include "coupling_tests.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace perideal;

namespace
{
  constexpr double L = 0.1, H = 0.01, thickness = 1e-3;
  constexpr double E = 2.5e9, nu = 0.25, rho = 1000., c = 100., k = 5e6, T0 = 300.;
  constexpr double U0 = 1e-5;
  // The conductivity of the adiabatic runs (the conduction left over one period is negligible);
  // only their samples need the energies and the thermoelastic measure.
  constexpr double adiabatic_conductivity = 1e-6;
  const double     lambda = E * nu / ((1. + nu) * (1. - 2. * nu)), mu = E / (2. * (1. + nu));
  const double     M = lambda + 2. * mu, q = numbers::PI / L;

  enum class Variant
  {
    pd,
    fe,
    blended
  };

  const char *
  name(const Variant v)
  {
    return v == Variant::pd ? "PD" : v == Variant::fe ? "FE" : "blended";
  }

  // The blending function of the blended bar (PD in the middle).
  const std::string blending = "min(1, max(0, (0.03 - abs(x - 0.05)) / 0.01))";

  std::string
  parameters(const Variant v,
             const double  alpha,
             const double  safety,
             const double  conductivity,
             const double  end_time)
  {
    const bool        particles = v != Variant::fe, mesh = v != Variant::pd;
    const std::string a = std::to_string(alpha);
    // The particles' conditions: u_y = 0 everywhere, u_x = 0 in the end layers (PD alone).
    std::string conditions;
    if (particles)
      conditions = std::string(R"(
subsection Boundary conditions
  set Names = lateral)") +
                   (v == Variant::pd ? ", left, right" : "") + R"(
  subsection lateral
    set Region     = )" +
                   std::string(v == Variant::pd ? "bar" : "core") + R"(
    set Components = y
    set Function   = 0
  end)" +
                   (v == Variant::pd ? R"(
  subsection left
    set Region     = left end
    set Components = x
    set Function   = 0
  end
  subsection right
    set Region     = right end
    set Components = x
    set Function   = 0
  end)" :
                                       "") +
                   R"(
end
)";
    std::string text = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Thickness       = 1e-3
  set Body            = )" +
                       std::string(particles ? "bar" : "") +
                       R"(
end
subsection Regions
  set Names = bar, left end, right end, core
  subsection bar
    set Lower corner = )" +
                       std::string(v == Variant::pd ? "-0.004, 0" : "0.015, 0") + R"(
    set Upper corner = )" +
                       std::string(v == Variant::pd ? "0.104, 0.01" : "0.085, 0.01") + R"(
  end
  subsection left end
    set Lower corner = -0.004, 0
    set Upper corner = 0, 0.01
  end
  subsection right end
    set Lower corner = 0.1, 0
    set Upper corner = 0.104, 0.01
  end
  subsection core
    set Lower corner = 0.03, 0
    set Upper corner = 0.07, 0.01
  end
end
subsection Material
  set Model   = bond based
  set Density = 1000
  set Planar assumption = plane strain
  subsection bond based
    set Young's modulus   = 2.5e9
    set Thermal expansion = ALPHA
  end
end
)" + conditions + R"(
subsection Initial conditions
  set Displacement = 1e-5 * sin(pi * x / 0.1) * (x > 0) * (x < 0.1); 0
end
subsection Temperature
  set Source                         = SOURCE
  set Reference temperature          = 300
  set Coupling                       = COUPLING
  set Absolute reference temperature = 300
end
subsection Physics
  set List = heat
end
subsection Heat
  subsection Material
    set Model   = bond based conduction
    set Density = 1000
    subsection bond based conduction
      set Conductivity  = CONDUCTIVITY
      set Specific heat = 100
    end
  end
  subsection Initial conditions
    set Displacement = 300
  end
  subsection Finite elements
    set Physics = heat
    set Density = 1000
    subsection heat
      set Conductivity  = CONDUCTIVITY
      set Specific heat = 100
    end
  end
end
subsection Solver
  set Type = explicit
end
subsection Time stepping
  set End time      = END
  set Safety factor = SAFETY
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
  set Statistics interval = 100000
end
)";
    if (mesh)
      text += R"(
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 100, 10 : 0, 0 : 0.1, 0.01 : true
  set Density             = 1000
  subsection Elasticity
    set Young's modulus   = 2.5e9
    set Poisson's ratio   = 0.25
    set Thermal expansion = ALPHA
  end
  subsection Boundary conditions
    set Names = ends, lateral
    subsection ends
      set Boundary ids = 0, 1
      set Components   = x
      set Function     = 0
    end
    subsection lateral
      set Boundary ids = 2, 3
      set Components   = y
      set Function     = 0
    end
  end
end
subsection Coupling
  set Blending function = )" +
              (v == Variant::fe ? std::string("0") : blending) + R"(
end
)";
    text = coupling_tests::substitute(text,
                                      {{"ALPHA", a},
                                       {"COUPLING", alpha > 0. ? "two way" : "one way"},
                                       {"SOURCE", alpha > 0. ? "heat" : "none"},
                                       {"SAFETY", std::to_string(safety)},
                                       {"CONDUCTIVITY", std::to_string(conductivity)},
                                       {"END", std::to_string(end_time)}});
    return text;
  }

  // The exact amplitude U(t) of the mode's equations (RK4 at a step far below the period).
  std::vector<double>
  exact_amplitude(const std::vector<double> &times, const double alpha, const double modulus)
  {
    const double          beta = (3. * lambda + 2. * mu) * alpha;
    std::array<double, 3> y    = {U0, 0., 0.}; // U, U', Theta
    const auto            rate = [&](const std::array<double, 3> &z) {
      return std::array<double, 3>{z[1],
                                   (-modulus * q * q * z[0] + beta * q * z[2]) / rho,
                                   (-k * q * q * z[2] - T0 * beta * q * z[1]) / (rho * c)};
    };
    std::vector<double> values;
    double              t = 0.;
    for (const double target : times)
      {
        while (t < target - 1e-15)
          {
            const double          h  = std::min(2e-8, target - t);
            const auto            k1 = rate(y);
            std::array<double, 3> z;
            for (int i = 0; i < 3; ++i)
              z[i] = y[i] + 0.5 * h * k1[i];
            const auto k2 = rate(z);
            for (int i = 0; i < 3; ++i)
              z[i] = y[i] + 0.5 * h * k2[i];
            const auto k3 = rate(z);
            for (int i = 0; i < 3; ++i)
              z[i] = y[i] + h * k3[i];
            const auto k4 = rate(z);
            for (int i = 0; i < 3; ++i)
              y[i] += h / 6. * (k1[i] + 2. * k2[i] + 2. * k3[i] + k4[i]);
            t += h;
          }
        values.push_back(y[0]);
      }
    return values;
  }

  struct Sample
  {
    double time, amplitude, energy;
    /// Per owned particle whose temperature moves (others 0): C_i T_i and V_i m_i.
    std::vector<double> heat, measure;
  };

  // The projection of u_x on sin(q x), int w u_x sin / int sin^2 over the bar (the particles
  // with their energy weights beta, the FE region with 1 - beta), as weights of the owned
  // particles' u_x and of the owned FE dofs, formed once per run.
  struct Projection
  {
    std::vector<double> particles;
    FEVector            fe;
  };

  Projection
  projection(CoupledProblem<2> &problem, const Variant v)
  {
    Physics<2> &mech = *problem.get_physics()[0];
    Projection  result;
    if (mech.pd.has_body())
      {
        const auto &ps = mech.pd.particles();
        const auto &x  = ps.positions();
        const auto &w  = ps.energy_weights();
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          result.particles.push_back(x[i][0] > 0. && x[i][0] < L ?
                                       w[i] * ps.volumes()[i] / thickness * std::sin(q * x[i][0]) :
                                       0.);
      }
    if (mech.fe.n_dofs() > 0)
      {
        const auto       &fe = mech.fe;
        FunctionParser<2> beta(1);
        beta.initialize("x,y", v == Variant::fe ? "0" : blending, {{"pi", numbers::PI}});
        fe.initialize_vector(result.fe);
        FEValues<2>                          fe_values(fe.get_fe_collection()[0],
                              QGauss<2>(3),
                              update_values | update_quadrature_points | update_JxW_values);
        std::vector<types::global_dof_index> dofs(fe_values.dofs_per_cell);
        Vector<double>                       cell_weights(fe_values.dofs_per_cell);
        for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
          if (cell->is_locally_owned() && cell->active_fe_index() == 0)
            {
              fe_values.reinit(cell);
              cell_weights = 0.;
              for (const unsigned int qp : fe_values.quadrature_point_indices())
                {
                  const Point<2> &p = fe_values.quadrature_point(qp);
                  const double    f = (1. - beta.value(p)) * std::sin(q * p[0]) * fe_values.JxW(qp);
                  for (unsigned int j = 0; j < fe_values.dofs_per_cell; ++j)
                    cell_weights(j) += f * fe_values.shape_value_component(j, qp, 0);
                }
              cell->get_dof_indices(dofs);
              for (unsigned int j = 0; j < dofs.size(); ++j)
                result.fe(dofs[j]) += cell_weights(j);
            }
        result.fe.compress(VectorOperation::add);
      }
    return result;
  }

  // The projection's amplitude; with @p adiabatic also the thermoelastic measure, the stored heat
  // and the energy of linear thermoelasticity.
  Sample
  sample(CoupledProblem<2> &problem,
         const Projection  &projection,
         const double       time,
         const double       alpha,
         const bool         adiabatic)
  {
    const auto    &physics  = problem.get_physics();
    Physics<2>    &mech     = *physics[0];
    Physics<2>    &heat     = *physics[1];
    auto          &state    = mech.state();
    const MPI_Comm comm     = MPI_COMM_WORLD;
    double         local[3] = {0., 0., 0.}; // projection, strain energy, heat energy
    Sample         result;
    for (std::size_t i = 0; i < projection.particles.size(); ++i)
      local[0] += projection.particles[i] * state.u.local_element(2 * i);
    for (unsigned int i = 0; i < projection.fe.locally_owned_size(); ++i)
      local[0] += projection.fe.local_element(i) * state.U.local_element(i);
    if (adiabatic && mech.pd.has_body())
      {
        auto &ps = mech.pd.particles();
        // The displacement with current ghost values (at step 0 the other physics start before
        // the mechanics' first forces update them).
        ParticleVector u;
        ps.reinit_vector(u, 2);
        u.copy_locally_owned_data_from(state.u);
        u.update_ghost_values();
        if (alpha > 0.)
          {
            std::vector<double> m;
            mech.pd.material().thermoelastic_measure(ps, u, m);
            const auto &hs = heat.state();
            for (unsigned int i = 0; i < ps.n_owned(); ++i)
              {
                const bool moves = hs.motion()[i] == CoupledState<2>::Motion::moves;
                result.measure.push_back(moves ? m[i] * ps.volumes()[i] : 0.);
                result.heat.push_back(
                  moves ? hs.particle_mass[i] * hs.inertia_ratio()[0] * hs.u.local_element(i) : 0.);
              }
          }
        // The energy of the whole strain: the model without its temperature change.
        const ParticleVector *delta_T = mech.pd.material().temperature_change();
        mech.pd.material().set_temperature_change(nullptr);
        ParticleVector      force(u);
        std::vector<double> density;
        mech.pd.material().compute_forces(ps, u, force, &density, 1e300);
        mech.pd.material().set_temperature_change(delta_T);
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          local[1] += density[i] * ps.volumes()[i];
        // The particles' heat: C_i (T - T_0)^2 / (2 T_0), the capacities of the heat's masses.
        const auto &hs = heat.state();
        for (unsigned int i = 0; i < ps.n_owned(); ++i)
          if (hs.motion()[i] == CoupledState<2>::Motion::moves)
            {
              const double dT = hs.u.local_element(i) - T0;
              local[2] += hs.particle_mass[i] * hs.inertia_ratio()[0] * dT * dT / (2. * T0);
            }
      }
    if (adiabatic && mech.fe.n_dofs() > 0)
      {
        const auto &fe = mech.fe;
        // 1/2 U.K.U (K of the whole strain) and the FE heat's C_k (T_k - T_0)^2 / (2 T_0).
        FEVector KU;
        fe.initialize_vector(KU);
        fe.stiffness_matrix().vmult(KU, state.U);
        local[1] += 0.5 * (KU * state.U) / Utilities::MPI::n_mpi_processes(comm);
        const auto &hs   = heat.state();
        const auto &mask = heat.fe.prescribed_mask();
        for (unsigned int i = 0; i < hs.U.locally_owned_size(); ++i)
          if (!mask[i])
            {
              const double dT = hs.U.local_element(i) - T0;
              local[2] += hs.mass.local_element(i) * dT * dT / (2. * T0);
            }
      }
    Utilities::MPI::sum(ArrayView<const double>(local, 3), comm, ArrayView<double>(local, 3));
    result.time      = time;
    result.amplitude = local[0] / (0.5 * L * H);
    result.energy    = state.kinetic_energy().total + local[1] + local[2];
    return result;
  }

  // Run one bar, sampling after each step.
  std::vector<Sample>
  run_bar(const Variant v,
          const double  alpha,
          const double  safety,
          const double  conductivity,
          const double  end_time)
  {
    const std::string file = "bar.prm";
    coupling_tests::write_file(file, parameters(v, alpha, safety, conductivity, end_time));
    std::ostringstream log;
    CoupledProblem<2>  problem(MPI_COMM_WORLD, log);
    coupling_tests::parse(problem, file);
    problem.setup();
    // The steps of the run (ExplicitDynamics::run()), each sampled at its end: the heat advances
    // inside the mechanics' step (the adiabatic split).
    std::vector<Sample> samples;
    auto               &physics   = *problem.get_physics()[0];
    auto               &state     = physics.state();
    double              dt        = state.time_step;
    const unsigned int  n_steps   = ParameterUtilities::equal_time_steps(end_time, dt);
    const bool          adiabatic = conductivity == adiabatic_conductivity;
    const Projection    weights   = projection(problem, v);
    physics.solver().start_state(state);
    samples.push_back(sample(problem, weights, 0., alpha, adiabatic));
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        physics.solver().advance(state, (step - 1) * dt, dt, true);
        samples.push_back(sample(problem, weights, step * dt, alpha, adiabatic));
      }
    return samples;
  }
} // namespace

// The period of the amplitude's oscillation: the mean spacing of its zero crossings (linear
// interpolation), times two.
double
period(const std::vector<Sample> &samples)
{
  std::vector<double> crossings;
  for (std::size_t n = 1; n < samples.size(); ++n)
    if ((samples[n - 1].amplitude > 0.) != (samples[n].amplitude > 0.))
      crossings.push_back(samples[n - 1].time +
                          (samples[n].time - samples[n - 1].time) * samples[n - 1].amplitude /
                            (samples[n - 1].amplitude - samples[n].amplitude));
  return 2. * (crossings.back() - crossings.front()) / (crossings.size() - 1);
}

// The largest change of the energy over the run, relative to the energy at the start.
double
drift(const std::vector<Sample> &samples)
{
  double d = 0.;
  for (const auto &s : samples)
    d = std::max(d, std::abs(s.energy - samples[0].energy));
  return d / samples[0].energy;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const double alpha = 1e-4, conductivity = k;
  const double period_0 = 2. * numbers::PI / (q * std::sqrt(M / rho));
  deallog << std::setprecision(3) << "Bar: coupling T0 beta^2 / (rho c M) = "
          << T0 * std::pow((3. * lambda + 2. * mu) * alpha, 2) / (rho * c * M)
          << ", omega tau = " << q * std::sqrt(M / rho) * rho * c / (conductivity * q * q)
          << ", period " << period_0 << " s" << std::endl;
  for (const Variant v : {Variant::fe, Variant::pd, Variant::blended})
    {
      // Adiabatic: the entropy per particle and the energy, over one period at two steps.
      const auto coarse  = run_bar(v, alpha, 0.5, adiabatic_conductivity, period_0);
      const auto fine    = run_bar(v, alpha, 0.25, adiabatic_conductivity, period_0);
      double     entropy = 0., heat = 0.;
      for (std::size_t i = 0; i < coarse.back().heat.size(); ++i)
        {
          const double gained = coarse.back().heat[i] - coarse[0].heat[i];
          entropy =
            std::max(entropy,
                     std::abs(gained + T0 * (coarse.back().measure[i] - coarse[0].measure[i])));
          heat = std::max(heat, std::abs(gained));
        }
      entropy = Utilities::MPI::max(entropy, MPI_COMM_WORLD);
      heat    = Utilities::MPI::max(heat, MPI_COMM_WORLD);
      // Conducting: the run's own period without the coupling gives its modulus, with which the
      // mode's equations are solved.
      const double        end     = 2. * period_0;
      const auto          plain   = run_bar(v, 0., 0.5, conductivity, end);
      const auto          coupled = run_bar(v, alpha, 0.5, conductivity, end);
      const double        own_M   = rho * std::pow(2. * numbers::PI / (period(plain) * q), 2);
      std::vector<double> times;
      for (const auto &s : coupled)
        times.push_back(s.time);
      const auto exact       = exact_amplitude(times, alpha, own_M);
      const auto exact_plain = exact_amplitude(times, 0., own_M);
      // The uncoupled run against the mode's equations at its own times: the two-way coupling
      // takes shorter steps (doc/theory/thermoelasticity.md, "The stable time step").
      std::vector<double> plain_times;
      for (const auto &s : plain)
        plain_times.push_back(s.time);
      const auto exact_own = exact_amplitude(plain_times, 0., own_M);
      double     error = 0., error_plain = 0., effect = 0.;
      for (std::size_t n = 0; n < coupled.size(); ++n)
        {
          error  = std::max(error, std::abs(coupled[n].amplitude - exact[n]));
          effect = std::max(effect, std::abs(exact[n] - exact_plain[n]));
        }
      for (std::size_t n = 0; n < plain.size(); ++n)
        error_plain = std::max(error_plain, std::abs(plain[n].amplitude - exact_own[n]));
      // The particles alone are held in layers a horizon thick beyond the ends, which also
      // conduct and heat: their error is first order in delta / L (doc/theory/thermoelasticity.md).
      const double tolerance = v == Variant::pd ? 0.06 : 0.01;
      {
        deallog << name(v) << ": modulus from the uncoupled period " << std::setprecision(3)
                << own_M / M << " of M\n  amplitude against the mode's equations: error "
                << std::setprecision(2) << error / U0 << " of U_0 "
                << coupling_tests::ok(error < tolerance * U0) << " (uncoupled " << error_plain / U0
                << "), the coupling changes it by " << effect / U0
                << " (over ten times the error: " << coupling_tests::ok(effect > 10. * error)
                << "); at " << end / period_0 << " periods " << coupled.back().amplitude / U0
                << " (exact " << exact.back() / U0 << ", uncoupled " << exact_plain.back() / U0
                << ")\n  adiabatic: ";
        if (v != Variant::fe)
          deallog << "the heat gained by each free particle is -T_0 times its measure's gain "
                  << coupling_tests::ok(entropy < 1e-8 * heat) << "; ";
        deallog << "energy drift " << drift(coarse) << " "
                << coupling_tests::ok(drift(coarse) < 2e-3) << ", at half the step " << drift(fine)
                << " (second order: " << coupling_tests::ok(drift(fine) < 0.35 * drift(coarse))
                << ")" << std::endl;
      }
    }
}
