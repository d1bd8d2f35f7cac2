// ---------------------------------------------------------------------
// PeriDeal: the surface correction of the PD models: the energy method, and the one dispatch
// between it and the stiffness fit from the law a model supplies.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/base/setup_times.h>
#include <perideal/pd/surface_correction.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

namespace perideal
{
  namespace
  {
    /**
     * @brief The energy method (apply_energy_surface_correction()) up to the bonds: hands
     * @p use the factor G of each bond, computed from the particles' directional factors when
     * asked (none is stored).
     */
    template <int dim>
    void
    energy_method(
      ParticleSystem<dim>                                                      &particles,
      const FieldLayout                                                        &layout,
      const std::array<double, dim>                                            &modulus,
      const std::function<void(const ParticleVector &, std::vector<double> &)> &energy_density,
      const std::function<void(const SurfaceFactors &)>                        &use)
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
      // Pre-cracked bonds take part: the correction describes the uncracked geometry (the broken
      // ones are listed, not the states of all bonds copied: this is the set-up's peak of memory).
      std::vector<unsigned int> broken;
      for (unsigned int b = 0; b < bonds.size(); ++b)
        if (bonds.intact[b] == 0)
          broken.push_back(b);
      bonds.set_state_of(broken, 1);

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
      bonds.set_state_of(broken, 0);
      factors.update_ghost_values();

      use([&](const unsigned int i, const std::size_t b) {
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
        return 1. / std::sqrt(sum);
      });
    }
  } // namespace

  template <int dim>
  void
  apply_energy_surface_correction(
    ParticleSystem<dim>                                                      &particles,
    const FieldLayout                                                        &layout,
    const std::array<double, dim>                                            &modulus,
    const std::function<void(const ParticleVector &, std::vector<double> &)> &energy_density)
  {
    BondList &bonds = particles.bonds();
    bonds.surface_factor.assign(bonds.size(), 1.);
    energy_method<dim>(particles, layout, modulus, energy_density, [&](const SurfaceFactors &g) {
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          bonds.surface_factor[b] = g(i, b);
    });
  }

  template <int dim>
  StiffnessFitReport
  apply_surface_correction(MaterialModel<dim>                                &model,
                           ParticleSystem<dim>                               &particles,
                           const ModelContext                                &context,
                           const std::function<void(const SurfaceFactors &)> &use)
  {
    const SetupTimes::Scope time(SetupStage::surface_correction);

    StiffnessFitReport report;
    BondList          &bonds = particles.bonds();
    const auto law = context.surface_correction ? model.surface_correction_law(particles) : nullptr;
    if (law && !context.stiffness_fit)
      {
        law->uncorrected_coefficients();
        if (use)
          energy_method<dim>(particles,
                             model.field_layout(),
                             law->modulus,
                             law->energy_density,
                             use);
        else
          apply_energy_surface_correction<dim>(particles,
                                               model.field_layout(),
                                               law->modulus,
                                               law->energy_density);
        return report;
      }
    if (law)
      {
        Assert(law->stiffness, dealii::ExcMessage("The model has no stiffness fit."));
        if (bonds.surface_factor.size() != bonds.size())
          bonds.surface_factor.assign(bonds.size(), 1.);
        report = apply_stiffness_fit<dim>(particles, law->stiffness, law->stiffness_modulus);
      }
    if (use)
      {
        if (law)
          use(
            [&bonds](const unsigned int, const std::size_t b) { return bonds.surface_factor[b]; });
        else
          use([](const unsigned int, const std::size_t) { return 1.; });
      }
    return report;
  }

  template <int dim>
  std::function<void(const ParticleVector &, std::vector<double> &)>
  model_energy_density(MaterialModel<dim> &model, ParticleSystem<dim> &particles)
  {
    auto force = std::make_shared<ParticleVector>();
    particles.reinit_vector(*force, model.field_layout().n_components());
    return [&model, &particles, force](const ParticleVector &u, std::vector<double> &density) {
      // The energy of the strain alone: no temperature change (a model re-initialized during a
      // run keeps its set_temperature_change()).
      const ParticleVector *delta_T = model.temperature_change();
      model.set_temperature_change(nullptr);
      model.compute_forces(particles, u, *force, &density, std::numeric_limits<double>::infinity());
      model.set_temperature_change(delta_T);
    };
  }

  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  elastic_surface_correction_law(MaterialModel<dim>          &model,
                                 ParticleSystem<dim>         &particles,
                                 const std::function<void()> &uncorrected_coefficients)
  {
    auto law                      = std::make_unique<SurfaceCorrectionLaw<dim>>();
    law->uncorrected_coefficients = uncorrected_coefficients;
    law->energy_density           = model_energy_density<dim>(model, particles);
    const auto C                  = model.elasticity_tensor();
    for (unsigned int a = 0; a < dim; ++a)
      law->modulus[a] = C[a][a][a][a];
    law->stiffness_modulus = C[0][0][0][0];
    return law;
  }

  template std::unique_ptr<SurfaceCorrectionLaw<2>>
  elastic_surface_correction_law<2>(MaterialModel<2> &,
                                    ParticleSystem<2> &,
                                    const std::function<void()> &);
  template std::unique_ptr<SurfaceCorrectionLaw<3>>
  elastic_surface_correction_law<3>(MaterialModel<3> &,
                                    ParticleSystem<3> &,
                                    const std::function<void()> &);
  template StiffnessFitReport
  apply_surface_correction<2>(MaterialModel<2> &,
                              ParticleSystem<2> &,
                              const ModelContext &,
                              const std::function<void(const SurfaceFactors &)> &);
  template StiffnessFitReport
  apply_surface_correction<3>(MaterialModel<3> &,
                              ParticleSystem<3> &,
                              const ModelContext &,
                              const std::function<void(const SurfaceFactors &)> &);
  template std::function<void(const ParticleVector &, std::vector<double> &)>
  model_energy_density<2>(MaterialModel<2> &, ParticleSystem<2> &);
  template std::function<void(const ParticleVector &, std::vector<double> &)>
  model_energy_density<3>(MaterialModel<3> &, ParticleSystem<3> &);

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
