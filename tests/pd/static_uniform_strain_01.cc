// The static solve reproduces a uniform strain exactly (to the solver tolerance) inside a body
// whose surrounding fictitious layer carries the uniform-strain field: PMB (2D, no surface
// correction) needs a layer of delta + dx/2 (every interior family is complete and
// point-symmetric); LPS (3D) needs twice that, since the force on i also involves the dilatation
// of its neighbours, which is exact only for complete families.
#include <deal.II/base/parameter_handler.h>

#include <perideal/pd/bond_based.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/static_solver.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cmath>

using namespace dealii;

template <int dim>
void
check(perideal::MaterialModel<dim> &model,
      const unsigned int            n,
      const unsigned int            layers,
      const bool                    surface_correction,
      const double                  horizon_factor,
      const std::string            &label)
{
  const double                                     dx = 1e-3;
  perideal::ParticleSystem<dim>                    ps(MPI_COMM_WORLD);
  typename perideal::ParticleSystem<dim>::Settings s;
  s.spacing   = dx;
  s.horizon   = horizon_factor * dx;
  s.thickness = 1e-3;
  Point<dim> lower, upper;
  for (unsigned int d = 0; d < dim; ++d)
    {
      lower[d] = -double(layers) * dx;
      upper[d] = (n + layers) * dx;
    }
  pd_tests::generate_box<dim>(ps, s, lower, upper);
  model.initialize(ps,
                   pd_tests::model_context(s.horizon,
                                           s.thickness,
                                           dim == 2 ? perideal::PlanarAssumption::plane_stress :
                                                      perideal::PlanarAssumption::three_dimensional,
                                           surface_correction));

  // eps = [[1e-4, 2e-5, 0], [2e-5, -3e-5, 1e-5], [0, 1e-5, 5e-5]].
  const double eps[3][3] = {{1e-4, 2e-5, 0.}, {2e-5, -3e-5, 1e-5}, {0., 1e-5, 5e-5}};
  const auto   exact     = [&](const Point<dim> &p, const unsigned int c) {
    double value = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      value += eps[c][d] * p[d];
    return value;
  };
  const auto inside = [&](const Point<dim> &p) {
    bool result = true;
    for (unsigned int d = 0; d < dim; ++d)
      result = result && p[d] > 0. && p[d] < n * dx;
    return result;
  };

  perideal::ParticleVector prescribed, zero, u;
  for (auto *v : {&prescribed, &zero, &u})
    ps.reinit_vector(*v, dim);
  const auto &x = ps.positions();
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    if (!inside(x[i]))
      for (unsigned int c = 0; c < dim; ++c)
        {
          prescribed.local_element(i * dim + c) = 1.;
          u.local_element(i * dim + c)          = exact(x[i], c);
        }
  typename perideal::StaticSolver<dim>::Settings settings;
  settings.tolerance = 1e-13;
  perideal::StaticSolver<dim> solver(settings);
  solver.solve(ps, model, prescribed, zero, u, "fictitious layer");

  double max_error = 0., max_u = 0.;
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    if (inside(x[i]))
      for (unsigned int c = 0; c < dim; ++c)
        {
          max_error = std::max(max_error, std::abs(u.local_element(i * dim + c) - exact(x[i], c)));
          max_u     = std::max(max_u, std::abs(exact(x[i], c)));
        }
  max_error = Utilities::MPI::max(max_error, MPI_COMM_WORLD);
  max_u     = Utilities::MPI::max(max_u, MPI_COMM_WORLD);
  deallog << label << ": particles " << ps.n_global() << ", layer " << layers
          << " dx, max |u - eps x| / max |eps x| in the body < 1e-9: "
          << (max_error < 1e-9 * max_u ? "yes" : "no") << std::endl;
  std::cerr << label << " relative error " << max_error / max_u << std::endl;
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no CG iteration lines
  {
    perideal::BondBased<2> pmb;
    pd_tests::parse_model(pmb, {{"Young's modulus", "192e9"}});
    check<2>(pmb, 20, 4, false, 3.015, "2D PMB, delta = 3.015 dx, no surface correction");
  }
  {
    perideal::LinearPeridynamicSolid<2> lps;
    pd_tests::parse_model(lps, {{"Young's modulus", "70e9"}, {"Poisson's ratio", "0.3"}});
    check<2>(lps, 16, 8, true, 3.015, "2D LPS, delta = 3.015 dx, discrete weighted volume");
  }
  {
    perideal::LinearPeridynamicSolid<3> lps;
    pd_tests::parse_model(lps, {{"Young's modulus", "70e9"}, {"Poisson's ratio", "0.3"}});
    check<3>(lps, 3, 6, true, 2.015, "3D LPS, delta = 2.015 dx, discrete weighted volume");
  }
}
