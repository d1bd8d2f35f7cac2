// ---------------------------------------------------------------------
// PeriDeal: the fixed direction that decides on which side of a surface a point lying on it is.
// ---------------------------------------------------------------------
#ifndef perideal_base_tie_break_h
#define perideal_base_tie_break_h

#include <deal.II/base/tensor.h>

namespace perideal
{
  /**
   * @brief The fixed direction v that breaks the tie of a point lying on a surface (a cell face,
   * a pre-crack's plane): the point counts on the side it would move into along v. The same
   * vector for every rule that needs one, so that they agree: the transfer operator gives a
   * particle on cell faces (and on the faces of a slit) to the cell it moves into along v, and a
   * pre-crack puts a bond's end on its plane on the side v points into (PreCrack::cuts()), so a
   * particle on a notch is bonded to the body on the side of the FE cell that holds it.
   *
   * v_d = 1 + 0.1 √2 (d + 1): v = (1.14, 1.28) in 2D, (1.14, 1.28, 1.42) in 3D. No component is
   * zero and no two are equal, so v lies in no plane normal to an axis nor in a diagonal plane
   * (x = y, ...): for a face or crack of an axis-aligned or diagonal plane v points strictly to
   * one side, the side of increasing coordinates (doc/theory/models.md, "Pre-cracks").
   */
  template <int dim>
  dealii::Tensor<1, dim>
  tie_break_direction();
} // namespace perideal

#endif
