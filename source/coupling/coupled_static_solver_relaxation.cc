// ---------------------------------------------------------------------
// PeriDeal: the static linear solve of an FE-PD coupling: adaptive dynamic relaxation of its
// unknowns.
// ---------------------------------------------------------------------
#include <perideal/coupling/coupled_static_solver.h>
#include <perideal/coupling/matrix_rows.h>

#include <cmath>


namespace perideal
{
  using namespace dealii;

  template <int dim>
  std::unique_ptr<AdaptiveDynamicRelaxation>
  CoupledStaticSolver<dim>::relaxation(
    const std::function<void(ParticleVector &, ParticleVector &)> &residual,
    const ParticleVector                                          &prescribed_values,
    const AdaptiveDynamicRelaxation::Settings                     &settings,
    const double                                                   safety) const
  {
    AdaptiveDynamicRelaxation::Operations operations;
    operations.clear_prescribed       = [this](ParticleVector &v) { clear_prescribed(v); };
    operations.prescribe_displacement = [this, &prescribed_values](ParticleVector &z) {
      for (std::size_t k = 0; k < prescribed.size(); ++k)
        if (prescribed[k])
          z.local_element(k) = prescribed_values.local_element(k);
    };
    operations.residual = [this, residual](ParticleVector &z, ParticleVector &force) {
      residual(z, force);
      clear_prescribed(force);
    };
    std::vector<double> bound(prescribed.size(), 0.);
    for_each_local_row(system_matrix,
                       [&](const auto row, const auto &columns, const double *values) {
                         for (std::size_t k = 0; k < columns.size(); ++k)
                           bound[row - z_first] += std::abs(values[k]);
                       });
    ParticleVector density;
    reinit_unknowns(density);
    AdaptiveDynamicRelaxation::fictitious_density(bound, safety, density);
    return std::make_unique<AdaptiveDynamicRelaxation>(operations, density, settings, comm);
  }

  template class CoupledStaticSolver<2>;
  template class CoupledStaticSolver<3>;
} // namespace perideal
