// ---------------------------------------------------------------------
// PeriDeal: the error of a quasi-static run against an exact displacement field.
// ---------------------------------------------------------------------
#include <deal.II/lac/vector.h>

#include <perideal/coupling/postprocessors/exact_error.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  ExactError<dim>::set_inputs(const PostprocessorInputs<dim> &inputs)
  {
    exact     = inputs.exact_displacement;
    tolerance = inputs.exact_tolerance;
    method    = inputs.method;
  }

  template <int dim>
  void
  ExactError<dim>::execute(const CoupledState<dim> &state, const StepData &data, StatisticsFile &)
  {
    if (!exact || !data.final_row)
      return;
    using Motion               = typename CoupledState<dim>::Motion;
    const auto        &ps      = state.pd().particles();
    const auto        &x       = ps.positions();
    const auto        &volume  = ps.volumes();
    const unsigned int n_owned = ps.n_owned(), nc = state.n_components();
    const MPI_Comm     comm = state.comm();

    // The exact field at the FE nodes and the particles (those slaved to the FE field through
    // the method's P, as the coupled model sees them).
    FEVector       U_exact, fe_residual;
    ParticleVector u_exact, force;
    state.fe().initialize_vector(U_exact);
    state.fe().initialize_vector(fe_residual);
    ps.reinit_vector(u_exact, nc);
    ps.reinit_vector(force, nc);
    state.fe().interpolate(*exact, U_exact);

    // The largest errors relative to the largest exact values.
    double fe_error = 0., fe_exact = 0., pd_error = 0., pd_exact = 0.;
    for (unsigned int k = 0; k < U_exact.locally_owned_size(); ++k)
      {
        fe_error =
          std::max(fe_error, std::abs(state.U.local_element(k) - U_exact.local_element(k)));
        fe_exact = std::max(fe_exact, std::abs(U_exact.local_element(k)));
      }
    Vector<double> value(nc);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        exact->vector_value(x[i], value);
        double e2 = 0., v2 = 0.;
        for (unsigned int c = 0; c < nc; ++c)
          {
            e2 += std::pow(state.u.local_element(i * nc + c) - value[c], 2);
            v2 += value[c] * value[c];
            u_exact.local_element(i * nc + c) = value[c];
          }
        pd_error = std::max(pd_error, std::sqrt(e2));
        pd_exact = std::max(pd_exact, std::sqrt(v2));
      }
    fe_error = Utilities::MPI::max(fe_error, comm);
    fe_exact = Utilities::MPI::max(fe_exact, comm);
    pd_error = Utilities::MPI::max(pd_error, comm);
    pd_exact = Utilities::MPI::max(pd_exact, comm);
    fe_error = fe_exact > 0. ? fe_error / fe_exact : fe_error;
    pd_error = pd_exact > 0. ? pd_error / pd_exact : pd_error;
    if (state.is_root())
      {
        const auto flags = state.log().flags();
        state.log()
          << std::scientific << std::setprecision(6)
          << "Displacement error (largest, relative to the largest exact value): FE nodes "
          << fe_error << ", particles " << pd_error << "\n";
        if (tolerance > 0.)
          state.log() << "Displacement error below " << tolerance << ": "
                      << (std::max(fe_error, pd_error) < tolerance ? "yes" : "no") << "\n";
        state.log() << std::flush;
        state.log().flags(flags);
      }

    // The residual K z - F of the exact field: the ghost force of the coupling for a state the
    // uncoupled models reproduce (the number explicit runs print at t = 0).
    U_exact.update_ghost_values();
    state.method().interpolate_to_particles(U_exact, u_exact);
    u_exact.update_ghost_values();
    Assert(method == &state.method(), ExcMessage("ExactError needs the state's method."));
    method->equilibrium_forces(U_exact,
                               u_exact,
                               state.fe_equation_load(),
                               state.external_force,
                               fe_residual,
                               force);
    const auto &mask    = state.fe().prescribed_mask();
    double      largest = 0., scale = 0.;
    for (unsigned int k = 0; k < U_exact.locally_owned_size(); ++k)
      if (!mask[k])
        largest = std::max(largest, std::abs(fe_residual.local_element(k)));
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      if (state.motion()[k] == Motion::moves)
        largest =
          std::max(largest,
                   std::abs(force.local_element(k) + state.external_force.local_element(k)) *
                     volume[k / nc]);
    for (const double sum : state.fe().absolute_row_sums(&U_exact))
      scale = std::max(scale, sum);
    state.log_residual("Force residual of the exact field", largest, scale);
  }

  template class ExactError<2>;
  template class ExactError<3>;
} // namespace perideal

PERIDEAL_REGISTER_POSTPROCESSOR(
  perideal::ExactError,
  "exact error",
  "quasi-static runs with <Coupling/Exact displacement>: the errors against it and its force residual, in the summary.")
