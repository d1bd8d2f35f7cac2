// Pre-cracks by a rule that round-off cannot flip: a bond that meets a crack only at its end
// (2D) or edge (3D) stays intact, a bond's end on the crack's plane lies on the side that
// tie_break_direction() points into; the cut bonds of lattices equal an exact integer count of
// that rule, mirror images cut mirror bonds, and 1 and 2 ranks agree.
#include <perideal/base/tie_break.h>
#include <perideal/pd/damage_model.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"

#include <array>

using namespace dealii;

namespace
{
  // A lattice of spacing dx from a corner, particles at corner + (index + 1/2) dx (as Lattice).
  // Positions in the exact count are integers in half spacings from the corner: 2 index + 1.
  template <int dim>
  struct Grid
  {
    Point<dim>           corner;
    double               dx;
    std::array<int, dim> n;
    Point<dim>
    point(const std::array<int, dim> &index) const
    {
      Point<dim> p;
      for (unsigned int d = 0; d < dim; ++d)
        p[d] = corner[d] + (index[d] + 0.5) * dx;
      return p;
    }
  };

  // The rule in exact arithmetic for a crack in the plane y = Yc (half spacings) that covers
  // Xa < x < Xb (and Za < z < Zb in 3D); an end on the plane counts on the side +y (the side of
  // tie_break_direction(), whose y component is positive). Returns 1 cut, 0 not, and sets
  // @p at_end if the crossing lies exactly on the crack's boundary.
  template <int dim>
  int
  exact_cut(const std::array<int, dim> &i,
            const std::array<int, dim> &j,
            const int                   Yc,
            const std::array<int, 4>   &range,
            bool                       &at_end)
  {
    at_end           = false;
    long long p[3]   = {2 * i[0] + 1, 2 * i[1] + 1, dim == 3 ? 2 * i[dim - 1] + 1 : 0};
    long long q[3]   = {2 * j[0] + 1, 2 * j[1] + 1, dim == 3 ? 2 * j[dim - 1] + 1 : 0};
    const int side_p = p[1] >= Yc ? 1 : -1, side_q = q[1] >= Yc ? 1 : -1;
    if (side_p == side_q)
      return 0;
    // The crossing p + (q - p) (Yc - p_y) / (q_y - p_y) = num / den, den > 0.
    long long den = q[1] - p[1];
    long long num[2];
    for (int c = 0; c < 2; ++c)
      {
        const int k = c == 0 ? 0 : 2;
        num[c]      = p[k] * den + (q[k] - p[k]) * (Yc - p[1]);
      }
    if (den < 0)
      {
        den    = -den;
        num[0] = -num[0];
        num[1] = -num[1];
      }
    // Inside the open crack, or on its boundary (in the closed crack, not in the open one).
    const int n_dirs = dim == 3 ? 2 : 1;
    bool      inside = true, closed = true;
    for (int c = 0; c < n_dirs; ++c)
      {
        const long long lo = range[2 * c] * den, hi = range[2 * c + 1] * den;
        inside = inside && num[c] > lo && num[c] < hi;
        closed = closed && num[c] >= lo && num[c] <= hi;
      }
    at_end = closed && !inside;
    return inside ? 1 : 0;
  }

