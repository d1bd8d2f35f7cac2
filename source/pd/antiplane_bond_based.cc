// ---------------------------------------------------------------------
// PeriDeal: the bond-based peridynamic model of antiplane shear (one scalar per particle).
// ---------------------------------------------------------------------
#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/antiplane_shear.h>
#include <perideal/pd/antiplane_torsion.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/surface_correction.h>

#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  struct AntiplaneBondBased<dim>::Kernel
  {
    /// The bonds in SIMD blocks, and bond_coefficient per lane.
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_coefficient;
    /// Kernel-order work fields: w, force, energy density.
    typename BondBlocks<dim>::Array w_field, f_field, e_field;
    /// Torsion: the fixed fields p = psi (x - x0), q = psi (y - y0) of TwistedSlopePairLaw
    /// (empty without a twist).
    typename BondBlocks<dim>::Array twist_field;

    /**
     * @brief The force loop of SlopePairLaw (the bond-based antiplane pair law), or of
     * TwistedSlopePairLaw if twist_field is set; the energy density is accumulated only if
     * @p with_energy.
     */
    template <bool with_energy>
    void
    force_loop(BondList &bonds, const double critical_slope)
    {
      std::array<double *, SlopePairLaw<dim, with_energy>::n_outputs> out;
      out[0] = blocks.component(f_field, 0);
      if constexpr (with_energy)
        out[1] = blocks.component(e_field, 0);
      const SlopePairLaw<dim, with_energy> law{lane_coefficient.data()};
      if (twist_field.empty())
        for_each_bond_block<1>(blocks,
                               {{blocks.component(w_field, 0)}},
                               out,
                               law,
                               bonds,
                               critical_slope);
      else
        for_each_bond_block<3>(blocks,
                               {{blocks.component(w_field, 0),
                                 blocks.component(twist_field, 0),
                                 blocks.component(twist_field, 1)}},
                               out,
                               TwistedSlopePairLaw<dim, with_energy>{law},
                               bonds,
                               critical_slope);
    }
  };

  template <int dim>
  AntiplaneBondBased<dim>::AntiplaneBondBased()
    : kernel(std::make_unique<Kernel>())
  {}

  template <int dim>
  AntiplaneBondBased<dim>::~AntiplaneBondBased() = default;

  template <int dim>
  void
  AntiplaneBondBased<dim>::declare_parameters(ParameterHandler &prm)
  {
    AntiplaneShear::declare_shear_modulus(prm);
    RegionModuli<dim>::declare_parameters(prm, "Shear moduli by region", "Pa");
    Torsion::declare_parameters(prm);
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    mu = AntiplaneShear::parse_shear_modulus(prm, "antiplane bond based");
    twist.parse_parameters(prm, "Material/antiplane bond based", dim);
    region_moduli.parse_parameters(prm, "Shear moduli by region", "Material/antiplane bond based");
    AssertThrow(!(twist.active() && !region_moduli.empty()),
                ExcMessage("The parameter <Material/antiplane bond based/Shear moduli by region> "
                           "is set together with a twist (<Twist per unit length>): torsion "
                           "takes one shear modulus; accepted: an empty list with a twist."));
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::resolve_regions(const RegionCollection<dim> &regions)
  {
    region_moduli.resolve(regions);
  }

  template <int dim>
  FieldLayout
  AntiplaneBondBased<dim>::field_layout() const
  {
    return FieldLayout::scalar("w");
  }

  template <int dim>
  double
  AntiplaneBondBased<dim>::shear_modulus() const
  {
    return mu;
  }

  template <int dim>
  double
  AntiplaneBondBased<dim>::micromodulus() const
  {
    return c;
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::initialize(ParticleSystem<dim> &particles,
                                      const ModelContext  &model_context)
  {
    context = model_context;
    c       = AntiplaneShear::micromodulus(dim, mu, context.horizon, context.thickness);
    if (twist.active())
      AntiplaneTorsion::check_section(particles, twist);
    BondBlocks<dim> &blocks = kernel->blocks;
    kernel->twist_field.clear();
    blocks.reinit(particles);
    blocks.reinit_field(kernel->w_field, 1);
    blocks.reinit_field(kernel->f_field, 1);
    blocks.reinit_field(kernel->e_field, 1);
    if (context.surface_correction)
      {
        ParticleVector force;
        particles.reinit_vector(force, 1);
        set_bond_coefficients(particles, false);
        const auto energy = [&](const ParticleVector &w, std::vector<double> &density) {
          compute_forces(particles, w, force, &density, std::numeric_limits<double>::infinity());
        };
        std::array<double, dim> modulus;
        modulus.fill(mu);
        apply_energy_surface_correction<dim>(particles, field_layout(), modulus, energy);
      }
    set_bond_coefficients(particles, true);
    if (twist.active())
      {
        blocks.reinit_field(kernel->twist_field, 2);
        blocks.gather(AntiplaneTorsion::twist_fields(particles, twist).data(),
                      2,
                      kernel->twist_field);
      }
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::set_bond_coefficients(const ParticleSystem<dim> &particles,
                                                 const bool                 with_surface_factor)
  {
    bond_pair_coefficients(particles, c, with_surface_factor, bond_coefficient);
    if (with_surface_factor)
      region_moduli.scale_bonds(particles, mu, bond_coefficient);
    kernel->blocks.to_lanes(bond_coefficient, kernel->lane_coefficient);
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                          const ParticleVector &w,
                                          ParticleVector       &force,
                                          std::vector<double>  *energy_density,
                                          const double          critical_slope)
  {
    Kernel &k = *kernel;
    k.blocks.sync_state(particles.bonds());
    k.blocks.gather(w.begin(), 1, k.w_field);
    std::fill(k.f_field.begin(), k.f_field.end(), 0.);
    const double *volume = particles.volumes().data();
    if (energy_density != nullptr)
      {
        std::fill(k.e_field.begin(), k.e_field.end(), 0.);
        k.template force_loop<true>(particles.bonds(), critical_slope);
        energy_density->resize(particles.n_owned());
        k.blocks.scatter_owned(k.e_field, 1, volume, energy_density->data());
      }
    else
      k.template force_loop<false>(particles.bonds(), critical_slope);
    k.blocks.scatter_owned(k.f_field, 1, volume, force.begin());
  }

  template <int dim>
  bool
  AntiplaneBondBased<dim>::has_prestrain() const
  {
    return twist.active();
  }

  template <int dim>
  std::vector<std::string>
  AntiplaneBondBased<dim>::integral_names() const
  {
    return twist.active() ? AntiplaneTorsion::integral_names() : std::vector<std::string>();
  }

  template <int dim>
  std::vector<double>
  AntiplaneBondBased<dim>::section_integrals(const ParticleSystem<dim> &particles,
                                             const ParticleVector      &u,
                                             const double               strain_energy) const
  {
    if (!twist.active())
      return {};
    return AntiplaneTorsion::section_integrals(particles, u, twist, mu, strain_energy);
  }

  template <int dim>
  std::vector<DerivedParticleField>
  AntiplaneBondBased<dim>::derived_fields(const ParticleSystem<dim> &particles,
                                          const ParticleVector      &u) const
  {
    if (!twist.active())
      return {};
    std::vector<Tensor<1, dim>> tau;
    AntiplaneTorsion::shear_stresses(particles, u, twist, mu, tau);
    DerivedParticleField field{"shear_stress", 2, {}};
    for (const auto &t : tau)
      field.values.insert(field.values.end(), {t[0], t[1]});
    return {field};
  }

  template <int dim>
  double
  AntiplaneBondBased<dim>::critical_stretch(const double fracture_energy) const
  {
    return AntiplaneShear::critical_slope(dim, fracture_energy, mu, context.horizon);
  }

  template <int dim>
  std::string
  AntiplaneBondBased<dim>::summary() const
  {
    std::ostringstream out;
    out << "antiplane bond based: mu = " << mu << " Pa, micromodulus c = " << c << " N/m^6";
    if (!region_moduli.empty())
      out << "; by region: " << region_moduli.summary();
    if (twist.active())
      out << "; torsion: twist " << twist.twist() << " rad/m about (" << twist.axis() << ")";
    return out.str();
  }

  template class AntiplaneBondBased<2>;
  template class AntiplaneBondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::AntiplaneBondBased,
                                 "antiplane bond based",
                                 "bond-based antiplane shear (seed 000): one scalar w per "
                                 "particle, the out-of-plane displacement; shear modulus mu.")
