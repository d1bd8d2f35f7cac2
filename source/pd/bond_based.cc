// ---------------------------------------------------------------------
// PeriDeal: the prototype microelastic brittle (PMB) bond-based model.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/bond_rows.h>
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
    rows.reinit(bonds, 1);
    inverse_length.resize(bonds.size());
    for (std::size_t b = 0; b < bonds.size(); ++b)
      inverse_length[b] = 1. / bonds.length[b];
    if (context.surface_correction)
      {
        const auto energy = [&](const ParticleVector &u, std::vector<double> &w) {
          ParticleVector force;
          particles.reinit_vector(force, dim);
          set_bond_coefficients(particles, false);
          // Pre-cracked bonds take part: the correction describes the uncracked geometry.
          const std::vector<std::uint8_t> intact = bonds.intact;
          std::fill(bonds.intact.begin(), bonds.intact.end(), 1);
          compute_forces(particles, u, force, &w, std::numeric_limits<double>::infinity());
          bonds.intact = intact;
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
  }

  template <int dim>
  void
  BondBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                 const ParticleVector &u,
                                 ParticleVector       &force,
                                 std::vector<double>  *energy_density,
                                 const double          critical_stretch)
  {
    double *f = force.begin();
    std::fill(f, f + std::size_t(particles.n_owned()) * dim, 0.);
    if (energy_density != nullptr)
      {
        energy_density->assign(particles.n_owned(), 0.);
        force_loop<true>(particles, u.begin(), f, energy_density->data(), critical_stretch);
      }
    else
      force_loop<false>(particles, u.begin(), f, nullptr, critical_stretch);
  }

  template <int dim>
  template <bool with_energy>
  void
  BondBased<dim>::force_loop(ParticleSystem<dim> &particles,
                             const double        *u,
                             double              *f,
                             double              *w,
                             const double         critical_stretch)
  {
    using namespace bond_simd;
    BondList           &bonds       = particles.bonds();
    const double       *volume      = particles.volumes().data();
    const unsigned int  n_owned     = particles.n_owned();
    const double       *x           = particles.coordinates().data();
    const unsigned int *row_start   = bonds.row_start.data();
    const unsigned int *nbr         = bonds.neighbor.data();
    const double       *length      = bonds.length.data();
    const double       *inverse     = inverse_length.data();
    const double       *coefficient = bond_coefficient.data();
    std::uint8_t       *intact      = bonds.intact.data();
    double             *energy      = rows.scalar(0);
    double             *buffer[dim];
    for (unsigned int d = 0; d < dim; ++d)
      buffer[d] = rows.component(d);

    // Pair forces F = k s (xi + eta)/|xi + eta| and pair energies k s^2 |xi| / 4 with
    // k = c G beta V_i V_j, summed per particle and divided by V_i at the end.
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const unsigned int first = row_start[i], n = row_start[i + 1] - first;
        rows.gather(x, u, i, nbr + first, n);
        Vector fi[dim] = {};
        Vector wi      = 0.;
        for (unsigned int l = 0; l < n; l += width)
          {
            const unsigned int b = first + l, n_valid = n - l;
            Vector             r[dim], len2           = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                r[d].copy_from(buffer[d] + l, stdx::element_aligned);
                len2 += r[d] * r[d];
              }
            const Vector len           = stdx::sqrt(len2);
            const Vector xi            = load(length + b, n_valid, 1.);
            const Vector s             = (len - xi) * load(inverse + b, n_valid, 1.);
            Mask         active        = intact_lanes(intact + b, n_valid);
            const Mask   overstretched = active && (s > critical_stretch);
            if (stdx::any_of(overstretched))
              active = active && !break_bonds(overstretched, intact + b);
            const Vector k         = load(coefficient + b, n_valid, 0.);
            Vector       t         = 0.;
            stdx::where(active, t) = k * s / len;
            for (unsigned int d = 0; d < dim; ++d)
              {
                r[d] *= t;
                fi[d] += r[d];
                r[d].copy_to(buffer[d] + l, stdx::element_aligned);
              }
            if constexpr (with_energy)
              {
                Vector e               = 0.;
                stdx::where(active, e) = 0.25 * k * s * s * xi;
                wi += e;
                e.copy_to(energy + l, stdx::element_aligned);
              }
          }
        rows.scatter(f, nbr + first, n, n_owned);
        for (unsigned int d = 0; d < dim; ++d)
          f[std::size_t(i) * dim + d] += stdx::reduce(fi[d]);
        if constexpr (with_energy)
          {
            w[i] += stdx::reduce(wi);
            rows.scatter_scalar(0, w, nbr + first, n, n_owned);
          }
      }
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        for (unsigned int d = 0; d < dim; ++d)
          f[std::size_t(i) * dim + d] /= volume[i];
        if constexpr (with_energy)
          w[i] /= volume[i];
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
