// ---------------------------------------------------------------------
// PeriDeal: the physics of <Physics/List> of a problem, advanced by operator splitting.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/coupled_problem.h>

#include <cmath>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  CoupledProblem<dim>::parse_other_physics(ParameterHandler &prm)
  {
    physics.resize(1);
    const auto list = Physics<dim>::parse_names(prm);
    if (list.empty())
      return;
    const std::string entry = "<Physics/List> = " + prm.get({"Physics"}, "List");
    const std::string field =
      pd.has_body() ? "<Material/Model> = " + prm.get({"Material"}, "Model") :
                      "<Finite elements/Physics> = " + prm.get({"Finite elements"}, "Physics");
    AssertThrow(!layout.has_temperature(),
                ExcMessage(entry +
                           " adds a temperature, but the top-level sections hold one "
                           "too (" +
                           field +
                           "): with a list they hold the mechanics; accepted there: a "
                           "mechanical model, the conduction model in <Heat/Material/Model>."));
    AssertThrow(settings.solver_type != SolverType::implicit,
                ExcMessage(entry + ": the first physics is advanced by <Solver/Type> = explicit, "
                                   "static or adaptive dynamic relaxation, the others within its "
                                   "steps (doc/architecture/16_multiphysics.md); accepted: "
                                   "explicit, static, adaptive dynamic relaxation."));
    if (settings.solver_type != SolverType::explicit_dynamics)
      {
        // The other physics advance to the time of the load factor solved (load factor x End
        // time); the events of a sequentially linear control have no such time.
        AssertThrow(control.method == LoadControl::load_steps,
                    ExcMessage(entry + ": <Solver/Control/Method> = sequentially linear scales "
                                       "one linear solution by each event's load factor, which "
                                       "falls when bonds break and rises again, so the events "
                                       "give the other physics no time to advance to (a "
                                       "transient heat cannot go back in time; a temperature "
                                       "held over the events would not scale with the "
                                       "mechanical load); accepted with a list: <Solver/Control/"
                                       "Method> = load steps (cut load steps included)."));
        AssertThrow(settings.end_time > 0.,
                    ExcMessage(entry + ": load step k of N of a quasi-static run ends at the time "
                                       "k/N <Time stepping/End time>, to which the other physics "
                                       "advance; <Time stepping/End time> is 0: accepted > 0."));
      }
    for (const auto &item : list)
      {
        physics.push_back(std::make_unique<Physics<dim>>(item.first, comm, log));
        Physics<dim> &field = *physics.back();
        field.parse_parameters(prm, settings, *physics[0]);
        const std::string section = Physics<dim>::section(field.name);
        AssertThrow(field.settings.solver_type != SolverType::static_linear ||
                      settings.solver_type != SolverType::explicit_dynamics,
                    ExcMessage("<" + section +
                               "/Solver/Type> = static solves a steady state "
                               "before each load step of a quasi-static first physics, but "
                               "<Solver/Type> = explicit; accepted there: explicit, implicit "
                               "(or a quasi-static <Solver/Type>: static, adaptive dynamic "
                               "relaxation)."));
        AssertThrow(!field.fe.has_mesh() || field.fe.get_density() > 0.,
                    ExcMessage("The parameter <" + section + "/Finite elements/Density> is " +
                               ParameterUtilities::format_number(field.fe.get_density()) +
                               "; explicit steps need the FE heat capacity rho c: accepted "
                               "values are > 0."));
      }
  }

  template <int dim>
  void
  CoupledProblem<dim>::check_other_physics()
  {
    for (unsigned int k = 1; k < physics.size(); ++k)
      {
        Physics<dim> &field = *physics[k];
        field.with_entry_names([&]() {
          field.fe.setup(
            [&field, this](const Point<dim> &x) { return field.method().fe_weight(blending(x)); });
          // The particles are the first physics': only this physics' model is set up on them.
          field.pd.setup({}, {}, false);
        });
        // The initial disks reach no FE condition of this physics either (those act on its FE
        // field only).
        if (adaptive.enabled())
          adaptive.check_conditions_outside(field.fe,
                                            adaptive.seed_points(),
                                            "With <Coupling/Adaptive region/Initial seeds>",
                                            Physics<dim>::section(field.name) + "/");
        if (is_root && field.pd.has_body())
          log << "Material (" << field.name << "): " << field.pd.material().summary() << std::endl;
        field.method().initialize(coupled_regions(field));
        field.set_state(std::make_unique<CoupledState<dim>>(comm,
                                                            log,
                                                            field.settings,
                                                            field.layout,
                                                            field.pd,
                                                            field.fe,
                                                            field.method()));
        field.state().setup();
        field.set_solver(create_solver<dim>(field.settings.solver_type, control));
        field.solver().check(field.state());
        PostprocessorInputs<dim> inputs;
        inputs.control = control;
        inputs.method  = &field.method();
        field.set_postprocessors(
          std::make_unique<Postprocessors<dim>>(postprocessor_names, inputs));
        field.postprocessors().initialize(field.state());
      }
  }

  template <int dim>
  void
  CoupledProblem<dim>::setup_other_physics()
  {
    if (physics.size() == 1)
      return;
    sub_steps.assign(physics.size() - 1, 0.);
    for (unsigned int k = 1; k < physics.size(); ++k)
      {
        Physics<dim> &field = *physics[k];
        if (is_root)
          log << "Physics " << field.name << ":" << std::endl;
        // An implicit physics takes one step per step of the first physics, as its run will
        // take it.
        if (field.settings.solver_type == SolverType::implicit)
          field.settings.time_step = split_step();
        field.solver().setup(field.state());
        choose_sub_steps(k);
        // Through a conversion of the adaptive PD region too (convert_regions()).
        if (state().adaptation_interval() > 0)
          field.state().set_adaptive_region({}, state().adaptation_interval());
        postprocessors().add_physics(field.name, field.state(), field.postprocessors());
        for (unsigned int c = 0; c < field.layout.n_components(); ++c)
          if (field.layout.kind(c) == ComponentKind::temperature)
            exchange
              .publish("temperature", field.state().u, field.state().U, field.fe, field.layout, c);
      }
    if (temperature.two_way())
      for (unsigned int k = 1; k < physics.size(); ++k)
        if (physics[k]->layout.has_temperature())
          heating.connect(pd, fe, state().u, state().U, temperature, physics[k]->state());
    // A two-way coupling advances the heat inside the mechanics' step (the adiabatic split).
    state().set_other_physics(
      [this](const unsigned int step, const double time, const double dt, const bool with_energy) {
        advance_other_physics(step, time, dt, with_energy);
      },
      heating.active());
    state().set_broken_bond_record(exchange.record());
  }

  template <int dim>
  void
  CoupledProblem<dim>::choose_sub_steps(const unsigned int k)
  {
    Physics<dim> &field = *physics[k];
    // A steady physics solves once per load step.
    const double step_length = split_step();
    if (field.settings.solver_type == SolverType::static_linear)
      field.state().time_step = step_length;
    // The largest step of at most its own (the safety factor times its stable step) that
    // divides the first physics' step, as its run takes it. The heat of a two-way coupling takes
    // an even number: its conduction over the step, (I - h C^-1 L)^n, is then a positive map
    // (every mode's factor in [0, 1]), which the adiabatic split needs to be stable
    // (doc/theory/thermoelasticity.md, "The stable time step").
    auto n = static_cast<unsigned int>(
      std::max(1., std::ceil(step_length / field.state().time_step * (1. - 1e-12))));
    if (temperature.two_way() && field.layout.has_temperature())
      n += n % 2;
    field.state().time_step = step_length / n;
    sub_steps[k - 1]        = field.state().time_step;
    if (is_root && field.settings.solver_type == SolverType::static_linear)
      log << "  a steady solve before each load step of the first physics" << std::endl;
    else if (is_root)
      log << "  " << n << " step" << (n > 1 ? "s" : "") << " of " << field.state().time_step
          << " s per step of the first physics" << std::endl;
  }

  template <int dim>
  void
  CoupledProblem<dim>::advance_other_physics(const unsigned int step,
                                             const double       time,
                                             const double       dt,
                                             const bool         with_energy)
  {
    // What the first physics broke in its step is broken for the others before theirs.
    exchange.share_broken_bonds(pd.particles().bonds());
    // A two-way coupling: the measure the first step heats from.
    if (heating.active() && step == 0)
      heating.start();
    for (unsigned int k = 1; k < physics.size(); ++k)
      {
        Physics<dim> &field = *physics[k];
        if (step == 0)
          {
            field.solver().start_state(field.state());
            continue;
          }
        // The fewest equal steps of at most the set-up's one: its n steps over a step of the
        // first physics, fewer over a cut load step.
        const auto n =
          static_cast<unsigned int>(std::max(1., std::ceil(dt / sub_steps[k - 1] * (1. - 1e-12))));
        const double length = dt / n;
        if (resume_other_physics)
          field.solver().resume_state(field.state(), time);
        // A two-way coupling: the adiabatic phase (the heating of the step at the mechanics' end
        // configuration, at once), then the conduction from the renewed rates.
        if (heating.active() && field.layout.has_temperature())
          {
            heating.heat_step();
            field.solver().renew_rates(field.state(), time);
          }
        for (unsigned int s = 0; s < n; ++s)
          field.solver().advance(field.state(),
                                 time + s * length,
                                 length,
                                 with_energy && s + 1 == n);
        // The force of the supports, for the reactions (explicit runs keep it from the last
        // step's residual).
        if (with_energy && field.settings.solver_type == SolverType::explicit_dynamics)
          field.state().fe_support.equ(-1., field.state().residual);
      }
    resume_other_physics = resume_other_physics && step == 0;
  }

  template <int dim>
  double
  CoupledProblem<dim>::split_step() const
  {
    if (settings.solver_type != SolverType::explicit_dynamics)
      return settings.end_time / settings.load_steps;
    double dt = state().time_step;
    ParameterUtilities::equal_time_steps(settings.end_time, dt);
    return dt;
  }

  template <int dim>
  const PhysicsExchange<dim> &
  CoupledProblem<dim>::get_exchange() const
  {
    return exchange;
  }

#define PERIDEAL_INSTANTIATE(dim)                                                 \
  template void CoupledProblem<dim>::parse_other_physics(ParameterHandler &);     \
  template void CoupledProblem<dim>::check_other_physics();                       \
  template void CoupledProblem<dim>::setup_other_physics();                       \
  template void CoupledProblem<dim>::choose_sub_steps(const unsigned int);        \
  template void CoupledProblem<dim>::advance_other_physics(const unsigned int,    \
                                                           const double,          \
                                                           const double,          \
                                                           const bool);           \
  template const PhysicsExchange<dim> &CoupledProblem<dim>::get_exchange() const; \
  template double                      CoupledProblem<dim>::split_step() const;
  PERIDEAL_INSTANTIATE(2)
  PERIDEAL_INSTANTIATE(3)
#undef PERIDEAL_INSTANTIATE
} // namespace perideal
