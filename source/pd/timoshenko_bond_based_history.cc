// ---------------------------------------------------------------------
// PeriDeal: the softening histories of the Timoshenko bond model: whether they grew, and their
// checkpoint values.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>

#include <perideal/pd/timoshenko_bond_based.h>
#include <perideal/pd/timoshenko_kernel.h>

#include <string>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  bool
  TimoshenkoBondBased<dim>::damage_changed() const
  {
    return failure == FailureLaw::softening &&
           Utilities::MPI::max(kernel->largest_growth, communicator) > softening_tolerance;
  }

  template <int dim>
  unsigned int
  TimoshenkoBondBased<dim>::n_bond_history_values() const
  {
    return failure == FailureLaw::softening ? 4 : 0;
  }

  template <int dim>
  std::vector<double>
  TimoshenkoBondBased<dim>::bond_history(const ParticleSystem<dim> &particles) const
  {
    if (failure != FailureLaw::softening)
      return {};
    const typename BondBlocks<dim>::Array *lanes[4] = {&kernel->history[0],
                                                       &kernel->history[1],
                                                       &kernel->history[2],
                                                       &kernel->dissipated};
    std::vector<double> per_bond(particles.bonds().size()), values(4 * per_bond.size());
    for (unsigned int v = 0; v < 4; ++v)
      {
        kernel->blocks.from_lanes(*lanes[v], per_bond);
        for (std::size_t b = 0; b < per_bond.size(); ++b)
          values[4 * b + v] = per_bond[b];
      }
    return values;
  }

  template <int dim>
  void
  TimoshenkoBondBased<dim>::set_bond_history(const ParticleSystem<dim> &particles,
                                             const std::vector<double> &values)
  {
    const std::size_t n_bonds = particles.bonds().size();
    AssertDimension(values.size(), n_bond_history_values() * n_bonds);
    if (failure != FailureLaw::softening)
      return;
    std::vector<double> per_bond(n_bonds), mu(n_bonds);
    for (unsigned int m = 0; m < 3; ++m)
      {
        for (std::size_t b = 0; b < n_bonds; ++b)
          {
            per_bond[b] = values[4 * b + m];
            mu[b]       = Timoshenko::softening_factor(per_bond[b], softening);
          }
        kernel->blocks.to_lanes(per_bond, kernel->history[m]);
        kernel->blocks.to_lanes(mu, kernel->factor[m]);
      }
    double total = 0.;
    for (std::size_t b = 0; b < n_bonds; ++b)
      {
        per_bond[b] = values[4 * b + 3];
        total += particles.bond_share(b) * per_bond[b];
      }
    kernel->blocks.to_lanes(per_bond, kernel->dissipated);
    kernel->dissipated_reported = total;
  }

  template bool
  TimoshenkoBondBased<2>::damage_changed() const;
  template bool
  TimoshenkoBondBased<3>::damage_changed() const;
  template unsigned int
  TimoshenkoBondBased<2>::n_bond_history_values() const;
  template unsigned int
  TimoshenkoBondBased<3>::n_bond_history_values() const;
  template std::vector<double>
  TimoshenkoBondBased<2>::bond_history(const ParticleSystem<2> &) const;
  template std::vector<double>
  TimoshenkoBondBased<3>::bond_history(const ParticleSystem<3> &) const;
  template void
  TimoshenkoBondBased<2>::set_bond_history(const ParticleSystem<2> &, const std::vector<double> &);
  template void
  TimoshenkoBondBased<3>::set_bond_history(const ParticleSystem<3> &, const std::vector<double> &);
} // namespace perideal
