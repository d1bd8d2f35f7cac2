// ---------------------------------------------------------------------
// PeriDeal: a cell list, the spatial binning of a set of points for searches within a radius.
// ---------------------------------------------------------------------
#ifndef perideal_base_cell_list_h
#define perideal_base_cell_list_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/point.h>

#include <algorithm>
#include <array>
#include <vector>

namespace perideal
{
  /**
   * @brief The points of a set binned into a regular grid of cubic cells of a given width over
   * their bounding box (compressed rows: the points of each cell in ascending index), so that
   * every point within one cell width of a query point lies in the 3^dim cells around the
   * query's cell. Building costs O(N + number of cells), a query O(points in 3^dim cells).
   *
   * Used by the family search of ParticleSystem, the nearest-particle search of the Schwarz
   * interface fit and the seed search of the adaptive PD region.
   */
  template <int dim>
  class CellList
  {
  public:
    /**
     * @brief Bin @p points into cells of width @p cell_width (> 0) over their bounding box.
     * The points are referenced by their position in @p points.
     */
    void
    reinit(const dealii::ArrayView<const dealii::Point<dim>> &points, const double cell_width);

    /**
     * @brief Call @p f(i) for every point i in the cells within one cell of the cell of @p x
     * (the 3^dim cells around it, those of the grid; none if @p x lies more than a cell outside
     * the grid): a superset of the points within one cell width of @p x. The cells are visited
     * with the first coordinate fastest, the points of a cell in ascending index.
     */
    template <typename Function>
    void
    for_each_near(const dealii::Point<dim> &x, const Function &f) const;

  private:
    dealii::Point<dim>            origin;
    double                        width = 1.;
    std::array<unsigned int, dim> n_cells{};
    /// The points of cell c are cell_points[cell_start[c] .. cell_start[c + 1]), c linear with
    /// the first coordinate fastest.
    std::vector<unsigned int> cell_start, cell_points;
  };


  template <int dim>
  template <typename Function>
  inline void
  CellList<dim>::for_each_near(const dealii::Point<dim> &x, const Function &f) const
  {
    if (cell_points.empty())
      return;
    std::array<unsigned int, dim> lo, hi;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double c = (x[d] - origin[d]) / width;
        if (!(c >= -1. && c < n_cells[d] + 1.))
          return;
        const int cell = static_cast<int>(c + 1.) - 1; // floor for c >= -1
        lo[d]          = cell <= 0 ? 0u : static_cast<unsigned int>(cell - 1);
        hi[d] = std::min<unsigned int>(n_cells[d] - 1, static_cast<unsigned int>(cell + 1));
      }
    std::array<unsigned int, dim> k = lo;
    while (true)
      {
        std::size_t cell = 0;
        for (unsigned int d = dim; d-- > 0;)
          cell = cell * n_cells[d] + k[d];
        for (unsigned int q = cell_start[cell]; q < cell_start[cell + 1]; ++q)
          f(cell_points[q]);
        unsigned int d = 0;
        for (; d < dim; ++d)
          {
            if (k[d] < hi[d])
              {
                ++k[d];
                break;
              }
            k[d] = lo[d];
          }
        if (d == dim)
          break;
      }
  }
} // namespace perideal

#endif
