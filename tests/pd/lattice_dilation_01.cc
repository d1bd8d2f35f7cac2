// The dilation of a set of lattice points by a ball of lattice offsets (LatticeDilation, the
// keep test of a coupled problem's particles, issue #41): against the direct scan of every
// offset at every point, on lattices of 2D and 3D boxes whose corner is off the origin, the
// marked set a few spheres and a half-space (and empty, and everything), the ball of radius
// delta + dx for delta = 3.015 dx (the coupled problem's) and 2.5 dx, tiles of 5, 8 and the
// default size, the points asked for in lattice order and in a shuffled order: every answer the
// same, and the predicate evaluated at most once per lattice point.
#include <perideal/pd/lattice.h>
#include <perideal/pd/lattice_dilation.h>

#include "../tests.h"

#include <algorithm>
#include <map>
#include <random>

namespace
{
  using namespace dealii;
  constexpr double dx = 1e-3;

  template <int dim>
  void
  check(const std::string                             &name,
        const std::function<bool(const Point<dim> &)> &marked,
        const double                                   radius,
        const unsigned int                             tile,
        const bool                                     shuffled)
  {
    perideal::Lattice<dim> lattice(dx);
    Point<dim>             low, high;
    const unsigned int     n[3] = {23, 17, 11};
    for (unsigned int d = 0; d < dim; ++d)
      {
        low[d]  = 0.37e-3 + 1.1e-3 * d;
        high[d] = low[d] + n[d] * dx;
      }
    lattice.cover(BoundingBox<dim>(std::make_pair(low, high)));
    perideal::Lattice<dim>      origin(dx);
    std::vector<Tensor<1, dim>> offsets = origin.vectors(radius);
    offsets.emplace_back();

    std::vector<Point<dim>>                points;
    typename perideal::Lattice<dim>::Index index{};
    while (true)
      {
        points.push_back(lattice.point(index));
        unsigned int d = 0;
        while (d < dim && ++index[d] == lattice.n_points(d))
          index[d++] = 0;
        if (d == dim)
          break;
      }
    if (shuffled)
      std::shuffle(points.begin(), points.end(), std::mt19937(7));

    // Every evaluation of the predicate, by lattice point.
    std::map<typename perideal::Lattice<dim>::Key, unsigned int> evaluated;
    perideal::LatticeDilation<dim>                               dilation(
      dx,
      offsets,
      [&](const Point<dim> &y) {
        ++evaluated[origin.key(y)];
        return marked(y);
      },
      tile);
    unsigned int kept = 0, differ = 0;
    for (const auto &x : points)
      {
        bool direct = false;
        for (const auto &o : offsets)
          direct = direct || marked(x + o);
        const bool tiled = dilation(x);
        kept += tiled;
        differ += (tiled != direct);
      }
    unsigned int most = 0;
    for (const auto &[key, count] : evaluated)
      most = std::max(most, count);
    deallog << dim << "D, " << name << ", radius " << radius / dx << " dx, tile "
            << (tile == 0 ? std::string("default") : std::to_string(tile))
            << (shuffled ? ", shuffled" : ", in order") << ": " << points.size() << " points, kept "
            << kept << ", different from the direct scan " << differ
            << ", each point evaluated at most once: "
            << (most <= 1 && dilation.n_evaluations() == evaluated.size() ? "yes" : "no")
            << std::endl;
  }

  template <int dim>
  void
  check_all()
  {
    Point<dim> c1, c2;
    for (unsigned int d = 0; d < dim; ++d)
      {
        c1[d] = 5e-3 + 1e-3 * d;
        c2[d] = 19e-3 - 2e-3 * d;
      }
    const std::vector<std::pair<std::string, std::function<bool(const Point<dim> &)>>> sets = {
      {"two spheres",
       [=](const Point<dim> &x) { return x.distance(c1) < 1.2e-3 || x.distance(c2) < 0.4e-3; }},
      {"a half-space", [](const Point<dim> &x) { return x[0] + 0.5 * x[1] > 17e-3; }},
      {"nothing", [](const Point<dim> &) { return false; }},
      {"everything", [](const Point<dim> &) { return true; }}};
    for (const auto &[name, marked] : sets)
      for (const double radius : {4.015 * dx, 2.5 * dx})
        for (const unsigned int tile : {5u, 8u, 0u})
          for (const bool shuffled : {false, true})
            check<dim>(name, marked, radius, tile, shuffled);
  }
} // namespace

int
main()
{
  initlog();
  check_all<2>();
  check_all<3>();
}
