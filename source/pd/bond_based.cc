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
    if (context.surface_correction)
      {
        const auto energy = [&](const ParticleVector &u, std::vector<double> &w) {
          ParticleVector force;
          particles.reinit_vector(force, dim);
          bond_modulus.resize(bonds.size());
          for (std::size_t b = 0; b < bonds.size(); ++b)
            bond_modulus[b] = c * bonds.volume_factor[b];
          // Pre-cracked bonds take part: the correction describes the uncracked geometry.
          const std::vector<std::uint8_t> intact = bonds.intact;
          std::fill(bonds.intact.begin(), bonds.intact.end(), 1);
          compute_forces(particles, u, force, &w, std::numeric_limits<double>::infinity());
          bonds.intact = intact;
        };
        apply_energy_surface_correction<dim>(particles, elasticity_tensor(), energy);
      }
    bond_modulus.resize(bonds.size());
    for (std::size_t b = 0; b < bonds.size(); ++b)
      bond_modulus[b] =
        c * bonds.surface_factor[b] * bonds.volume_factor[b] * bonds.energy_weight[b];
  }

  template <int dim>
  void
  BondBased<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                 const ParticleVector &u,
                                 ParticleVector       &force,
                                 std::vector<double>  *energy_density,
                                 const double          critical_stretch)
  {
    const BondList &bonds = particles.bonds();
    if (inverse_length.size() != bonds.size())
      {
        inverse_length.resize(bonds.size());
        for (std::size_t b = 0; b < bonds.size(); ++b)
          inverse_length[b] = 1. / bonds.length[b];
      }
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
    BondList           &bonds     = particles.bonds();
    const double       *volume    = particles.volumes().data();
    const unsigned int  n_owned   = particles.n_owned();
    const double       *x         = particles.coordinates().data();
    const unsigned int *row_start = bonds.row_start.data();
    const unsigned int *nbr       = bonds.neighbor.data();
    const double       *length    = bonds.length.data();
    const double       *inverse   = inverse_length.data();
    const double       *modulus   = bond_modulus.data();
    std::uint8_t       *intact    = bonds.intact.data();

    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double *xi      = x + std::size_t(i) * dim;
        const double *ui      = u + std::size_t(i) * dim;
        const double  vi      = volume[i];
        double        fi[dim] = {};
        double        wi      = 0.;
        const auto    row_end = row_start[i + 1];
        for (unsigned int b = row_start[i]; b < row_end; ++b)
          {
            const std::uint8_t state = intact[b];
            if (state == 0)
              continue;
            const unsigned int j  = nbr[b];
            const double      *xj = x + std::size_t(j) * dim;
            const double      *uj = u + std::size_t(j) * dim;
            double             r[dim];
            double             len2 = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                r[d] = (xj[d] - xi[d]) + (uj[d] - ui[d]);
                len2 += r[d] * r[d];
              }
            const double len = std::sqrt(len2);
            const double s   = (len - length[b]) * inverse[b];
            if (s > critical_stretch && state == 1)
              {
                intact[b] = 0;
                continue;
              }
            const double t  = modulus[b] * s / len;
            const double vj = volume[j];
            for (unsigned int d = 0; d < dim; ++d)
              fi[d] += t * vj * r[d];
            if (j < n_owned)
              for (unsigned int d = 0; d < dim; ++d)
                f[std::size_t(j) * dim + d] -= t * vi * r[d];
            if constexpr (with_energy)
              {
                const double e = 0.25 * modulus[b] * s * s * length[b];
                wi += e * vj;
                if (j < n_owned)
                  w[j] += e * vi;
              }
          }
        for (unsigned int d = 0; d < dim; ++d)
          f[std::size_t(i) * dim + d] += fi[d];
        if constexpr (with_energy)
          w[i] += wi;
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
