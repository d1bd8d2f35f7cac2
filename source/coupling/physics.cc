// ---------------------------------------------------------------------
// PeriDeal: one physics of a problem (its field, particle part, FE part, coupling and state).
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/physics.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <utility>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The registered FE physics that can join particles with the unknowns @p layout (the same
    // or @p layout without its rotations), separated by ', ' ("none").
    template <int dim>
    std::string
    fe_physics_of(const FieldLayout &layout)
    {
      using Registry = PluginRegistry<FEPhysics<dim>>;
      std::string names;
      for (const auto &name : Utilities::split_string_list(Registry::pattern_string(), '|'))
        {
          const FieldLayout fe_layout =
            Registry::create(name, "Finite elements/Physics")->field_layout();
          if (fe_layout == layout || layout.extends_by_rotations(fe_layout))
            names += (names.empty() ? "" : ", ") + name;
        }
      return names.empty() ? "none" : names;
    }
  } // namespace

  template <int dim>
  Physics<dim>::Physics(const std::string &name, const MPI_Comm comm, std::ostream &log)
    : name(name)
    , pd(comm, log)
    , fe(comm)
  {}

  template <int dim>
  const std::vector<std::string> &
  Physics<dim>::names()
  {
    static const std::vector<std::string> list = {"heat"};
    return list;
  }

  template <int dim>
  std::string
  Physics<dim>::section(const std::string &name)
  {
    std::string capitalized = name;
    capitalized[0]          = std::toupper(capitalized[0]);
    return capitalized;
  }

  template <int dim>
  void
  Physics<dim>::declare_names(ParameterHandler &prm)
  {
    prm.enter_subsection("Physics");
    prm.declare_entry("List",
                      "",
                      Patterns::Anything(),
                      "The physics the problem solves besides the one of the top-level "
                      "sections (the mechanics, or whatever field <Material/Model> and "
                      "<Finite elements/Physics> give), separated by ','; each reads its "
                      "subsection of the same name capitalized and shares the particles, their "
                      "bonds and the mesh. Accepted: heat (a temperature: <Heat/Material/Model> "
                      "= bond based conduction, <Heat/Finite elements/Physics> = heat). Empty: "
                      "one physics. See doc/architecture/16_multiphysics.md.");
    prm.leave_subsection();
    for (const auto &name : names())
      {
        prm.enter_subsection(section(name));
        BoundaryConditions<dim>::declare_names(prm);
        FERegion<dim>::declare_condition_names(prm);
        prm.leave_subsection();
      }
  }

  template <int dim>
  std::vector<std::pair<std::string, typename Physics<dim>::ConditionNames>>
  Physics<dim>::parse_names(ParameterHandler &prm)
  {
    const std::vector<std::string> listed =
      ParameterUtilities::split_names(prm.get({"Physics"}, "List"));
    std::vector<std::pair<std::string, ConditionNames>> list;
    for (const auto &name : listed)
      {
        std::string accepted;
        for (const auto &known : names())
          accepted += (accepted.empty() ? "" : ", ") + known;
        AssertThrow(std::find(names().begin(), names().end(), name) != names().end(),
                    ExcMessage("<Physics/List> names the physics <" + name +
                               ">, which does not exist; accepted: " + accepted +
                               " (the first physics is the one of the top-level sections)."));
        AssertThrow(std::count(listed.begin(), listed.end(), name) == 1,
                    ExcMessage("<Physics/List> names the physics <" + name +
                               "> twice; each physics is listed once (accepted: " + accepted +
                               ")."));
        prm.enter_subsection(section(name));
        ConditionNames conditions;
        conditions.particles = BoundaryConditions<dim>::parse_names(prm);
        conditions.fe        = FERegion<dim>::parse_names(prm);
        prm.leave_subsection();
        list.emplace_back(name, conditions);
      }
    return list;
  }

  template <int dim>
  void
  Physics<dim>::declare_parameters(ParameterHandler                            &prm,
                                   const std::map<std::string, ConditionNames> &condition_names)
  {
    declare_names(prm);
    for (const auto &name : names())
      {
        const auto           found = condition_names.find(name);
        const ConditionNames conditions =
          found != condition_names.end() ? found->second : ConditionNames();
        prm.enter_subsection(section(name));
        ParticleRegion<dim>::declare_physics_parameters(prm, conditions.particles);
        FERegion<dim>::declare_physics_parameters(prm, conditions.fe);
        ProblemSettings<dim>::declare_field_parameters(prm);
        prm.enter_subsection("Solver");
        prm.declare_entry("Type",
                          "explicit",
                          Patterns::Selection("explicit|implicit|static"),
                          "How this physics advances within each step of the first one (operator "
                          "splitting; a load step of a quasi-static run at the load factor f "
                          "ends at f <Time stepping/End time>: k/N for step k of N, or a cut "
                          "one): 'explicit' (forward-Euler sub-steps at its own stable step "
                          "times <Time stepping/Safety factor>, as many as divide the step; "
                          "fewer in a cut load step), 'implicit' (one theta step of <Time "
                          "stepping/Theta> per step, with <Solver/Linear solver>), 'static' (a "
                          "steady run: before each load step of a quasi-static first physics, "
                          "its own static solve at the same load factor, with the top-level "
                          "<Solver> entries; refused if the first physics is explicit).");
        prm.leave_subsection();
        prm.enter_subsection("Coupling");
        using Methods = PluginRegistry<CouplingMethod<dim>>;
        prm.declare_entry("Method",
                          "blended",
                          Patterns::Selection(Methods::pattern_string()),
                          "How this physics' FE part and particles are joined through the "
                          "problem's overlap (<Coupling/Blending function>): " +
                            Methods::documentation() + "Each method reads its own subsection.");
        Methods::declare_parameters(prm);
        prm.leave_subsection();
        prm.leave_subsection();
      }
  }

  template <int dim>
  void
  Physics<dim>::parse_parameters(ParameterHandler           &prm,
                                 const ProblemSettings<dim> &problem_settings,
                                 const Physics<dim>         &first)
  {
    const std::string prefix = section(name) + "/";
    settings                 = problem_settings;
    // Its own stable step (CoupledProblem sub-cycles it within the first physics' steps).
    settings.time_step     = 0.;
    settings.base_name     = problem_settings.base_name + "_" + name;
    settings.solution_name = problem_settings.solution_name + "_" + name;
    prm.enter_subsection(section(name));
    with_entry_names([&]() {
      settings.parse_field_parameters(prm);
      settings.solver_type = solver_type_from_name(prm.get({"Solver"}, "Type"));
      pd.parse_physics_parameters(prm, section(name), first.pd);
      fe.parse_physics_parameters(prm, first.fe);
      parse_field(prm, prefix);
      parse_method(prm);
    });
    prm.leave_subsection();
    AssertThrow(method_name == first.method_name,
                ExcMessage("<" + prefix + "Coupling/Method> = " + method_name +
                           ", but <Coupling/Method> = " + first.method_name +
                           ": the physics share the particles, which one method's weights "
                           "place; accepted: " +
                           first.method_name + "."));
    AssertThrow(!pd.has_body() || layout.has_temperature(),
                ExcMessage("<" + prefix + "Material/Model> = <" +
                           prm.get({section(name), "Material"}, "Model") + "> has the unknowns " +
                           layout.description() + "; the physics " + name +
                           " has a temperature: accepted <" + prefix +
                           "Material/Model> = bond based conduction."));
    AssertThrow(!fe.has_mesh() || fe.field_layout().has_temperature(),
                ExcMessage("<" + prefix + "Finite elements/Physics> = <" +
                           prm.get({section(name), "Finite elements"}, "Physics") +
                           "> has the unknowns " + fe.field_layout().description() +
                           "; the physics " + name + " has a temperature: accepted <" + prefix +
                           "Finite elements/Physics> = heat."));
  }

  template <int dim>
  std::string
  Physics<dim>::named_in_section(const ExceptionBase &exc) const
  {
    std::ostringstream info;
    exc.print_info(info);
    std::string message = info.str();
    // The subsections declare_parameters() gives each physics.
    static const std::vector<std::string> own    = {"Material",
                                                    "Boundary conditions",
                                                    "Finite elements",
                                                    "Initial conditions",
                                                    "Body force",
                                                    "Solver",
                                                    "Coupling"};
    const std::string                     prefix = section(name) + "/";
    for (const auto &subsection : own)
      for (const std::string &closing : {std::string("/"), std::string(">")})
        {
          const std::string entry = "<" + subsection + closing;
          for (auto at = message.find(entry); at != std::string::npos;
               at      = message.find(entry, at + prefix.size() + entry.size()))
            message.insert(at + 1, prefix);
        }
    // print_info() indents the message and ends it with a line break, which ExcMessage adds
    // again.
    const auto first = message.find_first_not_of(" \n");
    const auto last  = message.find_last_not_of(" \n");
    return first == std::string::npos ? message : message.substr(first, last - first + 1);
  }

  template <int dim>
  void
  Physics<dim>::parse_field(ParameterHandler &prm, const std::string &prefix)
  {
    const std::string model_entry = prefix + "Material/Model";
    const std::string fe_entry    = prefix + "Finite elements/Physics";
    const std::string model_name  = prm.get({"Material"}, "Model");
    const std::string fe_name     = prm.get({"Finite elements"}, "Physics");
    // The unknowns: the particles' and the FE region's, the same in a coupled problem, or the
    // FE translations and the particles' rotations (half the curl of the FE displacement).
    layout = pd.has_body() ? pd.field_layout() : fe.field_layout();
    AssertThrow(!pd.has_body() || !fe.has_mesh() || pd.field_layout() == fe.field_layout() ||
                  pd.field_layout().extends_by_rotations(fe.field_layout()),
                ExcMessage("<" + model_entry + "> = <" + model_name + "> has the unknowns " +
                           pd.field_layout().description() + ", <" + fe_entry + "> = <" + fe_name +
                           "> has " + fe.field_layout().description() +
                           ": a coupled problem needs the same on both sides (the particles "
                           "may add rotations to FE translations). Accepted values of <" +
                           fe_entry + "> with this material model: " +
                           fe_physics_of<dim>(pd.field_layout()) + "."));
    model_lines = "material model = " + (pd.has_body() ? model_name : std::string("none")) +
                  "\nFE physics = " + (fe.has_mesh() ? fe_name : std::string("none")) + "\n";
    // Every expression is parsed here, so that --validate finds a malformed one.
    const unsigned int n_components = layout.n_components();
    ParameterUtilities::make_function<dim>(settings.initial_displacement,
                                           n_components,
                                           prefix + "Initial conditions/Displacement");
    ParameterUtilities::make_function<dim>(settings.initial_velocity,
                                           n_components,
                                           prefix + "Initial conditions/Velocity");
    // One body force for the whole body: the particles take it with their weights beta_i
    // (BoundaryConditions::add_loads), the FE region with 1 - beta (FERegion's load).
    std::shared_ptr<Function<dim>> body_force =
      ParameterUtilities::make_function<dim>(settings.body_force,
                                             n_components,
                                             prefix + "Body force/Function");
    const auto parts = Utilities::split_string_list(settings.body_force, ';');
    if (std::all_of(parts.begin(), parts.end(), [](const std::string &part) {
          return part == "0";
        }))
      body_force.reset();
    pd.boundary_conditions().set_body_force(body_force);
    if (body_force)
      fe.set_body_force(body_force);
  }

  template <int dim>
  void
  Physics<dim>::parse_method(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    method_name     = prm.get("Method");
    coupling_method = PluginRegistry<CouplingMethod<dim>>::create(method_name, "Coupling/Method");
    prm.enter_subsection(method_name);
    coupling_method->parse_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    coupling_method->check_solver(settings.solver_type);
    model_lines += "coupling method = " + method_name + "\n";
  }

  template <int dim>
  const CouplingMethod<dim> &
  Physics<dim>::method() const
  {
    Assert(coupling_method, ExcMessage("The method of the physics " + name + " is not made yet."));
    return *coupling_method;
  }

  template <int dim>
  CouplingMethod<dim> &
  Physics<dim>::method()
  {
    Assert(coupling_method, ExcMessage("The method of the physics " + name + " is not made yet."));
    return *coupling_method;
  }

  template <int dim>
  const CoupledState<dim> &
  Physics<dim>::state() const
  {
    Assert(coupled_state, ExcMessage("The state of the physics " + name + " is not made yet."));
    return *coupled_state;
  }

  template <int dim>
  CoupledState<dim> &
  Physics<dim>::state()
  {
    Assert(coupled_state, ExcMessage("The state of the physics " + name + " is not made yet."));
    return *coupled_state;
  }

  template <int dim>
  const Solver<dim> &
  Physics<dim>::solver() const
  {
    Assert(physics_solver, ExcMessage("The solver of the physics " + name + " is not made yet."));
    return *physics_solver;
  }

  template <int dim>
  Solver<dim> &
  Physics<dim>::solver()
  {
    Assert(physics_solver, ExcMessage("The solver of the physics " + name + " is not made yet."));
    return *physics_solver;
  }

  template <int dim>
  const Postprocessors<dim> &
  Physics<dim>::postprocessors() const
  {
    Assert(physics_postprocessors,
           ExcMessage("The postprocessors of the physics " + name + " is not made yet."));
    return *physics_postprocessors;
  }

  template <int dim>
  Postprocessors<dim> &
  Physics<dim>::postprocessors()
  {
    Assert(physics_postprocessors,
           ExcMessage("The postprocessors of the physics " + name + " is not made yet."));
    return *physics_postprocessors;
  }

  template <int dim>
  void
  Physics<dim>::set_state(std::unique_ptr<CoupledState<dim>> new_state)
  {
    coupled_state = std::move(new_state);
  }

  template <int dim>
  void
  Physics<dim>::set_solver(std::unique_ptr<Solver<dim>> new_solver)
  {
    physics_solver = std::move(new_solver);
  }

  template <int dim>
  void
  Physics<dim>::set_postprocessors(std::unique_ptr<Postprocessors<dim>> new_postprocessors)
  {
    physics_postprocessors = std::move(new_postprocessors);
  }

  template class Physics<2>;
  template class Physics<3>;
} // namespace perideal
