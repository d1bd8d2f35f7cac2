// ---------------------------------------------------------------------
// PeriDeal: the bond-based peridynamic model of antiplane shear (one scalar per particle).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/bond_loop.h>
#include <perideal/pd/surface_correction.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief The antiplane pair law of for_each_bond_block(): slope r = (w_b - w_a)/|xi|, pair
     * force k r on the particle side (-k r on the neighbour) and, if @p with_energy, the pair
     * energy k r^2 |xi| / 4 at both ends, with k = c G beta V_i V_j per lane; a bond breaks
     * where |r| exceeds the critical slope (the law does not depend on the bond's orientation).
     */
    template <int dim, bool with_energy>
    struct AntiplanePairLaw
    {
      static constexpr unsigned int n_outputs    = 1 + (with_energy ? 1 : 0);
      static constexpr bool         breaks_bonds = true;
      /// k per lane.
      const double *coefficient;

      /// Nothing read per group on the particle side.
      struct Side
      {};

      Side
      side(const unsigned int) const
      {
        return {};
      }

      /// The slope and its magnitude (what breaks a bond).
      struct Slope
      {
        bond_simd::Vector value, stretch;
      };

      Slope
      strain(const typename BondBlocks<dim>::BondClass &bond,
             const bond_simd::Vector                   *w_a,
             const bond_simd::Vector                   *w_b) const
      {
        const bond_simd::Vector r = (w_b[0] - w_a[0]) * bond.inverse_length;
        return {r, std::experimental::abs(r)};
      }

      void
      pair(const typename BondBlocks<dim>::BondClass &bond,
           const Slope                               &r,
           const Side &,
           const BondLanes   &lanes,
           bond_simd::Vector *to_a,
           bond_simd::Vector *to_b) const
      {
        using namespace bond_simd;
        const Vector k(coefficient + lanes.first_lane, stdx::element_aligned);
        Vector       t               = 0.;
        stdx::where(lanes.active, t) = k * r.value;
        to_a[0]                      = t;
        to_b[0]                      = -t;
        if constexpr (with_energy)
          {
            Vector e                     = 0.;
            stdx::where(lanes.active, e) = (0.25 * bond.length) * k * r.value * r.value;
            to_a[1]                      = e;
            to_b[1]                      = e;
          }
      }
    };
  } // namespace

  template <int dim>
  struct AntiplaneBondBased<dim>::Kernel
  {
    /// The bonds in SIMD blocks, and bond_coefficient per lane.
    BondBlocks<dim>                 blocks;
    typename BondBlocks<dim>::Array lane_coefficient;
    /// Kernel-order work fields: w, force, energy density.
    typename BondBlocks<dim>::Array w_field, f_field, e_field;

    /**
     * @brief The force loop of AntiplanePairLaw; the energy density is accumulated only if
     * @p with_energy.
     */
    template <bool with_energy>
    void
    force_loop(BondList &bonds, const double critical_slope)
    {
      std::array<double *, AntiplanePairLaw<dim, with_energy>::n_outputs> out;
      out[0] = blocks.component(f_field, 0);
      if constexpr (with_energy)
        out[1] = blocks.component(e_field, 0);
      for_each_bond_block<1>(blocks,
                             {{blocks.component(w_field, 0)}},
                             out,
                             AntiplanePairLaw<dim, with_energy>{lane_coefficient.data()},
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
    prm.declare_entry("Shear modulus",
                      "0",
                      Patterns::Double(0.),
                      "Shear modulus mu [Pa] of antiplane shear (the field w is the "
                      "out-of-plane displacement, its stresses tau_xz, tau_yz = mu grad w).");
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    mu = prm.get_double("Shear modulus");
    ParameterUtilities::require_positive(mu, "Material/antiplane bond based/Shear modulus");
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
    context            = model_context;
    const double delta = context.horizon, pi = numbers::PI;
    c                       = (dim == 2) ? 6. * mu / (pi * context.thickness * std::pow(delta, 3)) :
                                           6. * mu / (pi * std::pow(delta, 4));
    BondBlocks<dim> &blocks = kernel->blocks;
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
  }

  template <int dim>
  void
  AntiplaneBondBased<dim>::set_bond_coefficients(const ParticleSystem<dim> &particles,
                                                 const bool                 with_surface_factor)
  {
    bond_pair_coefficients(particles, c, with_surface_factor, bond_coefficient);
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
  double
  AntiplaneBondBased<dim>::critical_stretch(const double fracture_energy) const
  {
    const double G = fracture_energy, delta = context.horizon, pi = numbers::PI;
    return (dim == 2) ? std::sqrt(2. * pi * G / (3. * mu * delta)) :
                        std::sqrt(5. * G / (3. * mu * delta));
  }

  template <int dim>
  std::string
  AntiplaneBondBased<dim>::summary() const
  {
    std::ostringstream out;
    out << "antiplane bond based: mu = " << mu << " Pa, micromodulus c = " << c << " N/m^6";
    return out.str();
  }

  template class AntiplaneBondBased<2>;
  template class AntiplaneBondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::AntiplaneBondBased,
                                 "antiplane bond based",
                                 "bond-based antiplane shear (seed 000): one scalar w per "
                                 "particle, the out-of-plane displacement; shear modulus mu.")
