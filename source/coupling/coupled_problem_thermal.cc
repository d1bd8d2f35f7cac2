// ---------------------------------------------------------------------
// PeriDeal: the thermal strain of the first physics (<Temperature>): its checks and its
// connection to the particles' model, the FE region and the state.
// ---------------------------------------------------------------------
#include <perideal/base/thermal_expansion.h>
#include <perideal/coupling/coupled_problem.h>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The <Thermal expansion> of subsection @p path (entered from the root), named @p section
    // in messages.
    ThermalExpansion
    expansion_in(ParameterHandler               &prm,
                 const std::vector<std::string> &path,
                 const std::string              &section)
    {
      for (const auto &name : path)
        prm.enter_subsection(name);
      ThermalExpansion expansion;
      try
        {
          expansion.parse_parameters(prm, section, true);
        }
      catch (...)
        {
          for (unsigned int k = 0; k < path.size(); ++k)
            prm.leave_subsection();
          throw;
        }
      for (unsigned int k = 0; k < path.size(); ++k)
        prm.leave_subsection();
      return expansion;
    }
  } // namespace

  template <int dim>
  void
  CoupledProblem<dim>::parse_thermal_strain(ParameterHandler &prm)
  {
    temperature.parse_parameters(prm);
    const std::string source = "<Temperature/Source> = " + prm.get({"Temperature"}, "Source");

    // The thermal expansion of each part: the particles' model's entry (a model with a thermal
    // strain declares it), the FE elasticity's (its own entry, or the particles' material).
    const std::string model      = pd.has_body() ? prm.get({"Material"}, "Model") : "";
    const bool        pd_thermal = pd.has_body() && pd.material().capabilities().thermal_strain;
    const std::string pd_entry   = "<Material/" + model + "/Thermal expansion>";
    ThermalExpansion  pd_expansion, fe_expansion;
    if (pd_thermal)
      pd_expansion = expansion_in(prm, {"Material", model}, "Material/" + model);
    const bool fe_elastic =
      fe.has_mesh() && fe.field_layout().kind(0) == ComponentKind::translation;
    const bool        fe_shared = fe_elastic && fe.physics().shares_particle_material();
    const std::string fe_entry =
      fe_shared ? pd_entry : "<Finite elements/Elasticity/Thermal expansion>";
    if (fe_elastic)
      fe_expansion =
        fe_shared ?
          pd_expansion :
          expansion_in(prm, {"Finite elements", "Elasticity"}, "Finite elements/Elasticity");
    const bool expands = !pd_expansion.is_zero() || !fe_expansion.is_zero();

    if (!temperature.active())
      {
        AssertThrow(!expands,
                    ExcMessage((!pd_expansion.is_zero() ? pd_entry : fe_entry) +
                               " is set, but <Temperature/Source> = none: the thermal strain "
                               "needs a temperature. Accepted <Temperature/Source>: function (a "
                               "prescribed T(x, t)), heat (the temperature of the physics heat "
                               "of <Physics/List>); or the thermal expansion 0."));
        return;
      }
    AssertThrow(!pd.has_body() || pd_thermal,
                ExcMessage(source + ", but <Material/Model> = " + model +
                           " has no thermal strain; accepted models: " +
                           material_models_with<dim>(&ModelCapabilities::thermal_strain) +
                           " (or <Temperature/Source> = none)."));
    AssertThrow(!fe.has_mesh() || fe_elastic,
                ExcMessage(source + ", but <Finite elements/Physics> = " +
                           prm.get({"Finite elements"}, "Physics") +
                           " has no thermal strain; accepted: elasticity (or <Temperature/Source> "
                           "= none)."));
    AssertThrow(expands,
                ExcMessage(source +
                           ", but no thermal expansion is set: the temperature would "
                           "act on nothing. Set " +
                           (pd.has_body() ? pd_entry : fe_entry) +
                           (pd.has_body() && fe.has_mesh() && !fe_shared ? " and " + fe_entry :
                                                                           std::string()) +
                           " (alpha [1/K]), or <Temperature/Source> = none."));
    AssertThrow(!pd.has_body() || !fe_elastic ||
                  (pd_expansion.tensor() - fe_expansion.tensor()).norm() <=
                    1e-12 * pd_expansion.tensor().norm(),
                ExcMessage(pd_entry + " and " + fe_entry +
                           " differ: the particles and the FE region are one material, joined "
                           "in the overlap; accepted: the same thermal expansion in both."));
    const auto &list = prm.get({"Physics"}, "List");
    AssertThrow(temperature.kind() != TemperatureSource<dim>::Kind::heat ||
                  list.find("heat") != std::string::npos,
                ExcMessage(source +
                           " reads the temperature of the physics heat, but <Physics/"
                           "List> = " +
                           list +
                           " does not list it; accepted: <Physics/List> = heat (and its "
                           "subsection Heat), or <Temperature/Source> = function."));
    AssertThrow(control.method == LoadControl::load_steps,
                ExcMessage(source +
                           ": <Solver/Control/Method> = sequentially linear scales the whole "
                           "load of one linear solve by each event's load factor, and a "
                           "thermal strain is a load of its own time; accepted with a "
                           "temperature: <Solver/Control/Method> = load steps."));
    if (temperature.two_way())
      check_two_way(prm);
  }

  template <int dim>
  void
  CoupledProblem<dim>::check_two_way(ParameterHandler &prm) const
  {
    // What the thermoelastic heating needs (doc/theory/thermoelasticity.md): the measure of the
    // particles' model, an explicit mechanics whose steps the heat follows, an explicit heat
    // (its source is held over each step as an applied load), and a run the conversions do not
    // cut (they do not carry the previous step's measure yet).
    const std::string entry = "<Temperature/Coupling> = two way";
    const std::string model = pd.has_body() ? prm.get({"Material"}, "Model") : "";
    AssertThrow(!pd.has_body() || pd.material().capabilities().thermoelastic_heating,
                ExcMessage(entry +
                           " heats by the particles' thermoelastic measure, which <Material/"
                           "Model> = " +
                           model + " does not give; accepted models: " +
                           material_models_with<dim>(&ModelCapabilities::thermoelastic_heating) +
                           " (or <Temperature/Coupling> = one way)."));
    AssertThrow(settings.solver_type == SolverType::explicit_dynamics,
                ExcMessage(entry + " heats by the rate of the deformation, which <Solver/Type> = " +
                           prm.get({"Solver"}, "Type") +
                           " has no time for; accepted: <Solver/Type> = explicit (or "
                           "<Temperature/Coupling> = one way)."));
    for (unsigned int k = 1; k < physics.size(); ++k)
      if (physics[k]->layout.has_temperature())
        AssertThrow(physics[k]->settings.solver_type == SolverType::explicit_dynamics,
                    ExcMessage(
                      entry + " adds the heating to the heat's explicit steps, but <" +
                      Physics<dim>::section(physics[k]->name) + "/Solver/Type> = " +
                      prm.get({Physics<dim>::section(physics[k]->name), "Solver"}, "Type") +
                      "; accepted: explicit (or <Temperature/Coupling> = one way)."));
    AssertThrow(!adaptive.enabled(),
                ExcMessage(entry + ": a conversion of the adaptive PD region does not carry the "
                                   "deformation's measure over yet; set <Coupling/Adaptive "
                                   "region/Criterion> = none (or <Temperature/Coupling> = one "
                                   "way)."));
  }

  template <int dim>
  void
  CoupledProblem<dim>::connect_temperature()
  {
    if (!temperature.active())
      return;
    temperature.connect(pd, fe, exchange);
    if (temperature.two_way())
      set_coupling_numbers();
    state().set_temperature([this](const double time) { temperature.update(time); });
  }

  template <int dim>
  void
  CoupledProblem<dim>::set_coupling_numbers()
  {
    // The heat's smallest capacity rho c at the particles and in the FE region: the largest
    // coupling number.
    double particle_capacity = std::numeric_limits<double>::max(),
           fe_capacity       = std::numeric_limits<double>::max();
    for (unsigned int k = 1; k < physics.size(); ++k)
      if (const Physics<dim> &heat = *physics[k]; heat.layout.has_temperature())
        {
          if (heat.pd.has_body())
            {
              const auto &material = heat.pd.material();
              const auto  inertia  = material.inertia_densities(heat.pd.density());
              const auto  scales = material.inertia_scales(heat.pd.particles(), heat.pd.density());
              for (unsigned int c = 0; c < heat.layout.n_components(); ++c)
                if (heat.layout.kind(c) == ComponentKind::temperature)
                  {
                    double smallest = scales.empty() ? 1. : std::numeric_limits<double>::max();
                    for (const double scale : scales)
                      smallest = std::min(smallest, scale);
                    particle_capacity = std::min(particle_capacity, inertia[c] * smallest);
                  }
            }
          if (heat.fe.has_mesh())
            fe_capacity =
              std::min(fe_capacity, heat.fe.get_density() * heat.fe.physics().mass_factor());
        }
    particle_capacity = Utilities::MPI::min(particle_capacity, comm);
    // delta = T_0 beta : alpha / (rho c), beta : alpha = alpha : C : alpha of the model's plane.
    const double T0 = temperature.absolute_reference_temperature();
    if (pd.has_body() && particle_capacity < std::numeric_limits<double>::max())
      {
        const auto alpha = pd.material().thermal_expansion();
        state().particle_coupling_number =
          T0 * (alpha * (pd.material().elasticity_tensor() * alpha)) / particle_capacity;
      }
    if (fe.has_mesh() && fe.has_thermal_strain() &&
        fe_capacity < std::numeric_limits<double>::max())
      state().fe_coupling_number = T0 * fe.physics().thermoelastic_coupling_modulus() / fe_capacity;
  }

  template void
  CoupledProblem<2>::parse_thermal_strain(ParameterHandler &);
  template void
  CoupledProblem<3>::parse_thermal_strain(ParameterHandler &);
  template void
  CoupledProblem<2>::check_two_way(ParameterHandler &) const;
  template void
  CoupledProblem<3>::check_two_way(ParameterHandler &) const;
  template void
  CoupledProblem<2>::set_coupling_numbers();
  template void
  CoupledProblem<3>::set_coupling_numbers();
  template void
  CoupledProblem<2>::connect_temperature();
  template void
  CoupledProblem<3>::connect_temperature();
} // namespace perideal
