// ---------------------------------------------------------------------
// PeriDeal: the ordered set of postprocessors a run executes.
// ---------------------------------------------------------------------
#include <perideal/coupling/postprocessors/postprocessor.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // Today's set, in its order: every file without a <Postprocess> section runs unchanged.
    const char *default_list = "energy statistics, displacement statistics, reactions, "
                               "fracture statistics, section integrals, exact error, probes, "
                               "field output";
  } // namespace

  template <int dim>
  void
  Postprocessors<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    prm.declare_entry(
      "List",
      default_list,
      Patterns::MultipleSelection(PluginRegistry<Postprocessor<dim>>::pattern_string()),
      "The postprocessors of the run, executed in this order after the steps the solver "
      "chooses (their columns of statistics.csv and lines of the summary follow it). '" +
        std::string(mandatory) +
        "' always runs, first if it is not listed: its energy balance stops an unstable "
        "explicit run. Without 'field output' no fields are written (nor the last iterate of a "
        "quasi-static step that does not converge). " +
        PluginRegistry<Postprocessor<dim>>::documentation());
    prm.leave_subsection();
  }

  template <int dim>
  std::vector<std::string>
  Postprocessors<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Postprocess");
    std::vector<std::string> names = Utilities::split_string_list(prm.get("List"));
    prm.leave_subsection();
    for (auto name = names.begin(); name != names.end(); ++name)
      AssertThrow(std::find(names.begin(), name, *name) == name,
                  ExcMessage("<Postprocess/List> names '" + *name +
                             "' twice; accepted values, each once: " +
                             PluginRegistry<Postprocessor<dim>>::pattern_string() + "."));
    if (std::find(names.begin(), names.end(), mandatory) == names.end())
      names.insert(names.begin(), mandatory);
    return names;
  }

  template <int dim>
  Postprocessors<dim>::Postprocessors(const std::vector<std::string> &names,
                                      const PostprocessorInputs<dim> &inputs)
  {
    for (const auto &name : names)
      {
        postprocessors.push_back(
          PluginRegistry<Postprocessor<dim>>::create(name, "Postprocess/List"));
        postprocessors.back()->set_inputs(inputs);
      }
  }

  template <int dim>
  void
  Postprocessors<dim>::initialize(const CoupledState<dim> &state)
  {
    for (const auto &postprocessor : postprocessors)
      postprocessor->initialize(state);
  }

  template <int dim>
  void
  Postprocessors<dim>::execute(const CoupledState<dim> &state, const StepData &data)
  {
    if (!statistics)
      create_statistics(state);
    if (data.write_statistics)
      {
        statistics->add_value("step", data.step);
        statistics->add_value("time", data.time);
        if (data.quasi_static)
          statistics->add_value("iterations", data.iterations);
      }
    if (data.final_row && state.is_root())
      {
        const auto flags = state.log().flags();
        state.log() << std::scientific << std::setprecision(6);
        if (data.quasi_static)
          state.log() << "Load factor: " << data.time << "\n";
        else
          state.log() << "Final time: " << data.time << " s\n";
        state.log().flags(flags);
      }
    for (const auto &postprocessor : postprocessors)
      postprocessor->execute(state, data, *statistics);
    for (const auto &[name, other_state, others] : physics)
      {
        if (data.final_row && state.is_root())
          state.log() << "Physics " << name << ":\n";
        // The other physics advance in time within the load steps of a quasi-static run (step
        // k of N ends at k/N of the end time), or take the same load steps (a steady physics:
        // its own equilibrium energy).
        StepData   other_data = data;
        const bool steady     = other_state->settings().solver_type == SolverType::static_linear;
        if (steady)
          other_data.pd_energy = other_state->equilibrium_particle_energy;
        else if (data.quasi_static)
          {
            other_data.quasi_static = false;
            other_data.time         = data.time * other_state->settings().end_time;
          }
        statistics->set_column_prefix(name + ".");
        for (const auto &postprocessor : others->postprocessors)
          postprocessor->execute(*other_state, other_data, *statistics);
        statistics->set_column_prefix("");
      }
    if (data.write_statistics)
      statistics->end_row();
  }

  template <int dim>
  void
  Postprocessors<dim>::add_physics(const std::string       &name,
                                   const CoupledState<dim> &other_state,
                                   Postprocessors<dim>     &others)
  {
    physics.emplace_back(name, &other_state, &others);
  }

  template <int dim>
  void
  Postprocessors<dim>::create_statistics(const CoupledState<dim> &state)
  {
    if (state.is_root())
      std::filesystem::create_directories(state.settings().output_directory);
    statistics =
      std::make_unique<StatisticsFile>(state.comm(),
                                       state.settings().output_directory + "/statistics.csv");
  }

  template <int dim>
  std::string
  Postprocessors<dim>::save_state(const CoupledState<dim> &state) const
  {
    std::vector<std::string> parts{statistics ? statistics->contents() : std::string()};
    for (const auto &postprocessor : postprocessors)
      parts.push_back(postprocessor->save_state(state));
    for (const auto &[name, other_state, others] : physics)
      for (const auto &postprocessor : others->postprocessors)
        parts.push_back(postprocessor->save_state(*other_state));
    const std::vector<char> packed = Utilities::pack(parts, false);
    return std::string(packed.begin(), packed.end());
  }

  template <int dim>
  void
  Postprocessors<dim>::load_state(const CoupledState<dim> &state, const std::string &packed)
  {
    const auto parts =
      Utilities::unpack<std::vector<std::string>>(std::vector<char>(packed.begin(), packed.end()),
                                                  false);
    std::size_t n_postprocessors = postprocessors.size();
    for (const auto &[name, other_state, others] : physics)
      n_postprocessors += others->postprocessors.size();
    AssertThrow(parts.size() == n_postprocessors + 1,
                ExcMessage("The checkpoint holds the state of " + std::to_string(parts.size() - 1) +
                           " postprocessors, the run has " + std::to_string(n_postprocessors) +
                           "."));
    create_statistics(state);
    statistics->resume(parts[0]);
    auto part = parts.begin() + 1;
    for (const auto &postprocessor : postprocessors)
      postprocessor->load_state(state, *part++);
    for (const auto &[name, other_state, others] : physics)
      for (const auto &postprocessor : others->postprocessors)
        postprocessor->load_state(*other_state, *part++);
  }

  template class Postprocessors<2>;
  template class Postprocessors<3>;
} // namespace perideal
