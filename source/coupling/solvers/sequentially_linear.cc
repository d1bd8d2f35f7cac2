// ---------------------------------------------------------------------
// PeriDeal: quasi-static fracture event by event (sequentially linear control).
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/solvers/equilibrium_state.h>
#include <perideal/coupling/solvers/run_control.h>
#include <perideal/coupling/solvers/sequentially_linear.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/material_model.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  SequentiallyLinear<dim>::SequentiallyLinear(const QuasiStaticControl &control)
    : LoadStepping<dim>(SolverType::static_linear, control)
  {}

  template <int dim>
  void
  SequentiallyLinear<dim>::check(const CoupledState<dim> &state) const
  {
    const std::string method = "<Solver/Control/Method> = sequentially linear";
    AssertThrow(state.pd().has_body(),
                ExcMessage(method + " needs particles (<Discretization/Body>): bonds are what "
                                    "breaks."));
    const auto &material = state.pd().material();
    AssertThrow(material.capabilities().sequentially_linear,
                ExcMessage(method +
                           " breaks bonds by the linearized stretch of a displacement field "
                           "(times each bond's breaking factor) against the critical stretch; "
                           "<Material/Model> accepted: " +
                           material_models_with<dim>(&ModelCapabilities::sequentially_linear) +
                           "."));
    AssertThrow(std::isfinite(state.pd().critical_stretch()),
                ExcMessage(method + " needs bonds that break: <Material/Damage model> = none; use "
                                    "'critical stretch'."));
    LoadStepping<dim>::check(state);
  }

  template <int dim>
  void
  SequentiallyLinear<dim>::setup(CoupledState<dim> &state)
  {
    LoadStepping<dim>::setup(state);
    measures.initialize(state, this->control);
    bond_factor.assign(state.pd().particles().bonds().size(), 0.);
    intact_bonds.assign(state.pd().particles().n_owned(), 0);
  }

  template <int dim>
  double
  SequentiallyLinear<dim>::critical_factors(const CoupledState<dim> &state)
  {
    const auto        &ps       = state.pd().particles();
    const auto        &bonds    = ps.bonds();
    const auto        &x        = ps.positions();
    const auto        &u        = state.u;
    const unsigned int nc       = state.n_components();
    const double       s0       = state.pd().critical_stretch();
    const auto         scale    = state.pd().material().breaking_factors(ps);
    const double       infinity = std::numeric_limits<double>::infinity();
    double             smallest = infinity;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          double factor = infinity;
          if (bonds.intact[b] == 1)
            {
              const unsigned int j         = bonds.neighbor[b];
              double             extension = 0.;
              for (unsigned int d = 0; d < dim; ++d)
                extension +=
                  (x[j][d] - x[i][d]) * (u.local_element(j * nc + d) - u.local_element(i * nc + d));
              const double stretch = scale[b] * extension / (bonds.length[b] * bonds.length[b]);
              if (stretch > 0.)
                factor = s0 / stretch;
            }
          bond_factor[b] = factor;
          smallest       = std::min(smallest, factor);
        }
    return Utilities::MPI::min(smallest, state.comm());
  }

  template <int dim>
  unsigned long
  SequentiallyLinear<dim>::loose_particles(const CoupledState<dim> &state, const double limit)
  {
    using Motion                = typename CoupledState<dim>::Motion;
    const auto        &ps       = state.pd().particles();
    const auto        &bonds    = ps.bonds();
    const auto        &material = state.pd().material();
    const unsigned int n        = ps.n_owned();
    std::fill(intact_bonds.begin(), intact_bonds.end(), 0u);
    // A bond at its limit that softens (rather than breaks) stays.
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b] != 0 && !(bond_factor[b] <= limit && material.bond_breaks_at_limit(b)))
          {
            ++intact_bonds[i];
            if (bonds.neighbor[b] < n)
              ++intact_bonds[bonds.neighbor[b]];
          }
    unsigned long loose = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (intact_bonds[i] == 0 && state.motion()[i * state.n_components()] == Motion::moves)
        ++loose;
    return Utilities::MPI::sum(loose, state.comm());
  }

  template <int dim>
  void
  SequentiallyLinear<dim>::break_bonds(CoupledState<dim> &state, const double limit) const
  {
    auto &particles = state.pd().particles();
    auto &material  = state.pd().material();
    auto &bonds     = particles.bonds();
    for (std::size_t b = 0; b < bonds.size(); ++b)
      if (bonds.intact[b] == 1 && bond_factor[b] <= limit)
        material.limit_reached(particles, state.u, b);
  }

  template <int dim>
  void
  SequentiallyLinear<dim>::run(CoupledState<dim>   &state,
                               Postprocessors<dim> &postprocessors,
                               Checkpoint<dim>     &checkpoint)
  {
    const auto  &settings = state.settings();
    auto        &pd       = state.pd();
    auto        &ps       = pd.particles();
    const double infinity = std::numeric_limits<double>::infinity();
    const auto   number   = [](const double x) { return ParameterUtilities::format_number(x); };
    this->conditions_at(state, settings.end_time);

    // The peak so far, which decides the end of the run: a part of the checkpoints.
    double       peak = 0., peak_factor = 0.;
    unsigned int peak_event = 0;
    checkpoint.add_part(
      "sequentially linear peak = load, load factor, event",
      [&](CheckpointWriter &writer) {
        writer.add_totals("sequentially linear/peak", {peak, peak_factor, double(peak_event)});
      },
      [&](CheckpointReader &reader) {
        const auto values = reader.read_totals("sequentially linear/peak", 3);
        peak              = values[0];
        peak_factor       = values[1];
        peak_event        = static_cast<unsigned int>(values[2]);
      });
    RunControl<dim>   run(state, postprocessors, checkpoint, true);
    const RunPosition start =
      run.start("sequentially linear", this->control.max_events, [&]() { state.start_work(); });
    for (unsigned int event = start.step + 1;; ++event)
      {
        // The linear solution at load factor 1 with the bonds broken so far.
        this->apply_load_factor(state, 1.);
        unsigned int iterations = 0;
        try
          {
            iterations =
              state.method().solve_equilibrium(state.f_ext, state.external_force, state.U, state.u);
          }
        catch (const ExcNotConverged &failure)
          {
            const std::string what = "The solve of event " + std::to_string(event);
            const std::string files =
              this->write_last_iterate(state, postprocessors, event, 1., what);
            AssertThrow(false,
                        ExcNotConverged(this->failure_text(failure) + "\n" + what +
                                        " did not converge. Its last iterate is written for "
                                        "inspection (" +
                                        files + "; statistics.csv ends at event " +
                                        std::to_string(event - 1) +
                                        "). Change <Solver/Linear solver>, <Solver/Tolerance> or "
                                        "<Solver/Maximum iterations> and run again."));
          }

        // Scaled to the load factor at which the most critical bond reaches s0.
        const double critical = critical_factors(state);
        const double factor   = std::min(critical, 1.);
        state.U *= factor;
        state.u *= factor;
        state.U.update_ghost_values();
        state.u.update_ghost_values();
        // The prescribed values are scaled with the solution; the loads follow.
        this->scale_loads(state, factor);
        pd.material().compute_forces(ps,
                                     state.u,
                                     state.internal_force,
                                     &state.energy_density,
                                     infinity);
        const double pd_energy = equilibrium_state(state);
        const auto   values    = measures.measure(state);
        const double load      = std::abs(values.load);
        if (load > peak)
          {
            peak        = load;
            peak_factor = factor;
            peak_event  = event;
          }

        // Whether the run ends here, and why.
        const double limit = critical * (1. + this->control.event_tolerance);
        std::string  reason;
        if (load < this->control.separation_fraction * peak)
          reason = "the body has separated: the load " + number(load) +
                   " N fell below <Solver/Control/Separation load fraction> = " +
                   number(this->control.separation_fraction) + " of its peak";
        else if (critical == infinity)
          reason = "no intact bond is stretched by the load, so none can break";
        else if (critical >= 1.)
          reason = "the load factor reached 1 (the conditions at <Time stepping/End time>) "
                   "before the body separated";
        else if (const auto loose = loose_particles(state, limit); loose > 0)
          reason = "the body has separated: breaking the next critical bonds would leave " +
                   std::to_string(loose) + " free particle(s) without a bond (a loose piece)";
        else if (event == this->control.max_events)
          reason = "<Solver/Control/Maximum events> = " + std::to_string(this->control.max_events) +
                   " reached before the body separated";

        if (state.is_root() && settings.show_progress)
          state.log() << "Event " << event << ": load factor " << factor << ", load " << values.load
                      << " N, " << values.broken_bonds << " broken bonds, " << iterations
                      << " CG iterations" << std::endl;
        // Fields after the last event only.
        StepData data     = run.plan(event, factor, !reason.empty());
        data.write_fields = data.final_row;
        data.iterations   = iterations;
        data.pd_energy    = pd_energy;
        run.write(data);
        if (data.final_row)
          {
            if (state.is_root())
              state.log() << "Sequentially linear control: " << event << " events, peak load "
                          << number(peak) << " N at event " << peak_event << " (load factor "
                          << number(peak_factor) << "); the run ends: " << reason << "."
                          << std::endl;
            return;
          }

        // The critical bonds break, or soften by a tooth, at this state (their energy is
        // dissipated).
        break_bonds(state, limit);
        state.accumulate_dissipated_energy();
        // The checkpoint of the event holds its broken bonds: a restart solves the next one.
        if (run.checkpoint(data))
          return;
      }
  }

  template class SequentiallyLinear<2>;
  template class SequentiallyLinear<3>;
} // namespace perideal
