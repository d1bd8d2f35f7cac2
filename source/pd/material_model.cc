// ---------------------------------------------------------------------
// PeriDeal: interface of peridynamic material models.
// ---------------------------------------------------------------------
#include <perideal/pd/material_model.h>

#include <cmath>
#include <limits>

namespace perideal
{
  void
  LinearizedModel::reinit(const unsigned int n_components, const unsigned int n_owned)
  {
    components = n_components;
    row_start.assign(1, 0);
    entries.clear();
    weights.clear();
    scale.assign(n_owned, 0.);
  }

  void
  LinearizedModel::add_row(const double weight, const std::vector<Entry> &row)
  {
    entries.insert(entries.end(), row.begin(), row.end());
    row_start.push_back(entries.size());
    weights.push_back(weight);
  }

  unsigned int
  LinearizedModel::n_components() const
  {
    return components;
  }

  std::size_t
  LinearizedModel::n_rows() const
  {
    return weights.size();
  }

  double
  LinearizedModel::weight(const std::size_t r) const
  {
    return weights[r];
  }

  const LinearizedModel::Entry *
  LinearizedModel::row_begin(const std::size_t r) const
  {
    return entries.data() + row_start[r];
  }

  const LinearizedModel::Entry *
  LinearizedModel::row_end(const std::size_t r) const
  {
    return entries.data() + row_start[r + 1];
  }

  std::vector<double> &
  LinearizedModel::stiffness_scale()
  {
    return scale;
  }

  const std::vector<double> &
  LinearizedModel::stiffness_scale() const
  {
    return scale;
  }

  template <int dim>
  double
  MaterialModel<dim>::stable_time_step(const ParticleSystem<dim> &particles,
                                       const double               density) const
  {
    std::vector<double> bound;
    stiffness_bound(particles, bound);
    double dt = std::numeric_limits<double>::max();
    for (const double k : bound)
      if (k > 0.)
        dt = std::min(dt, std::sqrt(4. * density / k));
    return dealii::Utilities::MPI::min(dt, particles.get_communicator());
  }

  template <int dim>
  void
  MaterialModel<dim>::linearize(const ParticleSystem<dim> &, LinearizedModel &) const
  {
    AssertThrow(false,
                dealii::ExcMessage("This material model provides no linearization; the static "
                                   "solver (<Solver/Type> = static) cannot use it. Choose "
                                   "<Solver/Type> = adaptive dynamic relaxation or explicit."));
  }

  template class MaterialModel<2>;
  template class MaterialModel<3>;
} // namespace perideal
