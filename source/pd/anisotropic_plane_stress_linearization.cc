// ---------------------------------------------------------------------
// PeriDeal: the stiffness bound and the linearization of the anisotropic plane-stress model
// (for the quasi-static solvers), apart from its force kernel (compiled with the kernel
// options).
// ---------------------------------------------------------------------
#include <perideal/pd/anisotropic_plane_stress.h>

#include <cmath>

namespace perideal
{
  using namespace dealii;

  // E = sum_i beta_i V_i W_i with W_i = 1/4 sum_j lambda_0 (xi . eta)^2 w - 1/2 B_i A_i^2 is,
  // per pair, 1/2 (k_b/|xi|) e_b^2 (e_b = n_b . (u_j - u_i), k_b = c_0(n) chi V_i V_j times
  // the coupling's energy weight) and, per particle, -1/2 (beta_i V_i B_i) A_i^2 with
  // A_i = sum_b g_b e_b / (V_i B_i) over the intact bonds of i. Hence: one row e_b per intact
  // bond with weight k_b/|xi| (times the bond's share), one row A_i per owned particle with the
  // (negative) weight -beta_i V_i B_i. The A_i row collects the bonds stored in row i and in the
  // rows of owned neighbours (e_b is the same seen from either end). With a temperature change
  // e_b is the mechanical extension, less o_b = |xi| n . alpha' . n DeltaT_b: the bond row's
  // offset is o_b, the A_i row's sum_b g_b o_b / (V_i B_i).
  void
  AnisotropicPlaneStress::linearize(const ParticleSystem<2> &particles,
                                    LinearizedModel         &linearized) const
  {
    const BondList                                  &bonds   = particles.bonds();
    const auto                                      &x       = particles.positions();
    const auto                                      &volume  = particles.volumes();
    const auto                                      &beta    = particles.energy_weights();
    const unsigned int                               n_owned = particles.n_owned();
    std::vector<std::vector<LinearizedModel::Entry>> A_rows(n_owned);
    std::vector<LinearizedModel::Entry>              row;
    const std::vector<double>                        offset = thermal_extensions(particles);
    std::vector<double>                              A_offset(n_owned, 0.);
    linearized.reinit(2, n_owned);
    std::vector<double> &scale = linearized.stiffness_scale();
    // Append factor * e_b (bond b of row i) to @p entries.
    const auto add_extension = [&](const unsigned int                   i,
                                   const std::size_t                    b,
                                   const double                         factor,
                                   std::vector<LinearizedModel::Entry> &entries) {
      const unsigned int j = bonds.neighbor[b];
      for (unsigned int d = 0; d < 2; ++d)
        {
          const double n_d = (x[j][d] - x[i][d]) / bonds.length[b];
          entries.push_back({i, d, -(factor * n_d)});
          entries.push_back({j, d, factor * n_d});
        }
    };
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          if (!bonds.intact[b])
            continue;
          const unsigned int j = bonds.neighbor[b];
          const double       k = k0[b] / bonds.length[b];
          scale[i] += std::abs(k);
          if (j < n_owned)
            scale[j] += std::abs(k);
          if (k != 0.)
            {
              row.clear();
              add_extension(i, b, 1., row);
              linearized.add_row(k * particles.bond_share(b), row, offset[b]);
            }
          if (g[b] != 0.)
            {
              add_extension(i, b, g[b] / (volume[i] * B[i]), A_rows[i]);
              A_offset[i] += g[b] / (volume[i] * B[i]) * offset[b];
              if (j < n_owned)
                {
                  add_extension(i, b, g[b] / (volume[j] * B[j]), A_rows[j]);
                  A_offset[j] += g[b] / (volume[j] * B[j]) * offset[b];
                }
            }
        }
    for (unsigned int i = 0; i < n_owned; ++i)
      if (beta[i] != 0. && !A_rows[i].empty())
        linearized.add_row(-beta[i] * volume[i] * B[i], A_rows[i], A_offset[i]);
  }

  // The bond term: bond_pair_stiffness_bound() with |k_b| (c_0(n) may be negative). The A term
  // -1/2 sum_r w_r A_r^2, w_r = beta_r V_r B_r, A_r = sum_k G_rk u_k: with s_r = sum_b |g_b| /
  // (V_r B_r) over the intact bonds of r, |G_rr| <= s_r and sum_k |G_rk| <= 2 s_r, so the row
  // of particle p of the force-density derivative is bounded by
  // (1/V_p) sum_r w_r |G_rp| 2 s_r = 2 beta_p B_p s_p^2 + sum_j 2 beta_j s_j |g_b| / V_p.
  void
  AnisotropicPlaneStress::stiffness_bound(const ParticleSystem<2> &particles,
                                          std::vector<double>     &per_particle) const
  {
    const BondList     &bonds   = particles.bonds();
    const auto         &volume  = particles.volumes();
    const auto         &beta    = particles.energy_weights();
    const unsigned int  n_owned = particles.n_owned();
    std::vector<double> magnitude(k0.size(), 0.);
    for (std::size_t b = 0; b < k0.size(); ++b)
      magnitude[b] = std::abs(k0[b]);
    bond_pair_stiffness_bound(particles, magnitude, 2, per_particle);

    std::vector<double> s(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            const unsigned int j = bonds.neighbor[b];
            s[i] += std::abs(g[b]) / (volume[i] * B[i]);
            if (j < n_owned)
              s[j] += std::abs(g[b]) / (volume[j] * B[j]);
          }
    ParticleVector beta_s;
    particles.reinit_vector(beta_s, 1);
    for (unsigned int i = 0; i < n_owned; ++i)
      beta_s.local_element(i) = beta[i] * s[i];
    beta_s.update_ghost_values();
    std::vector<double> extra(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      extra[i] += 2. * beta[i] * B[i] * s[i] * s[i];
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b])
          {
            const unsigned int j = bonds.neighbor[b];
            extra[i] += 2. * beta_s.local_element(j) * std::abs(g[b]) / volume[i];
            if (j < n_owned)
              extra[j] += 2. * beta_s.local_element(i) * std::abs(g[b]) / volume[j];
          }
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int d = 0; d < 2; ++d)
        per_particle[i * 2 + d] += extra[i];
  }
} // namespace perideal
