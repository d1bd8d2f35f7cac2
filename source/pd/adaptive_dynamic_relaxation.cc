// ---------------------------------------------------------------------
// PeriDeal: adaptive dynamic relaxation for quasi-static peridynamics.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/base/exact_sum.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/base/problem_settings.h>
#include <perideal/pd/adaptive_dynamic_relaxation.h>

#include <cmath>
#include <sstream>
#include <utility>

namespace perideal
{
  using namespace dealii;

  AdaptiveDynamicRelaxation::AdaptiveDynamicRelaxation(const Operations     &operations,
                                                       const ParticleVector &density,
                                                       const Settings       &settings,
                                                       const MPI_Comm        comm)
    : operations(operations)
    , lambda(density)
    , settings(settings)
    , round_off_force(1e-12 * settings.length_scale * exact_l2_norm(density))
    , communicator(comm)
  {}

  void
  AdaptiveDynamicRelaxation::fictitious_density(const std::vector<double> &bound,
                                                const double               safety,
                                                ParticleVector            &density)
  {
    for (std::size_t k = 0; k < bound.size(); ++k)
      {
        // An isolated particle (no bond) still gets a positive density.
        const double value = bound[k] > 0. ? 0.25 * safety * bound[k] : 1.;
        // Rounded up to 9 significant bits (at most 0.2 % more): the bound is summed from the
        // entries of a matrix assembled on the ranks, so its last bits depend on the partition
        // (differences of 1e-14 measured), and the relaxation would amplify them. The rounded
        // value is the same on any number of ranks unless the bound lies within 1e-14 of one of
        // the 512 points of its binary octave (probability about 1e-11 per unknown).
        int          exponent;
        const double fraction    = std::frexp(value, &exponent);
        density.local_element(k) = std::ldexp(std::ceil(std::ldexp(fraction, 9)), exponent - 9);
      }
  }

  AdaptiveDynamicRelaxation::Result
  AdaptiveDynamicRelaxation::solve(ParticleVector &u, const double external_norm)
  {
    const std::size_t n_values = u.locally_owned_size();
    ParticleVector    force, previous_force, v;
    force.reinit(u, true);
    previous_force.reinit(u, true);
    v.reinit(u, true);

    operations.prescribe_displacement(u);
    operations.residual(u, force);
    // Every global sum below is exact (ExactSum), so the iterations are the same on any number
    // of ranks when the forces are (doc/architecture/08_solvers.md).
    const double initial_norm = exact_l2_norm(force);
    const double scale        = std::max(external_norm, initial_norm);
    Result       result;
    if (scale <= round_off_force)
      return result;

    std::vector<std::pair<unsigned int, double>> history;
    const unsigned int report_every = std::max(1u, settings.max_iterations / 10);
    history.emplace_back(0, initial_norm / scale);

    // v^{1/2} = F^0 / (2 lambda) (dt = 1).
    for (std::size_t k = 0; k < n_values; ++k)
      v.local_element(k) = 0.5 * force.local_element(k) / lambda.local_element(k);
    operations.clear_prescribed(v);

    double residual = initial_norm / scale;
    for (unsigned int n = 1; n <= settings.max_iterations; ++n)
      {
        u += v;
        operations.prescribe_displacement(u);
        previous_force.swap(force);
        operations.residual(u, force);
        residual = exact_l2_norm(force) / scale;
        AssertThrow(std::isfinite(residual),
                    ExcMessage("Adaptive dynamic relaxation diverged at iteration " +
                               std::to_string(n) +
                               " (non-finite residual): the fictitious density is below the "
                               "stiffness bound of the model."));
        if (n % report_every == 0)
          history.emplace_back(n, residual);
        result.iterations        = n;
        result.relative_residual = residual;
        if (residual < settings.tolerance)
          return result;

        // Damping from the local Rayleigh quotient with the diagonal stiffness estimate, over
        // the moving components (prescribed ones have v = 0 and no stiffness estimate).
        std::vector<ExactSum> local(2);
        for (std::size_t k = 0; k < n_values; ++k)
          {
            const double uk = u.local_element(k), vk = v.local_element(k);
            if (vk != 0.)
              {
                const double K = -(force.local_element(k) - previous_force.local_element(k)) /
                                 (lambda.local_element(k) * vk);
                local[0].add(uk * K * uk);
                local[1].add(uk * uk);
              }
          }
        const std::vector<double> global = ExactSum::global_sums(std::move(local), communicator);
        double                    c      = 0.;
        if (global[0] > 0. && global[1] > 0.)
          c = 2. * std::sqrt(global[0] / global[1]);
        if (c > 2.)
          c = 1.9;

        for (std::size_t k = 0; k < n_values; ++k)
          v.local_element(k) = ((2. - c) * v.local_element(k) +
                                2. * force.local_element(k) / lambda.local_element(k)) /
                               (2. + c);
        operations.clear_prescribed(v);
      }

    std::ostringstream message;
    message << "Adaptive dynamic relaxation did not converge in " << settings.max_iterations
            << " iterations (<Solver/Maximum iterations>): the relative residual ||F|| / "
               "max(||F_ext||, ||F_0||) is "
            << residual << ", the tolerance (<Solver/Tolerance>) " << settings.tolerance
            << ". Residual history (iteration: relative residual):";
    for (const auto &[iteration, value] : history)
      message << "\n  " << iteration << ": " << value;
    message << "\nIncrease <Solver/Maximum iterations> or <Solver/Load steps>, or relax the "
               "tolerance.";
    AssertThrow(false, ExcNotConverged(message.str()));
    return result;
  }
} // namespace perideal
