// ---------------------------------------------------------------------
// PeriDeal: interface of peridynamic material models.
// ---------------------------------------------------------------------
#include <perideal/base/setup_times.h>
#include <perideal/pd/material_model.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace perideal
{
  void
  LinearizedModel::reinit(const unsigned int n_components, const unsigned int n_owned)
  {
    components = n_components;
    row_start.assign(1, 0);
    entries.clear();
    weights.clear();
    offsets.clear();
    scale.assign(n_owned, 0.);
  }

  void
  LinearizedModel::add_row(const double                          weight,
                           const dealii::ArrayView<const Entry> &row,
                           const double                          offset)
  {
    entries.insert(entries.end(), row.begin(), row.end());
    row_start.push_back(entries.size());
    weights.push_back(weight);
    offsets.push_back(offset);
  }

  unsigned int
  LinearizedModel::n_components() const
  {
    return components;
  }

  std::size_t
  LinearizedModel::n_rows() const
  {
    return weights.size();
  }

  double
  LinearizedModel::weight(const std::size_t r) const
  {
    return weights[r];
  }

  double
  LinearizedModel::offset(const std::size_t r) const
  {
    return offsets[r];
  }

  const LinearizedModel::Entry *
  LinearizedModel::row_begin(const std::size_t r) const
  {
    return entries.data() + row_start[r];
  }

  const LinearizedModel::Entry *
  LinearizedModel::row_end(const std::size_t r) const
  {
    return entries.data() + row_start[r + 1];
  }

  std::vector<double> &
  LinearizedModel::stiffness_scale()
  {
    return scale;
  }

  const std::vector<double> &
  LinearizedModel::stiffness_scale() const
  {
    return scale;
  }

  template <int dim>
  double
  MaterialModel<dim>::stable_time_step(const ParticleSystem<dim> &particles,
                                       const double               density) const
  {
    const SetupTimes::Scope time(SetupStage::stable_time_step);
    std::vector<double>     bound;
    stiffness_bound(particles, bound);
    const std::vector<double> inertia = inertia_densities(density);
    const std::vector<double> scales  = inertia_scales(particles, density);
    const FieldLayout         layout  = field_layout();
    const std::size_t         nc      = inertia.size();
    double                    dt      = std::numeric_limits<double>::max();
    // Velocity Verlet of a second-order component: sqrt(4 rho / B); forward Euler of a
    // temperature, rho c dT/dt = -K T + q: 2 rho c / B (every eigenvalue of K / (rho c) at most
    // B / (rho c), and forward Euler is stable for dt lambda <= 2); rho (rho c) of the particle
    // (inertia_scales()).
    for (std::size_t k = 0; k < bound.size(); ++k)
      if (bound[k] > 0.)
        {
          const double rho = inertia[k % nc] * (scales.empty() ? 1. : scales[k / nc]);
          dt               = std::min(dt,
                        layout.kind(k % nc) == ComponentKind::temperature ?
                                        2. * rho / bound[k] :
                                        std::sqrt(4. * rho / bound[k]));
        }
    return dealii::Utilities::MPI::min(dt, particles.get_communicator());
  }

  template <int dim>
  double
  MaterialModel<dim>::released_energy(ParticleSystem<dim> &particles, const ParticleVector &u)
  {
    BondList &bonds = particles.bonds();
    if (dealii::Utilities::MPI::max(bonds.newly_broken.empty() ? 0u : 1u,
                                    particles.get_communicator()) == 0)
      return 0.;
    ParticleVector      force;
    std::vector<double> density;
    particles.reinit_vector(force, field_layout().n_components());
    const auto energy = [&](const std::uint8_t state) {
      bonds.set_state_of(bonds.newly_broken, state);
      compute_forces(particles, u, force, &density, std::numeric_limits<double>::infinity());
      double sum = 0.;
      for (unsigned int i = 0; i < particles.n_owned(); ++i)
        sum += density[i] * particles.volumes()[i];
      return sum;
    };
    // The broken state last: what a model keeps of an evaluation (the LPS dilatation) is then
    // that of the bonds as they are.
    const double with_bonds = energy(1);
    const double without    = energy(0);
    bonds.newly_broken.clear();
    return with_bonds - without;
  }

  template <int dim>
  bool
  MaterialModel<dim>::damage_changed() const
  {
    return false;
  }

  template <int dim>
  unsigned int
  MaterialModel<dim>::n_bond_history_values() const
  {
    return 0;
  }

  template <int dim>
  std::vector<double>
  MaterialModel<dim>::bond_history(const ParticleSystem<dim> &) const
  {
    return {};
  }

  template <int dim>
  void
  MaterialModel<dim>::set_bond_history(const ParticleSystem<dim> &,
                                       const std::vector<double> &values)
  {
    AssertThrow(values.empty(), dealii::ExcMessage("This material model keeps no bond histories."));
  }

  template <int dim>
  std::vector<double>
  MaterialModel<dim>::inertia_densities(const double density) const
  {
    const FieldLayout layout = field_layout();
    AssertThrow(layout.n_components(ComponentKind::rotation) == 0,
                dealii::ExcMessage("The material model has rotations (" + layout.description() +
                                   ") but states no rotational inertia: it must override "
                                   "MaterialModel::inertia_densities()."));
    return std::vector<double>(layout.n_components(), density);
  }

  template <int dim>
  std::vector<double>
  MaterialModel<dim>::inertia_ratios(const double density) const
  {
    const double        rho    = density > 0. ? density : 1.;
    std::vector<double> ratios = inertia_densities(rho);
    for (double &ratio : ratios)
      ratio /= rho;
    return ratios;
  }

  template <int dim>
  std::vector<double>
  MaterialModel<dim>::inertia_scales(const ParticleSystem<dim> &, const double) const
  {
    return {};
  }

  template <int dim>
  dealii::SymmetricTensor<4, dim>
  MaterialModel<dim>::elasticity_tensor() const
  {
    AssertThrow(false,
                dealii::ExcMessage("This material model has no elasticity tensor: its unknowns "
                                   "are " +
                                   field_layout().description() + ", not a displacement."));
    return {};
  }

  template <int dim>
  void
  MaterialModel<dim>::resolve_regions(const RegionCollection<dim> &)
  {}

  template <int dim>
  bool
  MaterialModel<dim>::has_prestrain() const
  {
    return false;
  }

  template <int dim>
  const Torsion *
  MaterialModel<dim>::torsion() const
  {
    return nullptr;
  }

  template <int dim>
  std::string
  MaterialModel<dim>::nonuniform_constants() const
  {
    return {};
  }

  template <int dim>
  std::vector<double>
  MaterialModel<dim>::breaking_factors(const ParticleSystem<dim> &particles) const
  {
    return std::vector<double>(particles.bonds().size(), 1.);
  }

  template <int dim>
  bool
  MaterialModel<dim>::bond_breaks_at_limit(const std::size_t) const
  {
    return true;
  }

  template <int dim>
  void
  MaterialModel<dim>::limit_reached(ParticleSystem<dim> &particles,
                                    const ParticleVector &,
                                    const std::size_t b)
  {
    particles.bonds().break_bond(static_cast<unsigned int>(b), true);
  }

  template <int dim>
  std::vector<std::string>
  MaterialModel<dim>::integral_names() const
  {
    return {};
  }

  template <int dim>
  std::vector<double>
  MaterialModel<dim>::section_integrals(const ParticleSystem<dim> &,
                                        const ParticleVector &,
                                        const double) const
  {
    return {};
  }

  template <int dim>
  std::vector<DerivedParticleField>
  MaterialModel<dim>::derived_fields(const ParticleSystem<dim> &, const ParticleVector &) const
  {
    return {};
  }

  template <int dim>
  dealii::SymmetricTensor<2, dim>
  MaterialModel<dim>::thermal_expansion() const
  {
    return dealii::SymmetricTensor<2, dim>();
  }

  template <int dim>
  void
  MaterialModel<dim>::set_temperature_change(const ParticleVector *temperature_change)
  {
    Assert(temperature_change == nullptr || capabilities().thermal_strain,
           dealii::ExcMessage("This model has no thermal strain."));
    delta_T = temperature_change;
  }

  template <int dim>
  const ParticleVector *
  MaterialModel<dim>::temperature_change() const
  {
    return delta_T;
  }

  template <int dim>
  void
  MaterialModel<dim>::thermoelastic_measure(ParticleSystem<dim> &,
                                            const ParticleVector &,
                                            std::vector<double> &)
  {
    AssertThrow(false,
                dealii::ExcMessage("This material model gives no thermoelastic measure (its "
                                   "capabilities() do not say thermoelastic_heating)."));
  }

  template <int dim>
  ModelCapabilities
  MaterialModel<dim>::capabilities() const
  {
    return {};
  }

  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  MaterialModel<dim>::surface_correction_law(ParticleSystem<dim> &)
  {
    return nullptr;
  }

  template <int dim>
  unsigned int
  MaterialModel<dim>::force_reach() const
  {
    return 1;
  }

  template <int dim>
  void
  MaterialModel<dim>::linearize(const ParticleSystem<dim> &, LinearizedModel &) const
  {
    AssertThrow(false,
                dealii::ExcMessage("This material model provides no linearization; the static "
                                   "solver (<Solver/Type> = static) cannot use it. Choose "
                                   "<Solver/Type> = adaptive dynamic relaxation or explicit."));
  }

  template <int dim>
  void
  bond_pair_coefficients(const ParticleSystem<dim> &particles,
                         const double               micromodulus,
                         const bool                 with_surface_factor,
                         std::vector<double>       &coefficient)
  {
    const BondList &bonds = particles.bonds();
    coefficient.resize(bonds.size());
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        coefficient[b] = bond_pair_coefficient(particles, micromodulus, with_surface_factor, i, b);
  }

  template <int dim>
  void
  bond_pair_stiffness_bound(const ParticleSystem<dim> &particles,
                            const std::vector<double> &coefficient,
                            const unsigned int         n_components,
                            std::vector<double>       &per_particle)
  {
    bond_pair_stiffness_bound<dim>(
      particles,
      [&coefficient](const unsigned int, const std::size_t b) { return coefficient[b]; },
      n_components,
      per_particle);
  }

  template <int dim>
  void
  bond_pair_stiffness_bound(
    const ParticleSystem<dim>                                          &particles,
    const std::function<double(const unsigned int, const std::size_t)> &coefficient,
    const unsigned int                                                  n_components,
    std::vector<double>                                                &per_particle)
  {
    const BondList     &bonds   = particles.bonds();
    const auto         &volume  = particles.volumes();
    const unsigned int  n_owned = particles.n_owned();
    std::vector<double> bound(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          if (!bonds.intact[b])
            continue;
          const unsigned int j = bonds.neighbor[b];
          const double       k = 2. * coefficient(i, b) / bonds.length[b];
          bound[i] += k / volume[i];
          if (j < n_owned)
            bound[j] += k / volume[j];
        }
    per_particle.resize(std::size_t(n_owned) * n_components);
    for (std::size_t k = 0; k < per_particle.size(); ++k)
      per_particle[k] = bound[k / n_components];
  }

  template <int dim>
  std::string
  material_models_with(bool ModelCapabilities::*capability)
  {
    std::string       names;
    const std::string all = PluginRegistry<MaterialModel<dim>>::pattern_string();
    for (std::size_t start = 0; start < all.size();)
      {
        const std::size_t end  = std::min(all.find('|', start), all.size());
        const std::string name = all.substr(start, end - start);
        if (PluginRegistry<MaterialModel<dim>>::create(name, "Material/Model")->capabilities().*
            capability)
          names += (names.empty() ? "" : ", ") + name;
        start = end + 1;
      }
    return names;
  }

  template std::string
  material_models_with<2>(bool ModelCapabilities::*);
  template std::string
  material_models_with<3>(bool ModelCapabilities::*);
  template void
  bond_pair_coefficients<2>(const ParticleSystem<2> &, double, bool, std::vector<double> &);
  template void
  bond_pair_coefficients<3>(const ParticleSystem<3> &, double, bool, std::vector<double> &);
  template void
  bond_pair_stiffness_bound<2>(const ParticleSystem<2> &,
                               const std::vector<double> &,
                               unsigned int,
                               std::vector<double> &);
  template void
  bond_pair_stiffness_bound<3>(const ParticleSystem<3> &,
                               const std::vector<double> &,
                               unsigned int,
                               std::vector<double> &);
  template void
  bond_pair_stiffness_bound<2>(const ParticleSystem<2> &,
                               const std::function<double(const unsigned int, const std::size_t)> &,
                               unsigned int,
                               std::vector<double> &);
  template void
  bond_pair_stiffness_bound<3>(const ParticleSystem<3> &,
                               const std::function<double(const unsigned int, const std::size_t)> &,
                               unsigned int,
                               std::vector<double> &);

  template class MaterialModel<2>;
  template class MaterialModel<3>;
} // namespace perideal
