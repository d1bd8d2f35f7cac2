// ---------------------------------------------------------------------
// PeriDeal: checkpoints of a run and the restart from them.
// ---------------------------------------------------------------------
#include <deal.II/grid/cell_id.h>

#include <perideal/coupling/checkpoint.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <map>
#include <numeric>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The first and the last 16 bytes of a checkpoint.
    constexpr std::size_t mark_size                 = 16;
    constexpr char        begin_mark[mark_size + 1] = "PERIDEAL-CKPT-01";
    constexpr char        end_mark[mark_size + 1]   = "PERIDEAL-CKPT-OK";
    using CellKey                                   = CellId::binary_type;

    // Where the sections of a checkpoint start, from the sizes in its header.
    struct FileLayout
    {
      std::uint64_t sums, particles, bonds, histories, fe, state, end, size;

      FileLayout(const std::uint64_t header_bytes,
                 const std::uint64_t n_ranks,
                 const std::uint64_t particle_bytes,
                 const std::uint64_t n_broken,
                 const std::uint64_t history_bytes,
                 const std::uint64_t fe_bytes,
                 const std::uint64_t state_bytes)
      {
        sums      = mark_size + sizeof(std::uint64_t) + header_bytes;
        particles = sums + n_ranks * 2 * sizeof(double);
        bonds     = particles + particle_bytes;
        histories = bonds + n_broken * 2 * sizeof(std::uint64_t);
        fe        = histories + history_bytes;
        state     = fe + fe_bytes;
        end       = state + state_bytes;
        size      = end + mark_size;
      }
    };

    // An MPI-IO file, closed (collectively) when it goes out of scope.
    class File
    {
    public:
      File(const MPI_Comm comm, const std::string &name, const int mode)
      {
        opened = MPI_File_open(comm, name.c_str(), mode, MPI_INFO_NULL, &handle) == MPI_SUCCESS;
      }

      ~File()
      {
        if (opened)
          MPI_File_close(&handle);
      }

      File(const File &) = delete;
      File &
      operator=(const File &) = delete;

      void
      close()
      {
        const int ierr = MPI_File_close(&handle);
        AssertThrowMPI(ierr);
        opened = false;
      }

      // Independent reads and writes at byte offsets, in pieces an int can count.
      void
      write(const std::uint64_t offset, const void *data, const std::uint64_t bytes)
      {
        const char *begin = static_cast<const char *>(data);
        for (std::uint64_t done = 0; done < bytes;)
          {
            const int piece = static_cast<int>(std::min<std::uint64_t>(bytes - done, 1u << 30));
            const int ierr  = MPI_File_write_at(handle,
                                               offset + done,
                                               begin + done,
                                               piece,
                                               MPI_BYTE,
                                               MPI_STATUS_IGNORE);
            AssertThrowMPI(ierr);
            done += piece;
          }
      }

      void
      read(const std::uint64_t offset, void *data, const std::uint64_t bytes)
      {
        char *begin = static_cast<char *>(data);
        for (std::uint64_t done = 0; done < bytes;)
          {
            const int piece = static_cast<int>(std::min<std::uint64_t>(bytes - done, 1u << 30));
            const int ierr  = MPI_File_read_at(handle,
                                              offset + done,
                                              begin + done,
                                              piece,
                                              MPI_BYTE,
                                              MPI_STATUS_IGNORE);
            AssertThrowMPI(ierr);
            done += piece;
          }
      }

      MPI_File handle;
      bool     opened = false;
    };

    // The sum of @p value over the ranks before this one.
    std::uint64_t
    sum_before(const std::uint64_t value, const MPI_Comm comm)
    {
      std::uint64_t before = 0;
      const int     ierr   = MPI_Exscan(&value, &before, 1, MPI_UINT64_T, MPI_SUM, comm);
      AssertThrowMPI(ierr);
      return Utilities::MPI::this_mpi_process(comm) == 0 ? 0 : before;
    }

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

    // The number of values per bond of the material model's bond histories (0 without one).
    template <int dim>
    unsigned int
    history_values(CoupledState<dim> &state)
    {
      return state.pd.has_body() ? state.pd.material().n_bond_history_values() : 0;
    }

    // Whether an owned cell carries FE unknowns (FE_Q, not FE_Nothing).
    template <int dim>
    bool
    carries_unknowns(const FERegion<dim> &fe, const typename DoFHandler<dim>::cell_iterator &cell)
    {
      return fe.n_dofs() > 0 && cell->is_locally_owned() && cell->active_fe_index() == 0;
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
  std::string
  Checkpoint<dim>::fingerprint(CoupledState<dim> &state) const
  {
    const auto        &fe       = state.fe;
    std::uint64_t      fe_cells = 0;
    const unsigned int fe_dofs_per_cell =
      fe.n_dofs() > 0 ? fe.get_dof_handler().get_fe_collection()[0].n_dofs_per_cell() : 0;
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      fe_cells += carries_unknowns(fe, cell);
    const auto         parts = state.stored_parts();
    std::ostringstream out;
    out << "dimension = " << dim << '\n'
        << problem_lines << "unknowns = " << state.layout.description() << '\n'
        << "particles = " << state.pd.particles().n_global() << '\n'
        << "bonds = " << state.pd.particles().n_global_bonds() << '\n'
        << "FE cells with unknowns = " << Utilities::MPI::sum(fe_cells, state.comm) << '\n'
        << "FE dofs = " << fe.n_dofs() << '\n'
        << "FE dofs per cell = " << fe_dofs_per_cell << '\n'
        << "particle fields = " << parts.particle_vectors.size() << " x " << state.n_components()
        << " + 1\n"
        << "FE fields = " << parts.fe_vectors.size() << '\n'
        << "bond history values = " << history_values(state) << '\n'
        << "solver = " << run_description << '\n';
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
    const auto parts = state.stored_parts();
    kept.particle_vectors.resize(parts.particle_vectors.size());
    for (unsigned int k = 0; k < parts.particle_vectors.size(); ++k)
      kept.particle_vectors[k] = *parts.particle_vectors[k];
    kept.energy_density = *parts.energy_density;
    kept.fe_vectors.resize(parts.fe_vectors.size());
    for (unsigned int k = 0; k < parts.fe_vectors.size(); ++k)
      kept.fe_vectors[k] = *parts.fe_vectors[k];
    kept.work           = *parts.work;
    kept.dissipated     = *parts.dissipated;
    kept.intact         = state.pd.particles().bonds().intact;
    kept.history        = history_values(state) > 0 ?
                            state.pd.material().bond_history(state.pd.particles()) :
                            std::vector<double>();
    kept.postprocessors = postprocessors.save_state(state);
    kept.position       = position;
    kept.valid          = true;
  }

  template <int dim>
  RunPosition
  Checkpoint<dim>::restore_kept(CoupledState<dim> &state) const
  {
    Assert(kept.valid, ExcMessage("restore_kept() without keep()."));
    auto parts = state.stored_parts();
    for (unsigned int k = 0; k < parts.particle_vectors.size(); ++k)
      *parts.particle_vectors[k] = kept.particle_vectors[k];
    *parts.energy_density = kept.energy_density;
    for (unsigned int k = 0; k < parts.fe_vectors.size(); ++k)
      *parts.fe_vectors[k] = kept.fe_vectors[k];
    *parts.work       = kept.work;
    *parts.dissipated = kept.dissipated;
    BondList &bonds   = state.pd.particles().bonds();
    bonds.set_states(kept.intact);
    if (history_values(state) > 0)
      state.pd.material().set_bond_history(state.pd.particles(), kept.history);
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
  Checkpoint<dim>::write(CoupledState<dim> &state,
                         const std::string &postprocessor_state,
                         const RunPosition &position) const
  {
    const MPI_Comm     comm    = state.comm;
    const auto        &ps      = state.pd.particles();
    const auto        &fe      = state.fe;
    const unsigned int n_owned = ps.n_owned(), nc = state.n_components();
    auto               parts = state.stored_parts();

    // The particles' records in the order of their invariant index.
    const unsigned int        width = parts.particle_vectors.size() * nc + 1;
    std::vector<unsigned int> order(n_owned);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return ps.invariant_index(a) < ps.invariant_index(b);
    });
    std::vector<double> particle_data(std::size_t(n_owned) * width);
    for (unsigned int r = 0; r < n_owned; ++r)
      {
        double *record = &particle_data[std::size_t(r) * width];
        for (const ParticleVector *vector : parts.particle_vectors)
          for (unsigned int c = 0; c < nc; ++c)
            *record++ = vector->local_element(order[r] * nc + c);
        *record = (*parts.energy_density)[order[r]];
      }

    // The broken bonds, each once: by the rank that lists it with the lower invariant index
    // first (a bond to a ghost is listed on two ranks).
    std::vector<std::uint64_t> broken;
    const BondList            &bonds = ps.bonds();
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b] == 0)
          {
            const std::uint64_t p = ps.invariant_index(i),
                                q = ps.invariant_index(bonds.neighbor[b]);
            if (ps.neighbor_is_owned(b) || p < q)
              {
                broken.push_back(std::min(p, q));
                broken.push_back(std::max(p, q));
              }
          }

    // The bond histories of the same bonds, each once, as records (p, q, values) of the bonds
    // whose values are not all 0 (the bonds that have been loaded).
    const unsigned int  n_values = history_values(state);
    const std::uint64_t history_record =
      2 * sizeof(std::uint64_t) + std::uint64_t(n_values) * sizeof(double);
    std::vector<char> history_data;
    if (n_values > 0)
      {
        const std::vector<double> values = state.pd.material().bond_history(ps);
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            {
              const std::uint64_t p = ps.invariant_index(i),
                                  q = ps.invariant_index(bonds.neighbor[b]);
              const double *begin   = &values[std::size_t(b) * n_values];
              if ((ps.neighbor_is_owned(b) || p < q) &&
                  std::any_of(begin, begin + n_values, [](const double v) { return v != 0.; }))
                {
                  const std::uint64_t key[2] = {std::min(p, q), std::max(p, q)};
                  const char         *k      = reinterpret_cast<const char *>(key);
                  const char         *v      = reinterpret_cast<const char *>(begin);
                  history_data.insert(history_data.end(), k, k + sizeof(key));
                  history_data.insert(history_data.end(), v, v + n_values * sizeof(double));
                }
            }
      }

    // The FE records: the cell's id and its dof values of every FE vector (ghosted copies, so
    // that the dofs other ranks own are current; the state's vectors are left as they are).
    std::vector<char> fe_data;
    if (fe.n_dofs() > 0)
      {
        std::vector<FEVector> ghosted(parts.fe_vectors.size());
        for (unsigned int k = 0; k < ghosted.size(); ++k)
          {
            fe.initialize_vector(ghosted[k]);
            ghosted[k] = *parts.fe_vectors[k];
            ghosted[k].update_ghost_values();
          }
        std::vector<types::global_dof_index> dofs;
        for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
          if (carries_unknowns(fe, cell))
            {
              const CellKey key = cell->id().template to_binary<dim>();
              const char   *k   = reinterpret_cast<const char *>(key.data());
              fe_data.insert(fe_data.end(), k, k + sizeof(CellKey));
              dofs.resize(cell->get_fe().n_dofs_per_cell());
              cell->get_dof_indices(dofs);
              for (const auto &vector : ghosted)
                for (const auto dof : dofs)
                  {
                    const double value = vector(dof);
                    const char  *v     = reinterpret_cast<const char *>(&value);
                    fe_data.insert(fe_data.end(), v, v + sizeof(double));
                  }
            }
      }

    // The postprocessors' state (rank 0's) and the header, the same on every rank.
    const std::string  &saved_state = postprocessor_state;
    const std::uint64_t state_bytes =
      Utilities::MPI::broadcast(comm, std::uint64_t(saved_state.size()), 0);
    const std::uint64_t n_broken = Utilities::MPI::sum<std::uint64_t>(broken.size() / 2, comm);
    const std::uint64_t fe_bytes = Utilities::MPI::sum<std::uint64_t>(fe_data.size(), comm);
    const std::uint64_t n_histories =
      Utilities::MPI::sum<std::uint64_t>(history_data.size(), comm) /
      (n_values > 0 ? history_record : 1);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    std::ostringstream header;
    header << fingerprint(state) << "ranks = " << n_ranks << '\n'
           << "step = " << position.step << '\n'
           << "time = " << exact_number(position.time) << '\n'
           << "next output = " << position.next_output << '\n'
           << "broken bonds = " << n_broken << '\n'
           << "bond histories = " << n_histories << '\n'
           << "FE record bytes = " << fe_bytes << '\n'
           << "state bytes = " << state_bytes << '\n';
    const std::string   header_text  = header.str();
    const std::uint64_t header_bytes = header_text.size();
    const FileLayout    layout(header_bytes,
                            n_ranks,
                            ps.n_global() * width * sizeof(double),
                            n_broken,
                            n_histories * history_record,
                            fe_bytes,
                            state_bytes);

    const std::string temporary = file + ".tmp";
    if (state.is_root)
      std::filesystem::create_directories(state.settings.output_directory);
    {
      File out(comm, temporary, MPI_MODE_CREATE | MPI_MODE_WRONLY);
      AssertThrow(out.opened,
                  ExcMessage("The checkpoint <" + temporary +
                             "> cannot be written (<Output/Directory>)."));
      int ierr = MPI_File_set_size(out.handle, layout.size);
      AssertThrowMPI(ierr);
      if (rank == 0)
        {
          out.write(0, begin_mark, mark_size);
          out.write(mark_size, &header_bytes, sizeof(header_bytes));
          out.write(mark_size + sizeof(header_bytes), header_text.data(), header_bytes);
          out.write(layout.state, saved_state.data(), state_bytes);
          out.write(layout.end, end_mark, mark_size);
        }
      const std::array<double, 2> sums{{*parts.work, *parts.dissipated}};
      out.write(layout.sums + rank * sizeof(sums), sums.data(), sizeof(sums));
      // Contiguous runs of invariant indices.
      for (unsigned int r = 0; r < n_owned;)
        {
          unsigned int end = r + 1;
          while (end < n_owned &&
                 ps.invariant_index(order[end]) == ps.invariant_index(order[end - 1]) + 1)
            ++end;
          out.write(layout.particles + ps.invariant_index(order[r]) * width * sizeof(double),
                    &particle_data[std::size_t(r) * width],
                    std::uint64_t(end - r) * width * sizeof(double));
          r = end;
        }
      out.write(layout.bonds + sum_before(broken.size(), comm) * sizeof(std::uint64_t),
                broken.data(),
                broken.size() * sizeof(std::uint64_t));
      out.write(layout.histories + sum_before(history_data.size(), comm),
                history_data.data(),
                history_data.size());
      out.write(layout.fe + sum_before(fe_data.size(), comm), fe_data.data(), fe_data.size());
      ierr = MPI_File_sync(out.handle);
      AssertThrowMPI(ierr);
      out.close();
    }
    // Complete on every rank: replace the previous checkpoint (rename is atomic).
    MPI_Barrier(comm);
    if (state.is_root)
      {
        std::filesystem::rename(temporary, file);
        state.log << "Checkpoint of step " << position.step << ": " << file << std::endl;
      }
    MPI_Barrier(comm);
  }

  template <int dim>
  RunPosition
  Checkpoint<dim>::load(CoupledState<dim> &state, Postprocessors<dim> &postprocessors)
  {
    const MPI_Comm     comm    = state.comm;
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const std::string  name    = "The checkpoint <" + file + ">";
    File               in(comm, file, MPI_MODE_RDONLY);
    AssertThrow(in.opened,
                ExcMessage(name + " cannot be opened, so the run cannot restart (--restart "
                                  "continues from the checkpoint in <Output/Directory>, written "
                                  "by <Output/Checkpoint interval> or <Output/Checkpoint time "
                                  "interval>, or by a quasi-static run that did not converge); "
                                  "nothing was written."));
    MPI_Offset size = 0;
    int        ierr = MPI_File_get_size(in.handle, &size);
    AssertThrowMPI(ierr);
    const auto damaged = [&](const std::string &what) {
      return ExcMessage(name + " is " + what +
                        "; restart from a complete checkpoint, or start the run again without "
                        "--restart. Nothing was written.");
    };
    std::array<char, mark_size> mark{};
    std::uint64_t               header_bytes = 0;
    AssertThrow(std::uint64_t(size) >= mark_size + sizeof(header_bytes),
                damaged("truncated (" + std::to_string(size) + " bytes)"));
    in.read(0, mark.data(), mark_size);
    AssertThrow(std::memcmp(mark.data(), begin_mark, mark_size) == 0,
                damaged("not a PeriDeal checkpoint (it does not start with " +
                        std::string(begin_mark) + ")"));
    in.read(mark_size, &header_bytes, sizeof(header_bytes));
    AssertThrow(mark_size + sizeof(header_bytes) + header_bytes <= std::uint64_t(size),
                damaged("truncated (" + std::to_string(size) + " bytes, shorter than its header)"));
    std::string header_text(header_bytes, '\0');
    in.read(mark_size + sizeof(header_bytes), header_text.data(), header_bytes);
    const auto header = parse_lines(header_text);

    // The same problem: every line of this run's fingerprint.
    for (const auto &[key, value] : parse_lines(fingerprint(state)))
      {
        const auto found = header.find(key);
        AssertThrow(found != header.end() && found->second == value,
                    ExcMessage(
                      name + " is from another problem: <" + key + "> is " +
                      (found == header.end() ? std::string("missing") : "<" + found->second + ">") +
                      " there, <" + value +
                      "> in this run. Restart with the parameter file of the run that wrote it, "
                      "or start the run without --restart. Nothing was written."));
      }
    const auto number = [&](const std::string &key) {
      const auto found = header.find(key);
      AssertThrow(found != header.end(), damaged("damaged (no <" + key + "> in its header)"));
      return std::stoull(found->second);
    };
    const auto         &ps    = state.pd.particles();
    auto                parts = state.stored_parts();
    const unsigned int  nc = state.n_components(), n_owned = ps.n_owned();
    const unsigned int  width       = parts.particle_vectors.size() * nc + 1;
    const unsigned int  saved_ranks = number("ranks");
    const std::uint64_t n_broken    = number("broken bonds");
    const std::uint64_t n_histories = number("bond histories");
    const std::uint64_t fe_bytes    = number("FE record bytes");
    const std::uint64_t state_bytes = number("state bytes");
    const unsigned int  n_values    = history_values(state);
    const std::uint64_t history_record =
      2 * sizeof(std::uint64_t) + std::uint64_t(n_values) * sizeof(double);
    const FileLayout layout(header_bytes,
                            saved_ranks,
                            ps.n_global() * width * sizeof(double),
                            n_broken,
                            n_histories * history_record,
                            fe_bytes,
                            state_bytes);
    AssertThrow(std::uint64_t(size) == layout.size,
                damaged("truncated or damaged (" + std::to_string(size) + " bytes, its header " +
                        "gives " + std::to_string(layout.size) + ")"));
    in.read(layout.end, mark.data(), mark_size);
    AssertThrow(std::memcmp(mark.data(), end_mark, mark_size) == 0,
                damaged("damaged (it does not end with " + std::string(end_mark) + ")"));

    // This rank's partial sums; on another number of ranks their totals on rank 0.
    std::array<double, 2> sums{{0., 0.}};
    if (saved_ranks == n_ranks)
      in.read(layout.sums + rank * sizeof(sums), sums.data(), sizeof(sums));
    else if (rank == 0)
      {
        std::vector<double> all(2 * saved_ranks);
        in.read(layout.sums, all.data(), all.size() * sizeof(double));
        for (unsigned int r = 0; r < saved_ranks; ++r)
          for (unsigned int k = 0; k < 2; ++k)
            sums[k] += all[2 * r + k];
      }
    *parts.work       = sums[0];
    *parts.dissipated = sums[1];

    // The particles' records, in contiguous runs of invariant indices.
    std::vector<unsigned int> order(n_owned);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return ps.invariant_index(a) < ps.invariant_index(b);
    });
    std::vector<double> particle_data(std::size_t(n_owned) * width);
    for (unsigned int r = 0; r < n_owned;)
      {
        unsigned int end = r + 1;
        while (end < n_owned &&
               ps.invariant_index(order[end]) == ps.invariant_index(order[end - 1]) + 1)
          ++end;
        in.read(layout.particles + ps.invariant_index(order[r]) * width * sizeof(double),
                &particle_data[std::size_t(r) * width],
                std::uint64_t(end - r) * width * sizeof(double));
        r = end;
      }
    for (unsigned int r = 0; r < n_owned; ++r)
      {
        const double *record = &particle_data[std::size_t(r) * width];
        for (ParticleVector *vector : parts.particle_vectors)
          for (unsigned int c = 0; c < nc; ++c)
            vector->local_element(order[r] * nc + c) = *record++;
        (*parts.energy_density)[order[r]] = *record;
      }

    // The broken bonds: every rank reads them all and breaks those it lists.
    std::vector<std::array<std::uint64_t, 2>> broken(n_broken);
    in.read(layout.bonds, broken.data(), n_broken * 2 * sizeof(std::uint64_t));
    std::sort(broken.begin(), broken.end());
    BondList &bonds   = state.pd.particles().bonds();
    double    matched = 0.;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const std::uint64_t p = ps.invariant_index(i), q = ps.invariant_index(bonds.neighbor[b]);
          if (std::binary_search(broken.begin(),
                                 broken.end(),
                                 std::array<std::uint64_t, 2>{{std::min(p, q), std::max(p, q)}}))
            {
              bonds.break_bond(b);
              matched += ps.bond_share(b);
            }
        }
    AssertThrow(std::llround(Utilities::MPI::sum(matched, comm)) == std::int64_t(n_broken),
                ExcMessage(name + " is from another problem: " + std::to_string(n_broken) +
                           " broken bonds, of which " +
                           std::to_string(std::llround(Utilities::MPI::sum(matched, comm))) +
                           " join particles of this run. Nothing was written."));

    // The bond histories: every rank reads them all and takes those of the bonds it lists.
    if (n_values > 0)
      {
        std::vector<char> history_data(n_histories * history_record);
        in.read(layout.histories, history_data.data(), history_data.size());
        std::map<std::array<std::uint64_t, 2>, const char *> records;
        for (std::uint64_t r = 0; r < n_histories; ++r)
          {
            std::array<std::uint64_t, 2> key;
            std::memcpy(key.data(), &history_data[r * history_record], sizeof(key));
            records[key] = &history_data[r * history_record + sizeof(key)];
          }
        std::vector<double> values(std::size_t(bonds.size()) * n_values, 0.);
        double              found = 0.;
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
            {
              const std::uint64_t p = ps.invariant_index(i),
                                  q = ps.invariant_index(bonds.neighbor[b]);
              const auto record     = records.find({{std::min(p, q), std::max(p, q)}});
              if (record != records.end())
                {
                  std::memcpy(&values[std::size_t(b) * n_values],
                              record->second,
                              n_values * sizeof(double));
                  found += ps.bond_share(b);
                }
            }
        AssertThrow(std::llround(Utilities::MPI::sum(found, comm)) == std::int64_t(n_histories),
                    ExcMessage(name + " is from another problem: " + std::to_string(n_histories) +
                               " bond histories, of which " +
                               std::to_string(std::llround(Utilities::MPI::sum(found, comm))) +
                               " belong to bonds of this run. Nothing was written."));
        state.pd.material().set_bond_history(ps, values);
      }

    // The FE records: every rank reads them all and takes those of its cells.
    const auto &fe = state.fe;
    if (fe.n_dofs() > 0)
      {
        std::vector<char> fe_data(fe_bytes);
        in.read(layout.fe, fe_data.data(), fe_bytes);
        const unsigned int dofs_per_cell =
          fe.get_dof_handler().get_fe_collection()[0].n_dofs_per_cell();
        const std::uint64_t record =
          sizeof(CellKey) + parts.fe_vectors.size() * dofs_per_cell * sizeof(double);
        std::map<CellKey, const char *> records;
        for (std::uint64_t offset = 0; offset + record <= fe_bytes; offset += record)
          {
            CellKey key;
            std::memcpy(key.data(), &fe_data[offset], sizeof(CellKey));
            records[key] = &fe_data[offset + sizeof(CellKey)];
          }
        std::vector<types::global_dof_index> dofs(dofs_per_cell);
        for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
          if (carries_unknowns(fe, cell))
            {
              const auto found = records.find(cell->id().template to_binary<dim>());
              AssertThrow(found != records.end(),
                          ExcMessage(name +
                                     " is from another problem: it has no values for the "
                                     "FE cell " +
                                     cell->id().to_string() + ". Nothing was written."));
              cell->get_dof_indices(dofs);
              const char *values = found->second;
              for (auto *vector : parts.fe_vectors)
                for (const auto dof : dofs)
                  {
                    double value;
                    std::memcpy(&value, values, sizeof(double));
                    values += sizeof(double);
                    if (vector->in_local_range(dof))
                      (*vector)(dof) = value;
                  }
            }
      }
    state.u.update_ghost_values();
    state.U.update_ghost_values();

    // The postprocessors (the statistics table is rewritten here, the first write).
    std::string saved_state(state_bytes, '\0');
    in.read(layout.state, saved_state.data(), state_bytes);
    in.close();
    postprocessors.load_state(state, saved_state);

    RunPosition position;
    position.step        = number("step");
    position.time        = std::stod(header.at("time"));
    position.next_output = number("next output");
    previous_time        = position.time;
    if (state.is_root)
      state.log << "Restart from the checkpoint of step " << position.step << ": " << file
                << std::endl;
    return position;
  }

  template class Checkpoint<2>;
  template class Checkpoint<3>;
} // namespace perideal
