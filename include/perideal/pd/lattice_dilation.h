// ---------------------------------------------------------------------
// PeriDeal: the lattice points within a set of lattice offsets of a marked point, by tiles.
// ---------------------------------------------------------------------
#ifndef perideal_pd_lattice_dilation_h
#define perideal_pd_lattice_dilation_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <perideal/pd/lattice.h>

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace perideal
{
  /**
   * @brief The dilation of a set of lattice points by a ball of lattice offsets: a lattice
   * point x is in it if the predicate @p marked holds at x + o for one of the offsets o (the
   * zero offset included). It answers one point at a time, as ParticleSystem::generate()
   * asks, but works by tiles of T^dim lattice points: the first query in a tile evaluates the
   * predicate on the tile and a halo of the offsets' reach (each lattice point once, kept in
   * its tile) and dilates the tile at once, row by row: a running count along the first axis
   * gives "marked within a distance a along it" for each half-width a of the ball, and a
   * point's answer is the OR of those rows at the ball's transverse offsets. The cost per
   * point is constant (about the number of transverse offsets, vectorized byte ORs), and the
   * memory is two bytes per lattice point of the tiles a rank asks for (and their halo), so
   * it stays within the rank's share of the lattice.
   *
   * The predicate is evaluated at x + (k' - k) dx, with x the query point that made the tile
   * and k, k' the integer coordinates of x and of the evaluated point: the same points as x +
   * o of a direct scan, up to round-off of the last bit.
   *
   * The offsets must be lattice vectors (integer multiples of the spacing) whose set is, for
   * each transverse part, a contiguous interval symmetric about zero along the first axis (a
   * ball, as Lattice::vectors() gives); the constructor checks that.
   */
  template <int dim>
  class LatticeDilation
  {
  public:
    /**
     * @brief The dilation by @p offsets (lattice vectors of spacing @p spacing; the zero
     * offset is always included) of the lattice points where @p marked holds, in tiles of
     * @p tile points per axis (0: 32 in 3D, 128 in 2D).
     */
    LatticeDilation(const double                                           spacing,
                    const std::vector<dealii::Tensor<1, dim>>             &offsets,
                    const std::function<bool(const dealii::Point<dim> &)> &marked,
                    const unsigned int                                     tile = 0);

    /**
     * @brief Whether @p x, a point of the lattice of all queries (the first query fixes it),
     * has a marked point within the offsets.
     */
    bool
    operator()(const dealii::Point<dim> &x);

    /// @brief How many times the predicate was evaluated.
    std::uint64_t
    n_evaluations() const;

  private:
    using Coordinates = std::array<long, dim>;

    /// A hash of tile coordinates (the lattice keys' hash: the same type).
    using CoordinatesHash = typename Lattice<dim>::KeyHash;

    /// One tile: the predicate per point (0 not evaluated, 1 false, 2 true) and the answer.
    struct Tile
    {
      /// The predicate at the tile's points.
      std::vector<std::uint8_t> marked;
      /// The dilation at the tile's points (empty until the tile is dilated).
      std::vector<std::uint8_t> dilated;
    };

    /// Dilate tile @p t, asked for at @p x of integer coordinates @p k.
    void
    dilate(const Coordinates &t, Tile &tile, const dealii::Point<dim> &x, const Coordinates &k);

    /// The tile of coordinates @p t, created empty if new.
    Tile &
    tile_at(const Coordinates &t);

    double                                          dx;
    std::function<bool(const dealii::Point<dim> &)> marked;
    long                                            T;
    long                                            halo = 0;
    /// The half-widths along the first axis and, per transverse offset, its index into them.
    std::vector<long>                                               half_widths;
    std::vector<std::pair<std::array<long, dim - 1>, unsigned int>> transverse;
    bool                                                            have_origin = false;
    dealii::Point<dim>                                              origin;
    std::unordered_map<Coordinates, Tile, CoordinatesHash>          tiles;
    Coordinates                                                     last_key{};
    Tile                                                           *last_tile   = nullptr;
    std::uint64_t                                                   evaluations = 0;
  };
} // namespace perideal

#endif
