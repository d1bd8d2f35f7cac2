// ---------------------------------------------------------------------
// PeriDeal: stiffness bounds and linearizations of the material models (for the quasi-static
// solvers). Kept apart from the force kernels of the models' own files.
// ---------------------------------------------------------------------
#include <perideal/pd/anisotropic_bond_based.h>
#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/antiplane_state_based.h>
#include <perideal/pd/bond_based.h>
#include <perideal/pd/bond_based_conduction.h>
#include <perideal/pd/linear_peridynamic_solid.h>

#include <algorithm>
#include <cmath>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /**
     * @brief Append to @p row the entries of @p factor n_b . (u_j - u_i), the linearized
     * extension of bond @p b stored in the row of particle @p i (n_b = (x_j - x_i)/|xi|, the
     * same for both ends).
     */
    template <int dim>
    void
    add_extension(const ParticleSystem<dim>           &particles,
                  const unsigned int                   i,
                  const std::size_t                    b,
                  const double                         factor,
                  std::vector<LinearizedModel::Entry> &row)
    {
      const BondList    &bonds = particles.bonds();
      const auto        &x     = particles.positions();
      const unsigned int j     = bonds.neighbor[b];
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double n_d = (x[j][d] - x[i][d]) / bonds.length[b];
          row.push_back({i, d, -(factor * n_d)});
          row.push_back({j, d, factor * n_d});
        }
    }

    /**
     * @brief The bond rows of a bond-based model: for every bond b with stiffness
     * @p k[b] != 0 (N/m, per BondList entry), the row that @p add_row(i, b, row) appends (the
     * bond's linearized extension) with weight k_b times the bond's share; the stiffness scale
     * of an owned particle is the sum of k_b over its bonds.
     */
    template <int dim, typename RowFunction>
    void
    add_bond_rows(const ParticleSystem<dim> &particles,
                  const std::vector<double> &k,
                  const RowFunction         &add_row,
                  LinearizedModel           &linearized)
    {
      const BondList                     &bonds   = particles.bonds();
      const unsigned int                  n_owned = particles.n_owned();
      std::vector<double>                &scale   = linearized.stiffness_scale();
      std::vector<LinearizedModel::Entry> row;
      for (unsigned int i = 0; i < n_owned; ++i)
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int j = bonds.neighbor[b];
            scale[i] += k[b];
            if (j < n_owned)
              scale[j] += k[b];
            if (k[b] != 0.)
              {
                row.clear();
                add_row(i, b, row);
                linearized.add_row(k[b] * particles.bond_share(b), row);
              }
          }
    }

    /**
     * @brief The stiffness k_b = @p coefficient[b] / |xi| of every intact bond (0 for broken
     * ones): the bond row weight of a bond-based model of pair coefficients @p coefficient
     * (bond_pair_coefficients()).
     */
    std::vector<double>
    intact_bond_stiffness(const BondList &bonds, const std::vector<double> &coefficient)
    {
      std::vector<double> k(bonds.size(), 0.);
      for (std::size_t b = 0; b < bonds.size(); ++b)
        if (bonds.intact[b])
          k[b] = coefficient[b] / bonds.length[b];
      return k;
    }

    /**
     * @brief The row w_j - w_i of bond b stored in the row of particle i: the bond slope of a
     * scalar field times |xi| (the antiplane models' bond-based energy).
     */
    auto
    slope_row(const BondList &bonds)
    {
      return [&bonds](const unsigned int                   i,
                      const std::size_t                    b,
                      std::vector<LinearizedModel::Entry> &row) {
        row.push_back({i, 0, -1.});
        row.push_back({bonds.neighbor[b], 0, 1.});
      };
    }

    /**
     * @brief The row n_b . (u_j - u_i) of bond b stored in the row of particle i: the
     * linearized extension of a displacement model.
     */
    template <int dim>
    auto
    extension_row(const ParticleSystem<dim> &particles)
    {
      return [&particles](const unsigned int                   i,
                          const std::size_t                    b,
                          std::vector<LinearizedModel::Entry> &row) {
        add_extension(particles, i, b, 1., row);
      };
    }
  } // namespace

  // PMB: the bond b couples i and j through the block k_b n n^T (force density per unit
  // displacement k_b = c G chi V_j / |xi|, i.e. bond_coefficient / (|xi| V_i)); block
  // Gershgorin with spectral norms gives |K_ii| + sum_j |K_ij| <= 2 sum_j k_b.
  template <int dim>
  void
  BondBased<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                  std::vector<double>       &per_particle) const
  {
    bond_pair_stiffness_bound(particles, bond_coefficient, dim, per_particle);
  }

  // PMB linearized: f_i V_i = sum_j (c G chi / |xi|) V_i V_j n n^T (u_j - u_i), i.e. one row
  // e_b = n_b . (u_j - u_i) per intact bond with weight k_b = c G chi V_i V_j / |xi|.
  template <int dim>
  void
  BondBased<dim>::linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const
  {
    linearized.reinit(this->field_layout().n_components(), particles.n_owned());
    add_bond_rows(particles,
                  intact_bond_stiffness(particles.bonds(), bond_coefficient),
                  extension_row<dim>(particles),
                  linearized);
  }

  // Anisotropic linearized bond: the block k_b n n^T of PMB with a direction factor that may be
  // negative, so the Gershgorin bound takes |k_b|.
  template <int dim>
  void
  AnisotropicBondBased<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                             std::vector<double>       &per_particle) const
  {
    std::vector<double> magnitude(bond_coefficient.size());
    std::transform(bond_coefficient.begin(),
                   bond_coefficient.end(),
                   magnitude.begin(),
                   [](const double k) { return std::abs(k); });
    bond_pair_stiffness_bound(particles, magnitude, dim, per_particle);
  }

  // Anisotropic linearized bond (the model is linear): PMB's rows with k_b = c(n_b) G chi V_i
  // V_j / |xi|.
  template <int dim>
  void
  AnisotropicBondBased<dim>::linearize(const ParticleSystem<dim> &particles,
                                       LinearizedModel           &linearized) const
  {
    linearized.reinit(this->field_layout().n_components(), particles.n_owned());
    add_bond_rows(particles,
                  intact_bond_stiffness(particles.bonds(), bond_coefficient),
                  extension_row<dim>(particles),
                  linearized);
  }

  // Antiplane: the bond b couples w_i and w_j through k_b = c G chi V_j / |xi| as PMB's
  // n n^T block does the displacements, hence the same bound.
  template <int dim>
  void
  AntiplaneBondBased<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                           std::vector<double>       &per_particle) const
  {
    bond_pair_stiffness_bound(particles, bond_coefficient, 1, per_particle);
  }

  // Antiplane linearized (the model is linear): f_i V_i = sum_j (c G chi / |xi|) V_i V_j
  // (w_j - w_i), i.e. one row w_j - w_i per intact bond with weight c G chi V_i V_j / |xi|.
  template <int dim>
  void
  AntiplaneBondBased<dim>::linearize(const ParticleSystem<dim> &particles,
                                     LinearizedModel           &linearized) const
  {
    const BondList &bonds = particles.bonds();
    linearized.reinit(this->field_layout().n_components(), particles.n_owned());
    add_bond_rows(particles,
                  intact_bond_stiffness(bonds, bond_coefficient),
                  slope_row(bonds),
                  linearized);
  }

  // Conduction: the bond b couples T_i and T_j through k_b = kappa G chi V_j / |xi| as the
  // antiplane bonds do w, hence the same bound and rows (the conductance matrix of K T = Q).
  template <int dim>
  void
  BondBasedConduction<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                            std::vector<double>       &per_particle) const
  {
    bond_pair_stiffness_bound(particles, bond_coefficient, 1, per_particle);
  }

  template <int dim>
  void
  BondBasedConduction<dim>::linearize(const ParticleSystem<dim> &particles,
                                      LinearizedModel           &linearized) const
  {
    const BondList &bonds = particles.bonds();
    linearized.reinit(1, particles.n_owned());
    add_bond_rows(particles,
                  intact_bond_stiffness(bonds, bond_coefficient),
                  slope_row(bonds),
                  linearized);
  }

  // Antiplane state based (doc/theory/models.md): E = sum_i W_i V_i with the shear angles
  // r_i,a = sum_j G_(i,a),j w_j linear in w, G_(i,a),j = b g_i,a omega chi V_j n_a for a
  // neighbour and minus their sum for i. Each row (i, a) has the weight
  // w_(i,a) = (1 - alpha) mu_i beta_i V_i (beta_i the energy weight, mu_i the particle's shear
  // modulus), with
  // S_i,a = sum_j |G_(i,a),j| (intact bonds) and |G_(i,a),i| = S_i,a; the row of a neighbour l
  // holds i with |G_(l,a),i| = b g_l,a omega chi V_i |n_a|. Gershgorin:
  // sum_k |K_ik| <= (1/V_i) sum_rows w_r |G_ri| sum_k |G_rk|
  //              = sum_a 2 (1 - alpha) mu_i beta_i S_i,a^2
  //                + sum_l sum_a P_l,a omega chi |n_a|,   P_l,a = 2 w_(l,a) S_l,a b g_l,a,
  // P of a ghost neighbour from its owner; plus the bond-based term's bound.
  template <int dim>
  void
  AntiplaneStateBased<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                            std::vector<double>       &per_particle) const
  {
    const BondList    &bonds   = particles.bonds();
    const auto        &volume  = particles.volumes();
    const auto        &x       = particles.positions();
    const auto        &beta    = particles.energy_weights();
    const unsigned int n_owned = particles.n_owned();
    // |n_a| omega chi V_i V_j per intact bond and direction.
    const auto n_weight = [&](const unsigned int i, const std::size_t b, const unsigned int a) {
      const unsigned int j = bonds.neighbor[b];
      return std::abs(x[j][a] - x[i][a]) / (bonds.length[b] * bonds.length[b]) *
             state_coefficient[b];
    };
    std::vector<double> S(std::size_t(n_owned) * dim, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            const unsigned int j = bonds.neighbor[b];
            for (unsigned int a = 0; a < dim; ++a)
              {
                const double p = n_weight(i, b, a);
                S[i * dim + a] += angle_factor[i * dim + a] * p / volume[i];
                if (j < n_owned)
                  S[j * dim + a] += angle_factor[j * dim + a] * p / volume[j];
              }
          }
    ParticleVector P;
    particles.reinit_vector(P, dim);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int a = 0; a < dim; ++a)
        P.local_element(i * dim + a) =
          2. * state_modulus[i] * beta[i] * volume[i] * S[i * dim + a] * angle_factor[i * dim + a];
    P.update_ghost_values();

    bond_pair_stiffness_bound(particles, bond_coefficient, 1, per_particle);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int a = 0; a < dim; ++a)
        per_particle[i] += 2. * state_modulus[i] * beta[i] * S[i * dim + a] * S[i * dim + a];
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            const unsigned int j = bonds.neighbor[b];
            for (unsigned int a = 0; a < dim; ++a)
              {
                const double p = n_weight(i, b, a);
                per_particle[i] += P.local_element(j * dim + a) * p / (volume[i] * volume[j]);
                if (j < n_owned)
                  per_particle[j] += P.local_element(i * dim + a) * p / (volume[i] * volume[j]);
              }
          }
  }

  // Antiplane state based linearized (the model is linear): per owned particle i and direction
  // a the row r_i,a (entries b g_i,a omega chi V_j n_a at j and their negatives at i, over the
  // intact bonds stored in row i and in the rows of owned neighbours) with weight
  // (1 - alpha) mu_i beta_i V_i; per intact bond the row w_j - w_i of the bond-based term with
  // weight alpha c G chi V_i V_j / |xi|. The stiffness scale adds the diagonal of the rows of
  // particle i, sum_a (1 - alpha) mu_i beta_i V_i S_i,a^2 (stiffness_bound()).
  template <int dim>
  void
  AntiplaneStateBased<dim>::linearize(const ParticleSystem<dim> &particles,
                                      LinearizedModel           &linearized) const
  {
    const BondList                                  &bonds   = particles.bonds();
    const auto                                      &volume  = particles.volumes();
    const auto                                      &x       = particles.positions();
    const auto                                      &beta    = particles.energy_weights();
    const unsigned int                               n_owned = particles.n_owned();
    std::vector<std::vector<LinearizedModel::Entry>> rows(std::size_t(n_owned) * dim);
    std::vector<double>                              S(rows.size(), 0.);
    // The entries g at the neighbour @p j and -g at @p i of the row (i, a), n = (x_j - x_i)/|xi|.
    const auto add = [&](const unsigned int i, const unsigned int j, const std::size_t b) {
      for (unsigned int a = 0; a < dim; ++a)
        {
          const double n_a = (x[j][a] - x[i][a]) / bonds.length[b];
          const double g =
            angle_factor[i * dim + a] * state_coefficient[b] * n_a / (bonds.length[b] * volume[i]);
          rows[i * dim + a].push_back({i, 0, -g});
          rows[i * dim + a].push_back({j, 0, g});
          S[i * dim + a] += std::abs(g);
        }
    };
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            const unsigned int j = bonds.neighbor[b];
            add(i, j, b);
            if (j < n_owned)
              add(j, i, b);
          }
    linearized.reinit(this->field_layout().n_components(), n_owned);
    add_bond_rows(particles,
                  intact_bond_stiffness(bonds, bond_coefficient),
                  slope_row(bonds),
                  linearized);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int a = 0; a < dim; ++a)
        {
          const double weight = state_modulus[i] * beta[i] * volume[i];
          linearized.add_row(weight, rows[i * dim + a]);
          linearized.stiffness_scale()[i] += weight * S[i * dim + a] * S[i * dim + a];
        }
  }

  // LPS: the Gershgorin estimate behind stable_time_step() (direct deviatoric stiffness plus the
  // dilatation coupling), doubled for the block Gershgorin bound.
  template <int dim>
  void
  LinearPeridynamicSolid<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                               std::vector<double>       &per_particle) const
  {
    const BondList     &bonds   = particles.bonds();
    const auto         &volume  = particles.volumes();
    const unsigned int  n_owned = particles.n_owned();
    const double        n       = dim;
    const double        alpha_m = shear_modulus * n * (n + 2.);
    const double        kappa   = std::abs(n * bulk_modulus - (n + 2.) * shear_modulus);
    const auto         &beta    = particles.energy_weights();
    std::vector<double> direct(n_owned, 0.), moment(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          if (!bonds.intact[b])
            continue;
          const unsigned int j = bonds.neighbor[b];
          const double       k = (beta[i] * alpha_m / weighted_volume.local_element(i) +
                            beta[j] * alpha_m / weighted_volume.local_element(j)) *
                           pair_weight[b];
          const double r = pair_weight[b] * bonds.length[b];
          direct[i] += k / volume[i];
          moment[i] += r / volume[i];
          if (j < n_owned)
            {
              direct[j] += k / volume[j];
              moment[j] += r / volume[j];
            }
        }
    per_particle.assign(std::size_t(n_owned) * dim, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double m_i = weighted_volume.local_element(i);
        for (unsigned int d = 0; d < dim; ++d)
          per_particle[i * dim + d] =
            2. * (direct[i] + 2. * n * kappa * beta[i] * moment[i] * moment[i] / (m_i * m_i));
      }
  }

  // LPS linearized (doc/theory/models.md): W_i = (n k - (n+2) mu)/(2 n) theta_i^2
  // + (alpha_i / 2) sum_j omega e^2 V_j chi, because the deviatoric sum expands to
  // sum omega e^2 V - theta_i^2 m_i / n^2 and alpha_i m_i = mu n (n + 2). Hence, with the
  // energy weights b_i of a blended coupling (E = sum_i b_i W_i V_i) and e_b = n_b . (u_j - u_i):
  // one row e_b per intact bond with weight k_b = (b_i alpha_i + b_j alpha_j) omega chi V_i V_j,
  // and one row theta_i = sum_{b at i} g_b^(i) e_b per owned particle with weight
  // w_i = b_i V_i (n k - (n+2) mu) / n, g_b^(i) = (n / m_i) omega chi |xi| V_j. theta_i collects
  // the bonds stored in row i and those stored in the row of an owned neighbour.
  template <int dim>
  void
  LinearPeridynamicSolid<dim>::linearize(const ParticleSystem<dim> &particles,
                                         LinearizedModel           &linearized) const
  {
    const BondList                                  &bonds   = particles.bonds();
    const auto                                      &volume  = particles.volumes();
    const unsigned int                               n_owned = particles.n_owned();
    const double                                     n       = dim;
    const double                                     alpha_m = shear_modulus * n * (n + 2.);
    const auto                                      &beta    = particles.energy_weights();
    std::vector<double>                              k(bonds.size(), 0.);
    std::vector<std::vector<LinearizedModel::Entry>> theta(n_owned);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        const double m_i = weighted_volume.local_element(i);
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            if (!bonds.intact[b])
              continue;
            const unsigned int j   = bonds.neighbor[b];
            const double       m_j = weighted_volume.local_element(j);
            k[b]             = (beta[i] * alpha_m / m_i + beta[j] * alpha_m / m_j) * pair_weight[b];
            const double r   = n * pair_weight[b] * bonds.length[b];
            const double g_i = r / m_i / volume[i], g_j = r / m_j / volume[j];
            if (g_i != 0.)
              add_extension(particles, i, b, g_i, theta[i]);
            if (j < n_owned && g_j != 0.)
              add_extension(particles, i, b, g_j, theta[j]);
          }
      }
    linearized.reinit(this->field_layout().n_components(), n_owned);
    add_bond_rows(particles, k, extension_row<dim>(particles), linearized);
    for (unsigned int i = 0; i < n_owned; ++i)
      linearized.add_row(beta[i] * volume[i] * (n * bulk_modulus - (n + 2.) * shear_modulus) / n,
                         theta[i]);
  }

  template void
  AnisotropicBondBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  AnisotropicBondBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  AnisotropicBondBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  AnisotropicBondBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
  template void
  BondBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  BondBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  BondBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  BondBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
  template void
  AntiplaneBondBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  AntiplaneBondBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  AntiplaneBondBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  AntiplaneBondBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
  template void
  BondBasedConduction<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  BondBasedConduction<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  BondBasedConduction<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  BondBasedConduction<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
  template void
  AntiplaneStateBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  AntiplaneStateBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  AntiplaneStateBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  AntiplaneStateBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
  template void
  LinearPeridynamicSolid<2>::stiffness_bound(const ParticleSystem<2> &,
                                             std::vector<double> &) const;
  template void
  LinearPeridynamicSolid<3>::stiffness_bound(const ParticleSystem<3> &,
                                             std::vector<double> &) const;
  template void
  LinearPeridynamicSolid<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  LinearPeridynamicSolid<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
} // namespace perideal
