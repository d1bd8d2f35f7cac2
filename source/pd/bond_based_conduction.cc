// ---------------------------------------------------------------------
// PeriDeal: bond-based peridynamic heat conduction (one temperature per particle).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/bond_based_conduction.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/surface_correction.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  struct BondBasedConduction<dim>::Kernel
  {
    /// The bonds in SIMD blocks, and bond_coefficient per lane.
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_coefficient;
    /// Kernel-order work fields: T, heat flow density, functional.
    typename BondBlocks<dim>::Array t_field, q_field, e_field;

    /// The loop of ConductionPairLaw; the functional is accumulated only if @p with_energy.
    template <bool with_energy>
    void
    loop(BondList &bonds)
    {
      std::array<double *, ConductionPairLaw<dim, with_energy>::n_outputs> out;
      out[0] = blocks.component(q_field, 0);
      if constexpr (with_energy)
        out[1] = blocks.component(e_field, 0);
      for_each_bond_block<1>(blocks,
                             {{blocks.component(t_field, 0)}},
                             out,
                             ConductionPairLaw<dim, with_energy>{{lane_coefficient.data()}},
                             bonds,
                             std::numeric_limits<double>::infinity());
    }
  };

  template <int dim>
  BondBasedConduction<dim>::BondBasedConduction()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  BondBasedConduction<dim>::~BondBasedConduction() = default;

  template <int dim>
  void
  BondBasedConduction<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Conductivity",
                      "0",
                      Patterns::Double(),
                      "The thermal conductivity k [W/m/K]; > 0.");
    prm.declare_entry("Specific heat",
                      "0",
                      Patterns::Double(),
                      "The specific heat c [J/kg/K] (the heat capacity per volume is rho c "
                      "with <Material/Density>); > 0.");
    RegionModuli<dim>::declare_parameters(prm, "Conductivities by region", "W/m/K");
    RegionModuli<dim>::declare_parameters(prm, "Densities by region", "kg/m^3", false);
    RegionModuli<dim>::declare_parameters(prm, "Specific heats by region", "J/kg/K", false);
  }

  template <int dim>
  void
  BondBasedConduction<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string path = "Material/bond based conduction/";
    conductivity           = prm.get_double("Conductivity");
    specific_heat          = prm.get_double("Specific heat");
    ParameterUtilities::require_positive(conductivity, path + "Conductivity");
    ParameterUtilities::require_positive(specific_heat, path + "Specific heat");
    region_conductivities.parse_parameters(prm,
                                           "Conductivities by region",
                                           "Material/bond based conduction");
    region_densities.parse_parameters(prm, "Densities by region", "Material/bond based conduction");
    region_specific_heats.parse_parameters(prm,
                                           "Specific heats by region",
                                           "Material/bond based conduction");
  }

  template <int dim>
  void
  BondBasedConduction<dim>::resolve_regions(const RegionCollection<dim> &regions)
  {
    region_conductivities.resolve(regions);
    region_densities.resolve(regions);
    region_specific_heats.resolve(regions);
  }

  template <int dim>
  FieldLayout
  BondBasedConduction<dim>::field_layout() const
  {
    return FieldLayout::temperature();
  }

  template <int dim>
  double
  BondBasedConduction<dim>::micro_conductivity() const
  {
    return kappa;
  }

  template <int dim>
  void
  BondBasedConduction<dim>::initialize(ParticleSystem<dim> &particles,
                                       const ModelContext  &model_context)
  {
    context = model_context;
    // doc/theory/heat_conduction.md: 1/4 int kappa (g . xi)^2 / |xi| dV = k |g|^2 / 2.
    const double pi = numbers::PI, delta = context.horizon;
    kappa = dim == 2 ? 6. * conductivity / (pi * context.thickness * std::pow(delta, 3)) :
                       6. * conductivity / (pi * std::pow(delta, 4));
    BondBlocks<dim> &blocks = kernel->blocks;
    blocks.reinit(particles);
    blocks.reinit_field(kernel->t_field, 1);
    blocks.reinit_field(kernel->q_field, 1);
    blocks.reinit_field(kernel->e_field, 1);
    if (context.surface_correction)
      {
        ParticleVector heat;
        particles.reinit_vector(heat, 1);
        set_bond_coefficients(particles, false);
        const auto functional = [&](const ParticleVector &t, std::vector<double> &density) {
          compute_forces(particles, t, heat, &density, std::numeric_limits<double>::infinity());
        };
        std::array<double, dim> modulus;
        modulus.fill(conductivity);
        apply_energy_surface_correction<dim>(particles, field_layout(), modulus, functional);
      }
    set_bond_coefficients(particles, true);
  }

  template <int dim>
  void
  BondBasedConduction<dim>::set_bond_coefficients(const ParticleSystem<dim> &particles,
                                                  const bool                 with_surface_factor)
  {
    bond_pair_coefficients(particles, kappa, with_surface_factor, bond_coefficient);
    if (with_surface_factor)
      region_conductivities.scale_bonds(particles, conductivity, bond_coefficient);
    kernel->blocks.to_lanes(bond_coefficient, kernel->lane_coefficient);
  }

  template <int dim>
  void
  BondBasedConduction<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                           const ParticleVector &temperature,
                                           ParticleVector       &heat,
                                           std::vector<double>  *functional,
                                           const double /*critical_stretch*/)
  {
    Kernel &k = *kernel;
    evaluate_bond_kernel<dim>(k.blocks,
                              particles,
                              temperature,
                              1,
                              k.t_field,
                              k.q_field,
                              k.e_field,
                              heat,
                              functional,
                              [&](auto with_energy) {
                                k.template loop<decltype(with_energy)::value>(particles.bonds());
                              });
  }

  template <int dim>
  std::vector<double>
  BondBasedConduction<dim>::inertia_densities(const double density) const
  {
    return {density * specific_heat};
  }

  template <int dim>
  std::vector<double>
  BondBasedConduction<dim>::inertia_scales(const ParticleSystem<dim> &particles,
                                           const double               density) const
  {
    if (region_densities.empty() && region_specific_heats.empty())
      return {};
    // A static run (no density) has no capacities: the ratio of the specific heats alone.
    const double        rho = density > 0. ? density : 1.;
    std::vector<double> scales(particles.n_owned());
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      {
        const auto &x = particles.positions()[i];
        scales[i]     = region_densities.at(x, rho) * region_specific_heats.at(x, specific_heat) /
                    (rho * specific_heat);
      }
    return scales;
  }

  template <int dim>
  std::vector<DerivedParticleField>
  BondBasedConduction<dim>::derived_fields(const ParticleSystem<dim> &particles,
                                           const ParticleVector      &temperature) const
  {
    const BondList      &bonds   = particles.bonds();
    const auto          &x       = particles.positions();
    const auto          &volume  = particles.volumes();
    const unsigned int   n_owned = particles.n_owned();
    DerivedParticleField flux{"heat_flux",
                              dim,
                              std::vector<double>(std::size_t(n_owned) * dim, 0.)};
    // A bond adds the same -1/2 k_b (T_j - T_i) xi / |xi| to both ends (both change sign); a
    // bond to a ghost is visited on both ranks, each adding to its own end.
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            const unsigned int j      = bonds.neighbor[b];
            const double       factor = -0.5 * bond_coefficient[b] *
                                  (temperature.local_element(j) - temperature.local_element(i)) /
                                  bonds.length[b];
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double contribution = factor * (x[j][d] - x[i][d]);
                flux.values[i * dim + d] += contribution / volume[i];
                if (j < n_owned)
                  flux.values[j * dim + d] += contribution / volume[j];
              }
          }
    return {flux};
  }

  template <int dim>
  double
  BondBasedConduction<dim>::critical_stretch(const double) const
  {
    return std::numeric_limits<double>::infinity();
  }

  template <int dim>
  std::string
  BondBasedConduction<dim>::summary() const
  {
    std::ostringstream out;
    out << "bond based conduction: k = " << conductivity << " W/(m K), c = " << specific_heat
        << " J/(kg K), micro-conductivity kappa = " << kappa
        << (dim == 2 ? " W/(m^4 K) / h" : " W/(m^5 K)");
    if (!region_conductivities.empty())
      out << "; conductivities by region: " << region_conductivities.summary();
    if (!region_densities.empty())
      out << "; densities by region: " << region_densities.summary();
    if (!region_specific_heats.empty())
      out << "; specific heats by region: " << region_specific_heats.summary();
    return out.str();
  }

  template class BondBasedConduction<2>;
  template class BondBasedConduction<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::BondBasedConduction,
                                 "bond based conduction",
                                 "bond-based heat conduction (Bobaru & Duangpanya 2010): one "
                                 "temperature T per particle; conductivity k, specific heat c.")
