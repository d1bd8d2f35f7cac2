// ---------------------------------------------------------------------
// PeriDeal: a finite-element-only elasticity problem driven by a parameter file.
// ---------------------------------------------------------------------
#include <deal.II/base/timer.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/progress_reporter.h>
#include <perideal/fem/fe_problem.h>

#include <cmath>
#include <filesystem>
#include <iomanip>

namespace perideal
{
  using namespace dealii;
  using Vector = LinearAlgebra::distributed::Vector<double>;

  template <int dim>
  FEProblem<dim>::FEProblem(const MPI_Comm comm, std::ostream &log)
    : comm(comm)
    , log(log)
    , is_root(Utilities::MPI::this_mpi_process(comm) == 0)
    , fe(comm)
  {}

  template <int dim>
  void
  FEProblem<dim>::declare_parameters(ParameterHandler               &prm,
                                     const std::vector<std::string> &condition_names)
  {
    prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "Space dimension (2 or 3).");
    FESolid<dim>::declare_parameters(prm, condition_names);
    prm.enter_subsection("Finite elements");
    prm.declare_entry("Planar assumption",
                      "plane stress",
                      Patterns::Selection("plane stress|plane strain"),
                      "2D only: the state of the third direction.");
    prm.declare_entry("Thickness",
                      "1",
                      Patterns::Double(0.),
                      "2D only: thickness h [m]; forces and energies are those of the slab.");
    prm.leave_subsection();
    prm.enter_subsection("Solver");
    prm.declare_entry("Type",
                      "static",
                      Patterns::Selection("static|explicit"),
                      "'static': one linear solve with the conditions at t = End time; "
                      "'explicit': velocity-Verlet dynamics with the lumped mass to End time.");
    prm.leave_subsection();
    prm.enter_subsection("Time stepping");
    ParameterUtilities::declare_time_stepping(prm);
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", Patterns::Anything(), "Where results are written.");
    prm.declare_entry("Output interval",
                      "0",
                      Patterns::Integer(0),
                      "Explicit: write the fields every this many steps (0: first and last).");
    prm.declare_entry("Statistics interval",
                      "1",
                      Patterns::Integer(1),
                      "Explicit: a row of statistics.csv every this many steps.");
    prm.declare_entry("Progress", "true", Patterns::Bool(), "Print progress and timing lines.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  FEProblem<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Finite elements");
    const PlanarAssumption planar = planar_assumption_from_name(prm.get("Planar assumption"), dim);
    const double           thickness = prm.get_double("Thickness");
    ParameterUtilities::require_positive(thickness, "Finite elements/Thickness");
    prm.leave_subsection();
    fe.parse_parameters(prm, planar, thickness);
    prm.enter_subsection("Solver");
    explicit_dynamics = (prm.get("Type") == "explicit");
    prm.leave_subsection();
    prm.enter_subsection("Time stepping");
    ParameterUtilities::parse_time_stepping(prm, end_time, requested_time_step, safety_factor);
    prm.leave_subsection();
    if (explicit_dynamics)
      {
        ParameterUtilities::require_positive(end_time, "Time stepping/End time");
        ParameterUtilities::require_positive(fe.get_density(), "Finite elements/Density");
      }
    prm.enter_subsection("Output");
    output_directory    = prm.get("Directory");
    output_interval     = prm.get_integer("Output interval");
    statistics_interval = prm.get_integer("Statistics interval");
    show_progress       = prm.get_bool("Progress");
    prm.leave_subsection();
  }

  template <int dim>
  void
  FEProblem<dim>::setup()
  {
    fe.setup();
    const std::string summary = fe.summary(); // collective
    if (is_root)
      {
        std::filesystem::create_directories(output_directory);
        log << summary << std::endl;
      }
    statistics = std::make_unique<StatisticsFile>(comm, output_directory + "/statistics.csv");
    fe.initialize_vector(f_ext);
    fe.initialize_vector(previous_f_ext);
    fe.initialize_vector(previous_u);
  }

  template <int dim>
  void
  FEProblem<dim>::run()
  {
    if (explicit_dynamics)
      run_explicit();
    else
      run_static();
  }

  template <int dim>
  void
  FEProblem<dim>::write_statistics(const double  time,
                                   const Vector &u,
                                   const Vector &v,
                                   const bool    final_row)
  {
    // Residual K u - f: on prescribed dofs, minus the force the support exerts on the body.
    Vector residual;
    fe.initialize_vector(residual);
    fe.stiffness_matrix().vmult(residual, u);
    residual -= f_ext;
    double kinetic = 0.;
    for (unsigned int k = 0; k < v.locally_owned_size(); ++k)
      kinetic += 0.5 * fe.lumped_mass().local_element(k) * v.local_element(k) * v.local_element(k);
    kinetic                    = Utilities::MPI::sum(kinetic, comm);
    const double strain_energy = fe.strain_energy(u);
    const auto   reactions     = fe.reactions(residual);
    statistics->add_value("time", time);
    statistics->add_value("strain_energy", strain_energy);
    statistics->add_value("kinetic_energy", kinetic);
    statistics->add_value("external_work", external_work);
    const char axes[] = {'x', 'y', 'z'};
    for (unsigned int k = 0; k < reactions.size(); ++k)
      if (fe.conditions()[k].type != FESolid<dim>::ConditionType::traction)
        for (unsigned int d = 0; d < dim; ++d)
          statistics->add_value("reaction_" + fe.conditions()[k].name + "_" + axes[d],
                                reactions[k][d]);
    statistics->end_row();

    const double max_displacement = u.linfty_norm();
    if (final_row && is_root)
      {
        const auto old_flags     = log.flags();
        const auto old_precision = log.precision();
        log << std::scientific << std::setprecision(6) << "Final time: " << time << " s\n"
            << "Kinetic energy: " << kinetic << " J\n"
            << "Strain energy: " << strain_energy << " J\n"
            << "External work: " << external_work << " J\n";
        for (unsigned int k = 0; k < reactions.size(); ++k)
          if (fe.conditions()[k].type != FESolid<dim>::ConditionType::traction)
            log << "Reaction of " << fe.conditions()[k].name << ": "
                << without_round_off(reactions[k]) << " N\n";
        log << "Max displacement: " << max_displacement << " m" << std::endl;
        log.flags(old_flags);
        log.precision(old_precision);
      }
  }

  template <int dim>
  void
  FEProblem<dim>::run_static()
  {
    Timer              timer;
    const unsigned int iterations = fe.solve_static(end_time);
    fe.assemble_load(end_time, f_ext);
    Vector u = fe.solution(), v;
    fe.initialize_vector(v);
    external_work = 0.;
    {
      // Work of the final loads along the linear path: 1/2 (f + R) . u = strain energy.
      Vector Ku;
      fe.initialize_vector(Ku);
      fe.stiffness_matrix().vmult(Ku, u);
      for (unsigned int k = 0; k < u.locally_owned_size(); ++k)
        external_work += 0.5 *
                         (fe.prescribed_mask()[k] ? Ku.local_element(k) : f_ext.local_element(k)) *
                         u.local_element(k);
      external_work = Utilities::MPI::sum(external_work, comm);
    }
    fe.write_output(output_directory, "solution", 0, end_time, u);
    write_statistics(end_time, u, v, true);
    if (is_root && show_progress)
      log << "static solve: " << iterations << " CG iterations, " << timer.wall_time() << " s"
          << std::endl;
  }

  template <int dim>
  void
  FEProblem<dim>::run_explicit()
  {
    const double stable_dt = fe.stable_time_step();
    double dt = ParameterUtilities::choose_time_step(requested_time_step, safety_factor, stable_dt);
    const unsigned int n_steps = ParameterUtilities::equal_time_steps(end_time, dt);
    if (is_root)
      log << "explicit dynamics: dt = " << dt << " s (stable " << stable_dt << " s), " << n_steps
          << " steps" << std::endl;

    Vector u, v, a, load, previous_load;
    for (Vector *x : {&u, &v, &a, &load, &previous_load})
      fe.initialize_vector(*x);
    const auto &mass = fe.lumped_mass();
    const auto &mask = fe.prescribed_mask();
    // The load that does work: the applied forces, and on prescribed dofs the internal force
    // the support balances (their inertia enters through the kinetic energy).
    const auto compute_acceleration_and_load = [&](const double time) {
      fe.assemble_load(time, f_ext);
      fe.stiffness_matrix().vmult(a, u);
      for (unsigned int k = 0; k < u.locally_owned_size(); ++k)
        {
          const double internal = a.local_element(k);
          if (mask[k])
            {
              load.local_element(k) = internal;
              a.local_element(k)    = 0.;
            }
          else
            {
              load.local_element(k) = f_ext.local_element(k);
              a.local_element(k)    = mass.local_element(k) > 0. ?
                                        (f_ext.local_element(k) - internal) / mass.local_element(k) :
                                        0.;
            }
        }
    };

    // The kinetic energy of the prescribed dofs: the support's force also accelerates them, and
    // that work (m a v on those dofs) is their change of kinetic energy.
    const auto prescribed_kinetic_energy = [&]() {
      double energy = 0.;
      for (unsigned int k = 0; k < v.locally_owned_size(); ++k)
        if (mask[k])
          energy += 0.5 * mass.local_element(k) * v.local_element(k) * v.local_element(k);
      return Utilities::MPI::sum(energy, comm);
    };

    double time = 0.;
    fe.prescribe(time, u, v);
    u.update_ghost_values();
    compute_acceleration_and_load(time);
    write_statistics(time, u, v, false);
    fe.write_output(output_directory, "solution", 0, time, u);
    ProgressReporter progress(comm, log, n_steps, end_time, show_progress);
    unsigned int     output_step = 1;
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const double previous_kinetic = prescribed_kinetic_energy();
        v.add(0.5 * dt, a);
        fe.prescribe(time + 0.5 * dt, u, v);
        previous_u    = u;
        previous_load = load;
        u.add(dt, v);
        time = step * dt;
        fe.prescribe(time, u, v);
        u.update_ghost_values();
        compute_acceleration_and_load(time);
        v.add(0.5 * dt, a);
        fe.prescribe(time, u, v);
        // Trapezoidal rule in the loads for the work.
        double work = 0.;
        for (unsigned int k = 0; k < u.locally_owned_size(); ++k)
          work += 0.5 * (load.local_element(k) + previous_load.local_element(k)) *
                  (u.local_element(k) - previous_u.local_element(k));
        external_work +=
          Utilities::MPI::sum(work, comm) + prescribed_kinetic_energy() - previous_kinetic;
        if (step % statistics_interval == 0 || step == n_steps)
          write_statistics(time, u, v, step == n_steps);
        if ((output_interval > 0 && step % output_interval == 0) || step == n_steps)
          fe.write_output(output_directory, "solution", output_step++, time, u);
        progress.update(step, time);
      }
  }

  template <int dim>
  const FESolid<dim> &
  FEProblem<dim>::solid() const
  {
    return fe;
  }

  template class FEProblem<2>;
  template class FEProblem<3>;
} // namespace perideal
