// ---------------------------------------------------------------------
// PeriDeal: load, load-point displacement and crack length of a fracture run.
// ---------------------------------------------------------------------
#include <perideal/coupling/fracture_measures.h>
#include <perideal/pd/damage_model.h>

#include <algorithm>
#include <cmath>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  FractureMeasures<dim>::initialize(const CoupledState<dim>  &state,
                                    const QuasiStaticControl &control)
  {
    const auto &pd = state.pd();
    if (pd.has_body())
      {
        std::vector<Tensor<1, dim>> xi;
        std::vector<double>         weight;
        pd.particles().lattice_family(xi, weight);
        double sum = 0.;
        for (std::size_t k = 0; k < xi.size(); ++k)
          sum += (weight[k] > 0.) ? xi[k].norm() : 0.;
        const double dx  = pd.discretization().spacing;
        crossing_density = (dim == 2) ? sum / (numbers::PI * dx * dx) : sum / (4. * dx * dx * dx);
      }
    active = !control.load_point.empty();
    if (!active)
      return;

    // The condition: a displacement condition of the particles or of the FE region.
    const auto              &conditions = pd.boundary_conditions();
    const auto               held       = conditions.names_of(Quantity::value);
    const auto              &fe_list    = state.fe().conditions();
    std::vector<std::string> accepted(held);
    for (const auto &c : fe_list)
      if (c.type == Quantity::value)
        accepted.push_back(c.name);
    std::string accepted_list;
    for (const auto &name : accepted)
      accepted_list += (accepted_list.empty() ? "" : ", ") + name;
    const std::string entry = "<Solver/Control/Load point> = <" + control.load_point + ">";
    AssertThrow(std::find(accepted.begin(), accepted.end(), control.load_point) != accepted.end(),
                ExcMessage(
                  "The parameter " + entry +
                  " names no displacement condition; accepted: a name of <Boundary "
                  "conditions/Names> or <Finite elements/Boundary conditions/Names> of "
                  "type 'displacement' (" +
                  (accepted_list.empty() ? std::string("none in this file") : accepted_list) +
                  ")."));
    const auto &pd_names = conditions.names();
    const auto  pd_it    = std::find(pd_names.begin(), pd_names.end(), control.load_point);
    fe_condition         = (std::find(held.begin(), held.end(), control.load_point) == held.end());

    // The component, among those the condition prescribes.
    const FieldLayout        &layout = state.layout();
    std::vector<unsigned int> prescribed;
    if (fe_condition)
      {
        for (unsigned int k = 0; k < fe_list.size(); ++k)
          if (fe_list[k].name == control.load_point)
            {
              condition  = k;
              prescribed = fe_list[k].components;
            }
      }
    else
      {
        condition  = static_cast<unsigned int>(pd_it - pd_names.begin());
        prescribed = conditions.reaction_components(condition);
      }
    std::string names;
    for (const unsigned int c : prescribed)
      names += (names.empty() ? "" : ", ") + layout.name(c);
    const auto listed =
      std::find_if(prescribed.begin(), prescribed.end(), [&](const unsigned int c) {
        return layout.name(c) == control.load_component;
      });
    AssertThrow(listed != prescribed.end(),
                ExcMessage("The parameter <Solver/Control/Load component> is <" +
                           control.load_component + ">, which the load point <" +
                           control.load_point + "> does not prescribe; accepted: " + names + "."));
    component      = *listed;
    reaction_index = static_cast<unsigned int>(listed - prescribed.begin());

    // Its size: the volume of its particles or the number of its dofs of that component.
    if (fe_condition)
      {
        state.fe().initialize_vector(fe_ones);
        for (unsigned int k = 0; k < fe_ones.locally_owned_size(); ++k)
          fe_ones.local_element(k) = 1.;
        size = state.fe().reactions(fe_ones)[condition][component];
      }
    else
      {
        pd.particles().reinit_vector(particle_ones, state.n_components());
        for (unsigned int k = 0; k < particle_ones.locally_owned_size(); ++k)
          particle_ones.local_element(k) = 1.;
        size = -conditions.reactions(particle_ones)[condition][reaction_index];
      }
    AssertThrow(size > 0.,
                ExcMessage("The parameter " + entry + " names a condition that holds " +
                           (fe_condition ? std::string("no FE dof (its boundary ids are on no "
                                                       "FE-carrying face)") :
                                           std::string("no particle (its region contains none, or "
                                                       "only particles slaved to the FE field)")) +
                           ", so it has no load; name a condition that holds part of the body."));
  }

  template <int dim>
  bool
  FractureMeasures<dim>::has_load_point() const
  {
    return active;
  }

  template <int dim>
  typename FractureMeasures<dim>::Values
  FractureMeasures<dim>::measure(const CoupledState<dim> &state) const
  {
    Values values;
    if (state.pd().has_body())
      {
        values.broken_bonds = n_broken_bonds(state.pd().particles());
        values.crack_length = double(values.broken_bonds) / crossing_density;
      }
    if (!active)
      return values;
    if (fe_condition)
      {
        values.load         = state.fe().reactions(state.fe_support)[condition][component];
        values.displacement = state.fe().reactions(state.U)[condition][component] / size;
      }
    else
      {
        const auto &conditions = state.pd().boundary_conditions();
        values.load         = conditions.reactions(state.internal_force)[condition][reaction_index];
        values.displacement = -conditions.reactions(state.u)[condition][reaction_index] / size;
      }
    return values;
  }

  template class FractureMeasures<2>;
  template class FractureMeasures<3>;
} // namespace perideal
