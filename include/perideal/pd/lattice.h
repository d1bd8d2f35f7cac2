// ---------------------------------------------------------------------
// PeriDeal: the lattice of the particles (points, perturbation offsets, keys).
// ---------------------------------------------------------------------
#ifndef perideal_pd_lattice_h
#define perideal_pd_lattice_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace perideal
{
  /**
   * @brief A regular lattice of spacing dx whose points sit at the centres of the cells of a
   * box: lattice point k is at corner + (k + 1/2) dx. On a perturbed lattice (perturbation
   * epsilon > 0) the particle of point k is moved by an offset uniform in [-epsilon dx/2,
   * epsilon dx/2] per coordinate, a hash (SplitMix64) of the seed and the indices k only, so
   * that it does not depend on the number of ranks or on which points a body keeps.
   */
  template <int dim>
  class Lattice
  {
  public:
    /// The indices of a lattice point of the box.
    using Index = std::array<unsigned int, dim>;
    /// The key of a point: its coordinates in half spacings, rounded (key()).
    using Key = std::array<long, dim>;

    /// A hash of Key, for unordered containers.
    struct KeyHash
    {
      /// The hash of @p key.
      std::size_t
      operator()(const Key &key) const
      {
        std::size_t h = 0;
        for (const long k : key)
          h = h * 1000003u ^ std::hash<long>()(k);
        return h;
      }
    };

    /// An empty lattice (spacing 0).
    Lattice() = default;

    /**
     * @brief A lattice of spacing @p spacing [m] whose particles are moved by offsets of
     * half-width @p perturbation dx / 2 (0 <= @p perturbation <= 1/2) drawn from @p seed.
     */
    Lattice(const double spacing, const double perturbation = 0., const unsigned int seed = 1);

    /**
     * @brief Place the lattice over @p box: its corner at the box's lower corner, ceil(side /
     * dx) points per axis (at least one), so that the lattice's cells cover the box.
     */
    void
    cover(const dealii::BoundingBox<dim> &box);

    /// @brief The spacing dx [m].
    double
    spacing() const;
    /// @brief The half-width of the perturbation offsets, epsilon dx / 2 [m] (0: unperturbed).
    double
    offset_bound() const;
    /// @brief The lower corner of the box of cover().
    const dealii::Point<dim> &
    lower_corner() const;
    /// @brief The upper corner of the lattice's cells, corner + n_points dx.
    dealii::Point<dim>
    upper_corner() const;
    /// @brief The number of lattice points along axis @p d.
    unsigned int
    n_points(const unsigned int d) const;

    /// @brief Lattice point @p index, the centre of its cell.
    dealii::Point<dim>
    point(const Index &index) const;
    /// @brief The particle of lattice point @p index: point() moved by its offset.
    dealii::Point<dim>
    particle(const Index &index) const;
    /**
     * @brief The (signed) indices of the lattice point whose particle is @p x; throws if @p x
     * is not within an offset of a lattice point.
     */
    std::array<long, dim>
    index_of(const dealii::Point<dim> &x) const;
    /**
     * @brief The key of @p x: its coordinates in half spacings from the origin, rounded. It
     * names a lattice point whatever the box the lattice covers (the box of a PD region that
     * grows may change).
     */
    Key
    key(const dealii::Point<dim> &x) const;
    /**
     * @brief The lattice vectors v != 0 with |v| <= @p radius, ordered by their indices (from
     * -n to n, the first fastest).
     */
    std::vector<dealii::Tensor<1, dim>>
    vectors(const double radius) const;

  private:
    double                        dx   = 0.;
    double                        a    = 0.;
    unsigned int                  seed = 1;
    dealii::Point<dim>            corner;
    std::array<unsigned int, dim> n{};
  };
} // namespace perideal

#endif
