// ---------------------------------------------------------------------
// PeriDeal: the bond-based peridynamic model of antiplane shear (one scalar per particle).
// ---------------------------------------------------------------------
#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/lattice_fracture.h>
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
    AntiplaneModel<dim>::declare_antiplane_parameters(prm);
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    this->parse_antiplane_parameters(prm, "antiplane bond based");
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
    const std::vector<double> twist_values = this->twist_fields(particles);
    BondBlocks<dim>          &blocks       = kernel->blocks;
    kernel->twist_field.clear();
    blocks.reinit(particles);
    blocks.reinit_field(kernel->w_field, 1);
    blocks.reinit_field(kernel->f_field, 1);
    blocks.reinit_field(kernel->e_field, 1);
    apply_surface_correction<dim>(*this, particles, context);
    set_bond_coefficients(particles, true);
    this->fracture_factor = 1.;
    if (context.lattice_fracture)
      {
        // A bond at the critical slope r0 holds k r0^2 |xi| / 2.
        const double r0       = this->critical_stretch(1.);
        this->fracture_factor = lattice_fracture_factor<dim>(
          particles,
          [&](const unsigned int, const std::size_t b) { return bond_coefficient[b]; },
          [r0](double r) { return 0.5 * r0 * r0 * r; });
      }
    if (twist.active())
      {
        blocks.reinit_field(kernel->twist_field, 2);
        blocks.gather(twist_values.data(), 2, kernel->twist_field);
      }
  }

  template <int dim>
  std::unique_ptr<SurfaceCorrectionLaw<dim>>
  AntiplaneBondBased<dim>::surface_correction_law(ParticleSystem<dim> &particles)
  {
    auto law                      = std::make_unique<SurfaceCorrectionLaw<dim>>();
    law->uncorrected_coefficients = [this, &particles]() {
      set_bond_coefficients(particles, false);
    };
    law->energy_density = model_energy_density<dim>(*this, particles);
    law->modulus.fill(mu);
    return law;
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
    evaluate_bond_kernel<dim>(
      k.blocks,
      particles,
      w,
      1,
      k.w_field,
      k.f_field,
      k.e_field,
      force,
      energy_density,
      [&](auto with_energy) {
        k.template force_loop<decltype(with_energy)::value>(particles.bonds(), critical_slope);
      });
  }

  template <int dim>
  std::string
  AntiplaneBondBased<dim>::summary() const
  {
    std::ostringstream out;
    out << "antiplane bond based: mu = " << mu << " Pa, micromodulus c = " << c << " N/m^6"
        << this->antiplane_summary();
    return out.str();
  }

  template class AntiplaneBondBased<2>;
  template class AntiplaneBondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::AntiplaneBondBased,
                                 "antiplane bond based",
                                 "bond-based antiplane shear (seed 000): one scalar w per "
                                 "particle, the out-of-plane displacement; shear modulus mu.")
