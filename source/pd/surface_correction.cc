// ---------------------------------------------------------------------
// PeriDeal: the energy method of surface correction for bond-based models.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/pd/surface_correction.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace perideal
{
  template <int dim>
  void
  apply_energy_surface_correction(
    ParticleSystem<dim>                                                      &particles,
    const FieldLayout                                                        &layout,
    const std::array<double, dim>                                            &modulus,
    const std::function<void(const ParticleVector &, std::vector<double> &)> &energy_density)
  {
    // The component that carries the test field of direction a.
    const unsigned int nc = layout.n_components();
    // A scalar field or a temperature: the one component carries every test field.
    const auto is_scalar = [&](const unsigned int c) {
      return layout.kind(c) == ComponentKind::scalar ||
             layout.kind(c) == ComponentKind::temperature;
    };
    const bool scalar = nc == 1 && is_scalar(0);
    AssertThrow(scalar || layout.n_components(ComponentKind::translation) == dim,
                dealii::ExcMessage("The energy method of surface correction takes a scalar "
                                   "field, a temperature or dim translations, not " +
                                   layout.description() + "."));
    const auto component = [&](const unsigned int a) {
      for (unsigned int c = 0; c < nc; ++c)
        if (scalar ? is_scalar(c) :
                     (layout.kind(c) == ComponentKind::translation && layout[c].axis == a))
          return c;
      return nc;
    };

    // Small enough that the geometric nonlinearity of the stretch is below 1e-6 relative.
    const double test_strain = 1e-6;
    BondList    &bonds       = particles.bonds();
    std::fill(bonds.surface_factor.begin(), bonds.surface_factor.end(), 1.);
    // Pre-cracked bonds take part: the correction describes the uncracked geometry.
    const std::vector<std::uint8_t> intact = bonds.intact;
    std::fill(bonds.intact.begin(), bonds.intact.end(), 1);
    ++bonds.revision;

    ParticleVector u, factors;
    particles.reinit_vector(u, nc);
    particles.reinit_vector(factors, dim);
    std::vector<double> energy(particles.n_owned());
    const auto         &x = particles.positions();
    for (unsigned int a = 0; a < dim; ++a)
      {
        u                    = 0.;
        const unsigned int c = component(a);
        for (unsigned int i = 0; i < particles.n_local(); ++i)
          u.local_element(i * nc + c) = test_strain * x[i][a];
        energy_density(u, energy);
        const double classical = 0.5 * modulus[a] * test_strain * test_strain;
        for (unsigned int i = 0; i < particles.n_owned(); ++i)
          factors.local_element(i * dim + a) = classical / energy[i];
      }
    bonds.intact = intact;
    ++bonds.revision;
    factors.update_ghost_values();

    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j   = bonds.neighbor[b];
          const auto         xi  = x[j] - x[i];
          double             sum = 0.;
          for (unsigned int a = 0; a < dim; ++a)
            {
              const double g_mean =
                0.5 * (factors.local_element(i * dim + a) + factors.local_element(j * dim + a));
              const double n = xi[a] / bonds.length[b];
              sum += (n / g_mean) * (n / g_mean);
            }
          bonds.surface_factor[b] = 1. / std::sqrt(sum);
        }
  }

  template void
  apply_energy_surface_correction<2>(
    ParticleSystem<2> &,
    const FieldLayout &,
    const std::array<double, 2> &,
    const std::function<void(const ParticleVector &, std::vector<double> &)> &);
  template void
  apply_energy_surface_correction<3>(
    ParticleSystem<3> &,
    const FieldLayout &,
    const std::array<double, 3> &,
    const std::function<void(const ParticleVector &, std::vector<double> &)> &);
} // namespace perideal
