// ---------------------------------------------------------------------
// PeriDeal: the static linear solve of an FE-PD coupling: assembly of the system, its solve
// and the forces of a state.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <perideal/coupling/coupled_static_solver.h>
#include <perideal/coupling/matrix_rows.h>

#include <algorithm>
#include <numeric>


namespace perideal
{
  using namespace dealii;

  namespace
  {
    /// @p result = @p A^T diag(@p w) @p A, with rows and columns partitioned as @p owned (A's
    /// columns): row i of the result is sum_r w_r a_ri a_r over the local rows r of A that have
    /// column i, summed row by row with a dense accumulator over the columns A touches
    /// (Gustavson's product with A's transpose), rows of other ranks sent by compress().
    /// Trilinos' transposed products (EpetraExt's Multiply with A transposed, with or without
    /// an explicit transpose) corrupt the heap on two ranks for some partitions (the coupled
    /// torsion of tests/coupling/torsion_edge_crack_02, the PD part of overlapping Schwarz), so
    /// the product is summed here.
    void
    weighted_gram(const SparseMatrix &A,
                  const SolverVector &w,
                  const IndexSet     &owned,
                  const MPI_Comm      comm,
                  SparseMatrix       &result)
    {
      // A's local rows in Epetra's compressed storage (columns numbered in A's column map),
      // the global indices of A's columns sorted, and each column's position among them.
      const Epetra_CrsMatrix &epetra    = A.trilinos_matrix();
      int                    *row_start = nullptr, *column = nullptr;
      double                 *value = nullptr;
      AssertThrow(epetra.ExtractCrsDataPointers(row_start, column, value) == 0,
                  ExcMessage("weighted_gram() needs a matrix in Epetra's optimized storage."));
      const unsigned int        n_rows    = epetra.NumMyRows();
      const unsigned int        n_columns = epetra.NumMyCols();
      std::vector<unsigned int> position(n_columns);
      std::iota(position.begin(), position.end(), 0u);
      std::sort(position.begin(), position.end(), [&](const unsigned int a, const unsigned int b) {
        return TrilinosWrappers::global_column_index(epetra, a) <
               TrilinosWrappers::global_column_index(epetra, b);
      });
      std::vector<types::global_dof_index> global_column(n_columns);
      for (unsigned int k = 0; k < n_columns; ++k)
        global_column[k] = TrilinosWrappers::global_column_index(epetra, position[k]);
      {
        const std::vector<unsigned int> sorted(position);
        for (unsigned int k = 0; k < n_columns; ++k)
          position[sorted[k]] = k;
      }
      std::vector<double> weight(n_rows);
      for (unsigned int r = 0; r < n_rows; ++r)
        weight[r] = w[TrilinosWrappers::global_row_index(epetra, r)];

      // A's columns as positions in the sorted order, and A's transpose: for each column
      // (sorted), the rows of A that have it and their entry.
      const unsigned int        n_entries = row_start[n_rows];
      std::vector<unsigned int> entry_column(n_entries);
      for (unsigned int k = 0; k < n_entries; ++k)
        entry_column[k] = position[column[k]];
      std::vector<unsigned int> column_start(n_columns + 1, 0);
      for (const unsigned int c : entry_column)
        ++column_start[c + 1];
      std::partial_sum(column_start.begin(), column_start.end(), column_start.begin());
      std::vector<unsigned int> transposed_row(n_entries), transposed_entry(n_entries);
      {
        std::vector<unsigned int> next(column_start.begin(), column_start.end() - 1);
        for (unsigned int r = 0; r < n_rows; ++r)
          for (int k = row_start[r]; k < row_start[r + 1]; ++k)
            {
              const unsigned int t = next[entry_column[k]]++;
              transposed_row[t]    = r;
              transposed_entry[t]  = k;
            }
      }

      // The sparsity: row i (sorted) of the result has the columns of the rows of A that have
      // column i, kept (sorted, as positions) for the sum below.
      IndexSet relevant(owned);
      relevant.add_indices(global_column.begin(), global_column.end());
      relevant.compress();
      DynamicSparsityPattern               dsp(owned.size(), owned.size(), relevant);
      std::vector<std::size_t>             pattern_start{0};
      std::vector<unsigned int>            pattern;
      std::vector<unsigned char>           is_set(n_columns, 0);
      std::vector<types::global_dof_index> global_columns;
      for (unsigned int i = 0; i < n_columns; ++i)
        {
          const auto row_begin = pattern.size();
          for (unsigned int t = column_start[i]; t < column_start[i + 1]; ++t)
            {
              const unsigned int r = transposed_row[t];
              for (int k = row_start[r]; k < row_start[r + 1]; ++k)
                if (!is_set[entry_column[k]])
                  {
                    is_set[entry_column[k]] = 1;
                    pattern.push_back(entry_column[k]);
                  }
            }
          std::sort(pattern.begin() + row_begin, pattern.end());
          global_columns.clear();
          for (auto c = pattern.begin() + row_begin; c != pattern.end(); ++c)
            {
              global_columns.push_back(global_column[*c]);
              is_set[*c] = 0;
            }
          pattern_start.push_back(pattern.size());
          dsp.add_entries(global_column[i], global_columns.begin(), global_columns.end(), true);
        }
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      result.reinit(owned, owned, dsp, comm);

      // The values: row i is sum_r w_r a_ri a_r, summed in a dense accumulator over the
      // columns and added to Trilinos once.
      std::vector<double> accumulated(n_columns, 0.), row_values;
      for (unsigned int i = 0; i < n_columns; ++i)
        {
          for (unsigned int t = column_start[i]; t < column_start[i + 1]; ++t)
            {
              const unsigned int r = transposed_row[t];
              const double       f = weight[r] * value[transposed_entry[t]];
              for (int k = row_start[r]; k < row_start[r + 1]; ++k)
                accumulated[entry_column[k]] += f * value[k];
            }
          global_columns.clear();
          row_values.clear();
          for (auto c = pattern.begin() + pattern_start[i];
               c != pattern.begin() + pattern_start[i + 1];
               ++c)
            {
              global_columns.push_back(global_column[*c]);
              row_values.push_back(accumulated[*c]);
              accumulated[*c] = 0.;
            }
          result.add(global_column[i],
                     global_columns.size(),
                     global_columns.data(),
                     row_values.data(),
                     false,
                     true);
        }
      result.compress(VectorOperation::add);
    }
  } // namespace

