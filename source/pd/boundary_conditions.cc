// ---------------------------------------------------------------------
// PeriDeal: prescribed displacement, velocity and traction on particle sets.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/boundary_conditions.h>

#include <algorithm>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  BoundaryConditions<dim>::declare_names(ParameterHandler &prm)
  {
    ParameterUtilities::declare_name_list(prm,
                                          "Boundary conditions",
                                          "Comma-separated names of the boundary conditions, "
                                          "each described in a subsection of its own name.");
  }

  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler               &prm,
                                              const std::vector<std::string> &names)
  {
    declare_names(prm);
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Region",
                          "",
                          Patterns::Anything(),
                          "The region whose particles it acts on.");
        prm.declare_entry("Type",
                          "displacement",
                          Patterns::Selection("displacement|velocity|traction"),
                          "'displacement' [m] or 'velocity' [m/s] of the listed components, or "
                          "'traction' [Pa] (all components) applied as a body force in the region, "
                          "a surface layer of thickness 'Layer thickness'.");
        ParameterUtilities::declare_prescribed_components<dim>(prm);
        prm.declare_entry("Layer thickness",
                          "0",
                          Patterns::Double(0.),
                          "Traction only: thickness of the loaded layer [m] (the region's extent "
                          "normal to the surface).");
        prm.leave_subsection();
      }
    prm.leave_subsection();
    prm.enter_subsection("Body force");
    prm.declare_entry("Function",
                      dim == 2 ? "0; 0" : "0; 0; 0",
                      Patterns::Anything(),
                      "Body force density b(x, t) [N/m^3], one expression per component separated "
                      "by ';'.");
    prm.leave_subsection();
  }

  template <int dim>
  std::vector<std::string>
  BoundaryConditions<dim>::parse_names(ParameterHandler &prm)
  {
    return ParameterUtilities::parse_name_list(prm, "Boundary conditions");
  }

  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(ParameterHandler            &prm,
                                            const RegionCollection<dim> &regions)
  {
    condition_names = parse_names(prm);
    conditions.clear();
    prm.enter_subsection("Boundary conditions");
    for (const auto &name : condition_names)
      {
        const std::string prefix = "Boundary conditions/" + name + "/";
        prm.enter_subsection(name);
        Condition c;
        c.name              = name;
        c.region            = &regions.get(prm.get("Region"), prefix + "Region");
        const std::string t = prm.get("Type");
        c.type              = (t == "displacement" ? Type::displacement :
                               t == "velocity"     ? Type::velocity :
                                                     Type::traction);
        if (c.type == Type::traction)
          {
            for (unsigned int d = 0; d < dim; ++d)
              c.components.push_back(d);
            c.layer_thickness = prm.get_double("Layer thickness");
            ParameterUtilities::require_positive(c.layer_thickness, prefix + "Layer thickness");
          }
        else
          c.components = ParameterUtilities::parse_components(prm);
        c.expression = prm.get("Function");
        c.function   = ParameterUtilities::make_function<dim>(c.expression,
                                                            c.components.size(),
                                                            prefix + "Function");
        conditions.push_back(std::move(c));
        prm.leave_subsection();
      }
    prm.leave_subsection();
    prm.enter_subsection("Body force");
    const std::string expression = prm.get("Function");
    body_force     = ParameterUtilities::make_function<dim>(expression, dim, "Body force/Function");
    has_body_force = false;
    for (const auto &part : Utilities::split_string_list(expression, ';'))
      if (part != "0")
        has_body_force = true;
    prm.leave_subsection();
  }

  template <int dim>
  void
  BoundaryConditions<dim>::setup(const ParticleSystem<dim> &particles)
  {
    particle_system = &particles;
    prescribed.assign(std::size_t(particles.n_owned()) * dim, 0);
    std::vector<int> owner(std::size_t(particles.n_owned()) * dim, -1);
    const auto      &x = particles.positions();
    for (unsigned int k = 0; k < conditions.size(); ++k)
      {
        Condition &c = conditions[k];
        c.particles.clear();
        for (unsigned int i = 0; i < particles.n_owned(); ++i)
          if (c.region->contains(x[i]))
            c.particles.push_back(i);
        const auto n_total =
          Utilities::MPI::sum<unsigned long>(c.particles.size(), particles.get_communicator());
        AssertThrow(n_total > 0,
                    ExcMessage("The region <" + c.region->name() + "> of <Boundary conditions/" +
                               c.name +
                               "/Region> holds no particle; enlarge it to cover at least one "
                               "lattice point of the body."));
        if (c.type == Type::traction)
          continue;
        for (const unsigned int i : c.particles)
          for (const unsigned int comp : c.components)
            {
              int &first = owner[i * dim + comp];
              AssertThrow(first < 0,
                          ExcMessage("The boundary conditions <" + conditions[first].name +
                                     "> and <" + c.name +
                                     "> both prescribe the same component of a particle; make "
                                     "their regions or <Components> disjoint."));
              first                      = k;
              prescribed[i * dim + comp] = 1;
            }
      }
  }

  template <int dim>
  void
  BoundaryConditions<dim>::prescribe_step_velocity(const double    time,
                                                   const double    dt,
                                                   ParticleVector &v) const
  {
    const auto &x = particle_system->positions();
    for (const auto &c : conditions)
      for (const unsigned int i : c.particles)
        for (unsigned int k = 0; k < c.components.size(); ++k)
          {
            double value = 0.;
            if (c.type == Type::velocity)
              {
                c.function->set_time(time + 0.5 * dt);
                value = c.function->value(x[i], k);
              }
            else if (c.type == Type::displacement)
              {
                c.function->set_time(time + dt);
                value = c.function->value(x[i], k);
                c.function->set_time(time);
                value = (value - c.function->value(x[i], k)) / dt;
              }
            else
              continue;
            v.local_element(i * dim + c.components[k]) = value;
          }
  }

  template <int dim>
  void
  BoundaryConditions<dim>::prescribe_displacement(const double time, ParticleVector &u) const
  {
    const auto &x = particle_system->positions();
    for (const auto &c : conditions)
      if (c.type == Type::displacement)
        {
          c.function->set_time(time);
          for (const unsigned int i : c.particles)
            for (unsigned int k = 0; k < c.components.size(); ++k)
              u.local_element(i * dim + c.components[k]) = c.function->value(x[i], k);
        }
  }

  template <int dim>
  bool
  BoundaryConditions<dim>::has_loads() const
  {
    return has_body_force || std::any_of(conditions.begin(), conditions.end(), [](const auto &c) {
             return c.type == Type::traction;
           });
  }

  template <int dim>
  void
  BoundaryConditions<dim>::add_loads(const double time, ParticleVector &force) const
  {
    const auto &x = particle_system->positions();
    for (const auto &c : conditions)
      if (c.type == Type::traction)
        {
          c.function->set_time(time);
          for (const unsigned int i : c.particles)
            for (unsigned int d = 0; d < dim; ++d)
              force.local_element(i * dim + d) += c.function->value(x[i], d) / c.layer_thickness;
        }
    if (has_body_force)
      {
        const auto &weight = particle_system->energy_weights();
        body_force->set_time(time);
        for (unsigned int i = 0; i < particle_system->n_owned(); ++i)
          for (unsigned int d = 0; d < dim; ++d)
            force.local_element(i * dim + d) += weight[i] * body_force->value(x[i], d);
      }
  }

  template <int dim>
  std::shared_ptr<Function<dim>>
  BoundaryConditions<dim>::body_force_function() const
  {
    return has_body_force ? body_force : nullptr;
  }

  template <int dim>
  std::vector<std::string>
  BoundaryConditions<dim>::names_of_type(const Type type) const
  {
    std::vector<std::string> result;
    for (const auto &c : conditions)
      if (c.type == type)
        result.push_back(c.name);
    return result;
  }

  template <int dim>
  const std::vector<std::string> &
  BoundaryConditions<dim>::names() const
  {
    return condition_names;
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  BoundaryConditions<dim>::reactions(const ParticleVector &internal_force) const
  {
    std::vector<Tensor<1, dim>> result(conditions.size());
    const auto                 &volume = particle_system->volumes();
    for (unsigned int k = 0; k < conditions.size(); ++k)
      {
        for (const unsigned int i : conditions[k].particles)
          for (unsigned int d = 0; d < dim; ++d)
            result[k][d] -= internal_force.local_element(i * dim + d) * volume[i];
        result[k] = Utilities::MPI::sum(result[k], particle_system->get_communicator());
      }
    return result;
  }

  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace perideal
