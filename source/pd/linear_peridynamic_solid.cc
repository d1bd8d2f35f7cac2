// ---------------------------------------------------------------------
// PeriDeal: the ordinary state-based linear peridynamic solid (LPS).
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/bond_rows.h>
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
    pair_weight.resize(bonds.size());
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        pair_weight[b] = influence->value(bonds.length[b], context.horizon) *
                         bonds.volume_factor[b] * volume[i] * volume[bonds.neighbor[b]];
    rows.reinit(bonds, 4);

    particles.reinit_vector(weighted_volume, 1);
    particles.reinit_vector(theta, 1);
    if (context.surface_correction)
      {
        for (unsigned int i = 0; i < particles.n_owned(); ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            {
              const unsigned int j  = bonds.neighbor[b];
              const double       r2 = bonds.length[b] * bonds.length[b];
              weighted_volume.local_element(i) += pair_weight[b] * r2 / volume[i];
              if (j < particles.n_owned())
                weighted_volume.local_element(j) += pair_weight[b] * r2 / volume[j];
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
    const double n       = dim;
    const double alpha_m = shear_modulus * n * (n + 2.);
    alpha.resize(particles.n_local());
    theta_over_m.resize(particles.n_local());
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      alpha[i] = alpha_m / weighted_volume.local_element(i);
  }

  template <int dim>
  void
  LinearPeridynamicSolid<dim>::compute_forces(ParticleSystem<dim>  &particles,
                                              const ParticleVector &u,
                                              ParticleVector       &force,
                                              std::vector<double>  *energy_density,
                                              const double          critical_stretch)
  {
    using namespace bond_simd;
    BondList           &bonds     = particles.bonds();
    const double       *x         = particles.coordinates().data();
    const double       *volume    = particles.volumes().data();
    const unsigned int  n_owned   = particles.n_owned();
    const unsigned int  n_local   = particles.n_local();
    const double       *uu        = u.begin();
    const double       *m         = weighted_volume.begin();
    const unsigned int *row_start = bonds.row_start.data();
    const unsigned int *nbr       = bonds.neighbor.data();
    const double       *length    = bonds.length.data();
    const double       *weight    = pair_weight.data();
    std::uint8_t       *intact    = bonds.intact.data();
    const double        n         = dim;
    double             *buffer[dim];
    for (unsigned int d = 0; d < dim; ++d)
      buffer[d] = rows.component(d);
    double *const theta_over_m_j = rows.scalar(0), *const alpha_j_buffer = rows.scalar(1),
                  *const theta_j = rows.scalar(2), *const energy_j = rows.scalar(3),
                  *const pair_dilatation = rows.scalar(0);

    // Pass 1: break overstretched bonds (extension e > s0 |xi|), then the dilatation from the
    // pair sums omega beta V_i V_j |xi| e, divided by V_i.
    theta      = 0.;
    double *th = theta.begin();
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const unsigned int first = row_start[i], count = row_start[i + 1] - first;
        rows.gather(x, uu, i, nbr + first, count);
        Vector sum = 0.;
        for (unsigned int l = 0; l < count; l += width)
          {
            const unsigned int b = first + l, n_valid = count - l;
            Vector             len2 = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const Vector r(buffer[d] + l, stdx::element_aligned);
                len2 += r * r;
              }
            const Vector xi            = load(length + b, n_valid, 1.);
            const Vector e             = stdx::sqrt(len2) - xi;
            Mask         active        = intact_lanes(intact + b, n_valid);
            const Mask   overstretched = active && (e > critical_stretch * xi);
            if (stdx::any_of(overstretched))
              active = active && !break_bonds(overstretched, intact + b);
            Vector a               = 0.;
            stdx::where(active, a) = load(weight + b, n_valid, 0.) * xi * e;
            sum += a;
            a.copy_to(pair_dilatation + l, stdx::element_aligned);
          }
        th[i] += stdx::reduce(sum);
        rows.scatter_scalar(0, th, nbr + first, count, n_owned);
      }
    for (unsigned int i = 0; i < n_owned; ++i)
      th[i] *= n / (m[i] * volume[i]);
    theta.update_ghost_values();
    for (unsigned int i = 0; i < n_local; ++i)
      theta_over_m[i] = th[i] / m[i];

    // Pass 2: forces (and energy). Pair force
    // [(n k - (n + 2) mu) |xi| (theta_i / m_i + theta_j / m_j) + (alpha_i + alpha_j) e]
    //   omega beta V_i V_j (xi + eta)/|xi + eta|, summed per particle and divided by V_i.
    const double dilatation_coefficient = n * bulk_modulus - (n + 2.) * shear_modulus;
    double      *f                      = force.begin();
    std::fill(f, f + std::size_t(n_owned) * dim, 0.);
    const bool energy = (energy_density != nullptr);
    if (energy)
      energy_density->assign(n_owned, 0.);
    double *w = energy ? energy_density->data() : nullptr;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const unsigned int first = row_start[i], count = row_start[i + 1] - first;
        rows.gather(x, uu, i, nbr + first, count);
        rows.gather_scalar(0, theta_over_m.data(), nbr + first, count);
        rows.gather_scalar(1, alpha.data(), nbr + first, count);
        if (energy)
          rows.gather_scalar(2, th, nbr + first, count);
        Vector fi[dim] = {};
        Vector wi      = 0.;
        for (unsigned int l = 0; l < count; l += width)
          {
            const unsigned int b = first + l, n_valid = count - l;
            Vector             r[dim], len2           = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                r[d].copy_from(buffer[d] + l, stdx::element_aligned);
                len2 += r[d] * r[d];
              }
            const Vector len    = stdx::sqrt(len2);
            const Vector xi     = load(length + b, n_valid, 1.);
            const Vector e      = len - xi;
            const Vector p      = load(weight + b, n_valid, 0.);
            const Mask   active = intact_lanes(intact + b, n_valid);
            const Vector alpha_j(alpha_j_buffer + l, stdx::element_aligned);
            const Vector t =
              dilatation_coefficient * xi *
                (theta_over_m[i] + Vector(theta_over_m_j + l, stdx::element_aligned)) +
              (alpha[i] + alpha_j) * e;
            Vector scale               = 0.;
            stdx::where(active, scale) = t * p / len;
            for (unsigned int d = 0; d < dim; ++d)
              {
                r[d] *= scale;
                fi[d] += r[d];
                r[d].copy_to(buffer[d] + l, stdx::element_aligned);
              }
            if (energy)
              {
                const Vector ei      = e - th[i] * xi / n;
                const Vector ej      = e - Vector(theta_j + l, stdx::element_aligned) * xi / n;
                Vector       wi_pair = 0., wj_pair = 0.;
                stdx::where(active, wi_pair) = 0.5 * alpha[i] * p * ei * ei;
                stdx::where(active, wj_pair) = 0.5 * alpha_j * p * ej * ej;
                wi += wi_pair;
                wj_pair.copy_to(energy_j + l, stdx::element_aligned);
              }
          }
        rows.scatter(f, nbr + first, count, n_owned);
        for (unsigned int d = 0; d < dim; ++d)
          f[std::size_t(i) * dim + d] += stdx::reduce(fi[d]);
        if (energy)
          {
            w[i] += stdx::reduce(wi);
            rows.scatter_scalar(3, w, nbr + first, count, n_owned);
          }
      }
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        for (unsigned int d = 0; d < dim; ++d)
          f[std::size_t(i) * dim + d] /= volume[i];
        if (energy)
          w[i] = 0.5 * bulk_modulus * th[i] * th[i] + w[i] / volume[i];
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
