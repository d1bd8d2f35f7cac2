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
    pair_weight.resize(bonds.size());
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        pair_weight[b] = influence->value(bonds.length[b], context.horizon) *
                         bonds.volume_factor[b] * volume[i] * volume[bonds.neighbor[b]];
    blocks.reinit(particles);
    blocks.to_lanes(pair_weight, lane_weight);
    for (auto *field : {&u_field, &f_field})
      blocks.reinit_field(*field, dim);
    for (auto *field :
         {&w_field, &theta_field, &theta_over_m_field, &alpha_field, &beta_over_m_field})
      blocks.reinit_field(*field, 1);

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
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      alpha[i] = alpha_m / weighted_volume.local_element(i);
    // The kernels work with the particles' force states weighted by their energy weights
    // beta_i (E = sum_i beta_i W_i V_i): beta alpha and beta theta / m.
    const auto         &beta = particles.energy_weights();
    std::vector<double> weighted(particles.n_local());
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      weighted[i] = beta[i] * alpha[i];
    blocks.gather(weighted.data(), 1, alpha_field);
    for (unsigned int i = 0; i < particles.n_local(); ++i)
      weighted[i] = beta[i] / weighted_volume.local_element(i);
    blocks.gather(weighted.data(), 1, beta_over_m_field);
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
    BondList           &bonds      = particles.bonds();
    const double       *volume     = particles.volumes().data();
    const unsigned int  n_owned    = particles.n_owned();
    const double       *m          = weighted_volume.begin();
    const auto         &groups     = blocks.groups();
    const auto         &block_list = blocks.blocks();
    const auto         &classes    = blocks.classes();
    const double       *weight     = lane_weight.data();
    const std::uint8_t *state      = blocks.state();
    const double        n          = dim;
    blocks.sync_state(bonds);
    blocks.gather(u.begin(), dim, u_field);
    const double *uu[dim];
    double       *f[dim];
    for (unsigned int d = 0; d < dim; ++d)
      {
        uu[d] = blocks.component(u_field, d);
        f[d]  = blocks.component(f_field, d);
      }
    // Lane l of a block: particle a + l, neighbour a + offset + l, lattice vector xi of the
    // block's class. Returns the bond vectors r = xi + eta and |r| / |xi| - 1.
    const auto bond_vectors = [&](const unsigned int                     a,
                                  const Vector                          *u_a,
                                  const typename BondBlocks<dim>::Block &block,
                                  Vector                                *r,
                                  Vector                                &rho) {
      const auto       &bond    = classes[block.bond_class];
      const std::size_t b       = std::size_t(std::ptrdiff_t(a) + block.offset);
      Vector            length2 = 0.;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const Vector u_b(uu[d] + b, stdx::element_aligned);
          r[d] = bond.xi[d] + (u_b - u_a[d]);
          length2 += r[d] * r[d];
        }
      const Vector ratio2 = length2 * (bond.inverse_length * bond.inverse_length);
      rho                 = inverse_sqrt(ratio2);
      return Vector(ratio2 * rho - 1.);
    };
    const auto add_to = [](double *target, const Vector &value) {
      Vector sum(target, stdx::element_aligned);
      sum += value;
      sum.copy_to(target, stdx::element_aligned);
    };

    // Pass 1: break overstretched bonds (stretch above the critical stretch), then the
    // dilatation from the pair sums omega beta V_i V_j |xi| e (e = |xi| s), divided by V_i.
    std::fill(theta_field.begin(), theta_field.end(), 0.);
    double *th = blocks.component(theta_field, 0);
    for (std::size_t g = 0; g + 1 < groups.size(); ++g)
      {
        const unsigned int a = groups[g].first_particle;
        Vector             u_a[dim], r[dim], rho;
        for (unsigned int d = 0; d < dim; ++d)
          u_a[d].copy_from(uu[d] + a, stdx::element_aligned);
        Vector theta_a = 0.;
        for (unsigned int q = groups[g].first_block; q < groups[g + 1].first_block; ++q)
          {
            const auto  &block  = block_list[q];
            const double xi     = classes[block.bond_class].length;
            const Vector s      = bond_vectors(a, u_a, block, r, rho);
            Mask         active = intact_lanes(state + std::size_t(q) * width);
            if (stdx::any_of(active && (s > critical_stretch)))
              {
                blocks.break_lanes(s, critical_stretch, q, bonds);
                active = intact_lanes(state + std::size_t(q) * width);
              }
            Vector pair = 0.;
            stdx::where(active, pair) =
              Vector(weight + std::size_t(q) * width, stdx::element_aligned) * s * (xi * xi);
            theta_a += pair;
            add_to(th + std::ptrdiff_t(a) + block.offset, pair);
          }
        add_to(th + a, theta_a);
      }
    double *theta_owned = theta.begin();
    blocks.scatter_owned(theta_field, 1, nullptr, theta_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      theta_owned[i] *= n / (m[i] * volume[i]);
    theta.update_ghost_values();
    blocks.gather(theta.begin(), 1, theta_field);
    const double *theta_k      = blocks.component(theta_field, 0);
    double       *theta_over_m = blocks.component(theta_over_m_field, 0);
    for (std::size_t k = 0; k < theta_field.size(); ++k)
      theta_over_m_field[k] = theta_field[k] * beta_over_m_field[k];

    // Pass 2: forces (and energy). Pair force
    // [(n k - (n + 2) mu) |xi| (theta_i / m_i + theta_j / m_j) + (alpha_i + alpha_j) e]
    //   omega beta V_i V_j (xi + eta)/|xi + eta|, summed per particle and divided by V_i.
    const double dilatation_coefficient = n * bulk_modulus - (n + 2.) * shear_modulus;
    std::fill(f_field.begin(), f_field.end(), 0.);
    const bool energy = (energy_density != nullptr);
    double    *w      = blocks.component(w_field, 0);
    if (energy)
      std::fill(w_field.begin(), w_field.end(), 0.);
    const double *alpha_k = blocks.component(alpha_field, 0);
    for (std::size_t g = 0; g + 1 < groups.size(); ++g)
      {
        const unsigned int a = groups[g].first_particle;
        Vector             u_a[dim], r[dim], rho, f_a[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            u_a[d].copy_from(uu[d] + a, stdx::element_aligned);
            f_a[d] = 0.;
          }
        const Vector theta_over_m_a(theta_over_m + a, stdx::element_aligned);
        const Vector alpha_a(alpha_k + a, stdx::element_aligned);
        const Vector theta_a(theta_k + a, stdx::element_aligned);
        Vector       w_a = 0.;
        for (unsigned int q = groups[g].first_block; q < groups[g + 1].first_block; ++q)
          {
            const auto       &block = block_list[q];
            const auto       &bond  = classes[block.bond_class];
            const std::size_t b     = std::size_t(std::ptrdiff_t(a) + block.offset);
            const Vector      s     = bond_vectors(a, u_a, block, r, rho);
            const Vector      e     = bond.length * s;
            const Vector      p(weight + std::size_t(q) * width, stdx::element_aligned);
            const Vector      alpha_b(alpha_k + b, stdx::element_aligned);
            const Vector      t = (dilatation_coefficient * bond.length) *
                               (theta_over_m_a + Vector(theta_over_m + b, stdx::element_aligned)) +
                             (alpha_a + alpha_b) * e;
            const Mask active          = intact_lanes(state + std::size_t(q) * width);
            Vector     scale           = 0.;
            stdx::where(active, scale) = t * p * (rho * bond.inverse_length);
            for (unsigned int d = 0; d < dim; ++d)
              {
                const Vector pair_force = r[d] * scale;
                f_a[d] += pair_force;
                Vector f_b(f[d] + b, stdx::element_aligned);
                f_b -= pair_force;
                f_b.copy_to(f[d] + b, stdx::element_aligned);
              }
            if (energy)
              {
                const Vector ei = e - theta_a * (bond.length / n);
                const Vector ej =
                  e - Vector(theta_k + b, stdx::element_aligned) * (bond.length / n);
                Vector wi_pair = 0., wj_pair = 0.;
                stdx::where(active, wi_pair) = 0.5 * alpha_a * p * ei * ei;
                stdx::where(active, wj_pair) = 0.5 * alpha_b * p * ej * ej;
                w_a += wi_pair;
                add_to(w + b, wj_pair);
              }
          }
        for (unsigned int d = 0; d < dim; ++d)
          add_to(f[d] + a, f_a[d]);
        if (energy)
          add_to(w + a, w_a);
      }
    blocks.scatter_owned(f_field, dim, volume, force.begin());
    if (energy)
      {
        energy_density->resize(n_owned);
        blocks.scatter_owned(w_field, 1, volume, energy_density->data());
        const auto &beta = particles.energy_weights();
        for (unsigned int i = 0; i < n_owned; ++i)
          (*energy_density)[i] += beta[i] * 0.5 * bulk_modulus * theta_owned[i] * theta_owned[i];
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
