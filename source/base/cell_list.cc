// ---------------------------------------------------------------------
// PeriDeal: a cell list, the spatial binning of a set of points for searches within a radius.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/base/cell_list.h>

#include <algorithm>
#include <numeric>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  CellList<dim>::reinit(const ArrayView<const Point<dim>> &points, const double cell_width)
  {
    Assert(cell_width > 0., ExcMessage("The cell width of a cell list must be positive."));
    width = cell_width;
    Point<dim> upper;
    if (points.size() > 0)
      origin = upper = points[0];
    for (const auto &p : points)
      for (unsigned int d = 0; d < dim; ++d)
        {
          origin[d] = std::min(origin[d], p[d]);
          upper[d]  = std::max(upper[d], p[d]);
        }
    std::size_t n_total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        n_cells[d] = 1 + static_cast<unsigned int>((upper[d] - origin[d]) / width);
        n_total *= n_cells[d];
      }
    const auto cell_of = [&](const Point<dim> &p) {
      std::size_t cell = 0;
      for (unsigned int d = dim; d-- > 0;)
        cell = cell * n_cells[d] +
               std::min(n_cells[d] - 1, static_cast<unsigned int>((p[d] - origin[d]) / width));
      return cell;
    };
    cell_start.assign(n_total + 1, 0);
    cell_points.resize(points.size());
    for (const auto &p : points)
      ++cell_start[cell_of(p) + 1];
    std::partial_sum(cell_start.begin(), cell_start.end(), cell_start.begin());
    std::vector<unsigned int> fill(cell_start.begin(), cell_start.end() - 1);
    for (unsigned int i = 0; i < points.size(); ++i)
      cell_points[fill[cell_of(points[i])]++] = i;
  }

  template class CellList<2>;
  template class CellList<3>;
} // namespace perideal
