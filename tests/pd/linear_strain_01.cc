// Linear strain: u_x = a x^2 (and u_y = a x^2) gives the force density of the Navier equation,
// f_x = 2 a C_xxxx (f_y = 2 a C_xyxy), at an interior particle, for PMB and LPS in 2D and 3D.
#include <deal.II/base/parameter_handler.h>

#include <perideal/pd/bond_based.h>
#include <perideal/pd/linear_peridynamic_solid.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cmath>
#include <limits>

using namespace dealii;

// The force density at the centre particle of an n^dim lattice for u_c = a x^2 (component c).
template <int dim>
double
centre_force(perideal::MaterialModel<dim>    &model,
             const perideal::PlanarAssumption planar,
             const double                     horizon_factor,
             const unsigned int               component,
             const double                     a,
             const bool                       discrete_weighted_volume)
{
  const double                                     dx = 1e-3;
  const int                                        n  = 2 * static_cast<int>(horizon_factor) + 5;
  perideal::ParticleSystem<dim>                    ps(MPI_COMM_WORLD);
  typename perideal::ParticleSystem<dim>::Settings s;
  s.spacing   = dx;
  s.horizon   = horizon_factor * dx;
  s.thickness = 1e-3;
  // The family that fills the horizon (no surface correction rescales the bulk here).
  s.partial_volume = perideal::PartialVolume::geometric;
  Point<dim> upper;
  for (unsigned int d = 0; d < dim; ++d)
    upper[d] = n * dx;
  pd_tests::generate_box<dim>(ps, s, Point<dim>(), upper);
  // PMB: the raw model (no surface correction). LPS: the discrete weighted volume m_i, the
  // usual discretization of the model (with the continuum m the dilatation carries the
  // quadrature error of m as well).
  model.initialize(
    ps,
    pd_tests::model_context(s.horizon, s.thickness, planar, discrete_weighted_volume));

  perideal::ParticleVector u, f;
  ps.reinit_vector(u, dim);
  ps.reinit_vector(f, dim);
  // Centred at the middle particle, so the field is symmetric about it.
  const double centre = 0.5 * n * dx;
  for (unsigned int i = 0; i < ps.n_local(); ++i)
    {
      const double x                       = ps.positions()[i][0] - centre;
      u.local_element(i * dim + component) = a * x * x;
    }
  model.compute_forces(ps, u, f, nullptr, std::numeric_limits<double>::infinity());
  double local = 0.;
  for (unsigned int i = 0; i < ps.n_owned(); ++i)
    {
      bool at_centre = true;
      for (unsigned int d = 0; d < dim; ++d)
        at_centre = at_centre && std::abs(ps.positions()[i][d] - centre) < 0.6 * dx;
      if (at_centre)
        local = f.local_element(i * dim + component);
    }
  return Utilities::MPI::sum(local, MPI_COMM_WORLD);
}

template <int dim>
void
check(const std::string               &model_name,
      const perideal::PlanarAssumption planar,
      const std::string               &label)
{
  const double a = 1e-3; // [1/m]: strain gradient; u stays ~1e-9 m, well inside linearity
  for (const double horizon_factor : {3., 4., 5.})
    {
      std::unique_ptr<perideal::MaterialModel<dim>> model;
      ParameterHandler                              prm;
      if (model_name == "bond based")
        {
          perideal::BondBased<dim>::declare_parameters(prm);
          model = std::make_unique<perideal::BondBased<dim>>();
        }
      else
        {
          perideal::LinearPeridynamicSolid<dim>::declare_parameters(prm);
          prm.set("Poisson's ratio", "0.3");
          model = std::make_unique<perideal::LinearPeridynamicSolid<dim>>();
        }
      prm.set("Young's modulus", "200e9");
      model->parse_parameters(prm);
      const bool   lps = (model_name != "bond based");
      const double fx  = centre_force<dim>(*model, planar, horizon_factor, 0, a, lps);
      const double fy  = centre_force<dim>(*model, planar, horizon_factor, 1, a, lps);
      const auto   C   = model->elasticity_tensor();
      const double rx  = fx / (2. * a * C[0][0][0][0]);
      const double ry  = fy / (2. * a * C[0][1][0][1]);
      // Seed note 002 (T8) bounds the one-point quadrature error at delta = 4 dx by 5 %. It is not
      // monotone in delta/dx on a lattice (it depends on the shells the horizon cuts): 3 dx and
      // 5 dx are regression values only.
      const double error = std::max(std::abs(rx - 1.), std::abs(ry - 1.));
      deallog << label << ", delta = " << horizon_factor << " dx: f_x / (2 a C_xxxx) = " << rx
              << ", f_y / (2 a C_xyxy) = " << ry;
      if (horizon_factor == 4.)
        deallog << (error < 0.05 ? ", within 5 %" : ", FAILED");
      deallog << std::endl;
    }
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  using P = perideal::PlanarAssumption;
  check<2>("bond based", P::plane_stress, "PMB plane stress");
  check<2>("bond based", P::plane_strain, "PMB plane strain");
  check<2>("linear peridynamic solid", P::plane_stress, "LPS plane stress");
  check<2>("linear peridynamic solid", P::plane_strain, "LPS plane strain");
  check<3>("bond based", P::three_dimensional, "PMB 3D");
  check<3>("linear peridynamic solid", P::three_dimensional, "LPS 3D");
}