  template <int dim>
  void
  CoupledStaticSolver<dim>::assemble(const MaterialModel<dim> &material,
                                     const std::string        &conditions)
  {
    Assert(fe != nullptr, ExcMessage("Call reinit() first."));
    const std::size_t n_local = prescribed.size();

    // The PD part (G T_f)^T diag(w) (G T_f) of the linearization about the reference state.
    LinearizedModel linearized;
    material.linearize(*particles, linearized);
    StaticSolver<dim>::extension_matrix(*particles, linearized, G, weights, offsets);
    SparseMatrix pd_part, GT;
    G.mmult(GT, T_free);
    weighted_gram(GT, weights, z_owned, comm, pd_part);

    // K = E_f^T K_FE E_f + (G T_f)^T diag(w) (G T_f) + D on the free and s on the prescribed
    // diagonal, summed row by row (both parts have the rows of z).
    std::vector<double> diagonal(n_local, 0.);
    // The factorization and the AMG hierarchy refer to the matrix: drop them before it changes.
    linear_system.clear();
    {
      DynamicSparsityPattern dsp(z_owned.size(), z_owned.size(), z_owned);
      for (const SparseMatrix *part : {&fe_part, &pd_part})
        for_each_local_row(*part, [&](const auto row, const auto &columns, const double *values) {
          dsp.add_entries(row, columns.begin(), columns.end());
          for (std::size_t k = 0; k < columns.size(); ++k)
            if (columns[k] == row)
              diagonal[row - z_first] += values[k];
        });
      for (std::size_t k = 0; k < n_local; ++k)
        dsp.add(z_first + k, z_first + k);
      system_matrix.reinit(z_owned, z_owned, dsp, comm);
    }
    for (const SparseMatrix *part : {&fe_part, &pd_part})
      for_each_local_row(*part, [&](const auto row, const auto &columns, const double *values) {
        system_matrix.add(row, columns.size(), columns.data(), values, false, false);
      });
    // The added diagonal D (set_diagonal()) on the free rows: a capacity holds every mode.
    double diagonal_sum = 0., n_free = 0., n_held = 0.;
    for (std::size_t k = 0; k < added_diagonal.size(); ++k)
      if (!prescribed[k] && added_diagonal[k] > 0.)
        {
          system_matrix.add(z_first + k, z_first + k, added_diagonal[k]);
          diagonal[k] += added_diagonal[k];
          n_held += 1.;
        }
    for (std::size_t k = 0; k < n_local; ++k)
      if (!prescribed[k])
        {
          diagonal_sum += diagonal[k];
          n_free += 1.;
        }
    diagonal_sum     = Utilities::MPI::sum(diagonal_sum, comm);
    n_free           = Utilities::MPI::sum(n_free, comm);
    prescribed_scale = (n_free > 0. && diagonal_sum > 0.) ? diagonal_sum / n_free : 1.;
    for (std::size_t k = 0; k < n_local; ++k)
      if (prescribed[k])
        {
          system_matrix.add(z_first + k, z_first + k, prescribed_scale);
          n_held += 1.;
        }
    system_matrix.compress(VectorOperation::add);
    find_mechanisms(material);
    // A convection condition holds a temperature too (its h int phi_i phi_j is in K_FE).
    for (const auto &c : fe->conditions())
      n_held += c.convection ? 1. : 0.;
    AssertThrow(Utilities::MPI::sum(n_held, comm) > 0.,
                ExcMessage("The coupled static system is singular: no displacement is prescribed "
                           "(boundary conditions: " +
                           (conditions.empty() ? std::string("none") : conditions) +
                           "), so rigid-body motions are free. Add a 'displacement' condition in "
                           "<Finite elements/Boundary conditions> (or on free particles in "
                           "<Boundary conditions>) that holds the rigid-body modes."));
  }

