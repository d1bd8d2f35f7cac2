// Static patch tests of the 2D anisotropic models (seed 004): the static solver (the models'
// linearize()) reproduces a uniform strain inside a body whose surrounding fictitious layer
// carries the uniform-strain field, to the solver tolerance, with the discrete calibration:
// 'anisotropic bond based' in plane strain (cubic NaCl rotated by 25 degrees) and in plane stress
// (isotropic nu = 1/3), and 'anisotropic plane stress' (the note's orthotropic tensor rotated by
// 30 degrees). The bond-based models (no surface correction) need a layer of delta + dx/2
// (complete interior families); the plane-stress model (per-particle B_i) twice that (its force
// uses the neighbours' A). Before, linearize() against compute_forces() for a random field, which
// checks the relative weights of the bond and A rows (the patch test alone does not).
#include <deal.II/base/parameter_handler.h>

#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/anisotropic_plane_stress.h>
#include <perideal/pd/static_solver.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cmath>
#include <limits>

using namespace dealii;

void
check(perideal::MaterialModel<2>      &model,
      const perideal::PlanarAssumption planar,
      const unsigned int               n,
      const unsigned int               layers,
      const bool                       surface_correction,
      const std::string               &label)
{
  const double                          dx = 1e-3;
  perideal::ParticleSystem<2>           ps(MPI_COMM_WORLD);
  perideal::ParticleSystem<2>::Settings s;
  s.spacing   = dx;
  s.horizon   = 3.015 * dx;
  s.thickness = 1e-3;
  pd_tests::generate_box<2>(ps,
                            s,
                            Point<2>(-double(layers) * dx, -double(layers) * dx),
                            Point<2>((n + layers) * dx, (n + layers) * dx));
  model.initialize(ps, pd_tests::model_context(s.horizon, s.thickness, planar, surface_correction));

  // linearize() against compute_forces() for a random field (the model is linear): forces and
  // energy.
  {
    perideal::ParticleVector r, f_model;
    ps.reinit_vector(r, 2);
    ps.reinit_vector(f_model, 2);
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int c = 0; c < 2; ++c)
        r.local_element(i * 2 + c) = 1e-6 * pd_tests::random_number(2 * ps.global_index(i) + c);
    r.update_ghost_values();
    std::vector<double> w;
    model.compute_forces(ps, r, f_model, &w, std::numeric_limits<double>::infinity());
    double energy_model = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      energy_model += w[i] * ps.volumes()[i];
    energy_model = Utilities::MPI::sum(energy_model, MPI_COMM_WORLD);
    perideal::LinearizedModel linearized;
    model.linearize(ps, linearized);
    perideal::ParticleVector f_linear;
    const double energy_linear = pd_tests::linearized_forces(ps, linearized, r, f_linear);
    double       difference = 0., scale = 0.;
    for (unsigned int q = 0; q < 2 * ps.n_owned(); ++q)
      {
        difference =
          std::max(difference, std::abs(f_linear.local_element(q) - f_model.local_element(q)));
        scale = std::max(scale, std::abs(f_model.local_element(q)));
      }
    difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
    scale      = Utilities::MPI::max(scale, MPI_COMM_WORLD);
    deallog << label << ": linearize() against compute_forces() for a random field, forces and "
            << "energy (tolerance 1e-11): "
            << pd_tests::ok(difference < 1e-11 * scale &&
                            std::abs(energy_linear - energy_model) < 1e-11 * std::abs(energy_model))
            << std::endl;
    std::cerr << label << " linearization force difference " << difference / scale << " energy "
              << (energy_linear - energy_model) / energy_model << std::endl;
  }

  const double eps[2][2] = {{1e-4, 2e-5}, {2e-5, -3e-5}};
  const auto   exact     = [&](const Point<2> &p, const unsigned int c) {
    return eps[c][0] * p[0] + eps[c][1] * p[1];
  };
  const auto inside = [&](const Point<2> &p) {
    return p[0] > 0. && p[0] < n * dx && p[1] > 0. && p[1] < n * dx;
  };
  perideal::ParticleVector prescribed, zero, u;
  for (auto *v : {&prescribed, &zero, &u})
    ps.reinit_vector(*v, 2);
  const auto &x = ps.positions();
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    if (!inside(x[i]))
      for (unsigned int c = 0; c < 2; ++c)
        {
          prescribed.local_element(i * 2 + c) = 1.;
          u.local_element(i * 2 + c)          = exact(x[i], c);
        }
  perideal::StaticSolver<2>::Settings settings;
  settings.tolerance = 1e-13;
  perideal::StaticSolver<2> solver(settings);
  solver.solve(ps, model, prescribed, zero, u, "fictitious layer");

  double max_error = 0., max_u = 0.;
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    if (inside(x[i]))
      for (unsigned int c = 0; c < 2; ++c)
        {
          max_error = std::max(max_error, std::abs(u.local_element(i * 2 + c) - exact(x[i], c)));
          max_u     = std::max(max_u, std::abs(exact(x[i], c)));
        }
  max_error = Utilities::MPI::max(max_error, MPI_COMM_WORLD);
  max_u     = Utilities::MPI::max(max_u, MPI_COMM_WORLD);
  deallog << label << ": particles " << ps.n_global() << ", layer " << layers
          << " dx, max |u - eps x| / max |eps x| in the body (tolerance 1e-9): "
          << pd_tests::ok(max_error < 1e-9 * max_u) << std::endl;
  std::cerr << label << " relative error " << max_error / max_u << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no CG iteration lines
  {
    perideal::AnisotropicBondBased<2> model;
    pd_tests::parse_model(model,
                          {{"Symmetry", "cubic"},
                           {"Cubic constants", "49.1e9, 12.8e9, 12.8e9"},
                           {"Orientation", "25, 0, 0"}});
    check(model,
          perideal::PlanarAssumption::plane_strain,
          16,
          4,
          false,
          "anisotropic bond based, plane strain, NaCl rotated by 25 degrees");
  }
  {
    perideal::AnisotropicBondBased<2> model;
    pd_tests::parse_model(model,
                          {{"Symmetry", "isotropic"},
                           {"Young's modulus", "30e9"},
                           {"Poisson's ratio", "0.3333333333333333"}});
    check(model,
          perideal::PlanarAssumption::plane_stress,
          16,
          4,
          false,
          "anisotropic bond based, plane stress, isotropic nu = 1/3");
  }
  {
    perideal::AnisotropicPlaneStress model;
    pd_tests::parse_model(
      model,
      {{"Symmetry", "orthotropic"},
       {"Young's moduli", "105283018867.92453, 82058823529.411758, 56363636363.63636"},
       {"Poisson's ratios", "0.30188679245283018, 0.28301886792452829, 0.088235294117647065"},
       {"Shear moduli", "30e9, 20e9, 10e9"},
       {"Orientation", "30, 0, 0"}});
    check(model,
          perideal::PlanarAssumption::plane_stress,
          16,
          8,
          true,
          "anisotropic plane stress, orthotropic (note 004) rotated by 30 degrees");
  }
}