  // Every bond of the grid (|xi| <= m dx) once: the number cut by @p crack, the bonds where it
  // disagrees with exact_cut(), the bonds crossing exactly on the crack's boundary (and how many
  // of them are cut), and the mirror bonds of @p mirror_crack (the crack mirrored in axis
  // @p axis) whose state differs.
  template <int dim>
  void
  count(const std::string                                                   &name,
        const Grid<dim>                                                     &grid,
        const double                                                         m,
        const perideal::PreCrack<dim>                                       &crack,
        const int                                                            Yc,
        const std::array<int, 4>                                            &range,
        const std::vector<std::pair<unsigned int, perideal::PreCrack<dim>>> &mirrors)
  {
    const int                         reach = static_cast<int>(m);
    std::vector<std::array<int, dim>> offsets;
    std::array<int, dim>              o;
    for (o[0] = 0; o[0] <= reach; ++o[0])
      for (o[1] = -reach; o[1] <= reach; ++o[1])
        for (int c = -reach * (dim == 3); c <= reach * (dim == 3); ++c)
          {
            if constexpr (dim == 3)
              o[2] = c;
            int norm2 = 0;
            for (unsigned int d = 0; d < dim; ++d)
              norm2 += o[d] * o[d];
            // Each bond once: the first non-zero offset component positive.
            bool positive = false;
            for (unsigned int d = 0; d < dim; ++d)
              if (o[d] != 0)
                {
                  positive = o[d] > 0;
                  break;
                }
            if (positive && norm2 <= m * m)
              offsets.push_back(o);
          }
    unsigned long              cut = 0, wrong = 0, ties = 0, ties_cut = 0, swapped = 0;
    std::vector<unsigned long> asymmetric(mirrors.size(), 0);
    std::array<int, dim>       i;
    const auto                 in_grid = [&](const std::array<int, dim> &k) {
      for (unsigned int d = 0; d < dim; ++d)
        if (k[d] < 0 || k[d] >= grid.n[d])
          return false;
      return true;
    };
    for (i[0] = 0; i[0] < grid.n[0]; ++i[0])
      for (i[1] = 0; i[1] < grid.n[1]; ++i[1])
        for (int c = 0; c < (dim == 3 ? grid.n[dim - 1] : 1); ++c)
          {
            if constexpr (dim == 3)
              i[2] = c;
            for (const auto &offset : offsets)
              {
                std::array<int, dim> j;
                for (unsigned int d = 0; d < dim; ++d)
                  j[d] = i[d] + offset[d];
                if (!in_grid(j))
                  continue;
                const Point<dim> x = grid.point(i), y = grid.point(j);
                const bool       is_cut = crack.cuts(x, y);
                swapped += is_cut != crack.cuts(y, x);
                bool      at_end;
                const int expected = exact_cut<dim>(i, j, Yc, range, at_end);
                cut += is_cut;
                wrong += static_cast<int>(is_cut) != expected;
                ties += at_end;
                ties_cut += at_end && is_cut;
                for (unsigned int k = 0; k < mirrors.size(); ++k)
                  {
                    const unsigned int   axis = mirrors[k].first;
                    std::array<int, dim> mi = i, mj = j;
                    mi[axis] = grid.n[axis] - 1 - i[axis];
                    mj[axis] = grid.n[axis] - 1 - j[axis];
                    asymmetric[k] +=
                      is_cut != mirrors[k].second.cuts(grid.point(mi), grid.point(mj));
                  }
              }
          }
    deallog << name << ": cut " << cut << ", differing from the exact rule " << wrong
            << ", crossing exactly on the crack's boundary " << ties << " (cut " << ties_cut
            << "), cuts(x, y) != cuts(y, x) " << swapped;
    for (unsigned int k = 0; k < mirrors.size(); ++k)
      deallog << ", mirror bonds differing (axis " << mirrors[k].first << ") " << asymmetric[k];
    deallog << std::endl;
  }

