// The vectorized force kernels (lattice bond blocks) against a plain scalar loop over the
// compressed-row bond list: PMB and LPS forces, PMB energy density and the bonds that break, for
// a random displacement field on a body with a hole (irregular lattice lines, surface-corrected
// bonds, bonds to ghost particles on two ranks).

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/bond_based.h>
#include <perideal/pd/influence_function.h>
#include <perideal/pd/linear_peridynamic_solid.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace
{
  using dealii::deallog;
  using perideal::ParticleVector;
  const double E = 72e9, nu = 0.25, h = 1e-3, dx = 1e-3, crit = 1e-3;

  // Lattice n^dim with a hole of radius 2.6 dx at the centre.
  template <int dim>
  void
  generate(perideal::ParticleSystem<dim> &ps, const int n)
  {
    typename perideal::ParticleSystem<dim>::Settings s;
    s.spacing   = dx;
    s.horizon   = 3.015 * dx;
    s.thickness = h;
    dealii::Point<dim> upper, centre;
    for (unsigned int d = 0; d < dim; ++d)
      {
        upper[d]  = n * dx;
        centre[d] = 0.5 * n * dx;
      }
    ps.generate(s,
                dealii::BoundingBox<dim>(std::make_pair(dealii::Point<dim>(), upper)),
                [&](const dealii::Point<dim> &p) { return p.distance(centre) > 2.6 * dx; },
                {});
  }

  // Random displacements of amplitude 2 crit dx, keyed by lattice position (rank independent).
  template <int dim>
  void
  random_field(const perideal::ParticleSystem<dim> &ps, ParticleVector &u)
  {
    ps.reinit_vector(u, dim);
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      {
        std::uint64_t key = 0;
        for (unsigned int d = 0; d < dim; ++d)
          key = 1000 * key + std::lround(ps.positions()[i][d] / dx - 0.5);
        for (unsigned int d = 0; d < dim; ++d)
          u.local_element(i * dim + d) = 2. * crit * dx * pd_tests::random_number(key * dim + d);
      }
  }

  // Bond vector (x_j - x_i) + (u_j - u_i) and its stretch.
  template <int dim>
  double
  bond_vector(const perideal::ParticleSystem<dim> &ps,
              const ParticleVector                &u,
              const unsigned int                   i,
              const unsigned int                   b,
              double                              *y)
  {
    const unsigned int j  = ps.bonds().neighbor[b];
    double             l2 = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        y[d] = (ps.positions()[j][d] - ps.positions()[i][d]) +
               (u.local_element(j * dim + d) - u.local_element(i * dim + d));
        l2 += y[d] * y[d];
      }
    return std::sqrt(l2);
  }

  // Compare force vectors (owned entries) and the states; print one line.
  template <int dim>
  void
  report(const std::string                   &name,
         const perideal::ParticleSystem<dim> &ps,
         const ParticleVector                &f,
         const std::vector<double>           &f_reference,
         const std::vector<std::uint8_t>     &intact,
         const std::vector<std::uint8_t>     &intact_reference,
         const double                         energy_error = -1.)
  {
    double difference = 0., scale = 0., broken = 0., mismatch = 0.;
    for (unsigned int k = 0; k < ps.n_owned() * dim; ++k)
      {
        difference = std::max(difference, std::abs(f.local_element(k) - f_reference[k]));
        scale      = std::max(scale, std::abs(f_reference[k]));
      }
    for (std::size_t b = 0; b < intact.size(); ++b)
      {
        broken += ps.bond_share(b) * (intact[b] == 0);
        mismatch += (intact[b] != intact_reference[b]);
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    difference          = dealii::Utilities::MPI::max(difference, comm);
    scale               = dealii::Utilities::MPI::max(scale, comm);
    broken              = dealii::Utilities::MPI::sum(broken, comm);
    mismatch            = dealii::Utilities::MPI::sum(mismatch, comm);
    deallog << name << ": " << ps.n_global_bonds() << " bonds, " << std::lround(broken)
            << " broken, states as the reference " << (mismatch == 0. ? "ok" : "FAILED")
            << ", max force difference / max force < 1e-12 "
            << (difference <= 1e-12 * scale ? "ok" : "FAILED");
    if (energy_error >= 0.)
      deallog << ", energy density < 1e-12 "
              << (dealii::Utilities::MPI::max(energy_error, comm) < 1e-12 ? "ok" : "FAILED");
    deallog << std::endl;
  }

  template <int dim>
  void
  check_pmb(const int n)
  {
    perideal::ParticleSystem<dim> ps(MPI_COMM_WORLD);
    generate(ps, n);
    perideal::BondBased<dim> model;
    pd_tests::parse_model(model, {{"Young's modulus", std::to_string(E)}});
    const auto planar = (dim == 3 ? perideal::PlanarAssumption::three_dimensional :
                                    perideal::PlanarAssumption::plane_stress);
    model.initialize(ps, pd_tests::model_context(3.015 * dx, h, planar, true));

    ParticleVector u, f;
    random_field(ps, u);
    ps.reinit_vector(f, dim);
    const auto               &bonds  = ps.bonds();
    const auto               &volume = ps.volumes();
    std::vector<double>       f_reference(ps.n_owned() * dim, 0.), w_reference(ps.n_owned(), 0.);
    std::vector<std::uint8_t> intact_reference = bonds.intact;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          double       y[dim];
          const double length = bond_vector(ps, u, i, b, y);
          const double xi     = bonds.length[b];
          const double s      = (length - xi) / xi;
          if (intact_reference[b] == 1 && s > crit)
            intact_reference[b] = 0;
          if (intact_reference[b] == 0)
            continue;
          const unsigned int j = bonds.neighbor[b];
          const double       k = model.pair_coefficient(ps, i, b);
          for (unsigned int d = 0; d < dim; ++d)
            {
              f_reference[i * dim + d] += k * s * y[d] / length / volume[i];
              if (j < ps.n_owned())
                f_reference[j * dim + d] -= k * s * y[d] / length / volume[j];
            }
          const double w = 0.25 * k * s * s * xi;
          w_reference[i] += w / volume[i];
          if (j < ps.n_owned())
            w_reference[j] += w / volume[j];
        }
    std::vector<double> w;
    model.compute_forces(ps, u, f, &w, crit);
    double w_error = 0., w_scale = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        w_error = std::max(w_error, std::abs(w[i] - w_reference[i]));
        w_scale = std::max(w_scale, std::abs(w_reference[i]));
      }
    w_scale = dealii::Utilities::MPI::max(w_scale, MPI_COMM_WORLD);
    report<dim>(std::to_string(dim) + "D PMB",
                ps,
                f,
                f_reference,
                bonds.intact,
                intact_reference,
                w_error / w_scale);
  }

  template <int dim>
  void
  check_lps(const int n)
  {
    perideal::ParticleSystem<dim> ps(MPI_COMM_WORLD);
    generate(ps, n);
    perideal::LinearPeridynamicSolid<dim> model;
    pd_tests::parse_model(model,
                          {{"Young's modulus", std::to_string(E)},
                           {"Poisson's ratio", std::to_string(nu)},
                           {"Influence function", "inverse distance"}});
    const auto   planar = (dim == 3 ? perideal::PlanarAssumption::three_dimensional :
                                      perideal::PlanarAssumption::plane_strain);
    const double delta  = 3.015 * dx;
    model.initialize(ps, pd_tests::model_context(delta, h, planar, true));

    // Moduli (3D or plane strain), weighted volumes over the whole family.
    const double mu = E / (2. * (1. + nu)), lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    const double kappa = (dim == 3 ? lambda + 2. * mu / 3. : lambda + mu), n_dim = dim;
    const perideal::InverseDistanceInfluence omega;
    const auto                              &bonds  = ps.bonds();
    const auto                              &volume = ps.volumes();
    const auto pair_weight = [&](const unsigned int i, const unsigned int b) {
      return omega.value(bonds.length[b], delta) * bonds.volume_factor(b) * volume[i] *
             volume[bonds.neighbor[b]];
    };
    ParticleVector m, theta, u, f;
    ps.reinit_vector(m, 1);
    ps.reinit_vector(theta, 1);
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j  = bonds.neighbor[b];
          const double       r2 = bonds.length[b] * bonds.length[b];
          m.local_element(i) += pair_weight(i, b) * r2 / volume[i];
          if (j < ps.n_owned())
            m.local_element(j) += pair_weight(i, b) * r2 / volume[j];
        }
    m.update_ghost_values();

    random_field(ps, u);
    ps.reinit_vector(f, dim);
    std::vector<std::uint8_t> intact_reference = bonds.intact;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          double       y[dim];
          const double e = bond_vector(ps, u, i, b, y) - bonds.length[b];
          if (intact_reference[b] == 1 && e > crit * bonds.length[b])
            intact_reference[b] = 0;
          if (intact_reference[b] == 0)
            continue;
          const unsigned int j = bonds.neighbor[b];
          const double       a = pair_weight(i, b) * bonds.length[b] * e;
          theta.local_element(i) += n_dim * a / (m.local_element(i) * volume[i]);
          if (j < ps.n_owned())
            theta.local_element(j) += n_dim * a / (m.local_element(j) * volume[j]);
        }
    theta.update_ghost_values();
    std::vector<double> f_reference(ps.n_owned() * dim, 0.);
    const double        c_d = n_dim * kappa - (n_dim + 2.) * mu;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          if (intact_reference[b] == 0)
            continue;
          double             y[dim];
          const unsigned int j      = bonds.neighbor[b];
          const double       length = bond_vector(ps, u, i, b, y);
          const double       xi = bonds.length[b], e = length - xi;
          const double       alpha_i = mu * n_dim * (n_dim + 2.) / m.local_element(i);
          const double       alpha_j = mu * n_dim * (n_dim + 2.) / m.local_element(j);
          const double       t       = (c_d * xi *
                              (theta.local_element(i) / m.local_element(i) +
                               theta.local_element(j) / m.local_element(j)) +
                            (alpha_i + alpha_j) * e) *
                           pair_weight(i, b);
          for (unsigned int d = 0; d < dim; ++d)
            {
              f_reference[i * dim + d] += t * y[d] / length / volume[i];
              if (j < ps.n_owned())
                f_reference[j * dim + d] -= t * y[d] / length / volume[j];
            }
        }
    model.compute_forces(ps, u, f, nullptr, crit);
    report<dim>(std::to_string(dim) + "D LPS", ps, f, f_reference, bonds.intact, intact_reference);
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  check_pmb<2>(23);
  check_pmb<3>(13);
  check_lps<2>(23);
  check_lps<3>(13);
}
