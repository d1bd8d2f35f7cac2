// ---------------------------------------------------------------------
// PeriDeal: the stiffness bound and the linearization of the antiplane bond-based model, for the
// stable step and the quasi-static solvers (compiled without the kernel options).
// ---------------------------------------------------------------------
#include <perideal/pd/antiplane_bond_based.h>
#include <perideal/pd/linearization_rows.h>

namespace perideal
{
  using namespace dealii;
  using namespace LinearizationRows;

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

  template void
  AntiplaneBondBased<2>::stiffness_bound(const ParticleSystem<2> &, std::vector<double> &) const;
  template void
  AntiplaneBondBased<3>::stiffness_bound(const ParticleSystem<3> &, std::vector<double> &) const;
  template void
  AntiplaneBondBased<2>::linearize(const ParticleSystem<2> &, LinearizedModel &) const;
  template void
  AntiplaneBondBased<3>::linearize(const ParticleSystem<3> &, LinearizedModel &) const;
} // namespace perideal
