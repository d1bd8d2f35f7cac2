// LPS: exact dilatation, expansion and shear energies, interior reduction to PMB at Cauchy nu.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/bond_based.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
  using dealii::deallog;
  const double E  = 192e9;
  const double h  = 1e-4;
  const double dx = 1e-4;

  double
  influence(const std::string &name, const double r, const double R)
  {
    if (name == "constant")
      return 1.;
    if (name == "inverse distance")
      return R / r;
    return std::exp(-r * r / (R * R));
  }

  using pd_tests::Body;
  using pd_tests::planar_name;
  using pd_tests::random_number;

  template <int dim>
  std::unique_ptr<perideal::LinearPeridynamicSolid<dim>>
  make_lps(Body<dim>                       &body,
           const perideal::PlanarAssumption planar,
           const double                     nu,
           const std::string               &omega,
           const bool                       correction)
  {
    auto               model = std::make_unique<perideal::LinearPeridynamicSolid<dim>>();
    std::ostringstream poisson; // all digits: std::to_string would cut 1/3 to 0.333333
    poisson << std::setprecision(17) << nu;
    pd_tests::parse_model(*model,
                          {{"Young's modulus", std::to_string(E)},
                           {"Poisson's ratio", poisson.str()},
                           {"Influence function", omega}});
    model->initialize(body.ps, pd_tests::model_context(body.delta, h, planar, correction));
    return model;
  }

  // The discrete shear-energy ratio of a full family: under u_x = g y, u_y = g x the extension
  // is e = 2 g |xi| n_x n_y (linearized) and theta = 0, so
  // W_PD / (2 mu g^2) = n (n + 2) sum omega chi |xi|^2 n_x^2 n_y^2 / sum omega chi |xi|^2,
  // which is 1 for the continuum (<n_x^2 n_y^2> = 1/8 on a circle, 1/15 on a sphere).
  template <int dim>
  double
  lattice_shear_ratio(const double R, const bool partial_volume, const std::string &omega)
  {
    double num = 0., den = 0.;
    pd_tests::for_each_lattice_offset<dim>(
      static_cast<int>(R) + 1,
      [&](const std::array<int, dim> &v) {
        double r2 = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          r2 += double(v[d]) * v[d];
        const double r = std::sqrt(r2);
        if (r > 0. && r <= R * (1. + 1e-10))
          {
            const double w =
              influence(omega, r, R) * ((!partial_volume || r <= R - 0.5) ? 1. : R + 0.5 - r);
            num += w * v[0] * v[0] * v[1] * v[1] / r2;
            den += w * r2;
          }
      });
    return dim * (dim + 2.) * num / den;
  }

  template <int dim>
  void
  check_energy(const perideal::PlanarAssumption planar, const std::string &omega)
  {
    const double horizon_factor = 4.;
    const int    R              = 4;
    const bool   partial_volume = true;
    const int    n              = 2 * R + 3;
    Body<dim>    body(n,
                   dx,
                   horizon_factor,
                   partial_volume ? perideal::PartialVolume::book : perideal::PartialVolume::none,
                   h);
    const auto   model = make_lps<dim>(body, planar, 0.3, omega, true);
    const auto   C     = model->elasticity_tensor();
    const auto   I     = dealii::unit_symmetric_tensor<dim>();

    perideal::ParticleVector u, f;
    body.ps.reinit_vector(f, dim);
    std::vector<double> w;

    // Isotropic expansion: e = eps |xi| exactly (no linearization), so with the discrete
    // weighted volume theta = n eps and the deviatoric extension vanishes at every particle,
    // near surfaces too: W = k theta^2 / 2 = eps I : C : eps I / 2 up to round-off. eps = 1e-4
    // keeps the cancellation in |y| - |xi| at 1e-12 of e.
    const double eps = 1e-4;
    body.set_field(u, [&](const unsigned int i) {
      return dealii::Tensor<1, dim>(eps * body.ps.positions()[i]);
    });
    model->compute_forces(body.ps, u, f, &w, std::numeric_limits<double>::infinity());
    const double classical_iso = 0.5 * (eps * I) * (C * (eps * I));
    double       theta_error = 0., iso_error = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      {
        theta_error =
          std::max(theta_error, std::abs(model->dilatation().local_element(i) / (dim * eps) - 1.));
        iso_error = std::max(iso_error, std::abs(w[i] / classical_iso - 1.));
      }
    theta_error = dealii::Utilities::MPI::max(theta_error, MPI_COMM_WORLD);
    iso_error   = dealii::Utilities::MPI::max(iso_error, MPI_COMM_WORLD);

    // Pure shear u_x = g y, u_y = g x: W = 2 mu g^2 = eps : C : eps / 2 with eps_xy = g.
    const double g = 1e-6;
    body.set_field(u, [&](const unsigned int i) {
      dealii::Tensor<1, dim> v;
      v[0] = g * body.ps.positions()[i][1];
      v[1] = g * body.ps.positions()[i][0];
      return v;
    });
    model->compute_forces(body.ps, u, f, &w, std::numeric_limits<double>::infinity());
    dealii::SymmetricTensor<2, dim> shear;
    shear[0][1]                  = g;
    const double classical_shear = 0.5 * shear * (C * shear);
    double       local           = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.depth(i) == R + 1)
        local = w[i] / classical_shear;
    const double ratio   = dealii::Utilities::MPI::max(local, MPI_COMM_WORLD);
    const double lattice = lattice_shear_ratio<dim>(horizon_factor, partial_volume, omega);

    deallog << planar_name(planar) << ", nu = 0.3, '" << omega
            << "': theta = n eps at all particles " << (theta_error < 1e-10 ? "ok" : "FAILED")
            << ", W_iso/W_classical = 1 (< 1e-8) " << (iso_error < 1e-8 ? "ok" : "FAILED")
            << std::endl;
    // The interior shear ratio is the one-point quadrature of <n_x^2 n_y^2> over the family:
    // it must equal the lattice value up to the geometric nonlinearity O(g) = 1e-6, and lie
    // within 5 % of 1 at delta = 4 dx (the quadrature error, 1-2.5 % for these influence
    // functions; seed note 002, sec. 8, T4 allows 3 % with partial volume).
    deallog << "  interior W_shear/W_classical = " << std::setprecision(5) << ratio
            << std::setprecision(6) << ", lattice value "
            << (std::abs(ratio - lattice) < 1e-5 ? "ok" : "FAILED") << ", |ratio - 1| < 0.05 "
            << (std::abs(ratio - 1.) < 0.05 ? "ok" : "FAILED") << std::endl;
  }

  // With omega = delta/|xi| and the Cauchy Poisson ratio (n k = (n + 2) mu), the LPS bond force
  // t_ij + t_ji = n (n + 2) mu omega e (1/m_i + 1/m_j) is that of PMB, c s, where m_i = m_j = m:
  // with the continuum weighted volume m (pi delta^5 in 3D, 2 pi h delta^4 / 3 in 2D) the PMB
  // micromodulus 3D 30 mu / (pi delta^4) = 12 E / (pi delta^4); 2D 24 mu / (pi h delta^3), i.e.
  // 9 E / (pi h delta^3) (plane stress, nu = 1/3) or 48 E / (5 pi h delta^3) (plane strain,
  // nu = 1/4). LPS takes each particle's discrete m_i; in the interior, where the family is
  // complete, m_i is the lattice sum m_int, so LPS gives the force of PMB with Young's modulus
  // E m / m_int at every particle whose neighbours all have complete families (depth >= 2 x 3
  // layers at delta = 3.015 dx).
  template <int dim>
  void
  check_reduction(const perideal::PlanarAssumption planar, const double nu)
  {
    const double horizon_factor = 3.015;
    Body<dim>    body(15, dx, horizon_factor, perideal::PartialVolume::none, h);
    const auto   lps = make_lps<dim>(body, planar, nu, "inverse distance", false);

    const double delta = body.delta;
    double       m_int = 0.;
    pd_tests::for_each_lattice_offset<dim>(3, [&](const std::array<int, dim> &v) {
      double r2 = 0.;
      for (const int c : v)
        r2 += double(c) * c;
      const double r = std::sqrt(r2) * dx;
      if (r2 > 0. && r <= delta)
        m_int += delta * r * (dim == 2 ? dx * dx * h : dx * dx * dx);
    });
    const double       m = dim == 3 ? dealii::numbers::PI * std::pow(delta, 5) :
                                      2. * dealii::numbers::PI * h * std::pow(delta, 4) / 3.;
    std::ostringstream young;
    young << std::setprecision(17) << E * m / m_int;
    perideal::BondBased<dim> pmb;
    pd_tests::parse_model(pmb, {{"Young's modulus", young.str()}});
    pmb.initialize(body.ps, pd_tests::model_context(body.delta, h, planar, false));

    perideal::ParticleVector u, f_lps, f_pmb;
    body.set_field(u, [&](const unsigned int i) {
      dealii::Tensor<1, dim> v;
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = 1e-3 * dx * random_number(body.lattice_index(i) * dim + d);
      return v;
    });
    body.ps.reinit_vector(f_lps, dim);
    body.ps.reinit_vector(f_pmb, dim);
    lps->compute_forces(body.ps, u, f_lps, nullptr, std::numeric_limits<double>::infinity());
    pmb.compute_forces(body.ps, u, f_pmb, nullptr, std::numeric_limits<double>::infinity());
    double difference = 0., size = 0.;
    for (unsigned int i = 0; i < body.ps.n_owned(); ++i)
      if (body.depth(i) >= 6)
        for (unsigned int d = 0; d < dim; ++d)
          {
            difference = std::max(difference,
                                  std::abs(f_lps.local_element(i * dim + d) -
                                           f_pmb.local_element(i * dim + d)));
            size       = std::max(size, std::abs(f_pmb.local_element(i * dim + d)));
          }
    difference = dealii::Utilities::MPI::max(difference, MPI_COMM_WORLD);
    size       = dealii::Utilities::MPI::max(size, MPI_COMM_WORLD);
    deallog << planar_name(planar) << ", nu = " << std::setprecision(4) << nu
            << std::setprecision(6)
            << ", 'inverse distance', interior (depth >= 6): max |f_LPS - f_PMB(E m / m_int)| / "
               "max |f_PMB| < 1e-10 "
            << (difference / size < 1e-10 ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  using P = perideal::PlanarAssumption;
  for (const std::string omega : {"constant", "inverse distance", "gaussian"})
    {
      check_energy<3>(P::three_dimensional, omega);
      check_energy<2>(P::plane_strain, omega);
      check_energy<2>(P::plane_stress, omega);
    }

  check_reduction<3>(P::three_dimensional, 0.25);
  check_reduction<2>(P::plane_strain, 0.25);
  check_reduction<2>(P::plane_stress, 1. / 3.);
}
