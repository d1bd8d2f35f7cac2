// ---------------------------------------------------------------------
// PeriDeal: the lattice points within a set of lattice offsets of a marked point, by tiles.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/pd/lattice_dilation.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /// floor(a / b) for b > 0.
    long
    floor_div(const long a, const long b)
    {
      return a >= 0 ? a / b : -((-a + b - 1) / b);
    }
  } // namespace

  template <int dim>
  LatticeDilation<dim>::LatticeDilation(const double                                   spacing,
                                        const std::vector<Tensor<1, dim>>             &offsets,
                                        const std::function<bool(const Point<dim> &)> &marked,
                                        const unsigned int                             tile)
    : dx(spacing)
    , marked(marked)
    , T(tile > 0 ? tile : (dim == 3 ? 32 : 128))
  {
    Assert(dx > 0., ExcMessage("The spacing must be positive."));
    // Per transverse part (the components after the first): the smallest and largest first
    // component and their count.
    std::map<std::array<long, dim - 1>, std::tuple<long, long, long>> rows;
    const auto add = [&](const std::array<long, dim> &k) {
      std::array<long, dim - 1> key;
      for (unsigned int d = 1; d < dim; ++d)
        key[d - 1] = k[d];
      const auto found = rows.find(key);
      if (found == rows.end())
        rows[key] = {k[0], k[0], 1};
      else
        {
          auto &[low, high, count] = found->second;
          low                      = std::min(low, k[0]);
          high                     = std::max(high, k[0]);
          ++count;
        }
      for (unsigned int d = 0; d < dim; ++d)
        halo = std::max(halo, std::abs(k[d]));
    };
    std::array<long, dim> zero{};
    bool                  has_zero = false;
    for (const auto &o : offsets)
      {
        std::array<long, dim> k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            k[d] = std::lround(o[d] / dx);
            AssertThrow(std::abs(o[d] - k[d] * dx) <= 1e-8 * dx,
                        ExcInternalError("LatticeDilation: an offset is not a lattice vector."));
          }
        has_zero = has_zero || k == zero;
        add(k);
      }
    if (!has_zero)
      add(zero);
    for (const auto &[key, range] : rows)
      {
        const auto [low, high, count] = range;
        AssertThrow(low == -high && count == high - low + 1,
                    ExcInternalError("LatticeDilation: the offsets of a transverse part are not a "
                                     "symmetric interval along the first axis."));
        auto found = std::find(half_widths.begin(), half_widths.end(), high);
        if (found == half_widths.end())
          found = half_widths.insert(half_widths.end(), high);
        transverse.emplace_back(key, static_cast<unsigned int>(found - half_widths.begin()));
      }
    AssertThrow(halo <= T,
                ExcInternalError("LatticeDilation: the offsets reach beyond a tile's neighbours."));
  }

  template <int dim>
  typename LatticeDilation<dim>::Tile &
  LatticeDilation<dim>::tile_at(const Coordinates &t)
  {
    Tile &tile = tiles[t];
    if (tile.marked.empty())
      {
        long size = 1;
        for (unsigned int d = 0; d < dim; ++d)
          size *= T;
        tile.marked.assign(size, 0);
      }
    return tile;
  }

  template <int dim>
  bool
  LatticeDilation<dim>::operator()(const Point<dim> &x)
  {
    if (!have_origin)
      {
        origin      = x;
        have_origin = true;
      }
    Coordinates k, t;
    for (unsigned int d = 0; d < dim; ++d)
      {
        k[d] = std::lround((x[d] - origin[d]) / dx);
        t[d] = floor_div(k[d], T);
      }
    if (last_tile == nullptr || t != last_key)
      {
        last_tile = &tile_at(t);
        last_key  = t;
      }
    Tile &tile = *last_tile;
    if (tile.dilated.empty())
      dilate(t, tile, x, k);
    long index = 0, stride = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        index += (k[d] - t[d] * T) * stride;
        stride *= T;
      }
    return tile.dilated[index] != 0;
  }

  template <int dim>
  void
  LatticeDilation<dim>::dilate(const Coordinates &t,
                               Tile              &tile,
                               const Point<dim>  &x,
                               const Coordinates &k)
  {
    const long E = T + 2 * halo;
    // The box of the tile and its halo: lower corner b, E points per axis, the first fastest.
    Coordinates b;
    long        box_size = 1, rows = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        b[d] = t[d] * T - halo;
        box_size *= E;
        if (d > 0)
          rows *= E;
      }
    std::vector<std::uint8_t> box(box_size);

    // The predicate on the box, from the 3^dim tiles around (evaluated where not yet).
    std::array<int, dim> s;
    s.fill(-1);
    while (true)
      {
        Coordinates n, low, high;
        bool        empty = false;
        for (unsigned int d = 0; d < dim; ++d)
          {
            n[d]    = t[d] + s[d];
            low[d]  = std::max(b[d], n[d] * T);
            high[d] = std::min(b[d] + E, (n[d] + 1) * T);
            empty   = empty || low[d] >= high[d];
          }
        if (!empty)
          {
            Tile       &neighbor = (n == t ? tile : tile_at(n));
            Coordinates c        = low;
            while (true)
              {
                long in_tile = 0, in_box = 0, tile_stride = 1, box_stride = 1;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    in_tile += (c[d] - n[d] * T) * tile_stride;
                    in_box += (c[d] - b[d]) * box_stride;
                    tile_stride *= T;
                    box_stride *= E;
                  }
                std::uint8_t &value = neighbor.marked[in_tile];
                if (value == 0)
                  {
                    Point<dim> y = x;
                    for (unsigned int d = 0; d < dim; ++d)
                      y[d] += (c[d] - k[d]) * dx;
                    value = marked(y) ? 2 : 1;
                    ++evaluations;
                  }
                box[in_box]    = (value == 2);
                unsigned int d = 0;
                while (d < dim && ++c[d] == high[d])
                  {
                    c[d] = low[d];
                    ++d;
                  }
                if (d == dim)
                  break;
              }
          }
        unsigned int d = 0;
        while (d < dim && ++s[d] > 1)
          s[d++] = -1;
        if (d == dim)
          break;
      }

    // Along the first axis: per half-width a, "marked within a" at the tile's columns
    // [halo, halo + T) of every row of the box, from a running count.
    std::vector<std::vector<std::uint8_t>> along(half_widths.size(),
                                                 std::vector<std::uint8_t>(rows * T));
    std::vector<long>                      count(E + 1);
    for (long r = 0; r < rows; ++r)
      {
        const std::uint8_t *row = box.data() + r * E;
        count[0]                = 0;
        for (long i = 0; i < E; ++i)
          count[i + 1] = count[i] + row[i];
        for (unsigned int h = 0; h < half_widths.size(); ++h)
          {
            const long    a   = half_widths[h];
            std::uint8_t *out = along[h].data() + r * T;
            for (long i = 0; i < T; ++i)
              out[i] = count[halo + i + a + 1] > count[halo + i - a];
          }
      }

    // Across: a tile row is the OR of the rows at the transverse offsets.
    long tile_rows = 1;
    for (unsigned int d = 1; d < dim; ++d)
      tile_rows *= T;
    tile.dilated.assign(tile_rows * T, 0);
    std::array<long, dim - 1> l{};
    for (long r = 0; r < tile_rows; ++r)
      {
        std::uint8_t *out = tile.dilated.data() + r * T;
        for (const auto &[o, h] : transverse)
          {
            long source = 0, stride = 1;
            for (unsigned int d = 0; d + 1 < dim; ++d)
              {
                source += (l[d] + halo + o[d]) * stride;
                stride *= E;
              }
            const std::uint8_t *in = along[h].data() + source * T;
            for (long i = 0; i < T; ++i)
              out[i] |= in[i];
          }
        for (unsigned int d = 0; d + 1 < dim && ++l[d] == T; ++d)
          l[d] = 0;
      }
  }

  template <int dim>
  std::uint64_t
  LatticeDilation<dim>::n_evaluations() const
  {
    return evaluations;
  }

  template class LatticeDilation<2>;
  template class LatticeDilation<3>;
} // namespace perideal
