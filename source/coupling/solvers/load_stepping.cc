// ---------------------------------------------------------------------
// PeriDeal: quasi-static load stepping with bond breaking.
// ---------------------------------------------------------------------
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/coupled_static_solver.h>
#include <perideal/coupling/solvers/equilibrium_state.h>
#include <perideal/coupling/solvers/load_stepping.h>
#include <perideal/coupling/solvers/run_control.h>
#include <perideal/pd/damage_model.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  LoadStepping<dim>::LoadStepping(const SolverType type, const QuasiStaticControl &control)
    : type(type)
    , control(control)
  {
    Assert(type != SolverType::explicit_dynamics, ExcInternalError());
  }

  template <int dim>
  void
  LoadStepping<dim>::check(const CoupledState<dim> &state) const
  {
    using Motion                  = typename CoupledState<dim>::Motion;
    const auto        &fe         = state.fe();
    const auto        &conditions = state.pd().boundary_conditions();
    const unsigned int nc         = state.n_components();

    CoupledStaticSolver<dim>::check_mesh(fe);

    // Conditions a static solve cannot apply, and components no condition holds.
    const auto        rates          = conditions.names_of(Quantity::rate);
    const std::string condition_list = condition_names(state);
    for (const auto &c : fe.conditions())
      AssertThrow(c.type != Quantity::rate,
                  ExcMessage("The FE boundary condition <" + c.name + "> is of type '" +
                             quantity_name(state.layout().kind(c.components[0]), Quantity::rate) +
                             "', which a quasi-static solve (<Solver/Type> = static or adaptive "
                             "dynamic relaxation) cannot apply; use '" +
                             quantity_name(state.layout().kind(c.components[0]), Quantity::value) +
                             "' (scaled by the load factor) instead."));
    // A convection's heat flux depends on the temperature: the static solve holds its
    // conductance in the matrix (setup()); the relaxation has no matrix term for it.
    for (unsigned int k = 0; k < conditions.names().size(); ++k)
      AssertThrow(type != SolverType::adaptive_dynamic_relaxation ||
                    conditions.type_name(k) != "convection",
                  ExcMessage("The boundary condition <" + conditions.names()[k] +
                             "> is of type 'convection', which <Solver/Type> = adaptive dynamic "
                             "relaxation cannot apply; accepted there: 'value' and 'flux' (or "
                             "<Solver/Type> = static, implicit or explicit dynamics)."));
    for (unsigned int k = 0; k < conditions.names().size(); ++k)
      AssertThrow(std::find(rates.begin(), rates.end(), conditions.names()[k]) == rates.end(),
                  ExcMessage("The boundary condition <" + conditions.names()[k] + "> is of type '" +
                             conditions.type_name(k) +
                             "', which a quasi-static solve (<Solver/Type> = static or adaptive "
                             "dynamic relaxation) cannot apply; use '" +
                             (conditions.type_name(k) == "velocity" ? "displacement" :
                              conditions.type_name(k) == "rate"     ? "value" :
                                                                      "rotation") +
                             "' (scaled by the load factor) instead."));
    const bool        relax       = (type == SolverType::adaptive_dynamic_relaxation);
    const std::string solver_name = relax ? "adaptive dynamic relaxation" : "static";
    check_convection_on_free_particles(state, solver_name);

    AssertThrow(control.history != LoadHistory::time || state.settings().end_time > 0.,
                ExcMessage("<Solver/Control/Load history> = time evaluates the conditions at t = "
                           "load factor x <Time stepping/End time>, which is 0: set End time > 0 "
                           "(the t at which the last load step ends)."));
    // The FE dofs held: those of value conditions and a held point (FEPhysics::held_point()).
    std::vector<double> constrained(nc, 0.);
    const auto         &held = fe.prescribed_mask();
    const auto          of   = fe.component_masks();
    const unsigned int  n_fe = fe.has_mesh() ? fe.field_layout().n_components() : 0;
    for (unsigned int c = 0; c < n_fe && fe.n_dofs() > 0; ++c)
      for (std::size_t k = 0; k < held.size(); ++k)
        constrained[c] += (held[k] && of[c][k]) ? 1. : 0.;
    // A convection condition holds a temperature (its h T is in the FE stiffness or, on
    // particles, in the diagonal of the static system).
    for (const auto &c : fe.conditions())
      if (c.convection)
        for (const unsigned int component : c.components)
          constrained[component] += 1.;
    if (conditions.has_convection())
      for (unsigned int c = 0; c < nc; ++c)
        constrained[c] += state.layout().kind(c) == ComponentKind::temperature ? 1. : 0.;
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      if (state.motion()[k] == Motion::prescribed)
        constrained[k % nc] += 1.;
    // Particle rotations the FE field lacks follow 1/2 curl of the FE displacement where
    // particles are slaved to it: the FE conditions that hold the translations hold them too.
    if (state.any_particle_slaved() && fe.has_mesh())
      for (unsigned int c = n_fe; c < nc; ++c)
        constrained[c] += 1.;
    // A component no displacement condition holds leaves a rigid mode free: the static system
    // is singular; the relaxation leaves it at rest while it is not loaded, but needs at least
    // one condition.
    const std::string where = state.is_coupled() ? "in <Finite elements/Boundary conditions> (type "
                                                   "'displacement') or on free particles in "
                                                   "<Boundary conditions>" :
                              fe.has_mesh()      ? "in <Finite elements/Boundary conditions> (type "
                                                   "'displacement')" :
                                                   "on a region in <Boundary conditions> (type "
                                                   "'displacement')";
    const std::string conditions_named =
      " (boundary conditions: " + (condition_list.empty() ? std::string("none") : condition_list) +
      ")";
    // Rotations of micropolar models are no rigid mode by themselves: a uniform rotation with
    // the translations at rest strains the bonds (seed 003: the bond's shear strain).
    double n_constrained = 0.;
    for (unsigned int c = 0; c < nc; ++c)
      {
        constrained[c] = Utilities::MPI::sum(constrained[c], state.comm());
        n_constrained += constrained[c];
        const std::string &name = state.layout().name(c);
        AssertThrow(constrained[c] > 0. || relax ||
                      state.layout().kind(c) == ComponentKind::rotation,
                    ExcMessage("No displacement condition prescribes the " + name +
                               " component anywhere" + conditions_named +
                               ", so a rigid translation in " + name +
                               " is free and the static system (<Solver/Type> = static) is "
                               "singular. Prescribe it " +
                               where +
                               ", or use 'adaptive dynamic relaxation', which leaves unloaded "
                               "rigid motions at rest."));
      }
    AssertThrow(n_constrained > 0.,
                ExcMessage("A quasi-static solve (<Solver/Type> = " + solver_name +
                           ") needs at least one displacement condition" + conditions_named +
                           ": without one every rigid motion is free. Prescribe one " + where +
                           "."));
  }

  template <int dim>
  void
  LoadStepping<dim>::setup(CoupledState<dim> &state)
  {
    using Motion = typename CoupledState<dim>::Motion;
    this->check(state);
    const auto        &fe = state.fe();
    const unsigned int nc = state.n_components();
    state.pd().particles().reinit_vector(prescribed, nc);
    // The conditions at one time (conditions_at()).
    state.pd().particles().reinit_vector(target, nc);
    state.pd().particles().reinit_vector(full_load, nc);
    fe.initialize_vector(fe_target);
    fe.initialize_vector(fe_full_load);
    for (std::size_t k = 0; k < state.motion().size(); ++k)
      if (state.motion()[k] == Motion::prescribed)
        prescribed.local_element(k) = 1.;

    const auto              &settings = state.settings();
    EquilibriumSettings<dim> equilibrium;
    equilibrium.type                      = type;
    equilibrium.linear.linear_solver      = settings.linear_solver;
    equilibrium.linear.tolerance          = settings.tolerance;
    equilibrium.linear.max_iterations     = settings.max_iterations;
    equilibrium.relaxation.tolerance      = settings.tolerance;
    equilibrium.relaxation.max_iterations = settings.max_iterations;
    equilibrium.relaxation.length_scale   = state.pd().discretization().horizon;
    equilibrium.relaxation_safety         = settings.density_safety_factor;
    state.method().initialize_equilibrium(prescribed, equilibrium, condition_names(state));
    const bool relax = (type == SolverType::adaptive_dynamic_relaxation);
    // A particle convection h (T_inf - T) / d: its conductance h V / d in the system's diagonal,
    // its ambient part h T_inf / d a load (conditions_at()).
    if (state.pd().boundary_conditions().has_convection())
      {
        FEVector       fe_diagonal;
        ParticleVector conductance;
        fe.initialize_vector(fe_diagonal);
        state.pd().particles().reinit_vector(conductance, nc);
        state.pd().boundary_conditions().add_convection_conductance(conductance);
        state.method().set_equilibrium_diagonal(fe_diagonal, conductance);
      }
    if (state.is_root())
      state.log() << (relax ? "Adaptive dynamic relaxation: " : "Static solve: ")
                  << state.method().n_unknowns() << " unknowns ("
                  << (state.is_coupled() ? "FE dofs and free particle components" :
                      fe.has_mesh()      ? "FE dofs" :
                                           "particle components")
                  << "), " << settings.load_steps << " load step(s)" << std::endl;
  }

  template <int dim>
  void
  LoadStepping<dim>::conditions_at(CoupledState<dim> &state, const double time)
  {
    full_load = 0.;
    state.pd().boundary_conditions().prescribe_displacement(time, target);
    state.pd().boundary_conditions().add_loads(time, full_load);
    state.pd().boundary_conditions().add_convection(time, nullptr, full_load);
    state.fe().prescribe(time, fe_target, state.V);
    state.fe().assemble_load(time, fe_full_load);
  }

  template <int dim>
  void
  LoadStepping<dim>::apply_load_factor(CoupledState<dim> &state, const double factor)
  {
    // The temperature of the thermal strain is that of the time of the load factor.
    state.update_temperature(factor * state.settings().end_time);
    double scale = factor;
    if (control.history == LoadHistory::time)
      {
        conditions_at(state, factor * state.settings().end_time);
        scale = 1.;
      }
    auto       &U    = state.U;
    auto       &u    = state.u;
    const auto &mask = state.fe().prescribed_mask();
    scale_loads(state, scale);
    for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
      if (mask[k])
        U.local_element(k) = scale * fe_target.local_element(k);
    for (unsigned int k = 0; k < u.locally_owned_size(); ++k)
      if (prescribed.local_element(k) != 0.)
        u.local_element(k) = scale * target.local_element(k);
  }

  template <int dim>
  void
  LoadStepping<dim>::scale_loads(CoupledState<dim> &state, const double factor) const
  {
    state.f_ext.equ(factor, fe_full_load);
    state.external_force.equ(factor, full_load);
  }

  template <int dim>
  void
  LoadStepping<dim>::run(CoupledState<dim>   &state,
                         Postprocessors<dim> &postprocessors,
                         Checkpoint<dim>     &checkpoint)
  {
    const auto        &settings = state.settings();
    auto              &pd       = state.pd();
    auto              &ps       = pd.particles();
    const bool         relax    = (type == SolverType::adaptive_dynamic_relaxation);
    const unsigned int n_steps  = settings.load_steps;

    // The conditions at t = End time, scaled by the load factor (a time history evaluates them
    // at each load factor).
    conditions_at(state, settings.end_time);

    // Cutting steps: the increment is not stored in checkpoints.
    const bool cutting = control.cut_threshold > 0;
    // The checkpoint intervals are refused when the parameters are read (CoupledProblem).
    AssertThrow(!cutting || !checkpoint.restarting(),
                ExcMessage("Load steps cut by <Solver/Control/Cut above broken bonds> write no "
                           "checkpoints yet (the current increment is not stored): run without "
                           "--restart, or set <Cut above broken bonds> to 0."));

    // What a restart must keep: the solver and its load steps (not its tolerance, iterations or
    // linear solver, which a restart after a step that did not converge may change).
    RunControl<dim>   run(state, postprocessors, checkpoint, true);
    const RunPosition start =
      run.start(std::string(relax ? "adaptive dynamic relaxation" : "static") + ", " +
                  std::to_string(n_steps) + " load steps" +
                  (control.history == LoadHistory::time ? ", time history" : ""),
                n_steps,
                [&]() {
                  state.start_work();
                  state.advance_other_physics(0, 0., 0., true);
                });
    // A restart takes the temperature of the load factor reached (the checkpoint held the one
    // the work of the temperature in the next step starts from, the kept one after a step that
    // did not converge).
    if (checkpoint.restarting())
      state.update_temperature(start.time * settings.end_time);
    // Without cutting, step k applies k/N; with cutting the load factor advances by increment.
    const double nominal   = 1. / n_steps;
    double       increment = nominal, reached = start.time;
    unsigned int cuts = 0;
    for (unsigned int step = start.step + 1; cutting ? reached < 1. : step <= n_steps; ++step)
      {
        // The state after the last converged step, for a checkpoint if this one fails and to
        // go back to if it is cut (every physics', before the others advance).
        checkpoint.keep(state, postprocessors, {step - 1, reached, step});
        const double factor = cutting ? std::min(1., reached + increment) : double(step) / n_steps;
        // The other physics of a problem with several advance first, to the time of the load
        // factor solved (load factor x End time; k/N of it without cuts).
        const double span = settings.end_time / n_steps;
        if (cutting)
          state.advance_other_physics(step,
                                      reached * settings.end_time,
                                      factor * settings.end_time - reached * settings.end_time,
                                      true);
        else
          state.advance_other_physics(step, (step - 1) * span, span, true);
        const auto broken_at_start = n_broken_bonds(ps);

        StepSolves solves;
        bool       failed = false;
        try
          {
            solves = solve_load_step(state, factor, step);
          }
        catch (const ExcNotConverged &failure)
          {
            if (!cutting || cuts == control.max_cuts)
              stop_without_convergence(state, postprocessors, checkpoint, step, factor, failure);
            failed = true;
          }
        const auto broken_in_step = n_broken_bonds(ps) - broken_at_start;
        if (cutting && (failed || broken_in_step > control.cut_threshold) &&
            cuts < control.max_cuts)
          {
            // Undo the step and solve it again with half the increment.
            checkpoint.restore_kept(state);
            if (state.is_root())
              state.log() << "Load step " << step << " (load factor " << factor << "): "
                          << (failed ? std::string("no convergence") :
                                       std::to_string(broken_in_step) + " bonds broke")
                          << ", cut to an increment of " << increment / 2. << std::endl;
            increment /= 2.;
            ++cuts;
            --step;
            continue;
          }
        cuts                   = 0;
        const double pd_energy = equilibrium_state(state);

        // Solves and broken bonds per step always (they are the same on every rank count);
        // iteration counts only with progress output.
        const auto broken = n_broken_bonds(ps);
        if (state.is_root())
          {
            state.log() << "Load step " << step;
            if (cutting)
              state.log() << " (load factor " << factor << ")";
            else
              state.log() << "/" << n_steps;
            state.log() << ": " << solves.passes + 1 << " solve(s)";
            if (pd.has_body())
              state.log() << ", " << broken << " broken bonds";
            if (settings.show_progress)
              state.log() << ", " << solves.iterations << (relax ? " relaxation" : " CG")
                          << " iterations";
            state.log() << std::endl;
          }
        StepData data   = run.plan(step, factor, cutting ? factor >= 1. : (step == n_steps));
        data.iterations = solves.iterations;
        data.pd_energy  = pd_energy;
        run.write(data);
        if (run.checkpoint(data))
          return;
        reached = factor;
        if (state.has_adaptive_region() && !data.final_row &&
            step % state.adaptation_interval() == 0)
          convert_regions(state, step, factor);
        if (cutting && 2 * broken_in_step <= control.cut_threshold)
          increment = std::min(nominal, 2. * increment);
      }
  }

  template <int dim>
  void
  LoadStepping<dim>::convert_regions(CoupledState<dim> &state,
                                     const unsigned int step,
                                     const double       factor)
  {
    const auto  &settings = state.settings();
    const double before   = state.strain_energy().fe + state.strain_energy().particles;
    if (!state.adapt_regions(step, factor * settings.end_time))
      return;
    // What the set-up derived from the regions (the prescribed components, the system and its
    // factors, the conditions), then the equilibrium of the grown region at the same load
    // factor: the new particles hold the FE field, which is not their equilibrium, and their
    // bonds may break at the load already reached.
    setup(state);
    conditions_at(state, settings.end_time);
    const StepSolves solves = solve_load_step(state, factor, step);
    equilibrium_state(state);
    state.carry_work();
    const double after  = state.strain_energy().fe + state.strain_energy().particles;
    const auto   broken = n_broken_bonds(state.pd().particles()); // collective
    if (state.is_root())
      state.log() << "  solved again at load factor " << factor << ": " << solves.passes + 1
                  << " solve(s), " << broken << " broken bonds; strain energy before " << before
                  << " J, after " << after << " J" << std::endl;
  }

  template <int dim>
  typename LoadStepping<dim>::StepSolves
  LoadStepping<dim>::solve_load_step(CoupledState<dim> &state,
                                     const double       factor,
                                     const unsigned int step)
  {
    auto      &pd = state.pd();
    auto      &ps = pd.particles();
    StepSolves solves;
    for (;; ++solves.passes)
      {
        const auto broken_before = n_broken_bonds(ps);
        apply_load_factor(state, factor);
        solves.iterations += state.method().solve_equilibrium(state.fe_equation_load(),
                                                              state.external_force,
                                                              state.U,
                                                              state.u);
        // The model's own forces and energy density at the solution (breaks bonds).
        pd.material().compute_forces(ps,
                                     state.u,
                                     state.internal_force,
                                     &state.energy_density,
                                     pd.critical_stretch());
        state.accumulate_dissipated_energy();
        if (breaking_settled(ps,
                             broken_before,
                             pd.material().damage_changed(),
                             step,
                             solves.passes))
          return solves;
      }
  }

  template <int dim>
  void
  LoadStepping<dim>::start_state(CoupledState<dim> &state)
  {
    conditions_at(state, state.settings().end_time);
    state.start_work();
  }

  template <int dim>
  void
  LoadStepping<dim>::advance(CoupledState<dim> &state,
                             const double       time,
                             const double       dt,
                             const bool)
  {
    // The load factor of the time reached (load factor x End time), in load step k of N if it
    // lies in ((k-1)/N, k/N].
    const auto        &settings = state.settings();
    const double       factor   = (time + dt) / settings.end_time;
    const unsigned int step     = static_cast<unsigned int>(
      std::max(1., std::ceil(factor * settings.load_steps * (1. - 1e-12))));
    solve_load_step(state, factor, step);
    equilibrium_state(state);
  }

  template <int dim>
  std::string
  LoadStepping<dim>::write_last_iterate(CoupledState<dim>   &state,
                                        Postprocessors<dim> &postprocessors,
                                        const unsigned int   step,
                                        const double         factor,
                                        const std::string   &what) const
  {
    const auto        &settings  = state.settings();
    const std::string &directory = settings.output_directory;
    auto              &ps        = state.pd().particles();

    // The last iterate for inspection: its forces and energy density (no bond breaks), its
    // fields in files of their own (FieldOutput); no statistics row.
    if (state.pd().has_body())
      state.pd().material().compute_forces(ps,
                                           state.u,
                                           state.internal_force,
                                           &state.energy_density,
                                           std::numeric_limits<double>::infinity());
    StepData data;
    data.quasi_static  = true;
    data.step          = step;
    data.time          = factor;
    data.write_fields  = true;
    data.output_index  = step;
    data.not_converged = true;
    postprocessors.execute(state, data);
    std::vector<std::string> files;
    if (state.pd().has_body() && settings.write_hdf5)
      files.push_back(directory + "/" + settings.base_name + "_not_converged.xdmf");
    if (state.pd().has_body() && settings.write_vtu)
      files.push_back(directory + "/" + settings.base_name + "_not_converged.pvd");
    if (state.fe().n_dofs() > 0 && settings.write_hdf5)
      files.push_back(directory + "/solution_not_converged.xdmf");
    std::string file_list;
    for (const auto &file : files)
      file_list += (file_list.empty() ? "" : ", ") + file;
    const auto broken = n_broken_bonds(ps);
    if (state.is_root())
      {
        state.log() << what << " did not converge";
        if (state.pd().has_body())
          state.log() << " (" << broken << " broken bonds at its last iterate)";
        state.log() << "; its last iterate: "
                    << (files.empty() ? std::string("no field files (<Output/Write HDF5> and "
                                                    "<Output/Write VTU> are false)") :
                                        file_list + " (output index " + std::to_string(step) + ")")
                    << std::endl;
      }
    return files.empty() ? std::string("no field files") : file_list;
  }

  template <int dim>
  std::string
  LoadStepping<dim>::failure_text(const ExcNotConverged &failure)
  {
    std::ostringstream message;
    failure.print_info(message);
    std::string text = message.str();
    text.erase(0, text.find_first_not_of(" \n"));
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
      text.pop_back();
    return text;
  }

  template <int dim>
  void
  LoadStepping<dim>::stop_without_convergence(CoupledState<dim>     &state,
                                              Postprocessors<dim>   &postprocessors,
                                              Checkpoint<dim>       &checkpoint,
                                              const unsigned int     step,
                                              const double           factor,
                                              const ExcNotConverged &failure) const
  {
    const unsigned int n_steps = state.settings().load_steps;
    const bool         cutting = control.cut_threshold > 0;
    const std::string  name    = "Load step " + std::to_string(step) +
                             (cutting ? " (load factor " + std::to_string(factor) + ", after " +
                                          std::to_string(control.max_cuts) + " cuts)" :
                                        "/" + std::to_string(n_steps));
    const std::string file_list = write_last_iterate(state, postprocessors, step, factor, name);

    // The checkpoint of the last converged load step (the state goes back to it).
    const RunPosition converged = checkpoint.write_kept(state);

    // How to continue, in the log and in the message of the error.
    const bool        relax = (type == SolverType::adaptive_dynamic_relaxation);
    const std::string how =
      cutting ?
        std::string("To continue, change <Solver/Control/Maximum step cuts>, <Solver/Maximum "
                    "iterations> or <Solver/Tolerance> and run again (cut load steps do not "
                    "restart from checkpoints).") :
        "To continue from it, change " +
          std::string(relax ? "<Solver/Maximum iterations>, <Solver/Tolerance> or <Solver/Density "
                              "safety factor>" :
                              "<Solver/Maximum iterations>, <Solver/Tolerance> or <Solver/Linear "
                              "solver>") +
          " in the parameter file and run 'perideal-solid --restart FILE.prm'; the problem, "
          "<Solver/Type> and <Solver/Load steps> must stay as they are (other load steps need a new "
          "run).";
    if (state.is_root())
      state.log() << "Load step " << converged.step << " is the last converged one. " << how
                  << std::endl;

    AssertThrow(false,
                ExcNotConverged(
                  failure_text(failure) + "\n" + name +
                  " did not converge. Its last iterate is written for inspection (" + file_list +
                  "; statistics.csv ends at load step " + std::to_string(converged.step) +
                  "), and the checkpoint of the last converged load step " +
                  std::to_string(converged.step) + " to " + checkpoint.filename() + ". " + how));
  }

  template class LoadStepping<2>;
  template class LoadStepping<3>;
} // namespace perideal
