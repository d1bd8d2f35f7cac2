// The Timoshenko-bond model with a tensile strength (issue #40, part 3; seed note 003, sec. 1.6,
// A11, A12; doc/theory/models.md, "Timoshenko bonds"):
//  1. the derived limits for the concrete of seed 003, sec. 3.2 (E = 32 GPa, nu = 0.2, G0 =
//     110 N/m, sigma_t = 3 MPa, sigma_c = 38.4 MPa, delta = 6 mm, h = 50 mm, plane stress): the
//     critical stretch is sigma_t / E, the shear limit keeps its ratio to it, and k satisfies
//     (k + 2)/k = (s_G / s_0)^2 with s_G the brittle critical stretch of G0 (seed eq. 13);
//  2. one bond pulled to separation with these limits: elastic to s_0 = sigma_t / E, then the
//     force C_N s_0 e^(-k (x - 1)), and the energy it dissipates equals the brittle work of G0,
//     C_N |xi| s_G^2 / 2 V_i V_j (to 1e-5), for a k and limits that differ from those of the
//     brittle law by a factor of about 10;
//     the same bond compressed: elastic to -sigma_c / E, then softening with the same k;
//  3. bad input: each entry named with the accepted values.
// 1 and 2 MPI ranks, the same numbers.

#include <deal.II/base/tensor.h>

#include <perideal/pd/timoshenko_bond_based.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cmath>
#include <limits>

namespace
{
  using namespace dealii;
  using pd_tests::ok;
  using perideal::PartialVolume;
  using perideal::ParticleVector;
  using perideal::PlanarAssumption;
  namespace T         = perideal::Timoshenko;
  const MPI_Comm comm = MPI_COMM_WORLD;

  const double E = 32e9, sigma_t = 3e6, sigma_c = 38.4e6, G0 = 110.;

  const std::vector<std::pair<std::string, std::string>> concrete = {{"Young's modulus", "32e9"},
                                                                     {"Poisson's ratio", "0.2"},
                                                                     {"Calibration", "continuum"},
                                                                     {"Failure law", "softening"},
                                                                     {"Tensile strength", "3e6"},
                                                                     {"Compressive strength",
                                                                      "38.4e6"}};

  perideal::ModelContext
  context(const double horizon, const double thickness)
  {
    return pd_tests::model_context(horizon, thickness, PlanarAssumption::plane_stress, false);
  }

  // Two particles at (0.5, 0.5) dx and (1.5, 0.5) dx: one bond along x, horizon 3 dx as in
  // seed 003, sec. 3.2.
  void
  generate_pair(perideal::ParticleSystem<2> &ps, const double dx, const double h)
  {
    typename perideal::ParticleSystem<2>::Settings s;
    s.spacing        = dx;
    s.horizon        = 3. * dx;
    s.thickness      = h;
    s.partial_volume = PartialVolume::none;
    ps.generate(s,
                BoundingBox<2>(std::make_pair(Point<2>(), Point<2>(2. * dx, dx))),
                [](const Point<2> &) { return true; },
                {});
  }

  void
  check_limits()
  {
    const double                dx = 2e-3, h = 0.05, delta = 3. * dx;
    perideal::ParticleSystem<2> ps(comm);
    generate_pair(ps, dx, h);
    perideal::TimoshenkoBondBased<2> model;
    pd_tests::parse_model(model, concrete);
    model.initialize(ps, context(delta, h));
    const auto  &C   = model.stiffness();
    const double s0  = model.critical_stretch(G0);
    const double s_G = T::brittle_stretch(C, 2, delta, h, G0);
    const double k   = model.softening_parameter();
    const auto   lim = model.failure_limits(s0);
    const double r   = T::limit_ratios(C, 2, delta)[0];
    deallog << "  s_0 = sigma_t / E " << ok(std::abs(s0 / (sigma_t / E) - 1.) < 1e-14)
            << "; s_G = " << s_G << " (seed note: 9.797607e-4) "
            << ok(std::abs(s_G / 9.797607e-4 - 1.) < 1e-6) << ", s_G / s_0 = " << s_G / s0
            << "; k = " << k << ", (k + 2)/k = (s_G / s_0)^2 "
            << ok(std::abs((k + 2.) / k / std::pow(s_G / s0, 2) - 1.) < 1e-12)
            << "; gamma_0 / s_0 as the brittle ratio "
            << ok(std::abs(lim[1] / (s0 * r) - 1.) < 1e-14) << std::endl;
  }

  // The bond of generate_pair() stretched (x > 0) or compressed (x < 0) to x times @p limit;
  // the force on the left particle along x, relative to C_N |limit| V_i V_j, and the energy
  // the bonds released, if @p released is given.
  double
  axial_force(perideal::TimoshenkoBondBased<2> &model,
              perideal::ParticleSystem<2>      &ps,
              const double                      dx,
              const double                      h,
              const double                      x,
              const double                      limit,
              double                           *released = nullptr)
  {
    const double   V = dx * dx * h;
    ParticleVector u, f;
    ps.reinit_vector(u, 3);
    ps.reinit_vector(f, 3);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      u.local_element(3 * i) = ps.positions()[i][0] > dx ? x * limit * dx : 0.;
    std::vector<double> e;
    model.compute_forces(ps, u, f, &e, model.critical_stretch(G0));
    if (released)
      *released += Utilities::MPI::sum(model.released_energy(ps, u), comm);
    double mine = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      if (ps.positions()[i][0] < dx)
        mine = f.local_element(3 * i) * V;
    return Utilities::MPI::sum(mine, comm) / (V * V * model.stiffness().normal * limit);
  }

