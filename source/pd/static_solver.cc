// ---------------------------------------------------------------------
// PeriDeal: static linear solve of the linearized peridynamic equations.
// ---------------------------------------------------------------------
#include <deal.II/base/index_set.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <perideal/pd/static_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /// The rectangular matrix G (rows: the model's strain rows, then the constraint rows), its
    /// row weights and, if @p offsets is given, its row offsets (0 for the constraint rows); the
    /// columns of a prescribed component are left out if @p eliminate.
    template <int dim>
    void
    build_extension_matrix(const ParticleSystem<dim> &particles,
                           const LinearizedModel     &linearized,
                           const ParticleVector      &prescribed,
                           const std::vector<double> &constraint_scale,
                           const bool                 eliminate,
                           SparseMatrix              &G,
                           SolverVector              &weights,
                           SolverVector              *offsets = nullptr)
    {
      const MPI_Comm     comm    = particles.get_communicator();
      const unsigned int n_owned = particles.n_owned();
      const unsigned int nc      = linearized.n_components();
      const IndexSet    &dofs    = particles.partitioner(nc)->locally_owned_range();

      struct Row
      {
        std::map<types::global_dof_index, double> entries;
        double                                    weight = 0.;
        double                                    offset = 0.;
      };
      std::vector<Row> rows(linearized.n_rows());
      for (std::size_t r = 0; r < rows.size(); ++r)
        {
          rows[r].weight = linearized.weight(r);
          rows[r].offset = linearized.offset(r);
          for (const auto *e = linearized.row_begin(r); e != linearized.row_end(r); ++e)
            if (!eliminate || prescribed.local_element(e->particle * nc + e->component) == 0.)
              rows[r].entries[particles.global_index(e->particle) * nc + e->component] +=
                e->coefficient;
        }
      // Constraint rows: s_c u_c.
      if (eliminate)
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int c = 0; c < nc; ++c)
            if (prescribed.local_element(i * nc + c) != 0.)
              {
                Row row;
                row.weight                                      = constraint_scale[i];
                row.entries[particles.global_index(i) * nc + c] = 1.;
                rows.push_back(std::move(row));
              }

      // Rows without entries (every column eliminated) carry nothing.
      rows.erase(std::remove_if(rows.begin(),
                                rows.end(),
                                [](const Row &row) { return row.entries.empty(); }),
                 rows.end());

      // Contiguous row ranges per rank.
      const unsigned long long n_local_rows = rows.size();
      unsigned long long       first_row = 0, n_rows = 0;
      MPI_Exscan(&n_local_rows, &first_row, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        first_row = 0;
      MPI_Allreduce(&n_local_rows, &n_rows, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
      AssertThrow(n_rows < std::numeric_limits<types::global_dof_index>::max(),
                  ExcMessage("The static system has more rows than deal.II's index type "
                             "holds; configure deal.II with 64-bit indices."));
      const types::global_dof_index first = first_row;
      IndexSet                      row_set(n_rows);
      row_set.add_range(first, first + n_local_rows);
      row_set.compress();

      DynamicSparsityPattern               dsp(n_rows, dofs.size(), row_set);
      std::vector<types::global_dof_index> columns;
      for (std::size_t r = 0; r < rows.size(); ++r)
        {
          columns.clear();
          for (const auto &entry : rows[r].entries)
            columns.push_back(entry.first);
          dsp.add_entries(first + r, columns.begin(), columns.end(), true);
        }
      G.reinit(row_set, dofs, dsp, comm);
      std::vector<double> values;
      for (std::size_t r = 0; r < rows.size(); ++r)
        {
          columns.clear();
          values.clear();
          for (const auto &entry : rows[r].entries)
            {
              columns.push_back(entry.first);
              values.push_back(entry.second);
            }
          if (!columns.empty())
            G.set(first + r, columns.size(), columns.data(), values.data());
        }
      G.compress(VectorOperation::insert);

      weights.reinit(row_set, comm);
      for (std::size_t r = 0; r < rows.size(); ++r)
        weights[first + r] = rows[r].weight;
      weights.compress(VectorOperation::insert);
      if (offsets != nullptr)
        {
          offsets->reinit(row_set, comm);
          for (std::size_t r = 0; r < rows.size(); ++r)
            (*offsets)[first + r] = rows[r].offset;
          offsets->compress(VectorOperation::insert);
        }
    }
  } // namespace

  template <int dim>
  StaticSolver<dim>::StaticSolver(const Settings &settings)
    : settings(settings)
  {}

  template <int dim>
  unsigned int
  StaticSolver<dim>::solve(const ParticleSystem<dim> &particles,
                           const MaterialModel<dim>  &material,
                           const ParticleVector      &prescribed_owned,
                           const ParticleVector      &external_force,
                           ParticleVector            &u,
                           const std::string         &conditions)
  {
    const MPI_Comm     comm    = particles.get_communicator();
    const unsigned int n_owned = particles.n_owned();
    const unsigned int nc      = material.field_layout().n_components();
    const IndexSet    &dofs    = particles.partitioner(nc)->locally_owned_range();
    const auto        &volume  = particles.volumes();

    ParticleVector prescribed;
    particles.reinit_vector(prescribed, nc);
    double n_prescribed = 0.;
    for (std::size_t k = 0; k < std::size_t(n_owned) * nc; ++k)
      {
        prescribed.local_element(k) = prescribed_owned.local_element(k) != 0. ? 1. : 0.;
        n_prescribed += prescribed.local_element(k);
      }
    prescribed.update_ghost_values();
    n_prescribed = Utilities::MPI::sum(n_prescribed, comm);
    AssertThrow(n_prescribed > 0.,
                ExcMessage("The static system is singular: no displacement component is "
                           "prescribed (boundary conditions: " +
                           (conditions.empty() ? std::string("none") : conditions) + "), so " +
                           material.field_layout().free_motions() +
                           " cost no energy. Add a displacement ('value' for a scalar field) "
                           "boundary condition that holds them."));

    LinearizedModel linearized;
    material.linearize(particles, linearized);
    AssertDimension(linearized.n_components(), nc);
    // Stiffness scale of each owned particle for its constraint rows.
    std::vector<double> scale = linearized.stiffness_scale();
    for (double &s : scale)
      if (s <= 0.)
        s = 1.;

    // Right-hand side F_f - K_fc g + (G^T diag(w) o)_f with K g = G^T diag(w) G g of the
    // unconstrained G and o its row offsets (the load of a thermal strain).
    SolverVector g(dofs, comm), rhs(dofs, comm), solution(dofs, comm);
    for (std::size_t k = 0; k < std::size_t(n_owned) * nc; ++k)
      if (prescribed.local_element(k) != 0.)
        g[dofs.nth_index_in_set(k)] = u.local_element(k);
    g.compress(VectorOperation::insert);
    {
      SparseMatrix G;
      SolverVector weights, offsets;
      build_extension_matrix<dim>(particles,
                                  linearized,
                                  prescribed,
                                  scale,
                                  false,
                                  G,
                                  weights,
                                  &offsets);
      SolverVector extension(weights);
      G.vmult(extension, g);
      extension -= offsets;
      extension.scale(weights);
      G.Tvmult(rhs, extension);
      rhs *= -1.;
    }
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int c = 0; c < nc; ++c)
        {
          const std::size_t k     = std::size_t(i) * nc + c;
          const auto        index = dofs.nth_index_in_set(k);
          if (prescribed.local_element(k) != 0.)
            {
              rhs[index]      = scale[i] * u.local_element(k);
              solution[index] = u.local_element(k);
            }
          else
            // Read, then set: mixing add and insert before compress() would trigger collective
            // assembly on some ranks only.
            rhs[index] =
              static_cast<double>(rhs[index]) + external_force.local_element(k) * volume[i];
        }
    rhs.compress(VectorOperation::insert);
    solution.compress(VectorOperation::insert);

    {
      SparseMatrix G;
      SolverVector weights;
      build_extension_matrix<dim>(particles, linearized, prescribed, scale, true, G, weights);
      G.Tmmult(system_matrix, G, weights);
    }

    LinearSystem       linear_system;
    const unsigned int iterations = linear_system.solve(
      system_matrix,
      rhs,
      solution,
      settings,
      [&]() {
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic = true;
        data.constant_modes.assign(nc, std::vector<bool>(dofs.n_elements(), false));
        for (std::size_t k = 0; k < dofs.n_elements(); ++k)
          data.constant_modes[k % nc][k] = true;
        return data;
      },
      "static solve",
      " The boundary conditions (" + conditions + ") may leave " +
        material.field_layout().free_motions() +
        " free (to be held by displacement conditions, 'value' for a scalar field), or broken "
        "bonds may have split the body into free pieces.");

    for (std::size_t k = 0; k < std::size_t(n_owned) * nc; ++k)
      u.local_element(k) = solution[dofs.nth_index_in_set(k)];
    u.update_ghost_values();
    return iterations;
  }

  template <int dim>
  void
  StaticSolver<dim>::LinearSystem::clear()
  {
    direct.reset();
    amg.reset();
  }

  template <int dim>
  unsigned int
  StaticSolver<dim>::LinearSystem::solve(
    const SparseMatrix                                                       &K,
    const SolverVector                                                       &b,
    SolverVector                                                             &x,
    const Settings                                                           &settings,
    const std::function<TrilinosWrappers::PreconditionAMG::AdditionalData()> &amg_data,
    const std::string                                                        &what,
    const std::string                                                        &advice)
  {
    const double rhs_norm = b.l2_norm();
    if (rhs_norm == 0.)
      return 0;
    unsigned int  iterations = 0;
    SolverControl control(settings.max_iterations, settings.tolerance * rhs_norm);
    try
      {
        if (settings.linear_solver == LinearSolverType::direct)
          {
            if (!direct)
              {
                direct = std::make_unique<TrilinosWrappers::SolverDirect>(direct_control);
                direct->initialize(K);
              }
            direct->solve(x, b);
          }
        else
          {
            if (!amg)
              {
                amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
                amg->initialize(K, amg_data());
              }
            SolverCG<SolverVector> cg(control);
            cg.solve(K, x, b, *amg);
            iterations = control.last_step();
          }
      }
    catch (const SolverControl::NoConvergence &e)
      {
        AssertThrow(false,
                    ExcNotConverged(
                      "The " + what + " did not converge: residual " +
                      std::to_string(e.last_residual / rhs_norm) + " after " +
                      std::to_string(e.last_step) +
                      " CG iterations (<Solver/Tolerance> = " + std::to_string(settings.tolerance) +
                      ", <Solver/Maximum iterations> = " + std::to_string(settings.max_iterations) +
                      ")." + advice));
      }
    catch (const std::exception &e)
      {
        AssertThrow(false,
                    ExcNotConverged("The " + what + " failed (the stiffness matrix is singular?)." +
                                    advice + " Solver message: " + e.what()));
      }
    // A singular system can yield a solution that is not finite.
    AssertThrow(std::isfinite(x.l2_norm()),
                ExcNotConverged("The " + what +
                                " produced a non-finite displacement: the stiffness matrix is "
                                "singular." +
                                advice));
    // Check the residual independently of the solver's own test.
    SolverVector residual(b);
    K.vmult(residual, x);
    residual -= b;
    AssertThrow(residual.l2_norm() <= std::max(1e3 * settings.tolerance, 1e-8) * rhs_norm,
                ExcNotConverged("The " + what + " left the residual " +
                                std::to_string(residual.l2_norm() / rhs_norm) +
                                " (relative): the stiffness matrix is singular or nearly so." +
                                advice));
    return iterations;
  }

  template <int dim>
  void
  StaticSolver<dim>::extension_matrix(const ParticleSystem<dim> &particles,
                                      const LinearizedModel     &linearized,
                                      SparseMatrix              &G,
                                      SolverVector              &weights,
                                      SolverVector              &offsets)
  {
    // Nothing is eliminated: the prescribed flags and constraint scales are not read.
    ParticleVector none;
    particles.reinit_vector(none, linearized.n_components());
    build_extension_matrix<dim>(particles, linearized, none, {}, false, G, weights, &offsets);
  }

  template <int dim>
  const SparseMatrix &
  StaticSolver<dim>::matrix() const
  {
    return system_matrix;
  }

  template class StaticSolver<2>;
  template class StaticSolver<3>;
} // namespace perideal
