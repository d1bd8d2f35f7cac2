// ---------------------------------------------------------------------
// PeriDeal: the temperature the mechanics measures its thermal strain from.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>
#include <deal.II/hp/q_collection.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/temperature_source.h>

#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    const ParameterUtilities::Choices<typename TemperatureSource<dim>::Kind> &
    source_names()
    {
      using Kind                                           = typename TemperatureSource<dim>::Kind;
      static const ParameterUtilities::Choices<Kind> names = {{"none", Kind::none},
                                                              {"function", Kind::function},
                                                              {"heat", Kind::heat}};
      return names;
    }
  } // namespace

  template <int dim>
  void
  TemperatureSource<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Temperature");
    prm.declare_entry(
      "Source",
      "none",
      Patterns::Selection(ParameterUtilities::selection(source_names<dim>())),
      "The temperature T of the thermal strain alpha (T - T_ref) of the mechanics (the models' "
      "and the FE elasticity's <Thermal expansion>): none; function (<Function> below, a "
      "prescribed T(x, y, (z), t)); heat (the temperature of the physics heat of "
      "<Physics/List>, at the particles and the FE nodes, as it advances).");
    prm.declare_entry("Function",
                      "",
                      Patterns::Anything(),
                      "Source = function: T(x, y, (z), t) [K], e.g. '20 + 100 * x / 0.05'.");
    prm.declare_entry("Reference temperature",
                      "",
                      Patterns::Anything(),
                      "T_ref [K]: the temperature at which the body is free of thermal strain. "
                      "Needed with a source (no default: a thermal strain is measured from it).");
    prm.declare_entry("Coupling",
                      "one way",
                      Patterns::Selection("one way|two way"),
                      "How the mechanics and the temperature act on each other: 'one way' (the "
                      "temperature strains the mechanics, and a crack changes the heat flow); "
                      "'two way' (also the thermoelastic heating -T_0 beta : d eps/dt of the "
                      "mechanics' deformation heats the physics heat, in the particles, the FE "
                      "region and the overlap: Source = heat, an explicit mechanics and an "
                      "explicit heat; doc/theory/thermoelasticity.md).");
    prm.declare_entry("Absolute reference temperature",
                      "",
                      Patterns::Anything(),
                      "Coupling = two way: T_0 [K] on the absolute scale, the temperature of the "
                      "heating -T_0 beta : d eps/dt (the reference temperature in kelvin, e.g. "
                      "293.15 for a reference of 20 degrees Celsius). No default.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  TemperatureSource<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Temperature");
    source =
      ParameterUtilities::choice(source_names<dim>(), prm.get("Source"), "Temperature/Source");
    expression                        = prm.get("Function");
    const std::string reference_entry = Utilities::trim(prm.get("Reference temperature"));
    two_way_coupling                  = prm.get("Coupling") == "two way";
    const std::string absolute_entry  = Utilities::trim(prm.get("Absolute reference temperature"));
    prm.leave_subsection();
    function.reset();
    AssertThrow(!two_way_coupling || source == Kind::heat,
                ExcMessage("<Temperature/Coupling> = two way heats the temperature by the "
                           "deformation, but <Temperature/Source> = " +
                           ParameterUtilities::choice_name(source_names<dim>(), source) +
                           " is not a temperature that can take heat; accepted: <Temperature/"
                           "Source> = heat (the physics heat of <Physics/List>), or "
                           "<Temperature/Coupling> = one way."));
    if (two_way_coupling)
      {
        const std::string entry = "<Temperature/Absolute reference temperature>";
        AssertThrow(!absolute_entry.empty(),
                    ExcMessage("<Temperature/Coupling> = two way, but " + entry +
                               " is missing: give T_0 [K] on the absolute scale (e.g. 293.15 "
                               "for 20 degrees Celsius)."));
        try
          {
            absolute_reference = Utilities::string_to_double(absolute_entry);
          }
        catch (...)
          {
            AssertThrow(false,
                        ExcMessage("The parameter " + entry + " = <" + absolute_entry +
                                   "> is not a number; accepted: T_0 > 0 [K]."));
          }
        AssertThrow(absolute_reference > 0.,
                    ExcMessage("The parameter " + entry + " is " + absolute_entry +
                               "; accepted values: T_0 > 0 K (the absolute scale)."));
      }
    if (source == Kind::none)
      return;
    AssertThrow(!reference_entry.empty(),
                ExcMessage("<Temperature/Source> = " +
                           ParameterUtilities::choice_name(source_names<dim>(), source) +
                           ", but <Temperature/Reference temperature> is missing: give T_ref [K], "
                           "the temperature at which the body is free of thermal strain."));
    try
      {
        reference = Utilities::string_to_double(reference_entry);
      }
    catch (...)
      {
        AssertThrow(false,
                    ExcMessage("The parameter <Temperature/Reference temperature> = <" +
                               reference_entry + "> is not a number; accepted: T_ref [K]."));
      }
    if (source == Kind::function)
      {
        AssertThrow(!Utilities::trim(expression).empty(),
                    ExcMessage("<Temperature/Source> = function, but <Temperature/Function> is "
                               "empty: give T(x, y, (z), t) [K]."));
        function = ParameterUtilities::make_function<dim>(expression, 1, "Temperature/Function");
      }
  }

  template <int dim>
  typename TemperatureSource<dim>::Kind
  TemperatureSource<dim>::kind() const
  {
    return source;
  }

  template <int dim>
  bool
  TemperatureSource<dim>::active() const
  {
    return source != Kind::none;
  }

  template <int dim>
  double
  TemperatureSource<dim>::reference_temperature() const
  {
    return reference;
  }

  template <int dim>
  bool
  TemperatureSource<dim>::two_way() const
  {
    return two_way_coupling;
  }

  template <int dim>
  double
  TemperatureSource<dim>::absolute_reference_temperature() const
  {
    return absolute_reference;
  }

  template <int dim>
  void
  TemperatureSource<dim>::connect(ParticleRegion<dim>        &pd,
                                  FERegion<dim>              &fe,
                                  const PhysicsExchange<dim> &physics_exchange)
  {
    exchange = &physics_exchange;
    heat_values.reset();
    if (pd.has_body())
      {
        particles = &pd.particles();
        particles->reinit_vector(delta_T, 1);
        pd.material().set_temperature_change(&delta_T);
      }
    if (fe.has_mesh())
      fe.set_temperature_change(
        [this](const FEValues<dim> &fe_values, const double time, std::vector<double> &values) {
          cell_change(fe_values, time, values);
        });
  }

  template <int dim>
  void
  TemperatureSource<dim>::update(const double time)
  {
    if (source == Kind::heat)
      {
        const auto &quantity = exchange->get("temperature");
        if (quantity.region->n_dofs() > 0)
          {
            if (heat_temperature.size() != quantity.fe->size())
              quantity.region->initialize_vector(heat_temperature);
            heat_temperature.copy_locally_owned_data_from(*quantity.fe);
            heat_temperature.update_ghost_values();
          }
      }
    if (particles == nullptr)
      return;
    if (source == Kind::function)
      {
        // Every local particle, ghosts included: no exchange.
        function->set_time(time);
        const auto &x = particles->positions();
        for (unsigned int i = 0; i < particles->n_local(); ++i)
          delta_T.local_element(i) = function->value(x[i]) - reference;
      }
    else
      {
        const auto        &quantity = exchange->get("temperature");
        const unsigned int nc       = quantity.layout.n_components();
        for (unsigned int i = 0; i < particles->n_owned(); ++i)
          delta_T.local_element(i) =
            quantity.particles->local_element(i * nc + quantity.component) - reference;
        delta_T.update_ghost_values();
      }
  }

  template <int dim>
  void
  TemperatureSource<dim>::cell_change(const FEValues<dim> &fe_values,
                                      const double         time,
                                      std::vector<double> &values) const
  {
    const unsigned int n_q = fe_values.n_quadrature_points;
    values.resize(n_q);
    if (source == Kind::function)
      {
        function->set_time(time);
        for (unsigned int q = 0; q < n_q; ++q)
          values[q] = function->value(fe_values.quadrature_point(q)) - reference;
        return;
      }
    const auto                      &heat = heat_cell_values(fe_values);
    const FEValuesExtractors::Scalar temperature(exchange->get("temperature").component);
    heat[temperature].get_function_values(heat_temperature, values);
    for (double &v : values)
      v -= reference;
  }

  template <int dim>
  const FEValues<dim> &
  TemperatureSource<dim>::heat_cell_values(const FEValues<dim> &fe_values) const
  {
    // The heat's cell of the same CellId (its own triangulation, built and partitioned alike),
    // evaluated at the mechanics' quadrature points.
    const auto &region = *exchange->get("temperature").region;
    const auto &tria   = region.get_triangulation();
    const auto  cell   = tria.create_cell_iterator(fe_values.get_cell()->id());
    const typename DoFHandler<dim>::active_cell_iterator heat_cell(&tria,
                                                                   cell->level(),
                                                                   cell->index(),
                                                                   &region.get_dof_handler());
    AssertThrow(heat_cell->get_fe().n_dofs_per_cell() > 0,
                ExcMessage("The heat has no FE temperature on an FE cell of the mechanics: both "
                           "physics need the same coupling method and blending function."));
    // The quadrature is the same for every cell of an assembly, but the output evaluates at
    // points of its own per cell.
    const auto &points = fe_values.get_quadrature().get_points();
    if (!heat_values || heat_points != points)
      {
        heat_points = points;
        heat_values =
          std::make_unique<hp::FEValues<dim>>(region.get_fe_collection(),
                                              hp::QCollection<dim>(fe_values.get_quadrature()),
                                              update_values);
      }
    heat_values->reinit(heat_cell);
    return heat_values->get_present_fe_values();
  }

  template <int dim>
  void
  TemperatureSource<dim>::add_at_heat_points(const FEValues<dim>       &fe_values,
                                             const std::vector<double> &values,
                                             FEVector                  &heat_vector) const
  {
    const auto                      &heat     = heat_cell_values(fe_values);
    const auto                      &quantity = exchange->get("temperature");
    const FEValuesExtractors::Scalar temperature(quantity.component);
    dealii::Vector<double>           cell_vector(heat.dofs_per_cell);
    for (const unsigned int q : heat.quadrature_point_indices())
      for (unsigned int k = 0; k < heat.dofs_per_cell; ++k)
        cell_vector(k) += values[q] * heat[temperature].value(k, q);
    const auto                                          &region = *quantity.region;
    const typename DoFHandler<dim>::active_cell_iterator heat_cell(&region.get_triangulation(),
                                                                   heat.get_cell()->level(),
                                                                   heat.get_cell()->index(),
                                                                   &region.get_dof_handler());
    region.add_cell_vector(heat_cell, cell_vector, heat_vector);
  }

  template <int dim>
  const ParticleVector &
  TemperatureSource<dim>::particle_change() const
  {
    return delta_T;
  }

  template <int dim>
  std::string
  TemperatureSource<dim>::summary() const
  {
    std::ostringstream out;
    out << "Temperature: " << ParameterUtilities::choice_name(source_names<dim>(), source);
    if (source == Kind::function)
      out << " T = " << expression;
    if (source == Kind::heat)
      out << " (the temperature of the physics heat)";
    out << ", T_ref = " << reference << " K";
    if (two_way_coupling)
      out << ", two way (thermoelastic heating, T_0 = " << absolute_reference << " K)";
    return out.str();
  }

  template class TemperatureSource<2>;
  template class TemperatureSource<3>;
} // namespace perideal
