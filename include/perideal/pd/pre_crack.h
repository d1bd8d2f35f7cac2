// ---------------------------------------------------------------------
// PeriDeal: pre-cracks that cut bonds in the reference configuration.
// ---------------------------------------------------------------------
#ifndef perideal_pd_pre_crack_h
#define perideal_pd_pre_crack_h

#include <deal.II/base/point.h>

#include <array>

namespace perideal
{
  /**
   * @brief A pre-crack: a segment (2D, vertices a and b) or a parallelogram (3D, the vertices a,
   * b and c span the corner a and the edges b - a and c - a; a rectangle when they are at right
   * angles). A bond whose reference segment meets the crack starts broken.
   */
  template <int dim>
  struct PreCrack
  {
    /// Its end points (2D) or corners (3D) [m].
    std::array<dealii::Point<dim>, dim> vertices;

    /**
     * @brief Whether the bond from @p x to @p y crosses the crack, by a rule that round-off
     * cannot flip (doc/theory/models.md, "Pre-cracks"). With the tolerance τ = relative_tolerance
     * times the bond's length:
     * - each end lies on a side of the crack's plane (line in 2D): the side of its signed
     *   distance, or, within τ of the plane, the side that tie_break_direction() points into
     *   (the side the transfer operator gives such a particle to);
     * - a bond with both ends on one side is not cut (a bond in the plane neither);
     * - otherwise it is cut if its crossing point (an end on the plane: that end) lies inside
     *   the crack farther than τ from the crack's boundary (end points in 2D, edges in 3D): a
     *   bond that meets the crack only at its boundary stays intact, the crack ends there.
     * Symmetric in @p x and @p y, bit for bit (the ends are ordered first), and independent of
     * the order of the vertices.
     */
    bool
    cuts(const dealii::Point<dim> &x, const dealii::Point<dim> &y) const;

    /// The tolerance of cuts() relative to the bond's length: an end this close to the plane
    /// is on it, a crossing this close to the crack's boundary is on the boundary.
    static constexpr double relative_tolerance = 1e-9;
  };
} // namespace perideal

#endif
