// ---------------------------------------------------------------------
// PeriDeal: the settings of a whole problem (solver, time stepping, initial conditions, output).
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/problem_settings.h>

#include <cmath>
#include <map>

namespace perideal
{
  using namespace dealii;

  SolverType
  solver_type_from_name(const std::string &name)
  {
    static const std::map<std::string, SolverType> types = {
      {"explicit", SolverType::explicit_dynamics},
      {"adaptive dynamic relaxation", SolverType::adaptive_dynamic_relaxation},
      {"static", SolverType::static_linear},
      {"implicit", SolverType::implicit}};
    const auto found = types.find(name);
    AssertThrow(found != types.end(),
                ExcMessage("The parameter <Solver/Type> is <" + name +
                           ">; accepted: explicit, adaptive dynamic relaxation, static, "
                           "implicit."));
    return found->second;
  }

  template <int dim>
  void
  ProblemSettings<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      std::to_string(dim),
                      Patterns::Integer(2, 3),
                      "2 (in-plane: plane stress or plane strain) or 3. Read first.");

    declare_field_parameters(prm);

    prm.enter_subsection("Time stepping");
    prm.declare_entry("End time", "0", Patterns::Double(0.), "Simulated time [s].");
    prm.declare_entry("Time step",
                      "0",
                      Patterns::Double(0.),
                      "Time step [s]; 0 chooses Safety factor times the stable limit. A value "
                      "above the stable limit is refused.");
    prm.declare_entry("Safety factor",
                      "0.8",
                      Patterns::Double(0.),
                      "Fraction of the stable time step used when 'Time step' is 0, in (0, 1].");
    prm.declare_entry("Theta",
                      "1",
                      Patterns::Double(),
                      "<Solver/Type> = implicit: the weight theta of the new state in "
                      "(C/dt + theta K) T_new = (C/dt - (1 - theta) K) T_old + theta Q_new + "
                      "(1 - theta) Q_old, in [0.5, 1]: 1 backward Euler (first order, damps "
                      "every mode), 0.5 Crank-Nicolson (second order).");
    prm.declare_entry("Damping",
                      "0",
                      Patterns::Double(0.),
                      "Mass-proportional damping coefficient [1/s] to reach a steady state; 0 for "
                      "dynamics.");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    prm.declare_entry("Type",
                      "explicit",
                      Patterns::Selection("explicit|adaptive dynamic relaxation|static|implicit"),
                      "'explicit': velocity-Verlet dynamics to <Time stepping/End time>; "
                      "'adaptive dynamic relaxation': quasi-static equilibrium (Kilic & Madenci "
                      "2010) in load steps with bond breaking; 'static': the model linearized "
                      "about the reference configuration, a sparse linear solve per load step. "
                      "Quasi-static runs evaluate the boundary-condition functions at t = End "
                      "time and scale them by the load factor. 'implicit': the theta scheme "
                      "(<Time stepping/Theta>) of a first-order field (a temperature) in steps "
                      "of <Time stepping/Time step> to End time, one linear solve per step, "
                      "unconditionally stable.");
    prm.declare_entry("Load steps",
                      "1",
                      Patterns::Integer(1),
                      "Quasi-static: number N of load steps; step k applies k/N of the prescribed "
                      "displacements and loads.");
    prm.declare_entry("Tolerance",
                      "1e-8",
                      Patterns::Double(0.),
                      "Quasi-static: relative residual at which a solve stops. Adaptive dynamic "
                      "relaxation: ||F|| / max(||F_ext||, ||F_0||) of the residual force density "
                      "on free components; static: ||K u - F|| / ||F|| of CG.");
    prm.declare_entry("Maximum iterations",
                      "100000",
                      Patterns::Integer(1),
                      "Quasi-static: largest number of iterations of one solve (relaxation "
                      "iterations or CG iterations).");
    prm.declare_entry("Density safety factor",
                      "1",
                      Patterns::Double(0.),
                      "Adaptive dynamic relaxation: the fictitious density is this factor times "
                      "1/4 of the model's Gershgorin stiffness bound; accepted: >= 1.");
    prm.declare_entry("Linear solver",
                      "cg amg",
                      Patterns::Selection("cg amg|direct"),
                      "Static: conjugate gradients with algebraic multigrid (Trilinos ML), or a "
                      "direct solver (Amesos KLU) for small problems.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", Patterns::Anything(), "Where results are written.");
    prm.declare_entry("Base name", "particles", Patterns::Anything(), "Prefix of particle files.");
    prm.declare_entry("Output interval",
                      "0",
                      Patterns::Integer(0),
                      "Explicit: write the particle and FE fields every this many steps (0: first "
                      "and last step only); quasi-static runs: every this many load steps and "
                      "after the last (0: the last only; events of 'sequentially linear': the "
                      "last only).");
    prm.declare_entry("Statistics interval",
                      "10",
                      Patterns::Integer(1),
                      "Write a row of statistics.csv every this many steps.");
    prm.declare_entry(
      "Checkpoint interval",
      "off",
      Patterns::Anything(),
      "Write the complete state of the run (of every physics of <Physics/List> too) to "
      "<Directory>/checkpoint every this many steps: time steps (explicit), load steps "
      "(quasi-static) or events (<Solver/Control/Method> = sequentially linear); off: not by "
      "steps. 'perideal-solid --restart FILE.prm' continues the run from it. With <Checkpoint "
      "time interval> too, a checkpoint is written when either is due. Never after the last "
      "step. Accepted: off or an integer >= 1.");
    prm.declare_entry("Checkpoint time interval",
                      "off",
                      Patterns::Anything(),
                      "Write the checkpoint after the first step that reaches each multiple of "
                      "this interval of simulated time: [s] of an explicit run; for quasi-static "
                      "runs the pseudo time is the load factor k/N of load step k (0 to 1), so "
                      "0.25 writes one each quarter of the load. off: not by time. Accepted: off "
                      "or a number > 0. A quasi-static run that stops without convergence writes "
                      "the checkpoint of its last converged load step whatever the intervals.");
    prm.declare_entry("Write HDF5", "true", Patterns::Bool(), "Particle fields as HDF5 + XDMF.");
    prm.declare_entry("Write VTU", "false", Patterns::Bool(), "Particle fields as VTU + PVD.");
    prm.declare_entry("Progress", "true", Patterns::Bool(), "Print progress and timing lines.");
    prm.declare_entry("Probe points",
                      "",
                      Patterns::Anything(),
                      "Points (coordinates separated by ',', points by ';') whose nearest "
                      "particle's field the statistics columns probe<k>_<component> (k = 1, 2, "
                      "...; SI units) and the final summary (micrometres, microradians) report. "
                      "Each point needs a particle within one lattice spacing (coupled runs: in "
                      "the PD region or its overlap). Empty: none.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ProblemSettings<dim>::parse_parameters(ParameterHandler &prm)
  {
    parse_field_parameters(prm);

    prm.enter_subsection("Solver");
    solver_type           = solver_type_from_name(prm.get("Type"));
    load_steps            = prm.get_integer("Load steps");
    tolerance             = prm.get_double("Tolerance");
    max_iterations        = prm.get_integer("Maximum iterations");
    density_safety_factor = prm.get_double("Density safety factor");
    AssertThrow(density_safety_factor >= 1.,
                ExcMessage("The parameter <Solver/Density safety factor> is " +
                           ParameterUtilities::format_number(density_safety_factor) +
                           "; accepted: >= 1 (below, the relaxation is not stable)."));
    ParameterUtilities::require_positive(tolerance, "Solver/Tolerance");
    linear_solver =
      prm.get("Linear solver") == "direct" ? LinearSolverType::direct : LinearSolverType::cg_amg;
    prm.leave_subsection();

    prm.enter_subsection("Time stepping");
    end_time      = prm.get_double("End time");
    time_step     = prm.get_double("Time step");
    safety_factor = prm.get_double("Safety factor");
    AssertThrow(safety_factor > 0. && safety_factor <= 1.,
                ExcMessage("The parameter <Time stepping/Safety factor> must lie in (0, 1]."));
    if (solver_type == SolverType::explicit_dynamics || solver_type == SolverType::implicit)
      ParameterUtilities::require_positive(end_time, "Time stepping/End time");
    theta = prm.get_double("Theta");
    AssertThrow(theta >= 0.5 && theta <= 1.,
                ExcMessage("The parameter <Time stepping/Theta> is " +
                           ParameterUtilities::format_number(theta) +
                           "; accepted values are in [0.5, 1] (below 1/2 the scheme is not "
                           "unconditionally stable)."));
    if (solver_type == SolverType::implicit)
      AssertThrow(time_step > 0.,
                  ExcMessage("The parameter <Time stepping/Time step> is 0; <Solver/Type> = "
                             "implicit has no stable limit to choose it from: accepted values "
                             "are > 0."));
    damping = prm.get_double("Damping");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_directory    = prm.get("Directory");
    base_name           = prm.get("Base name");
    output_interval     = prm.get_integer("Output interval");
    statistics_interval = prm.get_integer("Statistics interval");
    // "off" or a positive interval: 0 and negative values are refused, so that no value reads
    // as "off" by accident.
    const auto interval_entry = [&prm](const std::string &entry, const bool integer) {
      const std::string text = Utilities::trim(prm.get(entry));
      if (text == "off")
        return 0.;
      std::size_t end   = 0;
      double      value = 0.;
      try
        {
          value = std::stod(text, &end);
        }
      catch (const std::exception &)
        {
          end = 0;
        }
      AssertThrow(end > 0 && end == text.size() && std::isfinite(value) && value > 0. &&
                    (!integer || (value == std::floor(value) && value < 4e9)),
                  ExcMessage("The parameter <Output/" + entry + "> is '" + text +
                             "'; accepted values are off (the default) or " +
                             (integer ? std::string("a number of steps >= 1.") :
                                        std::string("an interval > 0 of simulated time [s] "
                                                    "(explicit) or of the load factor "
                                                    "(quasi-static)."))));
      return value;
    };
    checkpoint_interval = static_cast<unsigned int>(interval_entry("Checkpoint interval", true));
    checkpoint_time_interval = interval_entry("Checkpoint time interval", false);
    write_hdf5               = prm.get_bool("Write HDF5");
    write_vtu                = prm.get_bool("Write VTU");
    show_progress            = prm.get_bool("Progress");
    probe_points.clear();
    for (const auto &item : Utilities::split_string_list(prm.get("Probe points"), ';'))
      if (!item.empty())
        probe_points.push_back(ParameterUtilities::parse_point<dim>(item, "Output/Probe points"));
    prm.leave_subsection();
  }

  template <int dim>
  double
  ProblemSettings<dim>::solution_accuracy() const
  {
    return solver_type == SolverType::static_linear && linear_solver == LinearSolverType::direct ?
             1e-10 :
             100. * tolerance;
  }

  template <int dim>
  void
  ProblemSettings<dim>::declare_field_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    prm.declare_entry("Displacement",
                      "0",
                      Patterns::Anything(),
                      "Initial value of the field: one expression of x, y(, z) per component "
                      "(the displacement u(x) [m] of a solid, rotations [rad] after it for "
                      "micropolar models, the temperature T(x) [K] of a conduction model), "
                      "separated by ';'; a single 0 is zero for all.");
    prm.declare_entry("Velocity",
                      "0",
                      Patterns::Anything(),
                      "Initial rate of the field (velocity v(x) [m/s]), one expression per "
                      "component; a single 0 is zero for all. Not read for a temperature (first "
                      "order in time: its rate follows from the heat flows).");
    prm.leave_subsection();

    prm.enter_subsection("Body force");
    prm.declare_entry("Function",
                      "0",
                      Patterns::Anything(),
                      "Body force density b(x, t) [N/m^3] on the whole body (a body couple "
                      "density [N m/m^3] for rotations, a source for a scalar field, a heat "
                      "source [W/m^3] for a temperature), one "
                      "expression of x, y(, z) and t per component of the field, separated by "
                      "';'; a single 0 is zero for all. Coupled problems weight it like the "
                      "energies: 1 - beta on the FE region, beta on the particles.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ProblemSettings<dim>::parse_field_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Initial conditions");
    initial_displacement = prm.get("Displacement");
    initial_velocity     = prm.get("Velocity");
    prm.leave_subsection();

    prm.enter_subsection("Body force");
    body_force = prm.get("Function");
    prm.leave_subsection();
  }

  template struct ProblemSettings<2>;
  template struct ProblemSettings<3>;
} // namespace perideal
