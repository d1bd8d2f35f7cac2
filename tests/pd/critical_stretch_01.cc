// Critical stretch from the fracture energy (PMB, LPS) and the damage index.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/bond_based.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/particle_system.h>
#include <perideal/pd/pre_crack.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
  using dealii::deallog;
  const double pi    = dealii::numbers::PI;
  const double E     = 192e9;
  const double h     = 1e-4;
  const double dx    = 1e-4;
  const double delta = 4e-4;
  const double G0    = 1000.;

  using pd_tests::planar_name;

  template <int dim>
  perideal::ParticleSystem<dim>
  make_particles(const int                                   n,
                 const double                                horizon,
                 const bool                                  partial_volume,
                 const std::vector<perideal::PreCrack<dim>> &cracks)
  {
    perideal::ParticleSystem<dim>                    ps(MPI_COMM_WORLD);
    typename perideal::ParticleSystem<dim>::Settings s;
    s.spacing   = dx;
    s.horizon   = horizon;
    s.thickness = h;
    s.partial_volume =
      partial_volume ? perideal::PartialVolume::book : perideal::PartialVolume::none;
    dealii::Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = n * dx;
    pd_tests::generate_box<dim>(ps, s, dealii::Point<dim>(), upper, cracks);
    return ps;
  }

  perideal::ModelContext
  context(const perideal::PlanarAssumption planar)
  {
    return pd_tests::model_context(delta, h, planar, false);
  }

  // Energy per unit crack area of all bonds that cross a plane when each stores the PMB
  // micropotential w = c s0^2 |xi| / 2 (seed 002, eq. 4.94). A bond of length r at angle t to
  // the plane normal crosses it for r cos t of source depths; the bonds of length r fill a
  // shell of measure 2 pi r^2 sin t dt (3D) or h r dt over t in (-pi/2, pi/2) (2D, per unit
  // thickness of the crack face). Gauss quadrature in (r, t), exact to round-off here.
  double
  fracture_energy(const int dim, const double c, const double s0)
  {
    const dealii::QGauss<1> gauss(12);
    double                  G = 0.;
    for (unsigned int qr = 0; qr < gauss.size(); ++qr)
      for (unsigned int qt = 0; qt < gauss.size(); ++qt)
        {
          const double r = delta * gauss.point(qr)[0], wr = delta * gauss.weight(qr);
          const double w = 0.5 * c * s0 * s0 * r;
          if (dim == 3)
            {
              const double t = 0.5 * pi * gauss.point(qt)[0], wt = 0.5 * pi * gauss.weight(qt);
              G += wr * wt * w * r * std::cos(t) * 2. * pi * r * r * std::sin(t);
            }
          else
            {
              const double t = pi * (gauss.point(qt)[0] - 0.5), wt = pi * gauss.weight(qt);
              G += wr * wt * w * r * std::cos(t) * h * r;
            }
        }
    return G;
  }

  template <int dim>
  void
  check_bond_based(const perideal::PlanarAssumption planar)
  {
    auto                     ps = make_particles<dim>(9, delta, false, {});
    perideal::BondBased<dim> model;
    pd_tests::parse_model(model, {{"Young's modulus", std::to_string(E)}});
    model.initialize(ps, context(planar));
    const double s0 = model.critical_stretch(G0);
    const double c  = model.micromodulus();
    const double G  = fracture_energy(dim, c, s0);
    // Closed forms of seed note 002, sec. 4.2.
    const double G_seed = (dim == 3 ? pi * c * s0 * s0 * std::pow(delta, 5) / 10. :
                                      c * s0 * s0 * h * std::pow(delta, 4) / 4.);
    deallog << "bond based, " << planar_name(planar) << ": s0 = " << s0
            << ", G(s0)/G0 = 1 (< 1e-12) " << (std::abs(G / G0 - 1.) < 1e-12 ? "ok" : "FAILED")
            << ", seed closed form " << (std::abs(G_seed / G - 1.) < 1e-12 ? "ok" : "FAILED")
            << std::endl;
  }

  // The LPS formula (inverse distance influence) must give the PMB value where the two models
  // coincide: nu = 1/4 in 3D and plane strain, nu = 1/3 in plane stress.
  template <int dim>
  void
  check_lps(const perideal::PlanarAssumption planar, const double nu)
  {
    auto                     ps = make_particles<dim>(9, delta, false, {});
    perideal::BondBased<dim> pmb;
    pd_tests::parse_model(pmb, {{"Young's modulus", std::to_string(E)}});
    pmb.initialize(ps, context(planar));
    perideal::LinearPeridynamicSolid<dim> lps;
    std::ostringstream                    poisson;
    poisson << std::setprecision(17) << nu;
    pd_tests::parse_model(lps,
                          {{"Young's modulus", std::to_string(E)},
                           {"Poisson's ratio", poisson.str()},
                           {"Influence function", "inverse distance"}});
    lps.initialize(ps, context(planar));
    const double s_lps = lps.critical_stretch(G0), s_pmb = pmb.critical_stretch(G0);
    deallog << "linear peridynamic solid, " << planar_name(planar)
            << ", nu = " << std::setprecision(4) << nu << std::setprecision(6) << ": s0 = " << s_lps
            << ", equals bond based (< 1e-12) "
            << (std::abs(s_lps / s_pmb - 1.) < 1e-12 ? "ok" : "FAILED") << std::endl;
  }

  // Damage: 0 everywhere before anything breaks; 1 at a particle that lost all its bonds, and
  // 1/28 at each of its neighbours with a full family (delta = 3.015 dx, 28 neighbours).
  void
  check_isolated_particle()
  {
    auto                   ps = make_particles<2>(15, 3.015 * dx, false, {});
    const dealii::Point<2> centre(7.5 * dx, 7.5 * dx);
    auto                   damage = perideal::damage_index(ps);
    double                 before = 0.;
    for (const double phi : damage)
      before = std::max(before, phi);
    before = dealii::Utilities::MPI::max(before, MPI_COMM_WORLD);

    perideal::BondList &bonds = ps.bonds();
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (ps.positions()[i].distance(centre) < 1e-3 * dx ||
            ps.positions()[bonds.neighbor[b]].distance(centre) < 1e-3 * dx)
          bonds.intact[b] = 0;
    damage            = perideal::damage_index(ps);
    double phi_centre = 0., worst_neighbour = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        const double r = ps.positions()[i].distance(centre);
        if (r < 1e-3 * dx)
          phi_centre = damage[i];
        else if (r <= 3.015 * dx)
          {
            // Full families: particles at least 3 layers from the boundary.
            bool full = true;
            for (unsigned int d = 0; d < 2; ++d)
              full &= (ps.positions()[i][d] > 3. * dx && ps.positions()[i][d] < 12. * dx);
            if (full)
              worst_neighbour = std::max(worst_neighbour, std::abs(damage[i] - 1. / 28.));
          }
      }
    phi_centre      = dealii::Utilities::MPI::sum(phi_centre, MPI_COMM_WORLD);
    worst_neighbour = dealii::Utilities::MPI::max(worst_neighbour, MPI_COMM_WORLD);
    deallog << "damage index: intact body max 0 " << (before == 0. ? "ok" : "FAILED")
            << "; isolated particle: broken bonds " << perideal::n_broken_bonds(ps) << ", damage 1 "
            << (std::abs(phi_centre - 1.) < 1e-14 ? "ok" : "FAILED") << ", neighbours 1/28 "
            << (worst_neighbour < 1e-14 ? "ok" : "FAILED") << std::endl;
  }

  // A grid-aligned pre-crack between two rows: a particle next to it loses the bonds to the
  // other side, 11/28 of its family, or 9.888146/24.806292 = 0.398614 of its volume-weighted
  // family with partial volume (seed note 000, sec. 3, delta = 3.015 dx).
  void
  check_pre_crack(const bool partial_volume)
  {
    perideal::PreCrack<2> crack;
    crack.vertices        = {{dealii::Point<2>(-dx, 7. * dx), dealii::Point<2>(16. * dx, 7. * dx)}};
    auto         ps       = make_particles<2>(15, 3.015 * dx, partial_volume, {crack});
    const auto   damage   = perideal::damage_index(ps);
    const double expected = partial_volume ? 9.888146 / 24.806292 : 11. / 28.;
    double       above = 0., below = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        if (ps.positions()[i].distance(dealii::Point<2>(7.5 * dx, 7.5 * dx)) < 1e-3 * dx)
          above = damage[i];
        if (ps.positions()[i].distance(dealii::Point<2>(7.5 * dx, 6.5 * dx)) < 1e-3 * dx)
          below = damage[i];
      }
    above = dealii::Utilities::MPI::sum(above, MPI_COMM_WORLD);
    below = dealii::Utilities::MPI::sum(below, MPI_COMM_WORLD);
    // The seed value has 7 digits.
    deallog << "pre-crack between rows, partial volume " << (partial_volume ? "on" : "off")
            << ": damage next to it " << above << ", expected " << expected << ": "
            << (std::abs(above - expected) < 1e-6 && std::abs(below - expected) < 1e-6 ? "ok" :
                                                                                         "FAILED")
            << ", broken bonds " << perideal::n_broken_bonds(ps) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  using P = perideal::PlanarAssumption;
  check_bond_based<3>(P::three_dimensional);
  check_bond_based<2>(P::plane_stress);
  check_bond_based<2>(P::plane_strain);

  check_lps<3>(P::three_dimensional, 0.25);
  check_lps<2>(P::plane_stress, 1. / 3.);
  check_lps<2>(P::plane_strain, 0.25);

  check_isolated_particle();
  check_pre_crack(false);
  check_pre_crack(true);
}
