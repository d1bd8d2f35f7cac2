// ---------------------------------------------------------------------
// PeriDeal: static linear solve of the blended FE-PD coupling.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <perideal/coupling/coupled_static_solver.h>

#include <algorithm>
#include <cmath>


namespace perideal
{
  using namespace dealii;

  namespace
  {
    /// Visit the locally owned rows of @p matrix: f(row, n, global columns, values).
    template <typename Function>
    void
    for_each_local_row(const SparseMatrix &matrix, const Function &f)
    {
      const auto                          &A = matrix.trilinos_matrix();
      std::vector<types::global_dof_index> columns;
      for (int row = 0; row < A.NumMyRows(); ++row)
        {
          int     n_entries = 0;
          double *values    = nullptr;
          int    *local     = nullptr;
          A.ExtractMyRowView(row, n_entries, values, local);
          columns.resize(n_entries);
          for (int k = 0; k < n_entries; ++k)
            columns[k] = TrilinosWrappers::global_column_index(A, local[k]);
          f(static_cast<types::global_dof_index>(TrilinosWrappers::global_row_index(A, row)),
            columns,
            values);
        }
    }

    /// @p result = @p A^T diag(@p w) @p A, with rows and columns partitioned as @p owned (A's
    /// columns): every local row r of A adds w_r a_r a_r^T, rows of other ranks sent by
    /// compress(). Trilinos' transposed products (EpetraExt's Multiply with A transposed, with or
    /// without an explicit transpose) corrupt the heap on two ranks for some partitions (the
    /// coupled torsion of tests/coupling/torsion_edge_crack_02, the PD part of overlapping
    /// Schwarz), so the product is summed here.
    void
    weighted_gram(const SparseMatrix &A,
                  const SolverVector &w,
                  const IndexSet     &owned,
                  const MPI_Comm      comm,
                  SparseMatrix       &result)
    {
      std::vector<types::global_dof_index> touched;
      for_each_local_row(A, [&](const auto, const auto &columns, const double *) {
        touched.insert(touched.end(), columns.begin(), columns.end());
      });
      std::sort(touched.begin(), touched.end());
      touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
      IndexSet relevant(owned);
      relevant.add_indices(touched.begin(), touched.end());
      relevant.compress();

      DynamicSparsityPattern dsp(owned.size(), owned.size(), relevant);
      for_each_local_row(A, [&](const auto, const auto &columns, const double *) {
        for (const auto column : columns)
          dsp.add_entries(column, columns.begin(), columns.end());
      });
      SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      result.reinit(owned, owned, dsp, comm);

      std::vector<double> row_values;
      for_each_local_row(A, [&](const auto row, const auto &columns, const double *values) {
        const double weight = w[row];
        row_values.resize(columns.size());
        for (std::size_t k = 0; k < columns.size(); ++k)
          {
            for (std::size_t l = 0; l < columns.size(); ++l)
              row_values[l] = weight * values[k] * values[l];
            result.add(columns[k], columns.size(), columns.data(), row_values.data(), false);
          }
      });
      result.compress(VectorOperation::add);
    }
  } // namespace

  template <int dim>
  CoupledStaticSolver<dim>::CoupledStaticSolver(const Settings &settings)
    : settings(settings)
  {}