  void
  check_one_bond()
  {
    const double                dx = 2e-3, h = 0.05, delta = 3. * dx, V = dx * dx * h;
    perideal::ParticleSystem<2> ps(comm);
    generate_pair(ps, dx, h);
    const double s0 = sigma_t / E;
    {
      perideal::TimoshenkoBondBased<2> model;
      pd_tests::parse_model(model, concrete);
      model.initialize(ps, context(delta, h));
      model.critical_stretch(G0);
      const double k     = model.softening_parameter();
      double       worst = std::abs(axial_force(model, ps, dx, h, 0.5, s0) - 0.5);
      worst              = std::max(worst, std::abs(axial_force(model, ps, dx, h, 1., s0) - 1.));
      worst =
        std::max(worst, std::abs(axial_force(model, ps, dx, h, 30., s0) - std::exp(-k * 29.)));
      deallog << "  tension: elastic to sigma_t / E, then e^(-k(x-1)) " << ok(worst < 1e-12)
              << std::endl;
    }
    {
      perideal::TimoshenkoBondBased<2> model;
      pd_tests::parse_model(model, concrete);
      model.initialize(ps, context(delta, h));
      const double s_G      = T::brittle_stretch(model.stiffness(), 2, delta, h, G0);
      double       released = 0.;
      // In steps of 0.05 s_0 to x = 1000 (the bond is removed at x = 1 + ln(1e6)/k).
      for (unsigned int step = 1; step <= 20000; ++step)
        axial_force(model, ps, dx, h, 0.05 * step, s0, &released);
      const double brittle = 0.5 * model.stiffness().normal * dx * s_G * s_G * V * V;
      deallog << "  to separation: dissipated / brittle work of G0 - 1 "
              << (std::abs(released / brittle - 1.) < 1e-5 ? "below 1e-5 " : "")
              << ok(std::abs(released / brittle - 1.) < 1e-5)
              << ", the bond broken: " << ok(perideal::n_broken_bonds(ps) == 1) << std::endl;
      ps.bonds().set_states(std::vector<std::uint8_t>(ps.bonds().size(), 1));
    }
    {
      perideal::TimoshenkoBondBased<2> model;
      pd_tests::parse_model(model, concrete);
      model.initialize(ps, context(delta, h));
      model.critical_stretch(G0);
      const double k = model.softening_parameter(), sc = sigma_c / E;
      // Elastic far beyond -s_0, to -sigma_c / E; then the same softening.
      double worst = std::abs(axial_force(model, ps, dx, h, -5. * s0 / sc, sc) + 5. * s0 / sc);
      worst        = std::max(worst, std::abs(axial_force(model, ps, dx, h, -1., sc) + 1.));
      worst = std::max(worst, std::abs(axial_force(model, ps, dx, h, -3., sc) + std::exp(-2. * k)));
      deallog << "  compression: elastic to -sigma_c / E, then -e^(-k(x-1)) " << ok(worst < 1e-12)
              << std::endl;
    }
  }

  void
  check_bad_input()
  {
    const double                dx = 2e-3, h = 0.05, delta = 3. * dx;
    perideal::ParticleSystem<2> ps(comm);
    generate_pair(ps, dx, h);
    const auto with = [](const std::vector<std::pair<std::string, std::string>> &changes) {
      auto entries = concrete;
      for (const auto &change : changes)
        {
          bool found = false;
          for (auto &entry : entries)
            if (entry.first == change.first)
              {
                entry.second = change.second;
                found        = true;
              }
          if (!found)
            entries.push_back(change);
        }
      return entries;
    };
    // Set up as the damage model does: the critical stretch from G0 (0: given as 1e-3).
    const auto refused = [&](const std::string                                      &label,
                             const std::vector<std::pair<std::string, std::string>> &entries,
                             const double fracture_energy) {
      pd_tests::check_refused(label, [&]() {
        perideal::TimoshenkoBondBased<2> model;
        pd_tests::parse_model(model, entries);
        model.initialize(ps, context(delta, h));
        const double   s0 = fracture_energy > 0. ? model.critical_stretch(fracture_energy) : 1e-3;
        ParticleVector u, f;
        ps.reinit_vector(u, 3);
        ps.reinit_vector(f, 3);
        model.compute_forces(ps, u, f, nullptr, s0);
      });
    };
    refused("strength and an explicit k", with({{"Softening parameter", "2"}}), G0);
    refused("strength with the brittle law", with({{"Failure law", "brittle"}}), G0);
    refused("compressive strength alone", with({{"Tensile strength", "0"}}), G0);
    refused("strength with a critical stretch given", concrete, 0.);
    refused("strength above E s_G", with({{"Tensile strength", "40e6"}}), G0);
    refused("k not a number",
            with({{"Tensile strength", "0"},
                  {"Compressive strength", "0"},
                  {"Softening parameter", "two"}}),
            G0);
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog << "1. the limits from the tensile strength" << std::endl;
  check_limits();
  deallog << "2. one bond" << std::endl;
  check_one_bond();
  deallog << "3. bad input" << std::endl;
  check_bad_input();
}
