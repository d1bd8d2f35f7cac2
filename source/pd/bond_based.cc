// ---------------------------------------------------------------------
// PeriDeal: the prototype microelastic brittle (PMB) bond-based model.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/surface_correction.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  BondBased<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus",
                      "0",
                      Patterns::Double(0.),
                      "Young's modulus E [Pa]. The model implies nu = 1/4 in 3D and plane strain, "
                      "nu = 1/3 in plane stress.");
  }

  template <int dim>
  void
  BondBased<dim>::parse_parameters(ParameterHandler &prm)
  {
    youngs_modulus = prm.get_double("Young's modulus");
    ParameterUtilities::require_positive(youngs_modulus, "Material/bond based/Young's modulus");
  }

  template <int dim>
  double
  BondBased<dim>::implied_poisson_ratio() const
  {
    return context.planar == PlanarAssumption::plane_stress ? 1. / 3. : 0.25;
  }

  template <int dim>
  double
  BondBased<dim>::micromodulus() const
  {
    return c;
  }

  template <int dim>
  void
  BondBased<dim>::initialize(ParticleSystem<dim> &particles, const ModelContext &model_context)
  {
    context            = model_context;
    const double delta = context.horizon, E = youngs_modulus, pi = numbers::PI;
    switch (context.planar)
      {
        case PlanarAssumption::three_dimensional:
          c = 12. * E / (pi * std::pow(delta, 4));
          break;
        case PlanarAssumption::plane_stress:
          c = 9. * E / (pi * context.thickness * std::pow(delta, 3));
          break;
        case PlanarAssumption::plane_strain:
          c = 48. * E / (5. * pi * context.thickness * std::pow(delta, 3));
          break;
      }
    BondList &bonds = particles.bonds();
    blocks.reinit(particles);
    blocks.reinit_field(u_field, dim);
    blocks.reinit_field(f_field, dim);
    blocks.reinit_field(w_field, 1);
    if (context.surface_correction)
      {
        const auto energy = [&](const ParticleVector &u, std::vector<double> &w) {
          ParticleVector force;
          particles.reinit_vector(force, dim);
          set_bond_coefficients(particles, false);
          // Pre-cracked bonds take part: the correction describes the uncracked geometry.
          const std::vector<std::uint8_t> intact = bonds.intact;
          std::fill(bonds.intact.begin(), bonds.intact.end(), 1);
          ++bonds.revision;
          compute_forces(particles, u, force, &w, std::numeric_limits<double>::infinity());
          bonds.intact = intact;
          ++bonds.revision;
        };
        apply_energy_surface_correction<dim>(particles, elasticity_tensor(), energy);
      }
    set_bond_coefficients(particles, true);
  }

  template <int dim>
  void
  BondBased<dim>::set_bond_coefficients(const ParticleSystem<dim> &particles,
                                        const bool                 with_surface_factor)
  {
    const BondList &bonds  = particles.bonds();
    const auto     &volume = particles.volumes();
    bond_coefficient.resize(bonds.size());
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        bond_coefficient[b] =
          c * (with_surface_factor ? bonds.surface_factor[b] * bonds.energy_weight[b] : 1.) *
          bonds.volume_factor[b] * volume[i] * volume[bonds.neighbor[b]];
    blocks.to_lanes(bond_coefficient, lane_coefficient);
  }

  template <int dim>
  void
  BondBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                 const ParticleVector &u,
                                 ParticleVector       &force,
                                 std::vector<double>  *energy_density,
                                 const double          critical_stretch)
  {
    blocks.sync_state(particles.bonds());
    blocks.gather(u.begin(), dim, u_field);
    std::fill(f_field.begin(), f_field.end(), 0.);
    const double *volume = particles.volumes().data();
    if (energy_density != nullptr)
      {
        std::fill(w_field.begin(), w_field.end(), 0.);
        force_loop<true>(particles.bonds(), critical_stretch);
        energy_density->resize(particles.n_owned());
        blocks.scatter_owned(w_field, 1, volume, energy_density->data());
      }
    else
      force_loop<false>(particles.bonds(), critical_stretch);
    blocks.scatter_owned(f_field, dim, volume, force.begin());
  }

  template <int dim>
  template <bool with_energy>
  void
  BondBased<dim>::force_loop(BondList &bonds, const double critical_stretch)
  {
    using namespace bond_simd;
    const auto         &groups      = blocks.groups();
    const auto         &block_list  = blocks.blocks();
    const auto         &classes     = blocks.classes();
    const double       *coefficient = lane_coefficient.data();
    const std::uint8_t *state       = blocks.state();
    const double       *u[dim];
    double             *f[dim];
    for (unsigned int d = 0; d < dim; ++d)
      {
        u[d] = blocks.component(u_field, d);
        f[d] = blocks.component(f_field, d);
      }
    double *w = blocks.component(w_field, 0);

    // Pair forces F = k s (xi + eta)/|xi + eta| and pair energies k s^2 |xi| / 4 with
    // k = c G beta V_i V_j, summed per particle (divided by V_i by the caller). Lane l of a
    // block: particle a + l, neighbour a + offset + l, lattice vector xi of the block's class.
    for (std::size_t g = 0; g + 1 < groups.size(); ++g)
      {
        const unsigned int a = groups[g].first_particle;
        Vector             u_a[dim], f_a[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            u_a[d].copy_from(u[d] + a, stdx::element_aligned);
            f_a[d] = 0.;
          }
        Vector w_a = 0.;
        for (unsigned int q = groups[g].first_block; q < groups[g + 1].first_block; ++q)
          {
            const auto       &block = block_list[q];
            const auto       &bond  = classes[block.bond_class];
            const std::size_t b = std::size_t(std::ptrdiff_t(a) + block.offset), lane = q * width;
            Vector            r[dim], length2                                         = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const Vector u_b(u[d] + b, stdx::element_aligned);
                r[d] = bond.xi[d] + (u_b - u_a[d]);
                length2 += r[d] * r[d];
              }
            // rho = |xi| / |xi + eta|, stretch s = |xi + eta| / |xi| - 1.
            const Vector ratio2 = length2 * (bond.inverse_length * bond.inverse_length);
            const Vector rho    = inverse_sqrt(ratio2);
            const Vector s      = ratio2 * rho - 1.;
            Mask         active = intact_lanes(state + lane);
            if (stdx::any_of(active && (s > critical_stretch)))
              {
                blocks.break_lanes(s, critical_stretch, q, bonds);
                active = intact_lanes(state + lane);
              }
            const Vector k(coefficient + lane, stdx::element_aligned);
            Vector       t         = 0.;
            stdx::where(active, t) = k * s * (rho * bond.inverse_length);
            for (unsigned int d = 0; d < dim; ++d)
              {
                const Vector force = r[d] * t;
                f_a[d] += force;
                Vector f_b(f[d] + b, stdx::element_aligned);
                f_b -= force;
                f_b.copy_to(f[d] + b, stdx::element_aligned);
              }
            if constexpr (with_energy)
              {
                Vector e               = 0.;
                stdx::where(active, e) = (0.25 * bond.length) * k * s * s;
                w_a += e;
                Vector w_b(w + b, stdx::element_aligned);
                w_b += e;
                w_b.copy_to(w + b, stdx::element_aligned);
              }
          }
        for (unsigned int d = 0; d < dim; ++d)
          {
            Vector sum(f[d] + a, stdx::element_aligned);
            sum += f_a[d];
            sum.copy_to(f[d] + a, stdx::element_aligned);
          }
        if constexpr (with_energy)
          {
            Vector sum(w + a, stdx::element_aligned);
            sum += w_a;
            sum.copy_to(w + a, stdx::element_aligned);
          }
      }
  }

  template <int dim>
  SymmetricTensor<4, dim>
  BondBased<dim>::elasticity_tensor() const
  {
    return isotropic_elasticity_tensor<dim>(youngs_modulus,
                                            implied_poisson_ratio(),
                                            context.planar);
  }

  template <int dim>
  double
  BondBased<dim>::critical_stretch(const double fracture_energy) const
  {
    const double G = fracture_energy, E = youngs_modulus, delta = context.horizon, pi = numbers::PI;
    switch (context.planar)
      {
        case PlanarAssumption::three_dimensional:
          return std::sqrt(5. * G / (6. * E * delta));
        case PlanarAssumption::plane_stress:
          return std::sqrt(4. * pi * G / (9. * E * delta));
        case PlanarAssumption::plane_strain:
          return std::sqrt(5. * pi * G / (12. * E * delta));
      }
    return 0.;
  }

  template <int dim>
  std::string
  BondBased<dim>::summary() const
  {
    std::ostringstream out;
    out << "bond based (PMB): E = " << youngs_modulus << " Pa, implied Poisson ratio "
        << implied_poisson_ratio() << ", micromodulus c = " << c << " N/m^6";
    return out.str();
  }

  template class BondBased<2>;
  template class BondBased<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::BondBased,
                                 "bond based",
                                 "prototype microelastic brittle (PMB) bond-based model; "
                                 "nu = 1/4 (3D, plane strain) or 1/3 (plane stress).")
