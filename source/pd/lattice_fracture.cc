// ---------------------------------------------------------------------
// PeriDeal: the fracture energy of the particles' actual lattice, for the lattice calibration of
// the critical stretch.
// ---------------------------------------------------------------------
#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <perideal/pd/lattice_fracture.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
    // particle (a bond between two owned particles is listed once: both ends take it). E_ij
    // without the blended coupling's energy weight (beta_i + beta_j)/2, which the models'
    // coefficients carry: the lattice's energy, not the share the coupling gives the particles
    // (with it, the particles in the coupling's overlap counted as if their lattice dissipated
    // less, and the factor depended on where the PD zone ends).
    std::vector<double>                  family(n_owned, 0.);
    std::vector<std::array<double, dim>> cut(n_owned, std::array<double, dim>{});
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j    = bonds.neighbor[b];
          const double       beta = particles.bond_energy_weight(i, j);
          family[i] += bonds.volume_factor(b) * volume[j];
          if (j < n_owned)
            family[j] += bonds.volume_factor(b) * volume[i];
          for (unsigned int a = 0; a < dim; ++a)
            {
              const double share =
                beta > 0. ? 0.5 * std::abs(x[j][a] - x[i][a]) * bond_energy[b] / beta : 0.;
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
    // the interior), and an energy weight above zero (every bond counted has one to divide by).
    const auto    &energy_weight = particles.energy_weights();
    ParticleVector flag;
    particles.reinit_vector(flag, 1);
    for (unsigned int i = 0; i < n_owned; ++i)
      flag.local_element(i) = family[i] >= 0.8 * complete && energy_weight[i] > 0. ? 1. : 0.;
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
  lattice_fracture_factor(
    const ParticleSystem<dim>                                          &particles,
    const std::function<double(const unsigned int, const std::size_t)> &coefficient,
    const std::function<double(double)>                                &energy)
  {
    const BondList     &bonds = particles.bonds();
    std::vector<double> bond_energy(bonds.size(), 0.);
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (std::size_t b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        bond_energy[b] = coefficient(i, b) * energy(bonds.length[b]);
    return 1. / std::sqrt(lattice_fracture_energy(particles, bond_energy));
  }

  template <int dim>
  double
  cleave_fracture_energy(const typename ParticleSystem<dim>::Settings &settings,
                         MaterialModel<dim>                           &model,
                         const ModelContext                           &context,
                         const double                                  critical,
                         const MPI_Comm                                communicator)
  {
    const double dx = settings.spacing, window = (dim == 2 ? 12. : 4.) * dx;
    const double side = window + 2. * std::ceil(2. * settings.horizon / dx) * dx;
    Point<dim>   upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = side;
    ParticleSystem<dim> particles(communicator);
    particles.generate(settings,
                       BoundingBox<dim>(std::make_pair(Point<dim>(), upper)),
                       [](const Point<dim> &) { return true; },
                       {});
    model.initialize(particles, context);

    const auto        &x       = particles.positions();
    const unsigned int n_owned = particles.n_owned();
    const double       cut     = 0.5 * side;
    const auto         across  = [&](const unsigned int i, const unsigned int j) {
      return (x[i][dim - 1] - cut) * (x[j][dim - 1] - cut) < 0.;
    };
    // The component that jumps: the scalar, or the translation normal to the cut.
    const FieldLayout  layout  = model.field_layout();
    const unsigned int nc      = layout.n_components();
    unsigned int       jumping = 0;
    for (unsigned int c = 0; c < nc; ++c)
      if (layout.kind(c) == ComponentKind::translation && layout[c].axis == dim - 1)
        jumping = c;
    const bool mode_III = nc == 1;
    // The jumps at which the bonds across the cut reach the critical value, binned.
    BondList           &bonds = particles.bonds();
    std::vector<double> jumps;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (across(i, bonds.neighbor[b]))
          {
            const double r = bonds.length[b],
                         n = std::abs(x[bonds.neighbor[b]][dim - 1] - x[i][dim - 1]);
            jumps.push_back(mode_III ? critical * r :
                                       std::sqrt(n * n + (2. + critical) * critical * r * r) - n);
          }
    std::vector<double> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, jumps))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    std::vector<double> steps;
    for (const double jump : all)
      if (steps.empty() || jump > steps.back() * (1. + 1e-4))
        steps.push_back(jump);
      else
        steps.back() = jump;

    ParticleVector u, force;
    particles.reinit_vector(u, nc);
    particles.reinit_vector(force, nc);
    const auto window_energy = [&]() {
      std::vector<double> w;
      model.compute_forces(particles, u, force, &w, std::numeric_limits<double>::infinity());
      double local = 0.;
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          bool inside = true;
          for (unsigned int a = 0; a + 1 < dim; ++a)
            inside = inside && std::abs(x[i][a] - cut) < 0.5 * window;
          if (inside)
            local += w[i] * particles.volumes()[i];
        }
      return Utilities::MPI::sum(local, communicator);
    };
    double dissipated = 0.;
    for (const double step : steps)
      {
        const double jump = step * (1. + 1e-9);
        for (unsigned int i = 0; i < particles.n_local(); ++i)
          u.local_element(i * nc + jumping) = x[i][dim - 1] > cut ? jump : 0.;
        const double before = window_energy();
        model.compute_forces(particles, u, force, nullptr, critical);
        dissipated += before - window_energy();
      }
    return dissipated / (std::pow(window, dim - 1) * (dim == 2 ? settings.thickness : 1.));
  }

  template double
  lattice_fracture_energy<2>(const ParticleSystem<2> &, const std::vector<double> &);
  template double
  lattice_fracture_energy<3>(const ParticleSystem<3> &, const std::vector<double> &);
  template double
  cleave_fracture_energy<2>(const ParticleSystem<2>::Settings &,
                            MaterialModel<2> &,
                            const ModelContext &,
                            double,
                            MPI_Comm);
  template double
  cleave_fracture_energy<3>(const ParticleSystem<3>::Settings &,
                            MaterialModel<3> &,
                            const ModelContext &,
                            double,
                            MPI_Comm);
  template double
  lattice_fracture_factor<2>(const ParticleSystem<2> &,
                             const std::function<double(const unsigned int, const std::size_t)> &,
                             const std::function<double(double)> &);
  template double
  lattice_fracture_factor<3>(const ParticleSystem<3> &,
                             const std::function<double(const unsigned int, const std::size_t)> &,
                             const std::function<double(double)> &);
} // namespace perideal
