// ---------------------------------------------------------------------
// PeriDeal: the stiffness bound and the linearization of the antiplane state-based model, for the
// stable step and the quasi-static solvers (compiled without the kernel options).
// ---------------------------------------------------------------------
#include <perideal/pd/antiplane_state_based.h>
#include <perideal/pd/linearization_rows.h>

#include <cmath>

namespace perideal
{
  using namespace dealii;
  using namespace LinearizationRows;

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

  template void
  AntiplaneStateBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  AntiplaneStateBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  AntiplaneStateBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  AntiplaneStateBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
} // namespace perideal
