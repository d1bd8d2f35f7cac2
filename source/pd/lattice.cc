// ---------------------------------------------------------------------
// PeriDeal: the lattice of the particles (points, perturbation offsets, keys).
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>

#include <perideal/pd/lattice.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /// SplitMix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit hash.
    std::uint64_t
    mix(std::uint64_t z)
    {
      z += 0x9e3779b97f4a7c15ULL;
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return z ^ (z >> 31);
    }
  } // namespace

  template <int dim>
  Lattice<dim>::Lattice(const double spacing, const double perturbation, const unsigned int seed)
    : dx(spacing)
    , a(0.5 * perturbation * spacing)
    , seed(seed)
  {}

  template <int dim>
  void
  Lattice<dim>::cover(const BoundingBox<dim> &box)
  {
    corner = box.get_boundary_points().first;
    for (unsigned int d = 0; d < dim; ++d)
      n[d] = std::max(1, static_cast<int>(std::ceil(box.side_length(d) / dx - 1e-8)));
  }

  template <int dim>
  double
  Lattice<dim>::spacing() const
  {
    return dx;
  }

  template <int dim>
  double
  Lattice<dim>::offset_bound() const
  {
    return a;
  }

  template <int dim>
  const Point<dim> &
  Lattice<dim>::lower_corner() const
  {
    return corner;
  }

  template <int dim>
  Point<dim>
  Lattice<dim>::upper_corner() const
  {
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = corner[d] + n[d] * dx;
    return upper;
  }

  template <int dim>
  unsigned int
  Lattice<dim>::n_points(const unsigned int d) const
  {
    return n[d];
  }

  template <int dim>
  Point<dim>
  Lattice<dim>::point(const Index &index) const
  {
    Point<dim> p;
    for (unsigned int d = 0; d < dim; ++d)
      p[d] = corner[d] + (index[d] + 0.5) * dx;
    return p;
  }

  template <int dim>
  Point<dim>
  Lattice<dim>::particle(const Index &index) const
  {
    Point<dim> p = point(index);
    if (a > 0.)
      {
        std::uint64_t h = mix(seed);
        for (unsigned int d = 0; d < dim; ++d)
          h = mix(h ^ index[d]);
        for (unsigned int d = 0; d < dim; ++d)
          {
            h = mix(h);
            // The top 53 bits as a double in [0, 1).
            p[d] += a * (2. * static_cast<double>(h >> 11) * 0x1.0p-53 - 1.);
          }
      }
    return p;
  }

  template <int dim>
  std::array<long, dim>
  Lattice<dim>::index_of(const Point<dim> &x) const
  {
    const double          tolerance = a / dx + 1e-6;
    std::array<long, dim> index;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double q = (x[d] - corner[d]) / dx - 0.5;
        index[d]       = std::lround(q);
        AssertThrow(std::abs(q - index[d]) < tolerance,
                    ExcMessage("Internal error: the particle at a coordinate " +
                               std::to_string(x[d]) +
                               " is not within its offset of the lattice of spacing " +
                               std::to_string(dx) + "; the force kernels need lattice particles."));
      }
    return index;
  }

  template <int dim>
  typename Lattice<dim>::Key
  Lattice<dim>::key(const Point<dim> &x) const
  {
    Key key;
    for (unsigned int d = 0; d < dim; ++d)
      key[d] = std::lround(x[d] / dx * 2.);
    return key;
  }

  template <int dim>
  std::vector<Tensor<1, dim>>
  Lattice<dim>::vectors(const double radius) const
  {
    const int                   reach = static_cast<int>(radius / dx) + 1;
    std::vector<Tensor<1, dim>> result;
    std::array<int, dim>        k;
    k.fill(-reach);
    while (true)
      {
        Tensor<1, dim> v;
        for (unsigned int d = 0; d < dim; ++d)
          v[d] = k[d] * dx;
        const double r = v.norm();
        if (r > 0. && r <= radius)
          result.push_back(v);
        unsigned int d = 0;
        while (d < dim && ++k[d] > reach)
          k[d++] = -reach;
        if (d == dim)
          break;
      }
    return result;
  }

  template class Lattice<2>;
  template class Lattice<3>;
} // namespace perideal
