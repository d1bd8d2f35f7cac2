// ---------------------------------------------------------------------
// PeriDeal: the one driver of every problem (particles, an FE region, or both).
// ---------------------------------------------------------------------
#include <perideal/base/memory_estimate.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/base/setup_times.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/antiplane_torsion.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/lattice.h>
#include <perideal/pd/lattice_dilation.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // Values within round-off of 0 or 1 are 0 or 1: whether a cell carries FE unknowns and
    // whether a particle is free must not depend on the last bit of a coordinate (it broke the
    // mirror symmetry of the Kalthoff-Winkler case).
    double
    snap_to_bounds(const double b)
    {
      return std::abs(b) < 1e-10 ? 0. : std::abs(b - 1.) < 1e-10 ? 1. : b;
    }
  } // namespace

  template <int dim>
  CoupledProblem<dim>::CoupledProblem(const MPI_Comm comm, std::ostream &log)
    : comm(comm)
    , log(log)
    , is_root(Utilities::MPI::this_mpi_process(comm) == 0)
    , physics([&]() {
      std::vector<std::unique_ptr<Physics<dim>>> list;
      list.push_back(std::make_unique<Physics<dim>>("mechanics", comm, log));
      return list;
    }())
    , settings(physics[0]->settings)
    , layout(physics[0]->layout)
    , pd(physics[0]->pd)
    , fe(physics[0]->fe)
    , method_name(physics[0]->method_name)
  {}

  template <int dim>
  void
  CoupledProblem<dim>::declare_parameters(
    ParameterHandler                                                   &prm,
    const std::vector<std::string>                                     &region_names,
    const std::vector<std::string>                                     &condition_names,
    const std::vector<std::string>                                     &fe_condition_names,
    const std::map<std::string, typename Physics<dim>::ConditionNames> &physics_condition_names)
  {
    ProblemSettings<dim>::declare_parameters(prm);
    QuasiStaticControl::declare_parameters(prm);
    ParticleRegion<dim>::declare_parameters(prm, region_names, condition_names);
    FERegion<dim>::declare_parameters(prm, fe_condition_names);
    prm.enter_subsection("Coupling");
    using Methods = PluginRegistry<CouplingMethod<dim>>;
    prm.declare_entry("Method",
                      "blended",
                      Patterns::Selection(Methods::pattern_string()),
                      "How the FE region and the particles are joined: " +
                        Methods::documentation() + "Each method reads its own subsection.");
    Methods::declare_parameters(prm);
    AdaptiveRegion<dim>::declare_parameters(prm);
    prm.declare_entry("Blending function",
                      "0",
                      Patterns::Anything(),
                      "beta(x, y, (z)) in [0, 1]: 1 where only PD acts, 0 where only FE acts, in "
                      "between in the overlap, which must be at least a horizon wide (e.g. "
                      "'min(1, max(0, (x - 0.04) / 0.01))').");
    prm.declare_entry("Exact displacement",
                      "",
                      Patterns::Anything(),
                      "Static runs, for verification: the exact displacement (one expression per "
                      "component, separated by ';', in x, y(, z)); if given, the summary prints "
                      "the largest error at the FE nodes and at the particles relative to the "
                      "largest exact value. Empty: no comparison.");
    prm.declare_entry("Exact displacement tolerance",
                      "0",
                      Patterns::Double(0.),
                      "Static runs with <Exact displacement>: the summary states whether both "
                      "relative errors are below this value (0: no verdict).");
    prm.leave_subsection();
    Postprocessors<dim>::declare_parameters(prm);
    Physics<dim>::declare_parameters(prm, physics_condition_names);
    TemperatureSource<dim>::declare_parameters(prm);
  }

  template <int dim>
  void
  CoupledProblem<dim>::parse_parameters(ParameterHandler &prm)
  {
    settings.parse_parameters(prm);
    control.parse_parameters(prm);
    postprocessor_names = Postprocessors<dim>::parse_parameters(prm);
    AssertThrow(control.method == LoadControl::load_steps ||
                  settings.solver_type == SolverType::static_linear,
                ExcMessage("<Solver/Control/Method> = sequentially linear needs <Solver/Type> = "
                           "static: it scales the linear solution of each event, which only the "
                           "linearized static solve gives."));
    AssertThrow(control.method == LoadControl::load_steps ||
                  settings.checkpoint_time_interval == 0.,
                ExcMessage("<Solver/Control/Method> = sequentially linear writes checkpoints by "
                           "events, not by time (an event's load factor falls when a crack "
                           "snaps back): set <Output/Checkpoint time interval> to off and "
                           "<Output/Checkpoint interval> to the events between two."));
    AssertThrow(control.cut_threshold == 0 || control.method != LoadControl::load_steps ||
                  settings.solver_type == SolverType::explicit_dynamics ||
                  settings.solver_type == SolverType::implicit ||
                  (settings.checkpoint_interval == 0 && settings.checkpoint_time_interval == 0.),
                ExcMessage("Load steps cut by <Solver/Control/Cut above broken bonds> write no "
                           "checkpoints yet (the current increment is not stored): set <Output/"
                           "Checkpoint interval> and <Output/Checkpoint time interval> to off, or "
                           "<Cut above broken bonds> to 0."));
    pd.parse_parameters(prm);
    fe.parse_parameters(prm, pd.planar_assumption(), pd.discretization().thickness);
    // A polycrystal's grains are a particle feature: an FE region needs the homogenized
    // constants, which are not the crystal's it would share.
    const std::string nonuniform = pd.has_body() ? pd.material().nonuniform_constants() : "";
    AssertThrow(!fe.has_mesh() || !fe.physics().shares_particle_material() || nonuniform.empty(),
                ExcMessage("<Finite elements/Elasticity/Same material as the particles> = true, "
                           "but " +
                           nonuniform +
                           ", whose homogenized stiffness is not the crystal's; accepted: false "
                           "and the homogenized constants in <Finite elements/Elasticity>."));
    AssertThrow(pd.has_body() || fe.has_mesh(),
                ExcMessage("The problem has neither particles nor an FE region: give "
                           "<Discretization/Body> (the regions filled with particles), "
                           "<Finite elements/Mesh file> or <Finite elements/Generator> (the FE "
                           "mesh), or both (a coupled problem)."));
    AssertThrow((settings.solver_type != SolverType::explicit_dynamics &&
                 settings.solver_type != SolverType::implicit) ||
                  !fe.has_mesh() || fe.get_density() > 0.,
                ExcMessage("The parameter <Finite elements/Density> is " +
                           ParameterUtilities::format_number(fe.get_density()) +
                           "; explicit dynamics and implicit time steps (<Solver/Type> = "
                           "explicit, implicit) need the FE mass (the heat capacity rho c of a "
                           "temperature): accepted values are > 0."));
    AssertThrow(!pd.has_body() || !pd.material().has_prestrain() ||
                  settings.solver_type != SolverType::static_linear,
                ExcMessage("<Material/Model> = <" + prm.get({"Material"}, "Model") +
                           "> carries a strain at zero displacement (the twist of torsion), "
                           "which the static linear solve does not assemble: set <Solver/Type> "
                           "= adaptive dynamic relaxation (accepted with a twist), or the "
                           "twist to 0."));
    physics[0]->parse_field(prm, "");
    physics[0]->parse_method(prm);
    prm.enter_subsection("Coupling");
    // With one region only, beta is fixed: 1 without a mesh, 0 without particles.
    blending_expression = prm.get("Blending function");
    AssertThrow((pd.has_body() && fe.has_mesh()) || blending_expression == "0",
                ExcMessage("<Coupling/Blending function> = <" + blending_expression +
                           "> is given, but the problem has " +
                           (fe.has_mesh() ? "no particles (<Discretization/Body> is empty)" :
                                            "no FE region (no <Finite elements/Mesh file> or "
                                            "<Finite elements/Generator>)") +
                           ": the blending function joins two regions; remove it."));
    if (!fe.has_mesh())
      blending_expression = "1";
    beta =
      ParameterUtilities::make_function<dim>(blending_expression, 1, "Coupling/Blending function");
    adaptive.parse_parameters(prm, pd.discretization().horizon);
    const std::string exact = prm.get("Exact displacement");
    exact_displacement.reset();
    if (!exact.empty())
      exact_displacement = ParameterUtilities::make_function<dim>(exact,
                                                                  layout.n_components(),
                                                                  "Coupling/Exact displacement");
    exact_tolerance = prm.get_double("Exact displacement tolerance");
    AssertThrow(exact_tolerance == 0. || exact_displacement,
                ExcMessage("<Coupling/Exact displacement tolerance> is set, but <Coupling/Exact "
                           "displacement> is empty: give the exact field or remove the "
                           "tolerance."));
    AssertThrow(!exact_displacement || (settings.solver_type != SolverType::explicit_dynamics &&
                                        settings.solver_type != SolverType::implicit),
                ExcMessage("<Coupling/Exact displacement> is compared in quasi-static runs only "
                           "(<Solver/Type> = static or adaptive dynamic relaxation); remove it or "
                           "change the solver type."));
    prm.leave_subsection();
    if (adaptive.enabled())
      {
        const std::string entry = "<Coupling/Adaptive region/Criterion> = " +
                                  prm.get({"Coupling", "Adaptive region"}, "Criterion");
        AssertThrow(pd.has_body() && fe.has_mesh(),
                    ExcMessage(entry + " converts FE cells into particles: the problem needs "
                                       "both an FE mesh and <Discretization/Body> (the body the "
                                       "particles may fill); set the criterion to none."));
        // Explicit steps and load steps convert after a step (ExplicitDynamics::run(),
        // LoadStepping::run()); the event-by-event control has no step to convert after.
        AssertThrow((settings.solver_type == SolverType::explicit_dynamics ||
                     settings.solver_type == SolverType::static_linear ||
                     settings.solver_type == SolverType::adaptive_dynamic_relaxation) &&
                      (settings.solver_type == SolverType::explicit_dynamics ||
                       control.method == LoadControl::load_steps),
                    ExcMessage(entry + " works in explicit runs and in quasi-static runs by load "
                                       "steps only: <Solver/Type> = explicit, static or adaptive "
                                       "dynamic relaxation with <Solver/Control/Method> = load "
                                       "steps, or the criterion none."));
        AssertThrow(settings.checkpoint_interval == 0 && settings.checkpoint_time_interval == 0.,
                    ExcMessage(entry + ": a run whose PD region grows cannot be checkpointed yet "
                                       "(its particles and FE space are not rebuilt by a "
                                       "restart); set <Output/Checkpoint interval> and "
                                       "<Output/Checkpoint time interval> to off."));
      }
    parse_other_physics(prm);
    parse_thermal_strain(prm);
  }

  template <int dim>
  const std::vector<std::unique_ptr<Physics<dim>>> &
  CoupledProblem<dim>::get_physics() const
  {
    return physics;
  }

  template <int dim>
  const ParticleSystem<dim> &
  CoupledProblem<dim>::particles() const
  {
    return pd.particles();
  }

  template <int dim>
  const MaterialModel<dim> &
  CoupledProblem<dim>::material() const
  {
    return pd.material();
  }

  template <int dim>
  const FERegion<dim> &
  CoupledProblem<dim>::fe_region() const
  {
    return fe;
  }

  template <int dim>
  double
  CoupledProblem<dim>::time_step() const
  {
    return state().time_step;
  }

  template <int dim>
  const ParticleVector &
  CoupledProblem<dim>::particle_displacement() const
  {
    return state().u;
  }

  template <int dim>
  const FEVector &
  CoupledProblem<dim>::fe_displacement() const
  {
    return state().U;
  }

  template <int dim>
  double
  CoupledProblem<dim>::blending(const Point<dim> &x) const
  {
    return snap_to_bounds(adaptive.enabled() ? std::max(beta->value(x), adaptive.blending(x)) :
                                               beta->value(x));
  }

  template <int dim>
  void
  CoupledProblem<dim>::check_blending() const
  {
    const std::string entry = "<Coupling/Blending function> = <" + blending_expression + ">";
    // beta in [0, 1] at the particles and the FE vertices.
    double lowest = 1., highest = 0.;
    for (const auto &x : pd.particles().positions())
      {
        const double b = blending(x);
        lowest         = std::min(lowest, b);
        highest        = std::max(highest, b);
      }
    for (const auto &cell : fe.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const double b = blending(cell->vertex(v));
            lowest         = std::min(lowest, b);
            highest        = std::max(highest, b);
          }
    lowest  = Utilities::MPI::min(lowest, comm);
    highest = Utilities::MPI::max(highest, comm);
    AssertThrow(lowest >= 0. && highest <= 1.,
                ExcMessage(entry + " takes values in [" +
                           ParameterUtilities::format_number(lowest) + ", " +
                           ParameterUtilities::format_number(highest) +
                           "]; it must lie in [0, 1] (clamp it with min(1, max(0, ...)))."));
  }

  template <int dim>
  void
  CoupledProblem<dim>::setup_particles(const bool log_summary)
  {
    // Particles where the method's particle weight is positive and within a horizon of such
    // points (lattice offsets up to delta + dx cover every bond).
    const double       dx = pd.discretization().spacing, delta = pd.discretization().horizon;
    const Lattice<dim> lattice(dx);
    std::vector<Tensor<1, dim>> offsets = lattice.vectors(delta + dx);
    offsets.emplace_back();
    // The file's beta: a lattice point is kept if the method's particle weight is positive at
    // one of the offsets, a dilation of the points of positive weight computed by tiles (O(1)
    // per point; beta is evaluated once per lattice point of the tiles a rank asks for and
    // their halo, doc/benchmarks/performance/README.md "Set-up that scales").
    LatticeDilation<dim> positive_weight(dx, offsets, [&](const Point<dim> &y) {
      return method().particle_weight(snap_to_bounds(beta->value(y))) > 0.;
    });
    // The disks of an adaptive region by their distance (a lattice scan at every conversion
    // would cost more than the run), the blending function at the offsets (not the constant 0).
    const bool file_blends  = blending_expression != "0";
    const auto in_pd_region = [&](const Point<dim> &x) {
      if (adaptive.enabled() && adaptive.within_reach(x, delta + dx))
        return true;
      return file_blends && positive_weight(x);
    };
    // A growing region keeps the partition of its first bins (ParticleSystem).
    pd.particles().set_balance_by_particles(!adaptive.enabled());
    pd.setup(
      in_pd_region,
      [this](const Point<dim> &x) { return method().particle_weight(blending(x)); },
      log_summary);
  }

  template <int dim>
  void
  CoupledProblem<dim>::check_twist_axis() const
  {
    const Torsion *torsion = pd.has_body() ? pd.material().torsion() : nullptr;
    if (torsion == nullptr)
      return;
    const BoundingBox<2> particles = AntiplaneTorsion::section_box(pd.particles());
    Point<2>             low       = particles.get_boundary_points().first,
             high                  = particles.get_boundary_points().second;
    if (fe.has_mesh())
      {
        for (const auto &cell : fe.get_triangulation().active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int d = 0; d < 2; ++d)
                {
                  low[d]  = std::min(low[d], cell->vertex(v)[d]);
                  high[d] = std::max(high[d], cell->vertex(v)[d]);
                }
        for (unsigned int d = 0; d < 2; ++d)
          {
            low[d]  = Utilities::MPI::min(low[d], comm);
            high[d] = Utilities::MPI::max(high[d], comm);
          }
      }
    torsion->check_axis(BoundingBox<2>(std::make_pair(low, high)));
  }

  template <int dim>
  CoupledRegions<dim>
  CoupledProblem<dim>::coupled_regions(Physics<dim> &field)
  {
    CoupledRegions<dim> regions;
    regions.fe             = &field.fe;
    regions.particles      = &field.pd.particles();
    regions.material       = &field.pd.material();
    regions.density        = field.pd.density();
    regions.layout         = field.layout;
    regions.blending       = [this](const Point<dim> &x) { return blending(x); };
    regions.blending_entry = "<Coupling/Blending function> = <" + blending_expression + ">" +
                             (adaptive.enabled() ? " with <Coupling/Adaptive region>" : "");
    regions.log = &log;
    return regions;
  }

  template <int dim>
  void
  CoupledProblem<dim>::check()
  {
    fe.setup([this](const Point<dim> &x) { return method().fe_weight(blending(x)); });
    setup_particles();
    check_blending();
    check_twist_axis();
    if (adaptive.enabled())
      {
        AssertThrow(std::isfinite(pd.critical_stretch()),
                    ExcMessage("<Coupling/Adaptive region/Criterion> compares with the critical "
                               "stretch and follows broken bonds: <Material/Damage model> = "
                               "none has neither; choose critical stretch."));
        for (const auto &seed : adaptive.seed_points())
          {
            std::ostringstream point;
            point << seed;
            AssertThrow(pd.in_body(seed),
                        ExcMessage("The point " + point.str() +
                                   " of <Coupling/Adaptive region/Initial seeds> lies outside the "
                                   "body (<Discretization/Body>)."));
          }
        adaptive.check_conditions_outside(fe,
                                          adaptive.seed_points(),
                                          "With <Coupling/Adaptive region/Initial seeds>");
        precrack_damage = damage_index(pd.particles());
      }
    method().initialize(coupled_regions(*physics[0]));
    physics[0]->set_state(
      std::make_unique<CoupledState<dim>>(comm, log, settings, layout, pd, fe, method()));
    state().setup();
    physics[0]->set_solver(create_solver<dim>(settings.solver_type, control));
    solver().check(state());
    // The postprocessors' own checks (probe points on particles, the load point and size of the
    // fracture measures) need only the state: --validate makes them too.
    PostprocessorInputs<dim> inputs;
    inputs.control            = control;
    inputs.exact_displacement = exact_displacement;
    inputs.exact_tolerance    = exact_tolerance;
    inputs.method             = &method();
    physics[0]->set_postprocessors(
      std::make_unique<Postprocessors<dim>>(postprocessor_names, inputs));
    postprocessors().initialize(state());
    check_other_physics();
  }

  template <int dim>
  void
  CoupledProblem<dim>::setup()
  {
    check();
    const std::string fe_summary = fe.summary(), coupling_summary = method().summary();
    if (is_root && fe.has_mesh())
      log << fe_summary << std::endl;
    if (is_root && state().is_coupled())
      log << "Coupling: " << method_name << ", " << coupling_summary << std::endl;
    if (adaptive.enabled())
      {
        state().set_adaptive_region(
          [this](const unsigned int step, const double time) {
            return convert_regions(step, time);
          },
          adaptive.check_interval());
      }
    connect_temperature();
    if (is_root && temperature.active())
      log << temperature.summary() << std::endl;
    solver().setup(state());
    setup_other_physics();
    if (settings.show_progress)
      {
        const std::string times = SetupTimes::summary(comm);
        if (is_root)
          log << times << std::endl;
      }
  }

  template <int dim>
  void
  CoupledProblem<dim>::restart_from_checkpoint()
  {
    restart              = true;
    resume_other_physics = physics.size() > 1;
  }

  template <int dim>
  void
  CoupledProblem<dim>::stop_after_step(const unsigned int step)
  {
    stop_step = step;
  }

  template <int dim>
  void
  CoupledProblem<dim>::run()
  {
    Checkpoint<dim> checkpoint(settings, physics[0]->model_lines, restart, stop_step);
    for (unsigned int k = 1; k < physics.size(); ++k)
      checkpoint.add_physics(physics[k]->name,
                             physics[k]->model_lines + "solver = " +
                               (physics[k]->settings.solver_type == SolverType::implicit ?
                                  "implicit\n" :
                                  "explicit\n"),
                             physics[k]->state());
    // The two-way coupling's measure of the last step, from which the next one heats.
    if (heating.active())
      checkpoint.add_part(
        "Temperature/Coupling = two way",
        [this](CheckpointWriter &writer) { heating.save(writer, "thermoelastic heating/"); },
        [this](CheckpointReader &reader) { heating.load(reader, "thermoelastic heating/"); });
    solver().run(state(), postprocessors(), checkpoint);
    // The two-way coupling's heat (part of the heat's heat in).
    if (heating.active())
      {
        const double heat = heating.heat();
        if (is_root)
          log << "Thermoelastic heat of the deformation: " << heat << " J (in heat.heat_in)"
              << std::endl;
      }
    if (settings.show_progress)
      {
        const auto       &particles = state().pd().particles();
        const std::string memory    = MemoryEstimate::peak_summary(comm,
                                                                particles.resident_memory_before(),
                                                                particles.n_global_bonds(),
                                                                particles.n_global());
        if (is_root)
          log << memory << std::endl;
      }
  }

  template class CoupledProblem<2>;
  template class CoupledProblem<3>;
} // namespace perideal
