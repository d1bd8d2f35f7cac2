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
   * components of the particles' FieldLayout, scalar or vector; partitioned like the
   * particles), columns FE dofs (partitioned like the dofs). A particle inside a cell with FE
   * unknowns is *slaved*: its rows hold the shape functions of that cell (each
   * particle is given to exactly one cell, so every slaved row sums to 1 per component). A
   * particle component is slaved to the FE component of the same name; a rotation the FE field
   * lacks (a micropolar model coupled to elasticity) follows half the curl of the FE
   * displacement, theta = 1/2 curl U (2D: theta_z = 1/2 (dU_y/dx - dU_x/dy)), whose rows are
   * the shape gradients of the cell (they sum to 0), so that P^T turns a moment m on a slaved
   * particle into nodal forces 1/2 m x grad N_a: no net force, moment m. A
   * particle inside an FE_Nothing cell is *free*: its row is empty. A particle outside the mesh
   * is an error. Each particle is sent to the ranks whose cells' boxes hold it and tried
   * against every owned cell there, so a particle's rank and its cell's rank may differ; the
   * rank that owns the cell computes the row and Trilinos moves it to the particle's rank.
   *
   * A particle on cells' boundaries (a face, an edge, a vertex, or the two coincident faces of a
   * slit) lies in several cells; it goes to the one it would move into along a fixed direction
   * v with v_x < v_y < v_z all positive, ties (a particle on the mesh's boundary, where v
   * points out) to the least CellId. The rule depends on the mesh and the particle only, so
   * every partition gives every particle the same cell (doc/benchmarks/many_ranks/README.md:
   * on a slit the result differed with the rank count before). deal.II's own search with a
   * unique mapping picks the cell by rank and misses the cells across a slit.
   */
  template <int dim>
  class TransferOperator
  {
  public:
    /**
     * @brief Build P for the current particle positions (reference configuration), with the
     * unknowns @p layout per particle and the FE region's per node. The two must name the same
     * components, except rotations the particles add to FE translations (throws otherwise,
     * naming both). Without FE unknowns P is empty but its rows still have the particles'
     * layout. With @p located (one entry per owned particle), only the particles it marks are
     * located in the mesh; the others are free (empty rows), wherever they lie.
     */
    void
    reinit(const FERegion<dim>       &fe,
           const ParticleSystem<dim> &particles,
           const FieldLayout         &layout,
           const std::vector<bool>   &located = {});

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

    /// The number of unknowns per particle (its rows).
    unsigned int
    n_point_components() const;

  private:
    /// What the rows of a particle are made of.
    struct ComponentRows
    {
      /// Per FE component, the particle component that takes its values.
      std::vector<unsigned int> value;
      /// The particle rotations that follow 1/2 curl of the FE translations.
      std::vector<unsigned int> curl;
      /// A particle component with value rows (its rows sum to 1 where slaved).
      unsigned int first_value_row = 0;
    };

    /// The rows of @p particle_layout from @p fe_layout; if @p check, throw on a mismatch.
    static ComponentRows
    component_rows(const FieldLayout &fe_layout,
                   const FieldLayout &particle_layout,
                   const bool         check);

    SparseMatrix                    P;
    std::vector<bool>               slaved;
    dealii::types::global_dof_index n_slaved = 0;
    /// Components per particle (the particles' layout).
    unsigned int           n_components = dim;
    mutable ParticleVector particle_buffer;
    mutable FEVector       fe_buffer;
  };
} // namespace perideal

#endif
