// ---------------------------------------------------------------------
// PeriDeal: the one place that names the linear-algebra types.
// ---------------------------------------------------------------------
#ifndef perideal_base_linear_algebra_h
#define perideal_base_linear_algebra_h

#include <deal.II/base/partitioner.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace perideal
{
  /**
   * A distributed vector of particle data: locally owned entries first, then ghost entries
   * ordered by global index, so that local element i*n_components + c belongs to local
   * particle i. Ghost values are imported with update_ghost_values().
   */
  using ParticleVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /**
   * A distributed vector of FE dofs (owned entries plus ghost entries, the FE region's
   * partitioner): the FE displacement, forces and masses of every coupled problem.
   */
  using FEVector = dealii::LinearAlgebra::distributed::Vector<double>;

  /// The owned and ghost particles (or dofs) of a ParticleVector.
  using Partitioner = dealii::Utilities::MPI::Partitioner;

  /// A distributed sparse matrix (Trilinos Epetra), rows partitioned like the particle dofs.
  using SparseMatrix = dealii::TrilinosWrappers::SparseMatrix;

  /// A distributed vector of the locally owned dofs for the Trilinos solvers (no ghosts).
  using SolverVector = dealii::TrilinosWrappers::MPI::Vector;
} // namespace perideal

#endif
