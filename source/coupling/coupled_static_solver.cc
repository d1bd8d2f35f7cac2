// ---------------------------------------------------------------------
// PeriDeal: the static linear solve of an FE-PD coupling: the numbering of the unknowns and the
// masks of the prescribed ones (assembly and solve in coupled_static_solver_assembly.cc, the
// relaxation in coupled_static_solver_relaxation.cc).
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <perideal/coupling/coupled_static_solver.h>
#include <perideal/coupling/matrix_rows.h>


namespace perideal
{
  using namespace dealii;

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
  CoupledStaticSolver<dim>::check_mesh(const FERegion<dim> &fe_region)
  {
    // T = [P; I] acts on the raw FE dofs: hanging-node constraints would have to enter it.
    AssertThrow(!fe_region.has_hanging_nodes(),
                ExcMessage("The FE mesh of <Finite elements> has hanging nodes, which the "
                           "quasi-static solve (<Solver/Type> = static or adaptive dynamic "
                           "relaxation) does not support; "
                           "use a conforming mesh (global refinement only)."));
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

    check_mesh(fe_region);
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
    added_diagonal.clear();
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

    // T: rows of P for particles slaved to the FE field, the identity for free ones.
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
  CoupledStaticSolver<dim>::set_diagonal(const FEVector       &fe_diagonal,
                                         const ParticleVector &particle_diagonal)
  {
    ParticleVector z;
    reinit_unknowns(z);
    to_unknowns(fe_diagonal, particle_diagonal, z);
    added_diagonal.assign(z.begin(), z.end());
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
  types::global_dof_index
  CoupledStaticSolver<dim>::n_unknowns() const
  {
    return z_owned.size();
  }

  template class CoupledStaticSolver<2>;
  template class CoupledStaticSolver<3>;
} // namespace perideal
