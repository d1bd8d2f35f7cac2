// ---------------------------------------------------------------------
// PeriDeal: the transfer operator from FE displacements to particle displacements.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_transfer_operator_h
#define perideal_coupling_transfer_operator_h

#include <perideal/base/linear_algebra.h>
#include <perideal/fem/fe_region.h>
#include <perideal/pd/particle_system.h>

#include <vector>

namespace perideal
{
  /**
   * @brief P, the FE shape functions evaluated at the particle positions, as a distributed
   * sparse matrix: u_particles = P U, forces back with P^T. A coupling method that slaves
   * particles to the FE field builds one (BlendedCoupling does).
   *
   * Rows are particle components (global index * n_components + component, with the
   * components of the FE region's FieldLayout, scalar or vector; partitioned like the
   * particles), columns FE dofs (partitioned like the dofs). A particle inside a cell with FE
   * unknowns is *slaved*: its rows hold the shape functions of that cell (each
   * particle is given to exactly one cell, so every slaved row sums to 1 per component). A
   * particle inside an FE_Nothing cell is *free*: its row is empty. A particle outside the mesh
   * is an error. The cells are located with deal.II's distributed point search, so a particle's
   * rank and its cell's rank may differ; the rank that owns the cell computes the row and
   * Trilinos moves it to the particle's rank.
   */
  template <int dim>
  class TransferOperator
  {
  public:
    using FEVector = dealii::LinearAlgebra::distributed::Vector<double>;

    /**
     * @brief Build P for the current particle positions (reference configuration), with the
     * unknowns @p layout per point (the problem's: both regions share it; without FE unknowns
     * P is empty but its rows still have the particles' layout).
     */
    void
    reinit(const FERegion<dim>       &fe,
           const ParticleSystem<dim> &particles,
           const FieldLayout         &layout);

    /**
     * @brief Overwrite the slaved particles' entries of @p u_particles (owned; call
     * update_ghost_values() afterwards) with P U; free particles keep theirs.
     */
    void
    interpolate(const FEVector &U, ParticleVector &u_particles) const;

    /**
     * @brief F += P^T f: the slaved particles' forces as FE nodal forces (the free particles'
     * rows are empty and contribute nothing).
     */
    void
    add_transpose(const ParticleVector &f, FEVector &F) const;

    /**
     * @brief Whether the owned particle @p i is slaved to the FE field.
     */
    bool
    is_slaved(const unsigned int i) const;

    /// Per owned particle, whether it is slaved to the FE field.
    const std::vector<bool> &
    slaved_particles() const;

    /// Number of slaved particles (all ranks).
    dealii::types::global_dof_index
    n_global_slaved() const;

    /// The matrix itself.
    const SparseMatrix &
    matrix() const;

    /// The number of unknowns per point (the rows of a particle, the columns of an FE node).
    unsigned int
    n_point_components() const;

  private:
    SparseMatrix                    P;
    std::vector<bool>               slaved;
    dealii::types::global_dof_index n_slaved = 0;
    /// Components per point (the FE region's layout, the particles' too).
    unsigned int           n_components = dim;
    mutable ParticleVector particle_buffer;
    mutable FEVector       fe_buffer;
  };
} // namespace perideal

#endif
