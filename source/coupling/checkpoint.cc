// ---------------------------------------------------------------------
// PeriDeal: checkpoints of a run and the restart from them.
// ---------------------------------------------------------------------
#include <perideal/coupling/checkpoint.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <map>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The "key = value" lines of @p text.
    std::map<std::string, std::string>
    parse_lines(const std::string &text)
    {
      std::map<std::string, std::string> entries;
      std::istringstream                 in(text);
      for (std::string line; std::getline(in, line);)
        {
          const auto equal = line.find(" = ");
          if (equal != std::string::npos)
            entries[line.substr(0, equal)] = line.substr(equal + 3);
        }
      return entries;
    }

    std::string
    exact_number(const double value)
    {
      std::ostringstream out;
      out << std::setprecision(17) << value;
      return out.str();
    }

    // @p lines ("key = value" lines) with every key prefixed by @p prefix.
    std::string
    prefixed(const std::string &lines, const std::string &prefix)
    {
      std::string        out;
      std::istringstream in(lines);
      for (std::string line; std::getline(in, line);)
        out += prefix + line + "\n";
      return out;
    }
  } // namespace

  template <int dim>
  Checkpoint<dim>::Checkpoint(const ProblemSettings<dim> &settings,
                              const std::string          &problem_lines,
                              const bool                  restart,
                              const unsigned int          stop_step)
    : file(settings.output_directory + "/checkpoint")
    , problem_lines(problem_lines)
    , interval(settings.checkpoint_interval)
    , time_interval(settings.checkpoint_time_interval)
    , restart(restart)
    , stop_step(stop_step)
  {}

  template <int dim>
  const std::string &
  Checkpoint<dim>::filename() const
  {
    return file;
  }

  template <int dim>
  void
  Checkpoint<dim>::set_run(const std::string &description, const unsigned int n_steps)
  {
    run_description = description;
    this->n_steps   = n_steps;
  }

  template <int dim>
  bool
  Checkpoint<dim>::restarting() const
  {
    return restart;
  }

  template <int dim>
  void
  Checkpoint<dim>::add_physics(const std::string &name,
                               const std::string &problem_lines,
                               CoupledState<dim> &state)
  {
    others.push_back({name, problem_lines, &state});
  }

  template <int dim>
  void
  Checkpoint<dim>::add_part(const std::string                             &line,
                            const std::function<void(CheckpointWriter &)> &save,
                            const std::function<void(CheckpointReader &)> &load)
  {
    parts.push_back({line, save, load});
  }

  template <int dim>
  std::vector<CoupledState<dim> *>
  Checkpoint<dim>::all_states(CoupledState<dim> &state) const
  {
    std::vector<CoupledState<dim> *> states{&state};
    for (const auto &other : others)
      states.push_back(other.state);
    return states;
  }

  template <int dim>
  std::string
  Checkpoint<dim>::fingerprint(const CoupledState<dim> &state) const
  {
    std::string list;
    for (const auto &other : others)
      list += (list.empty() ? "" : ", ") + other.name;
    std::ostringstream out;
    out << "dimension = " << dim << '\n'
        << "Physics/List = " << (list.empty() ? std::string("none") : list) << '\n'
        << problem_lines << state.fingerprint("") << "solver = " << run_description << '\n';
    for (const auto &other : others)
      out << prefixed(other.problem_lines, other.name + "/")
          << other.state->fingerprint(other.name + "/");
    for (const auto &part : parts)
      out << part.line << '\n';
    return out.str();
  }

  template <int dim>
  bool
  Checkpoint<dim>::due(const RunPosition &position) const
  {
    if (position.step >= n_steps)
      return false;
    if (interval > 0 && position.step % interval == 0)
      return true;
    // The multiples of the time interval reached by a time, with a margin for the round-off of
    // a time that is a multiple by construction (k dt, k / N).
    const auto multiples = [&](const double time) {
      const double ratio = time / time_interval;
      return std::floor(ratio + 1e-9 * std::max(1., std::abs(ratio)));
    };
    return time_interval > 0. && multiples(position.time) > multiples(previous_time);
  }

  template <int dim>
  bool
  Checkpoint<dim>::after_step(CoupledState<dim>         &state,
                              const Postprocessors<dim> &postprocessors,
                              const RunPosition         &position)
  {
    const bool stop = (position.step == stop_step);
    if (stop || due(position))
      write(state, postprocessors.save_state(state), position);
    previous_time = position.time;
    return stop;
  }

  template <int dim>
  void
  Checkpoint<dim>::keep(CoupledState<dim>         &state,
                        const Postprocessors<dim> &postprocessors,
                        const RunPosition         &position)
  {
    for (auto *each : all_states(state))
      each->keep();
    kept.intact         = state.pd().particles().bonds().intact;
    kept.postprocessors = postprocessors.save_state(state);
    kept.position       = position;
    kept.valid          = true;
  }

  template <int dim>
  RunPosition
  Checkpoint<dim>::restore_kept(CoupledState<dim> &state) const
  {
    Assert(kept.valid, ExcMessage("restore_kept() without keep()."));
    // The bonds first: the models' histories belong to the states of the bonds (set_states()
    // shows every physics' kernel the kept states; CoupledState::restore_kept() drops the record
    // of the bonds broken since keep()).
    state.pd().particles().bonds().set_states(kept.intact);
    for (auto *each : all_states(state))
      each->restore_kept();
    return kept.position;
  }

  template <int dim>
  RunPosition
  Checkpoint<dim>::write_kept(CoupledState<dim> &state)
  {
    restore_kept(state);
    write(state, kept.postprocessors, kept.position);
    return kept.position;
  }

  template <int dim>
  void
  Checkpoint<dim>::write(const CoupledState<dim> &state,
                         const std::string       &postprocessor_state,
                         const RunPosition       &position) const
  {
    const MPI_Comm   comm = state.comm();
    CheckpointWriter writer(comm);
    for (const auto &[key, value] : parse_lines(fingerprint(state)))
      writer.add_line(key, value);
    writer.add_line("ranks", std::to_string(Utilities::MPI::n_mpi_processes(comm)));
    writer.add_line("step", std::to_string(position.step));
    writer.add_line("time", exact_number(position.time));
    writer.add_line("next output", std::to_string(position.next_output));
    // The bonds once (the physics share them), then each physics' state.
    state.pd().save_bond_states(writer, "broken bonds");
    state.save(writer, "");
    for (const auto &other : others)
      other.state->save(writer, other.name + "/");
    for (const auto &part : parts)
      part.save(writer);
    // The postprocessors' state: rank 0's.
    writer.add_bytes("postprocessors",
                     state.is_root() ?
                       std::vector<char>(postprocessor_state.begin(), postprocessor_state.end()) :
                       std::vector<char>());

    const std::string temporary = file + ".tmp";
    if (state.is_root())
      std::filesystem::create_directories(state.settings().output_directory);
    writer.write(temporary);
    // Complete on every rank: replace the previous checkpoint (rename is atomic).
    MPI_Barrier(comm);
    if (state.is_root())
      {
        std::filesystem::rename(temporary, file);
        state.log() << "Checkpoint of step " << position.step << ": " << file << std::endl;
      }
    MPI_Barrier(comm);
  }

  template <int dim>
  RunPosition
  Checkpoint<dim>::load(CoupledState<dim> &state, Postprocessors<dim> &postprocessors)
  {
    CheckpointReader in(state.comm(),
                        file,
                        ", so the run cannot restart (--restart continues from the checkpoint in "
                        "<Output/Directory>, written by <Output/Checkpoint interval> or "
                        "<Output/Checkpoint time interval>, or by a quasi-static run that did "
                        "not converge); nothing was written.");
    const auto      &header = in.header();

    // The same problem: every line of this run's fingerprint.
    for (const auto &[key, value] : parse_lines(fingerprint(state)))
      {
        const auto found = header.find(key);
        AssertThrow(found != header.end() && found->second == value,
                    ExcMessage(
                      in.description() + " is from another problem: <" + key + "> is " +
                      (found == header.end() ? std::string("missing") : "<" + found->second + ">") +
                      " there, <" + value +
                      "> in this run. Restart with the parameter file of the run that wrote it, "
                      "or start the run without --restart. Nothing was written."));
      }

    state.pd().load_bond_states(in, "broken bonds");
    state.load(in, "");
    for (const auto &other : others)
      other.state->load(in, other.name + "/");
    for (const auto &part : parts)
      part.load(in);

    // The postprocessors (the statistics table is rewritten here, the first write).
    const std::vector<char> saved_state = in.read_all("postprocessors");
    postprocessors.load_state(state, std::string(saved_state.begin(), saved_state.end()));

    RunPosition position;
    position.step        = in.number("step");
    position.time        = std::stod(header.at("time"));
    position.next_output = in.number("next output");
    previous_time        = position.time;
    if (state.is_root())
      state.log() << "Restart from the checkpoint of step " << position.step << ": " << file
                  << std::endl;
    return position;
  }

  template class Checkpoint<2>;
  template class Checkpoint<3>;
} // namespace perideal
