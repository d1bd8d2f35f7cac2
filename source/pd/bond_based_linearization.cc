// ---------------------------------------------------------------------
// PeriDeal: the stiffness bound and the linearization of the bond-based model (PMB), for the
// stable step and the quasi-static solvers (compiled without the kernel options).
// ---------------------------------------------------------------------
#include <perideal/pd/bond_based.h>
#include <perideal/pd/linearization_rows.h>

namespace perideal
{
  using namespace dealii;
  using namespace LinearizationRows;

  // PMB: the bond b couples i and j through the block k_b n n^T (force density per unit
  // displacement k_b = c G chi V_j / |xi|, i.e. bond_pair_coefficient() / (|xi| V_i)); block
  // Gershgorin with spectral norms gives |K_ii| + sum_j |K_ij| <= 2 sum_j k_b.
  template <int dim>
  void
  BondBased<dim>::stiffness_bound(const ParticleSystem<dim> &particles,
                                  std::vector<double>       &per_particle) const
  {
    const auto coefficient = pair_coefficients(particles);
    bond_pair_stiffness_bound<dim>(
      particles,
      [&coefficient](const unsigned int, const std::size_t b) { return coefficient(b); },
      dim,
      per_particle);
  }

  // PMB linearized: f_i V_i = sum_j (c G chi / |xi|) V_i V_j n n^T (u_j - u_i - s_th xi), i.e.
  // one row e_b = n_b . (u_j - u_i) per intact bond with weight k_b = c G chi V_i V_j / |xi| and
  // offset s_th |xi|, the thermal extension.
  template <int dim>
  void
  BondBased<dim>::linearize(const ParticleSystem<dim> &particles, LinearizedModel &linearized) const
  {
    linearized.reinit(this->field_layout().n_components(), particles.n_owned());
    const auto          coefficient = pair_coefficients(particles);
    std::vector<double> bond_coefficient(particles.bonds().size());
    for (std::size_t b = 0; b < bond_coefficient.size(); ++b)
      bond_coefficient[b] = coefficient(b);
    std::vector<double> offset;
    if (this->temperature_change() != nullptr)
      {
        const BondList &bonds = particles.bonds();
        offset.assign(bonds.size(), 0.);
        for (std::size_t b = 0; b < bonds.size(); ++b)
          offset[b] = thermal_stretch(particles, b) * bonds.length[b];
      }
    add_bond_rows(particles,
                  intact_bond_stiffness(particles.bonds(), bond_coefficient),
                  extension_row<dim>(particles),
                  linearized,
                  offset.empty() ? nullptr : &offset);
  }

  template void
  BondBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  BondBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  BondBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  BondBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
} // namespace perideal
