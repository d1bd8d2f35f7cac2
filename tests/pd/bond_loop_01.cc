// The shared bond-block loop (for_each_bond_block) with the scalar pair law of one component per
// particle (SlopePairLaw, the antiplane models' bond-based law), the antiplane form u = w e_z: bond
// strain s = (w_j - w_i)/|xi|, pair energy k s^2 |xi| / 4 at each end and force k s on i (-k s on
// j), breaking where |s| exceeds the critical stretch (the loop orients a bond from its end of
// lower kernel index, so a law must not depend on the orientation); forces, energies and broken
// bonds against a plain loop over the compressed-row bond list on a body with a hole, in 2D and 3D,
// with bonds to ghost particles.

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/bond_loop.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace
{
  using dealii::deallog;
  const double dx = 1e-3, crit = 1e-3;

  template <int dim>
  void
  check(const int n)
  {
    // Lattice n^dim with a hole of radius 2.6 dx at the centre.
    perideal::ParticleSystem<dim>                    ps(MPI_COMM_WORLD);
    typename perideal::ParticleSystem<dim>::Settings settings;
    settings.spacing   = dx;
    settings.horizon   = 3.015 * dx;
    settings.thickness = dx;
    dealii::Point<dim> upper, centre;
    for (unsigned int d = 0; d < dim; ++d)
      {
        upper[d]  = n * dx;
        centre[d] = 0.5 * n * dx;
      }
    ps.generate(settings,
                dealii::BoundingBox<dim>(std::make_pair(dealii::Point<dim>(), upper)),
                [&](const dealii::Point<dim> &p) { return p.distance(centre) > 2.6 * dx; },
                {});

    // Random w of amplitude 2 crit dx keyed by lattice position (rank independent), and
    // k = chi V_i V_j per bond.
    auto               &bonds  = ps.bonds();
    const auto         &volume = ps.volumes();
    std::vector<double> w(ps.n_local()), k(bonds.size());
    for (unsigned int i = 0; i < ps.n_local(); ++i)
      {
        std::uint64_t key = 0;
        for (unsigned int d = 0; d < dim; ++d)
          key = 1000 * key + std::lround(ps.positions()[i][d] / dx - 0.5);
        w[i] = 2. * crit * dx * pd_tests::random_number(key);
      }
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        k[b] = bonds.volume_factor(b) * volume[i] * volume[bonds.neighbor[b]];

    // The plain loop.
    std::vector<double>       f_reference(ps.n_owned(), 0.), e_reference(ps.n_owned(), 0.);
    std::vector<std::uint8_t> intact_reference = bonds.intact;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j = bonds.neighbor[b];
          const double       s = (w[j] - w[i]) / bonds.length[b];
          if (intact_reference[b] == 1 && std::abs(s) > crit)
            intact_reference[b] = 0;
          if (intact_reference[b] == 0)
            continue;
          const double e = 0.25 * k[b] * s * s * bonds.length[b];
          f_reference[i] += k[b] * s;
          e_reference[i] += e;
          if (j < ps.n_owned())
            {
              f_reference[j] -= k[b] * s;
              e_reference[j] += e;
            }
        }

    // The shared loop with one component.
    perideal::BondBlocks<dim> blocks;
    blocks.reinit(ps);
    typename perideal::BondBlocks<dim>::Array w_field, f_field, e_field, lane_k;
    blocks.reinit_field(w_field, 1);
    blocks.reinit_field(f_field, 1);
    blocks.reinit_field(e_field, 1);
    blocks.gather(w.data(), 1, w_field);
    blocks.to_lanes(k, lane_k);
    perideal::for_each_bond_block<1>(blocks,
                                     {{blocks.component(w_field, 0)}},
                                     {{blocks.component(f_field, 0), blocks.component(e_field, 0)}},
                                     perideal::SlopePairLaw<dim, true>{lane_k.data()},
                                     bonds,
                                     crit);
    std::vector<double> f(ps.n_owned()), e(ps.n_owned());
    blocks.scatter_owned(f_field, 1, nullptr, f.data());
    blocks.scatter_owned(e_field, 1, nullptr, e.data());

    double f_difference = 0., f_scale = 0., e_difference = 0., e_scale = 0., broken = 0.,
           mismatch = 0.;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        f_difference = std::max(f_difference, std::abs(f[i] - f_reference[i]));
        f_scale      = std::max(f_scale, std::abs(f_reference[i]));
        e_difference = std::max(e_difference, std::abs(e[i] - e_reference[i]));
        e_scale      = std::max(e_scale, std::abs(e_reference[i]));
      }
    for (std::size_t b = 0; b < bonds.size(); ++b)
      {
        broken += ps.bond_share(b) * (bonds.intact[b] == 0);
        mismatch += (bonds.intact[b] != intact_reference[b]);
      }
    const MPI_Comm comm = MPI_COMM_WORLD;
    f_difference        = dealii::Utilities::MPI::max(f_difference, comm);
    f_scale             = dealii::Utilities::MPI::max(f_scale, comm);
    e_difference        = dealii::Utilities::MPI::max(e_difference, comm);
    e_scale             = dealii::Utilities::MPI::max(e_scale, comm);
    broken              = dealii::Utilities::MPI::sum(broken, comm);
    mismatch            = dealii::Utilities::MPI::sum(mismatch, comm);
    deallog << dim << "D scalar: " << ps.n_global_bonds() << " bonds, " << std::lround(broken)
            << " broken, states as the reference " << (mismatch == 0. ? "ok" : "FAILED")
            << ", max force difference / max force < 1e-12 "
            << (f_difference <= 1e-12 * f_scale ? "ok" : "FAILED")
            << ", max energy difference / max energy < 1e-12 "
            << (e_difference <= 1e-12 * e_scale ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  check<2>(23);
  check<3>(13);
}