  // The lattice of ParticleSystem with the same crack: the broken bonds on all ranks.
  template <int dim>
  std::uint64_t
  generated(const Grid<dim> &grid, const double m, const perideal::PreCrack<dim> &crack)
  {
    perideal::ParticleSystem<dim>                    particles(MPI_COMM_WORLD);
    typename perideal::ParticleSystem<dim>::Settings settings;
    settings.spacing        = grid.dx;
    settings.horizon        = m * grid.dx;
    settings.partial_volume = perideal::PartialVolume::none;
    Point<dim> upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = grid.corner[d] + grid.n[d] * grid.dx;
    particles.generate(settings,
                       BoundingBox<dim>(std::make_pair(grid.corner, upper)),
                       [](const Point<dim> &) { return true; },
                       {crack});
    return perideal::n_broken_bonds(particles);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  const Tensor<1, 2> v = perideal::tie_break_direction<2>();
  deallog << "tie_break_direction<2>: " << v << ", <3>: " << perideal::tie_break_direction<3>()
          << std::endl;

  // Single bonds against the segment (0, 0)-(1, 0), and against the same segment given from
  // its other end.
  perideal::PreCrack<2> segment, reversed;
  segment.vertices  = {{Point<2>(0., 0.), Point<2>(1., 0.)}};
  reversed.vertices = {{Point<2>(1., 0.), Point<2>(0., 0.)}};
  const std::vector<std::pair<std::string, std::array<Point<2>, 2>>> bonds = {
    {"crossing inside", {{Point<2>(0.5, -0.1), Point<2>(0.6, 0.1)}}},
    {"through the end point", {{Point<2>(0.9, -0.1), Point<2>(1.1, 0.1)}}},
    {"through the start point", {{Point<2>(-0.1, 0.1), Point<2>(0.1, -0.1)}}},
    {"beyond the end by 1e-6 of its length",
     {{Point<2>(1. - 0.1, -0.1), Point<2>(1.1 + 2e-7, 0.1)}}},
    {"inside by 1e-6 of its length", {{Point<2>(1. - 0.1, -0.1), Point<2>(1.1 - 2e-7, 0.1)}}},
    {"an end on the line inside, the other below", {{Point<2>(0.5, 0.), Point<2>(0.5, -0.2)}}},
    {"an end on the line inside, the other above", {{Point<2>(0.5, 0.), Point<2>(0.5, 0.2)}}},
    {"an end 1e-18 below the line, the other below",
     {{Point<2>(0.5, -1e-18), Point<2>(0.4, -0.2)}}},
    {"an end 1e-18 below the line, the other above", {{Point<2>(0.5, -1e-18), Point<2>(0.4, 0.2)}}},
    {"an end on the end point, the other below", {{Point<2>(1., 0.), Point<2>(0.9, -0.2)}}},
    {"in the line", {{Point<2>(0.2, 0.), Point<2>(0.6, 0.)}}},
    {"parallel below", {{Point<2>(0.2, -0.1), Point<2>(0.6, -0.1)}}}};
  for (const auto &[name, ends] : bonds)
    deallog << name << ": " << segment.cuts(ends[0], ends[1])
            << " (ends swapped: " << segment.cuts(ends[1], ends[0])
            << ", crack reversed: " << reversed.cuts(ends[0], ends[1]) << ")" << std::endl;

  // The compact-tension notch of doc/benchmarks/compact_tension: the specimen [-10, 40] x [-24,
  // 24] mm ([-9, 39] at dx = 1.5 mm), the crack along y = 0 from the front edge to x_t = 20 mm
  // (19.5 mm), midway between two particle columns. The bonds that cross y = 0 exactly at x_t
  // (6 for m = 3, 10 for m = 4) stay intact. Mirror images: in y (the same crack) and in x
  // (the crack from the back edge to the mirror of x_t).
  struct CT
  {
    double dx, front, back, tip;
  };
  for (const CT &ct : {CT{2e-3, -0.010, 0.040, 0.020},
                       CT{1.5e-3, -0.009, 0.039, 0.0195},
                       CT{1e-3, -0.010, 0.040, 0.020},
                       CT{0.5e-3, -0.010, 0.040, 0.020}})
    for (const double m : {3.015, 4.015})
      {
        Grid<2> grid;
        grid.corner = Point<2>(ct.front, -0.024);
        grid.dx     = ct.dx;
        grid.n      = {static_cast<int>(std::round((ct.back - ct.front) / ct.dx)),
                       static_cast<int>(std::round(0.048 / ct.dx))};
        perideal::PreCrack<2> crack, mirror_x;
        crack.vertices    = {{Point<2>(ct.front - 0.001, 0.), Point<2>(ct.tip, 0.)}};
        mirror_x.vertices = {
          {Point<2>(ct.back + 0.001, 0.), Point<2>(ct.front + ct.back - ct.tip, 0.)}};
        const int Yc = static_cast<int>(std::round(0.048 / ct.dx));
        const int Xb = static_cast<int>(std::round(2 * (ct.tip - ct.front) / ct.dx));
        count<2>("CT dx = " + std::to_string(ct.dx * 1e3).substr(0, 3) +
                   " mm, m = " + std::to_string(m).substr(0, 5),
                 grid,
                 m,
                 crack,
                 Yc,
                 {-1, Xb, 0, 0}, // the crack starts outside the body
                 {{1, crack}, {0, mirror_x}});
        if (ct.dx == 2e-3)
          deallog << "  ParticleSystem: broken bonds " << generated<2>(grid, m, crack) << std::endl;
      }

  // Particles on the crack's line (doc/benchmarks/many_ranks): rows at y = -0.1 + (j + 1/2)
  // 0.002 m, the row j = 37 6.9e-18 m below the crack at y = -0.025; the crack ends at the
  // particle x = 0.031 of that row. The row counts as above the line: its bonds to the rows
  // below that cross inside the crack are cut, those to the rows above are not; the bonds through
  // the end particle stay intact. Mirror image in x only (a mirror in y moves the row's side).
  {
    Grid<2> grid;
    grid.corner = Point<2>(0., -0.1);
    grid.dx     = 0.002;
    grid.n      = {30, 50};
    perideal::PreCrack<2> crack, mirror_x;
    crack.vertices    = {{Point<2>(-0.001, -0.025), Point<2>(0.031, -0.025)}};
    mirror_x.vertices = {{Point<2>(0.061, -0.025), Point<2>(0.029, -0.025)}};
    deallog << "row 37 at y = " << grid.point({{0, 37}})[1] << std::endl;
    count<2>("on the line, m = 3.015", grid, 3.015, crack, 75, {-1, 31, 0, 0}, {{0, mirror_x}});
    unsigned int below = 0, above = 0;
    for (int i = 0; i < 15; ++i)
      for (const int b : {-1, 1})
        {
          below += crack.cuts(grid.point({{i, 37}}), grid.point({{i, 37 + b}})) && b < 0;
          above += crack.cuts(grid.point({{i, 37}}), grid.point({{i, 37 + b}})) && b > 0;
        }
    deallog << "  the row's vertical bonds cut: to the row below " << below << ", to the row above "
            << above << std::endl;
    deallog << "  ParticleSystem: broken bonds " << generated<2>(grid, 3.015, crack) << std::endl;
  }

  // 3D: a rectangle in y = 0 over x < 0 and |z| < 2 mm, its edges x = 0 and z = +-2 mm midway
  // between particle layers (dx = 1 mm, corner (-8, -4, -4) mm). Mirror images in y and z (the
  // same rectangle) and x (the rectangle over x > 0, given from another corner).
  {
    Grid<3> grid;
    grid.corner = Point<3>(-0.008, -0.004, -0.004);
    grid.dx     = 1e-3;
    grid.n      = {16, 8, 8};
    perideal::PreCrack<3> crack, mirror_x;
    crack.vertices = {
      {Point<3>(-0.009, 0., -0.002), Point<3>(0., 0., -0.002), Point<3>(-0.009, 0., 0.002)}};
    mirror_x.vertices = {
      {Point<3>(0.009, 0., 0.002), Point<3>(0.009, 0., -0.002), Point<3>(0., 0., 0.002)}};
    count<3>("3D rectangle, m = 3.015",
             grid,
             3.015,
             crack,
             8,
             {-2, 16, 4, 12},
             {{1, crack}, {2, crack}, {0, mirror_x}});
    deallog << "  ParticleSystem: broken bonds " << generated<3>(grid, 3.015, crack) << std::endl;
  }
}