  template <int dim>
  unsigned int
  CoupledStaticSolver<dim>::solve(const MaterialModel<dim> &material,
                                  const FEVector           &f_fe,
                                  const ParticleVector     &f_pd,
                                  FEVector                 &U,
                                  ParticleVector           &u,
                                  const std::string        &conditions)
  {
    assemble(material, conditions);
    return solve_assembled(material, f_fe, f_pd, U, u, conditions);
  }

  template <int dim>
  unsigned int
  CoupledStaticSolver<dim>::solve_assembled(const MaterialModel<dim> &material,
                                            const FEVector           &f_fe,
                                            const ParticleVector     &f_pd,
                                            FEVector                 &U,
                                            ParticleVector           &u,
                                            const std::string        &conditions)
  {
    const std::size_t n_local    = prescribed.size();
    const std::size_t n_fe_owned = fe_owned.n_elements();
    const auto       &volume     = particles->volumes();
    const double      s          = prescribed_scale;

    // Right-hand side: F - K g on free rows, s g on prescribed rows.
    SolverVector g(z_owned, comm), F(z_owned, comm), rhs(z_owned, comm), z(z_owned, comm);
    for (std::size_t k = 0; k < n_fe_owned; ++k)
      if (prescribed[k])
        g.begin()[k] = U.local_element(k);
    for (std::size_t k = 0; k < particle_z.size(); ++k)
      if (particle_z[k] != numbers::invalid_dof_index && prescribed[particle_z[k] - z_first])
        g.begin()[particle_z[k] - z_first] = u.local_element(k);
    {
      // F = E^T f_FE + T^T (V f_PD).
      SolverVector load;
      gather_particles(f_pd, load);
      for (std::size_t k = 0; k < load.locally_owned_size(); ++k)
        load.begin()[k] *= volume[k / n_components];
      T.Tvmult(F, load);
      for (std::size_t k = 0; k < n_fe_owned; ++k)
        F.begin()[k] += f_fe.local_element(k);
      // K g of the unconstrained operator less the load of the offsets:
      // E^T K_FE E g + T^T G^T diag(w) (G T g - o).
      SolverVector g_fe(fe_owned, comm), Kg_fe(fe_owned, comm), Tg(particle_rows, comm),
        Gg(weights), GtGg(particle_rows, comm), Kg(z_owned, comm);
      for (std::size_t k = 0; k < n_fe_owned; ++k)
        g_fe.begin()[k] = g.begin()[k];
      fe->stiffness_matrix().vmult(Kg_fe, g_fe);
      T.vmult(Tg, g);
      G.vmult(Gg, Tg);
      Gg -= offsets;
      Gg.scale(weights);
      G.Tvmult(GtGg, Gg);
      T.Tvmult(Kg, GtGg);
      for (std::size_t k = 0; k < n_fe_owned; ++k)
        Kg.begin()[k] += Kg_fe.begin()[k];
      for (std::size_t k = 0; k < n_local; ++k)
        {
          rhs.begin()[k] = prescribed[k] ? s * g.begin()[k] : F.begin()[k] - Kg.begin()[k];
          z.begin()[k]   = prescribed[k] ? g.begin()[k] : 0.;
        }
    }

    const unsigned int iterations = linear_system.solve(
      system_matrix,
      rhs,
      z,
      settings,
      [&]() {
        // Near-null space: the constant field of each component (of each FE dof and particle
        // unknown; the FE region's component masks follow the same layout).
        const auto                                        fe_modes = fe->component_masks();
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic = true;
        // One mode per FE component and per particle component (particle rotations the FE
        // field lacks have modes of their own). A rank without rows keeps the FE region's
        // (none without owned dofs), as ML expects.
        data.constant_modes.assign(n_local > 0 ?
                                     std::max<std::size_t>(fe_modes.size(), n_components) :
                                     fe_modes.size(),
                                   std::vector<bool>(n_local, false));
        for (unsigned int d = 0; d < fe_modes.size(); ++d)
          for (std::size_t k = 0; k < n_fe_owned; ++k)
            data.constant_modes[d][k] = fe_modes[d][k];
        for (std::size_t k = 0; k < particle_z.size(); ++k)
          if (particle_z[k] != numbers::invalid_dof_index)
            data.constant_modes[k % n_components][particle_z[k] - z_first] = true;
        data.higher_order_elements = fe->get_fe_collection()[0].degree > 1;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        return data;
      },
      "coupled static solve",
      " The boundary conditions (" + conditions + ") may leave " +
        material.field_layout().free_motions() +
        " free (to be held by displacement conditions, 'value' for a scalar field), or broken "
        "bonds may have split off free pieces of the PD region.");

    // Back to the FE dofs and the particles (those slaved to the FE field through P).
    ParticleVector solution;
    reinit_unknowns(solution);
    for (std::size_t k = 0; k < n_local; ++k)
      solution.local_element(k) = z.begin()[k];
    from_unknowns(solution, U, u);
    follow_neighbours_in_mechanisms(u);
    return iterations;
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::find_mechanisms(const MaterialModel<dim> &material)
  {
    mechanisms.clear();
    any_mechanism             = false;
    const FieldLayout &layout = material.field_layout();
    if (n_components != dim || layout.kind(0) != ComponentKind::translation)
      return;
    // The projector onto the null space of each free particle's diagonal block of K, where
    // the block has one (eigenvalues below 1e-10 of its largest: a single bond leaves
    // round-off, two bonds at the lattice's angles leave 1e-2 and more).
    const unsigned int n_owned = particles->n_owned();
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        bool free = true;
        for (unsigned int c = 0; c < dim; ++c)
          free = free && particle_z[i * dim + c] != numbers::invalid_dof_index &&
                 !prescribed[particle_z[i * dim + c] - z_first];
        if (!free)
          continue;
        SymmetricTensor<2, dim> block;
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = c; d < dim; ++d)
            block[c][d] = system_matrix.el(particle_z[i * dim + c], particle_z[i * dim + d]);
        const auto eigen = eigenvectors(block); // descending
        if (!(eigen[0].first > 0.) || eigen[dim - 1].first > 1e-10 * eigen[0].first)
          continue;
        Tensor<2, dim> projector;
        for (unsigned int e = 1; e < dim; ++e)
          if (eigen[e].first <= 1e-10 * eigen[0].first)
            projector += outer_product(eigen[e].second, eigen[e].second);
        mechanisms.emplace_back(i, projector);
      }
    any_mechanism = Utilities::MPI::max(mechanisms.empty() ? 0u : 1u, comm) != 0;
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::follow_neighbours_in_mechanisms(ParticleVector &u) const
  {
    if (!any_mechanism)
      return;
    const unsigned int n_owned = particles->n_owned();

    // The bonded neighbours' mean displacement (a row lists a bond between owned particles
    // once, a bond to a ghost on both ranks: each end's rank sees it).
    std::vector<unsigned int> slot(n_owned, numbers::invalid_unsigned_int);
    for (std::size_t h = 0; h < mechanisms.size(); ++h)
      slot[mechanisms[h].first] = h;
    std::vector<Tensor<1, dim>> sum(mechanisms.size());
    std::vector<unsigned int>   count(mechanisms.size(), 0);
    const BondList             &bonds = particles->bonds();
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        if (bonds.intact[b] != 0)
          {
            const unsigned int j = bonds.neighbor[b];
            for (const auto &[end, other] : {std::pair{i, j}, std::pair{j, i}})
              if (end < n_owned && slot[end] != numbers::invalid_unsigned_int)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    sum[slot[end]][d] += u.local_element(other * dim + d);
                  ++count[slot[end]];
                }
          }
    for (std::size_t h = 0; h < mechanisms.size(); ++h)
      if (count[h] > 0)
        {
          const unsigned int i = mechanisms[h].first;
          Tensor<1, dim>     own;
          for (unsigned int d = 0; d < dim; ++d)
            own[d] = u.local_element(i * dim + d);
          const Tensor<1, dim> moved =
            own + mechanisms[h].second * (sum[h] / static_cast<double>(count[h]) - own);
          for (unsigned int d = 0; d < dim; ++d)
            u.local_element(i * dim + d) = moved[d];
        }
    u.update_ghost_values();
  }

  template <int dim>
  double
  CoupledStaticSolver<dim>::forces(const FEVector       &U,
                                   const ParticleVector &u,
                                   const FEVector       &f_fe,
                                   const ParticleVector &f_pd,
                                   FEVector             &fe_residual,
                                   ParticleVector       &pd_force) const
  {
    const auto &volume = particles->volumes();
    // Particles: e = G u - o, energy 1/2 e^T diag(w) e, force -G^T diag(w) e.
    SolverVector up, extension(weights), stress(weights), force(particle_rows, comm);
    gather_particles(u, up);
    G.vmult(extension, up);
    extension -= offsets;
    stress.scale(extension);
    const double energy = 0.5 * (stress * extension);
    stress              = extension;
    stress.scale(weights);
    G.Tvmult(force, stress);
    ParticleVector nodal_force;
    particles->reinit_vector(nodal_force, n_components);
    for (std::size_t k = 0; k < particle_rows.n_elements(); ++k)
      {
        const double V            = volume[k / n_components];
        pd_force.local_element(k) = -force.begin()[k] / V;
        // The particles' unbalanced force, internal plus applied, for P^T.
        nodal_force.local_element(k) = -force.begin()[k] + f_pd.local_element(k) * V;
      }
    fe_forces(U, f_fe, nodal_force, fe_residual);
    return energy;
  }

  template <int dim>
  std::array<double, 2>
  CoupledStaticSolver<dim>::particle_energies(const MaterialModel<dim> &material,
                                              const ParticleVector     &u_0,
                                              const ParticleVector     &u_1) const
  {
    LinearizedModel linearized;
    material.linearize(*particles, linearized);
    SparseMatrix extension_rows;
    SolverVector row_weights, row_offsets;
    StaticSolver<dim>::extension_matrix(*particles,
                                        linearized,
                                        extension_rows,
                                        row_weights,
                                        row_offsets);
    std::array<double, 2> energies;
    SolverVector          up, extension(row_weights), stress(row_weights);
    for (const unsigned int k : {0u, 1u})
      {
        gather_particles(k == 0 ? u_0 : u_1, up);
        extension_rows.vmult(extension, up);
        extension -= row_offsets;
        stress = extension;
        stress.scale(row_weights);
        energies[k] = 0.5 * (stress * extension);
      }
    return energies;
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::fe_forces(const FEVector       &U,
                                      const FEVector       &f_fe,
                                      const ParticleVector &nodal_force,
                                      FEVector             &fe_residual) const
  {
    // K_FE U - f_FE - P^T (nodal force) of the particles slaved to the FE field:
    // -(f_FE - K_FE U + P^T f).
    fe->stiffness_matrix().vmult(fe_residual, U);
    fe_residual.sadd(-1., 1., f_fe);
    transfer->add_transpose(nodal_force, fe_residual);
    fe_residual *= -1.;
  }

  template <int dim>
  const SparseMatrix &
  CoupledStaticSolver<dim>::matrix() const
  {
    return system_matrix;
  }

  template class CoupledStaticSolver<2>;
  template class CoupledStaticSolver<3>;
} // namespace perideal
