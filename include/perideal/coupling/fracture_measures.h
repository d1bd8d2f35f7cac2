// ---------------------------------------------------------------------
// PeriDeal: load, load-point displacement and crack length of a fracture run.
// ---------------------------------------------------------------------
#ifndef perideal_coupling_fracture_measures_h
#define perideal_coupling_fracture_measures_h

#include <perideal/coupling/coupled_state.h>
#include <perideal/coupling/solvers/quasi_static_control.h>

#include <cstdint>

namespace perideal
{
  /**
   * @brief What a fracture run reports per load step or event: the load (the reaction of the
   * displacement condition <Solver/Control/Load point> in <Load component>), the load-point
   * displacement (the mean of that component over the condition's particles, volume-weighted,
   * or over its FE dofs), the number of broken bonds and a crack-length measure.
   *
   * The crack length is the number of broken bonds (pre-cracks included) divided by the number
   * of bonds of the lattice family that cross a unit length (2D) or unit area (3D) of a plane
   * crack, averaged over the crack's directions: sum_xi (xi . n)^+ / dx^dim averaged over the
   * unit normals n is sum_xi |xi| / (pi dx^2) in 2D and sum_xi |xi| / (4 dx^3) in 3D, sums over
   * the family of an interior particle (ParticleSystem::lattice_family()). For a crack along a
   * lattice axis the lattice count differs from the average by a few per cent (doc/theory/
   * fracture_control.md); the measure is meant for the growth of one crack, not for its exact
   * length.
   */
  template <int dim>
  class FractureMeasures
  {
  public:
    /// The measures of one state.
    struct Values
    {
      /// The reaction of the load point [N].
      double load = 0.;
      /// Its mean displacement [m].
      double displacement = 0.;
      /// Broken bonds (each bond once over the ranks).
      std::uint64_t broken_bonds = 0;
      /// Crack length [m] (2D) or area [m^2] (3D).
      double crack_length = 0.;
    };

    /**
     * @brief Find @p control's load point among the particle and FE conditions of @p state and
     * its component in the layout; stop with a message naming <Solver/Control/Load point> or
     * <Load component> if it names no displacement condition, a component the condition does not
     * prescribe, or a condition that holds no particle and no FE dof. Nothing to do without a
     * load point. Collective.
     */
    void
    initialize(const CoupledState<dim> &state, const QuasiStaticControl &control);

    /// Whether a load point is set.
    bool
    has_load_point() const;

    /**
     * @brief The measures of @p state after CouplingMethod::equilibrium_forces() (internal
     * forces of the particles, CoupledState::fe_support). Collective.
     */
    Values
    measure(const CoupledState<dim> &state) const;

  private:
    bool         active       = false;
    bool         fe_condition = false;
    unsigned int condition = 0, component = 0, reaction_index = 0;
    /// The volume (particles) or number of dofs (FE) of the load point.
    double size = 0.;
    /// Bonds crossing a unit length (2D) or area (3D) of crack, averaged over directions.
    double crossing_density = 0.;
    /// 1 on every owned particle component, 1 on every FE dof (for the sizes).
    ParticleVector particle_ones;
    FEVector       fe_ones;
  };
} // namespace perideal

#endif
