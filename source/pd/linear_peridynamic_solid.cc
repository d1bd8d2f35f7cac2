// ---------------------------------------------------------------------
// PeriDeal: the ordinary state-based linear peridynamic solid (LPS).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/linear_peridynamic_solid.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Young's modulus", "0", Patterns::Double(0.), "Young's modulus E [Pa].");
    prm.declare_entry("Poisson's ratio",
                      "0.25",
                      Patterns::Double(-1., 0.5),
                      "Poisson's ratio nu [-], in (-1, 1/2).");
    prm.declare_entry("Influence function",
                      "inverse distance",
                      Patterns::Selection(PluginRegistry<InfluenceFunction>::pattern_string()),
                      "The influence function omega(|xi|). " +
                        PluginRegistry<InfluenceFunction>::documentation());
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::parse_parameters(ParameterHandler &prm)
  {
    const std::string prefix = "Material/linear peridynamic solid/";
    youngs_modulus           = prm.get_double("Young's modulus");
    ParameterUtilities::require_positive(youngs_modulus, prefix + "Young's modulus");
    poisson_ratio = prm.get_double("Poisson's ratio");
    AssertThrow(poisson_ratio > -1. && poisson_ratio < 0.5,
                ExcMessage("The parameter <" + prefix + "Poisson's ratio> is " +
                           ParameterUtilities::format_number(poisson_ratio) +
                           "; accepted: -1 < nu < 0.5."));
    influence_name = prm.get("Influence function");
    influence =
      PluginRegistry<InfluenceFunction>::create(influence_name, prefix + "Influence function");
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::initialize(ParticleSystem<dim> &particles,
                                          const ModelContext  &model_context)
  {
    context        = model_context;
    const double E = youngs_modulus, nu = poisson_ratio;
    shear_modulus       = E / (2. * (1. + nu));
    const double lambda = E * nu / ((1. + nu) * (1. - 2. * nu));
    switch (context.planar)
      {
        case PlanarAssumption::three_dimensional:
          bulk_modulus = lambda + 2. * shear_modulus / 3.;
          break;
        case PlanarAssumption::plane_strain:
          bulk_modulus = lambda + shear_modulus;
          break;
        case PlanarAssumption::plane_stress:
          bulk_modulus = E / (2. * (1. - nu));
          break;
      }

    const BondList &bonds  = particles.bonds();
    const auto     &volume = particles.volumes();
    bond_weight.resize(bonds.size());
    for (std::size_t b = 0; b < bonds.size(); ++b)
      bond_weight[b] = influence->value(bonds.length[b], context.horizon) * bonds.volume_factor[b];

    particles.reinit_vector(weighted_volume, 1);
    particles.reinit_vector(theta, 1);
    if (context.surface_correction)
      {
        for (unsigned int i = 0; i < particles.n_owned(); ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            {
              const unsigned int j  = bonds.neighbor[b];
              const double       r2 = bonds.length[b] * bonds.length[b];
              weighted_volume.local_element(i) += bond_weight[b] * r2 * volume[j];
              if (j < particles.n_owned())
                weighted_volume.local_element(j) += bond_weight[b] * r2 * volume[i];
            }
        weighted_volume.update_ghost_values();
      }
    else
      {
        const double m = continuum_weighted_volume<dim>(*influence,
                                                        context.horizon,
                                                        dim == 2 ? context.thickness : 0.);
        for (unsigned int i = 0; i < particles.n_local(); ++i)
          weighted_volume.local_element(i) = m;
      }
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                              const ParticleVector &u,
                                              ParticleVector       &force,
                                              std::vector<double>  *energy_density,
                                              const double          critical_stretch)
  {
    BondList                      &bonds   = particles.bonds();
    const std::vector<Point<dim>> &x       = particles.positions();
    const std::vector<double>     &volume  = particles.volumes();
    const unsigned int             n_owned = particles.n_owned();
    const double                  *uu      = u.begin();
    const double                  *m       = weighted_volume.begin();
    const unsigned int            *nbr     = bonds.neighbor.data();
    const double                  *length  = bonds.length.data();
    const double                  *weight  = bond_weight.data();
    std::uint8_t                  *intact  = bonds.intact.data();
    const double                   n       = dim;

    const auto deformed = [&](const unsigned int i, const unsigned int j, double *y) {
      double len2 = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          y[d] = x[j][d] - x[i][d] + uu[j * dim + d] - uu[i * dim + d];
          len2 += y[d] * y[d];
        }
      return std::sqrt(len2);
    };

    // Pass 1: break overstretched bonds, then the dilatation.
    theta      = 0.;
    double *th = theta.begin();
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          if (!intact[b])
            continue;
          const unsigned int j = nbr[b];
          double             y[dim];
          const double       e = deformed(i, j, y) - length[b];
          if (e > critical_stretch * length[b] && intact[b] == 1)
            {
              intact[b] = 0;
              continue;
            }
          const double a = weight[b] * length[b] * e;
          th[i] += a * volume[j];
          if (j < n_owned)
            th[j] += a * volume[i];
        }
    for (unsigned int i = 0; i < n_owned; ++i)
      th[i] *= n / m[i];
    theta.update_ghost_values();

    // Pass 2: forces (and energy).
    const double dilatation_coefficient = n * bulk_modulus - (n + 2.) * shear_modulus;
    const double alpha_m                = shear_modulus * n * (n + 2.);
    double      *f                      = force.begin();
    std::fill(f, f + std::size_t(n_owned) * dim, 0.);
    const bool energy = (energy_density != nullptr);
    if (energy)
      {
        energy_density->assign(n_owned, 0.);
        for (unsigned int i = 0; i < n_owned; ++i)
          (*energy_density)[i] = 0.5 * bulk_modulus * th[i] * th[i];
      }
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        double       fi[dim] = {};
        const double ai      = alpha_m / m[i];
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            if (!intact[b])
              continue;
            const unsigned int j = nbr[b];
            double             y[dim];
            const double       len = deformed(i, j, y);
            const double       e   = len - length[b];
            const double       aj  = alpha_m / m[j];
            const double       wr  = weight[b] * length[b];
            const double       t   = dilatation_coefficient * wr * (th[i] / m[i] + th[j] / m[j]) +
                             (ai + aj) * weight[b] * e;
            const double scale = t / len;
            for (unsigned int d = 0; d < dim; ++d)
              fi[d] += scale * y[d] * volume[j];
            if (j < n_owned)
              for (unsigned int d = 0; d < dim; ++d)
                f[j * dim + d] -= scale * y[d] * volume[i];
            if (energy)
              {
                const double ei = e - th[i] * length[b] / n;
                (*energy_density)[i] += 0.5 * ai * weight[b] * ei * ei * volume[j];
                if (j < n_owned)
                  {
                    const double ej = e - th[j] * length[b] / n;
                    (*energy_density)[j] += 0.5 * aj * weight[b] * ej * ej * volume[i];
                  }
              }
          }
        for (unsigned int d = 0; d < dim; ++d)
          f[i * dim + d] += fi[d];
      }
  }

  template <int dim>
  SymmetricTensor<4, dim>
  LinearPeridynamicSolid<dim>::elasticity_tensor() const
  {
    return isotropic_elasticity_tensor<dim>(youngs_modulus, poisson_ratio, context.planar);
  }

  template <int dim>
  double
  LinearPeridynamicSolid<dim>::critical_stretch(const double fracture_energy) const
  {
    const double G = fracture_energy, mu = shear_modulus, k = bulk_modulus, delta = context.horizon,
                 pi = numbers::PI;
    if (dim == 3)
      return std::sqrt(G / ((3. * mu + std::pow(0.75, 4) * (k - 5. * mu / 3.)) * delta));
    return std::sqrt(G / ((6. * mu / pi + 16. / (9. * pi * pi) * (k - 2. * mu)) * delta));
  }

  template <int dim>
  std::string
  LinearPeridynamicSolid<dim>::summary() const
  {
    std::ostringstream out;
    out << "linear peridynamic solid: E = " << youngs_modulus << " Pa, nu = " << poisson_ratio
        << ", bulk modulus k = " << bulk_modulus << " Pa, shear modulus mu = " << shear_modulus
        << " Pa, influence function '" << influence_name << "'";
    return out.str();
  }

  template <int dim>
  const ParticleVector &
  LinearPeridynamicSolid<dim>::dilatation() const
  {
    return theta;
  }

  template class LinearPeridynamicSolid<2>;
  template class LinearPeridynamicSolid<3>;
} // namespace perideal

PERIDEAL_REGISTER_MATERIAL_MODEL(perideal::LinearPeridynamicSolid,
                                 "linear peridynamic solid",
                                 "ordinary state-based linear peridynamic solid (LPS), any nu.")
