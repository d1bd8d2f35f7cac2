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
     * @brief Whether the segment from @p x to @p y meets the crack.
     */
    bool
    cuts(const dealii::Point<dim> &x, const dealii::Point<dim> &y) const;
  };
} // namespace perideal

#endif
