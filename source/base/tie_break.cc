// ---------------------------------------------------------------------
// PeriDeal: the fixed direction that decides on which side of a surface a point lying on it is.
// ---------------------------------------------------------------------
#include <perideal/base/tie_break.h>

#include <cmath>

namespace perideal
{
  template <int dim>
  dealii::Tensor<1, dim>
  tie_break_direction()
  {
    dealii::Tensor<1, dim> v;
    for (unsigned int d = 0; d < dim; ++d)
      v[d] = 1. + 0.1 * std::sqrt(2.) * (d + 1);
    return v;
  }

  template dealii::Tensor<1, 2>
  tie_break_direction<2>();
  template dealii::Tensor<1, 3>
  tie_break_direction<3>();
} // namespace perideal
