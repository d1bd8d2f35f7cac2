// ParticleSystem bond lists equal a brute-force neighbour search (2D, 3D, 1 or 2 ranks).

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <perideal/pd/particle_system.h>

#include "../tests.h"
#include "pd_tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace
{
  template <int dim>
  void
  test(const std::array<int, dim> &n_points, const double horizon_factor)
  {
    const MPI_Comm comm = MPI_COMM_WORLD;
    const double   dx   = 1e-3;
    // A box away from the origin, so that lattice positions are not trivially small integers.
    dealii::Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = -0.003 + 0.0017 * d;
        upper[d] = lower[d] + n_points[d] * dx;
      }

    perideal::ParticleSystem<dim>                    ps(comm);
    typename perideal::ParticleSystem<dim>::Settings s;
    s.spacing        = dx;
    s.horizon        = horizon_factor * dx;
    s.thickness      = 1e-4;
    s.partial_volume = perideal::PartialVolume::none;
    pd_tests::generate_box<dim>(ps, s, lower, upper);

    // Lattice index of a particle from its position (cell centres at lower + (i + 1/2) dx).
    const auto lattice_index = [&](const dealii::Point<dim> &x) {
      std::int64_t index = 0;
      for (unsigned int d = dim; d-- > 0;)
        {
          const auto i = std::lround((x[d] - lower[d]) / dx - 0.5);
          AssertThrow(std::abs((x[d] - lower[d]) / dx - 0.5 - i) < 1e-9,
                      dealii::ExcMessage("particle off the lattice"));
          index = index * n_points[d] + i;
        }
      return index;
    };
    const auto lattice_point = [&](std::int64_t index) {
      std::array<int, dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        {
          p[d] = static_cast<int>(index % n_points[d]);
          index /= n_points[d];
        }
      return p;
    };
    std::int64_t n_lattice = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_lattice *= n_points[d];

    // Map lattice index -> global index from the owned particles of all ranks.
    // Flat (lattice index, global index) pairs.
    std::vector<std::int64_t> mine;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        mine.push_back(lattice_index(ps.positions()[i]));
        mine.push_back(ps.global_index(i));
      }
    std::map<std::int64_t, std::uint64_t> global_of;
    std::int64_t                          n_owned_total = 0;
    for (const auto &part : dealii::Utilities::MPI::all_gather(comm, mine))
      for (std::size_t k = 0; k < part.size(); k += 2)
        {
          global_of[part[k]] = part[k + 1];
          ++n_owned_total;
        }
    // Every lattice point is owned exactly once.
    const bool partition_ok =
      (n_owned_total == n_lattice && static_cast<std::int64_t>(global_of.size()) == n_lattice &&
       ps.n_global() == static_cast<std::uint64_t>(n_lattice));

    // Ghosts carry the global index of their owner.
    unsigned int bad_ghosts = 0;
    for (unsigned int i = ps.n_owned(); i < ps.n_local(); ++i)
      if (global_of.at(lattice_index(ps.positions()[i])) != ps.global_index(i))
        ++bad_ghosts;

    // Families from the bond list: each owned-owned bond serves both ends, bonds to ghosts the
    // owned end. Also check the stored bond lengths.
    const perideal::BondList               &bonds = ps.bonds();
    std::vector<std::vector<std::uint64_t>> family(ps.n_owned());
    unsigned int                            bad_lengths = 0;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j = bonds.neighbor[b];
          family[i].push_back(ps.global_index(j));
          if (j < ps.n_owned())
            family[j].push_back(ps.global_index(i));
          if (std::abs(bonds.length[b] - ps.positions()[i].distance(ps.positions()[j])) >
              1e-12 * dx)
            ++bad_lengths;
        }

    // Brute force over all lattice points, in integer arithmetic: |xi|^2 <= delta^2 counts the
    // neighbours at exactly delta (seed note 002, sec. 5.3: "<= delta", 48 for delta = 4 dx).
    const double  reach2     = horizon_factor * horizon_factor * (1. + 1e-9);
    unsigned int  bad_family = 0, max_family = 0;
    std::uint64_t n_half = 0;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        const auto                 pi = lattice_point(lattice_index(ps.positions()[i]));
        std::vector<std::uint64_t> expected;
        for (std::int64_t q = 0; q < n_lattice; ++q)
          {
            const auto pq = lattice_point(q);
            long       r2 = 0;
            for (unsigned int d = 0; d < dim; ++d)
              r2 += long(pq[d] - pi[d]) * (pq[d] - pi[d]);
            if (r2 > 0 && r2 <= reach2)
              expected.push_back(global_of.at(q));
          }
        std::sort(expected.begin(), expected.end());
        std::sort(family[i].begin(), family[i].end());
        if (family[i] != expected)
          ++bad_family;
        max_family = std::max<unsigned int>(max_family, family[i].size());
        n_half += family[i].size();
      }

    // The largest possible family: lattice offsets within the horizon.
    unsigned int full_family = 0;
    pd_tests::for_each_lattice_offset<dim>(static_cast<int>(horizon_factor),
                                           [&](const std::array<int, dim> &v) {
                                             long r2 = 0;
                                             for (unsigned int d = 0; d < dim; ++d)
                                               r2 += long(v[d]) * v[d];
                                             if (r2 > 0 && r2 <= reach2)
                                               ++full_family;
                                           });

    bad_ghosts  = dealii::Utilities::MPI::sum(bad_ghosts, comm);
    bad_lengths = dealii::Utilities::MPI::sum(bad_lengths, comm);
    bad_family  = dealii::Utilities::MPI::sum(bad_family, comm);
    max_family  = dealii::Utilities::MPI::max(max_family, comm);
    n_half      = dealii::Utilities::MPI::sum(n_half, comm);

    dealii::deallog << dim << "D lattice";
    for (unsigned int d = 0; d < dim; ++d)
      dealii::deallog << (d == 0 ? " " : "x") << n_points[d];
    dealii::deallog << ", delta = " << horizon_factor << " dx: " << ps.n_global()
                    << " particles, partition " << (partition_ok ? "ok" : "FAILED")
                    << ", ghost indices " << (bad_ghosts == 0 ? "ok" : "FAILED") << std::endl;
    dealii::deallog << "  families equal to brute force: " << (bad_family == 0 ? "ok" : "FAILED")
                    << " (" << bad_family << " differ), bond lengths "
                    << (bad_lengths == 0 ? "ok" : "FAILED") << std::endl;
    // Each unique bond appears in two families.
    dealii::deallog << "  unique bonds n_global_bonds() = " << ps.n_global_bonds()
                    << ", brute force = " << n_half / 2 << ": "
                    << (ps.n_global_bonds() * 2 == n_half ? "ok" : "FAILED") << std::endl;
    // Only a lattice wider than two horizons has a particle with a full family.
    bool has_interior = true;
    for (unsigned int d = 0; d < dim; ++d)
      has_interior &= (n_points[d] >= 2 * static_cast<int>(horizon_factor) + 1);
    dealii::deallog << "  largest family " << max_family << ", full horizon " << full_family;
    if (has_interior)
      dealii::deallog << ": " << (max_family == full_family ? "ok" : "FAILED");
    else
      dealii::deallog << " (no interior particle)";
    dealii::deallog << std::endl;
    if (dim == 2 && horizon_factor == 4.)
      dealii::deallog << "  thesis: 48 neighbours of an interior particle for delta = 4 dx: "
                      << (max_family == 48 ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  test<2>({{23, 17}}, 3.015);
  // Thesis value (seed note 002, sec. 5.3): an interior particle has 48 neighbours for
  // delta = 4 dx with |xi| <= delta; the 23x17 lattice has interior particles.
  test<2>({{23, 17}}, 4.);
  test<3>({{9, 8, 7}}, 3.015);
  test<3>({{9, 8, 7}}, 4.);
}
