// ---------------------------------------------------------------------
// PeriDeal: the fracture energy of the particles' actual lattice, for the lattice calibration of
// the critical stretch.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <perideal/pd/lattice_fracture.h>

#include <cmath>
#include <numeric>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  double
  lattice_fracture_energy(const ParticleSystem<dim> &particles,
                          const std::vector<double> &bond_energy)
  {
    const BondList    &bonds   = particles.bonds();
    const auto        &volume  = particles.volumes();
    const auto        &x       = particles.positions();
    const unsigned int n_owned = particles.n_owned();

    // The family volume sum_j chi V_j and the cut sums 1/2 sum_j |xi . e_a| E_ij of every owned
    // particle (a bond between two owned particles is listed once: both ends take it).
    std::vector<double>                  family(n_owned, 0.);
    std::vector<std::array<double, dim>> cut(n_owned, std::array<double, dim>{});
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j = bonds.neighbor[b];
          family[i] += bonds.volume_factor[b] * volume[j];
          if (j < n_owned)
            family[j] += bonds.volume_factor[b] * volume[i];
          for (unsigned int a = 0; a < dim; ++a)
            {
              const double share = 0.5 * std::abs(x[j][a] - x[i][a]) * bond_energy[b];
              cut[i][a] += share;
              if (j < n_owned)
                cut[j][a] += share;
            }
        }

    std::vector<Tensor<1, dim>> xi;
    std::vector<double>         weight;
    particles.lattice_family(xi, weight);
    const double complete = std::accumulate(weight.begin(), weight.end(), 0.);
    // Interior: the particle, its neighbours and theirs have nearly complete families, so that
    // the particle's bonds join particles with complete families (and the surface factors of
    // the interior).
    ParticleVector flag;
    particles.reinit_vector(flag, 1);
    for (unsigned int i = 0; i < n_owned; ++i)
      flag.local_element(i) = family[i] >= 0.8 * complete ? 1. : 0.;
    std::vector<double> spread(n_owned);
    for (unsigned int round = 0; round < 2; ++round)
      {
        flag.update_ghost_values();
        for (unsigned int i = 0; i < n_owned; ++i)
          spread[i] = flag.local_element(i);
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            {
              const unsigned int j = bonds.neighbor[b];
              spread[i] *= flag.local_element(j);
              if (j < n_owned)
                spread[j] *= flag.local_element(i);
            }
        flag.zero_out_ghost_values();
        for (unsigned int i = 0; i < n_owned; ++i)
          flag.local_element(i) = spread[i];
      }

    double sums[2] = {0., 0.};
    for (unsigned int i = 0; i < n_owned; ++i)
      if (flag.local_element(i) > 0.)
        {
          for (unsigned int a = 0; a < dim; ++a)
            sums[0] += cut[i][a] / dim;
          sums[1] += volume[i];
        }
    Utilities::MPI::sum(sums, particles.get_communicator(), sums);
    AssertThrow(sums[1] > 0.,
                ExcMessage("The lattice calibration of the fracture energy (<Material/critical "
                           "stretch/Fracture energy calibration> = lattice) needs particles "
                           "whose neighbours' neighbours have complete families (about 2.4 "
                           "horizons from the boundary); this body has none: use a smaller "
                           "horizon or the continuum calibration."));
    return sums[0] / sums[1];
  }

  template <int dim>
  double
  lattice_fracture_factor(const ParticleSystem<dim>           &particles,
                          const std::vector<double>           &coefficient,
                          const std::function<double(double)> &energy)
  {
    const BondList     &bonds = particles.bonds();
    std::vector<double> bond_energy(bonds.size(), 0.);
    for (unsigned int b = 0; b < bonds.row_start[particles.n_owned()]; ++b)
      bond_energy[b] = coefficient[b] * energy(bonds.length[b]);
    return 1. / std::sqrt(lattice_fracture_energy(particles, bond_energy));
  }

  template double
  lattice_fracture_energy<2>(const ParticleSystem<2> &, const std::vector<double> &);
  template double
  lattice_fracture_energy<3>(const ParticleSystem<3> &, const std::vector<double> &);
  template double
  lattice_fracture_factor<2>(const ParticleSystem<2> &,
                             const std::vector<double> &,
                             const std::function<double(double)> &);
  template double
  lattice_fracture_factor<3>(const ParticleSystem<3> &,
                             const std::vector<double> &,
                             const std::function<double(double)> &);
} // namespace perideal
