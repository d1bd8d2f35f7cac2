// ---------------------------------------------------------------------
// PeriDeal: the solver of <Solver/Type>.
// ---------------------------------------------------------------------
#include <perideal/coupling/solvers/explicit_dynamics.h>
#include <perideal/coupling/solvers/load_stepping.h>
#include <perideal/coupling/solvers/sequentially_linear.h>
#include <perideal/coupling/solvers/solver.h>
#include <perideal/coupling/solvers/theta_scheme.h>

namespace perideal
{
  template <int dim>
  void
  Solver<dim>::check(const CoupledState<dim> &) const
  {}

  template <int dim>
  void
  Solver<dim>::start_state(CoupledState<dim> &)
  {
    AssertThrow(false,
                dealii::ExcMessage("This <Solver/Type> cannot advance a physics of "
                                   "<Physics/List> by operator splitting; accepted: explicit, "
                                   "implicit, static."));
  }

  template <int dim>
  void
  Solver<dim>::advance(CoupledState<dim> &, const double, const double, const bool)
  {
    AssertThrow(false,
                dealii::ExcMessage("This <Solver/Type> cannot advance a physics of "
                                   "<Physics/List> by operator splitting; accepted: explicit, "
                                   "implicit, static."));
  }

  template <int dim>
  void
  Solver<dim>::resume_state(CoupledState<dim> &, const double)
  {}

  template <int dim>
  void
  Solver<dim>::renew_regions(CoupledState<dim> &, const double)
  {
    AssertThrow(false,
                dealii::ExcMessage("This <Solver/Type> cannot follow a conversion of "
                                   "<Coupling/Adaptive region> in a physics of <Physics/List>; "
                                   "accepted: explicit, implicit."));
  }

  template <int dim>
  void
  Solver<dim>::renew_rates(CoupledState<dim> &, const double)
  {
    AssertThrow(false,
                dealii::ExcMessage("This <Solver/Type> cannot take the heating of "
                                   "<Temperature/Coupling> = two way; accepted: explicit."));
  }

  template <int dim>
  std::unique_ptr<Solver<dim>>
  create_solver(const SolverType type, const QuasiStaticControl &control)
  {
    if (type == SolverType::explicit_dynamics)
      return std::make_unique<ExplicitDynamics<dim>>();
    if (type == SolverType::implicit)
      return std::make_unique<ThetaScheme<dim>>();
    if (control.method == LoadControl::sequentially_linear)
      return std::make_unique<SequentiallyLinear<dim>>(control);
    return std::make_unique<LoadStepping<dim>>(type, control);
  }

  template class Solver<2>;
  template class Solver<3>;
  template std::unique_ptr<Solver<2>>
  create_solver<2>(const SolverType, const QuasiStaticControl &);
  template std::unique_ptr<Solver<3>>
  create_solver<3>(const SolverType, const QuasiStaticControl &);
} // namespace perideal