  template <int dim>
  types::global_dof_index
  CoupledStaticSolver<dim>::fe_to_z(const types::global_dof_index dof) const
  {
    // The last rank whose first dof is <= dof and that owns dofs.
    for (unsigned int r = rank_fe_first.size(); r-- > 0;)
      if (rank_fe_count[r] > 0 && rank_fe_first[r] <= dof)
        {
          Assert(dof < rank_fe_first[r] + rank_fe_count[r], ExcInternalError());
          return rank_z_first[r] + (dof - rank_fe_first[r]);
        }
    Assert(false, ExcInternalError());
    return numbers::invalid_dof_index;
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::reinit(const FERegion<dim>         &fe_region,
                                   const ParticleSystem<dim>   &particle_system,
                                   const TransferOperator<dim> &transfer_operator,
                                   const ParticleVector        &particle_prescribed)
  {
    fe        = &fe_region;
    particles = &particle_system;
    transfer  = &transfer_operator;
    comm      = particle_system.get_communicator();

    // T = [P; I] acts on the raw FE dofs: hanging-node constraints would have to enter it.
    AssertThrow(!fe_region.has_hanging_nodes(),
                ExcMessage("The FE mesh of <Finite elements> has hanging nodes, which the "
                           "static coupled solve (<Solver/Type> = static) does not support; "
                           "use a conforming mesh (global refinement only)."));
    fe_owned = fe_region.get_dof_handler().locally_owned_dofs();
    AssertThrow(fe_owned.is_contiguous(),
                ExcInternalError("The owned FE dofs are not contiguous."));
    // The particles' unknowns (the FE region's, or those and rotations; CoupledProblem checks).
    n_components               = transfer_operator.n_point_components();
    const unsigned int nc      = n_components;
    particle_rows              = particle_system.partitioner(nc)->locally_owned_range();
    const unsigned int n_owned = particle_system.n_owned();

    // z: the owned FE dofs, then the owned free particles' components.
    const types::global_dof_index n_fe_owned = fe_owned.n_elements();
    types::global_dof_index       n_free     = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      n_free += transfer_operator.is_slaved(i) ? 0 : nc;
    const types::global_dof_index n_local = n_fe_owned + n_free;
    unsigned long long            local = n_local, first = 0;
    MPI_Exscan(&local, &first, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      first = 0;
    const types::global_dof_index n_total = Utilities::MPI::sum(n_local, comm);
    z_first                               = first;
    z_owned                               = IndexSet(n_total);
    z_owned.add_range(z_first, z_first + n_local);
    z_owned.compress();
    rank_fe_first =
      Utilities::MPI::all_gather(comm, n_fe_owned > 0 ? fe_owned.nth_index_in_set(0) : 0);
    rank_fe_count = Utilities::MPI::all_gather(comm, n_fe_owned);
    rank_z_first  = Utilities::MPI::all_gather(comm, z_first);

    particle_z.assign(std::size_t(n_owned) * nc, numbers::invalid_dof_index);
    prescribed.assign(n_local, false);
    const auto &fe_mask = fe_region.prescribed_mask();
    for (types::global_dof_index k = 0; k < n_fe_owned; ++k)
      prescribed[k] = fe_mask[k];
    types::global_dof_index next = n_fe_owned;
    for (unsigned int i = 0; i < n_owned; ++i)
      if (!transfer_operator.is_slaved(i))
        for (unsigned int c = 0; c < nc; ++c, ++next)
          {
            particle_z[i * nc + c] = z_first + next;
            prescribed[next]       = particle_prescribed.local_element(i * nc + c) != 0.;
          }

    // T: rows of P for slaved particles, the identity for free ones.
    {
      DynamicSparsityPattern dsp(particle_rows.size(), n_total, particle_rows);
      for_each_local_row(transfer_operator.matrix(),
                         [&](const auto row, const auto &columns, const double *) {
                           for (const auto column : columns)
                             dsp.add(row, fe_to_z(column));
                         });
      for (std::size_t k = 0; k < particle_z.size(); ++k)
        if (particle_z[k] != numbers::invalid_dof_index)
          dsp.add(particle_rows.nth_index_in_set(k), particle_z[k]);
      T.reinit(particle_rows, z_owned, dsp, comm);
      for_each_local_row(transfer_operator.matrix(),
                         [&](const auto row, const auto &columns, const double *values) {
                           for (std::size_t k = 0; k < columns.size(); ++k)
                             T.set(row, fe_to_z(columns[k]), values[k]);
                         });
      for (std::size_t k = 0; k < particle_z.size(); ++k)
        if (particle_z[k] != numbers::invalid_dof_index)
          T.set(particle_rows.nth_index_in_set(k), particle_z[k], 1.);
      T.compress(VectorOperation::insert);
    }

    // T with the prescribed columns dropped: T D with D the 0/1 mask of the free unknowns.
    {
      SparseMatrix           D;
      DynamicSparsityPattern dsp(n_total, n_total, z_owned);
      for (types::global_dof_index k = 0; k < n_local; ++k)
        if (!prescribed[k])
          dsp.add(z_first + k, z_first + k);
      D.reinit(z_owned, z_owned, dsp, comm);
      for (types::global_dof_index k = 0; k < n_local; ++k)
        if (!prescribed[k])
          D.set(z_first + k, z_first + k, 1.);
      D.compress(VectorOperation::insert);
      T.mmult(T_free, D);
    }
    // E_f^T K_FE E_f with E_f the 0/1 map of the free unknowns to the FE dofs. Without FE
    // unknowns (the FE region is empty) the FE part is empty: Trilinos' products of matrices
    // without rows corrupt the heap on more than one rank.
    if (fe_owned.size() > 0)
      {
        SparseMatrix           E_free, K_E;
        DynamicSparsityPattern dsp(fe_owned.size(), n_total, fe_owned);
        for (types::global_dof_index k = 0; k < n_fe_owned; ++k)
          if (!prescribed[k])
            dsp.add(fe_owned.nth_index_in_set(k), z_first + k);
        E_free.reinit(fe_owned, z_owned, dsp, comm);
        for (types::global_dof_index k = 0; k < n_fe_owned; ++k)
          if (!prescribed[k])
            E_free.set(fe_owned.nth_index_in_set(k), z_first + k, 1.);
        E_free.compress(VectorOperation::insert);
        fe_region.stiffness_matrix().mmult(K_E, E_free);
        E_free.Tmmult(fe_part, K_E);
      }
    else
      {
        DynamicSparsityPattern dsp(n_total, n_total, z_owned);
        fe_part.reinit(z_owned, z_owned, dsp, comm);
      }
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::gather_particles(const ParticleVector &u, SolverVector &result) const
  {
    result.reinit(particle_rows, comm);
    auto *values = result.begin();
    for (std::size_t k = 0; k < particle_rows.n_elements(); ++k)
      values[k] = u.local_element(k);
  }

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
    StaticSolver<dim>::extension_matrix(*particles, linearized, G, weights);
    SparseMatrix pd_part, GT;
    G.mmult(GT, T_free);
    weighted_gram(GT, weights, z_owned, comm, pd_part);

    // K = E_f^T K_FE E_f + (G T_f)^T diag(w) (G T_f) + s on the prescribed diagonal, summed
    // row by row (both parts have the rows of z).
    std::vector<double> diagonal(n_local, 0.);
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
    double diagonal_sum = 0., n_free = 0.;
    for (std::size_t k = 0; k < n_local; ++k)
      if (!prescribed[k])
        {
          diagonal_sum += diagonal[k];
          n_free += 1.;
        }
    diagonal_sum     = Utilities::MPI::sum(diagonal_sum, comm);
    n_free           = Utilities::MPI::sum(n_free, comm);
    prescribed_scale = (n_free > 0. && diagonal_sum > 0.) ? diagonal_sum / n_free : 1.;
    double n_p       = 0.;
    for (std::size_t k = 0; k < n_local; ++k)
      if (prescribed[k])
        {
          system_matrix.add(z_first + k, z_first + k, prescribed_scale);
          n_p += 1.;
        }
    system_matrix.compress(VectorOperation::add);
    linear_system.clear();
    AssertThrow(Utilities::MPI::sum(n_p, comm) > 0.,
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
      // K g of the unconstrained operator: E^T K_FE E g + T^T G^T diag(w) G T g.
      SolverVector g_fe(fe_owned, comm), Kg_fe(fe_owned, comm), Tg(particle_rows, comm),
        Gg(weights), GtGg(particle_rows, comm), Kg(z_owned, comm);
      for (std::size_t k = 0; k < n_fe_owned; ++k)
        g_fe.begin()[k] = g.begin()[k];
      fe->stiffness_matrix().vmult(Kg_fe, g_fe);
      T.vmult(Tg, g);
      G.vmult(Gg, Tg);
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

    // Back to the FE dofs and the particles (slaved ones through P).
    ParticleVector solution;
    reinit_unknowns(solution);
    for (std::size_t k = 0; k < n_local; ++k)
      solution.local_element(k) = z.begin()[k];
    from_unknowns(solution, U, u);
    return iterations;
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
    // Particles: e = G u, energy 1/2 e^T diag(w) e, force -G^T diag(w) e.
    SolverVector up, extension(weights), stress(weights), force(particle_rows, comm);
    gather_particles(u, up);
    G.vmult(extension, up);
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
  void
  CoupledStaticSolver<dim>::fe_forces(const FEVector       &U,
                                      const FEVector       &f_fe,
                                      const ParticleVector &nodal_force,
                                      FEVector             &fe_residual) const
  {
    // K_FE U - f_FE - P^T (nodal force) of the slaved particles: -(f_FE - K_FE U + P^T f).
    fe->stiffness_matrix().vmult(fe_residual, U);
    fe_residual.sadd(-1., 1., f_fe);
    transfer->add_transpose(nodal_force, fe_residual);
    fe_residual *= -1.;
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::reinit_unknowns(ParticleVector &z) const
  {
    z.reinit(z_owned, comm);
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::to_unknowns(const FEVector       &U,
                                        const ParticleVector &u,
                                        ParticleVector       &z) const
  {
    for (std::size_t k = 0; k < fe_owned.n_elements(); ++k)
      z.local_element(k) = U.local_element(k);
    for (std::size_t k = 0; k < particle_z.size(); ++k)
      if (particle_z[k] != numbers::invalid_dof_index)
        z.local_element(particle_z[k] - z_first) = u.local_element(k);
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::from_unknowns(const ParticleVector &z,
                                          FEVector             &U,
                                          ParticleVector       &u) const
  {
    for (std::size_t k = 0; k < fe_owned.n_elements(); ++k)
      U.local_element(k) = z.local_element(k);
    U.update_ghost_values();
    for (std::size_t k = 0; k < particle_z.size(); ++k)
      if (particle_z[k] != numbers::invalid_dof_index)
        u.local_element(k) = z.local_element(particle_z[k] - z_first);
    transfer->interpolate(U, u);
    u.update_ghost_values();
  }

  template <int dim>
  bool
  CoupledStaticSolver<dim>::is_prescribed(const std::size_t k) const
  {
    return prescribed[k];
  }

  template <int dim>
  void
  CoupledStaticSolver<dim>::clear_prescribed(ParticleVector &v) const
  {
    for (std::size_t k = 0; k < prescribed.size(); ++k)
      if (prescribed[k])
        v.local_element(k) = 0.;
  }

  template <int dim>
  std::unique_ptr<AdaptiveDynamicRelaxation>
  CoupledStaticSolver<dim>::relaxation(
    const std::function<void(ParticleVector &, ParticleVector &)> &residual,
    const ParticleVector                                          &prescribed_values,
    const AdaptiveDynamicRelaxation::Settings                     &settings,
    const double                                                   safety) const
  {
    AdaptiveDynamicRelaxation::Operations operations;
    operations.clear_prescribed       = [this](ParticleVector &v) { clear_prescribed(v); };
    operations.prescribe_displacement = [this, &prescribed_values](ParticleVector &z) {
      for (std::size_t k = 0; k < prescribed.size(); ++k)
        if (prescribed[k])
          z.local_element(k) = prescribed_values.local_element(k);
    };
    operations.residual = [this, residual](ParticleVector &z, ParticleVector &force) {
      residual(z, force);
      clear_prescribed(force);
    };
    std::vector<double> bound(prescribed.size(), 0.);
    for_each_local_row(system_matrix,
                       [&](const auto row, const auto &columns, const double *values) {
                         for (std::size_t k = 0; k < columns.size(); ++k)
                           bound[row - z_first] += std::abs(values[k]);
                       });
    ParticleVector density;
    reinit_unknowns(density);
    AdaptiveDynamicRelaxation::fictitious_density(bound, safety, density);
    return std::make_unique<AdaptiveDynamicRelaxation>(operations, density, settings, comm);
  }

  template <int dim>
  types::global_dof_index
  CoupledStaticSolver<dim>::n_unknowns() const
  {
    return z_owned.size();
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
