// Pre-cracks: a segment (2D) and a rectangle (3D) break exactly the bonds that cross them.
#include <perideal/pd/damage_model.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  // Geometry of single segments.
  perideal::PreCrack<2> segment;
  segment.vertices = {Point<2>(0., 0.), Point<2>(1., 0.)};
  deallog << "crossing: " << segment.cuts(Point<2>(0.5, -0.1), Point<2>(0.6, 0.1))
          << ", beside: " << segment.cuts(Point<2>(1.5, -0.1), Point<2>(1.6, 0.1))
          << ", parallel: " << segment.cuts(Point<2>(0., 0.1), Point<2>(1., 0.1)) << std::endl;
  perideal::PreCrack<3> rectangle;
  rectangle.vertices = {Point<3>(0., 0., 0.), Point<3>(1., 0., 0.), Point<3>(0., 1., 0.)};
  deallog << "crossing: " << rectangle.cuts(Point<3>(0.5, 0.5, -0.1), Point<3>(0.5, 0.6, 0.1))
          << ", beside: " << rectangle.cuts(Point<3>(1.5, 0.5, -0.1), Point<3>(1.5, 0.5, 0.1))
          << ", same side: " << rectangle.cuts(Point<3>(0.5, 0.5, 0.1), Point<3>(0.5, 0.5, 0.2))
          << std::endl;

  // A 2D lattice 20 x 20 (dx = 1, delta = 3.015) cut along y = 10 for 0 <= x <= 20: every bond
  // between the rows below and above the line is broken, none else. Count by brute force.
  perideal::ParticleSystem<2>           particles(MPI_COMM_WORLD);
  perideal::ParticleSystem<2>::Settings settings;
  settings.spacing        = 1.;
  settings.horizon        = 3.015;
  settings.partial_volume = perideal::PartialVolume::none;
  perideal::PreCrack<2> crack;
  crack.vertices = {Point<2>(-1., 10.), Point<2>(21., 10.)};
  particles.generate(settings,
                     BoundingBox<2>(std::make_pair(Point<2>(0., 0.), Point<2>(20., 20.))),
                     [](const Point<2> &) { return true; },
                     {crack});
  unsigned long expected = 0;
  for (int a = 0; a < 400; ++a)
    for (int b = a + 1; b < 400; ++b)
      {
        const Point<2> p(a % 20 + 0.5, a / 20 + 0.5), q(b % 20 + 0.5, b / 20 + 0.5);
        if (p.distance(q) <= 3.015 && (p[1] - 10.) * (q[1] - 10.) < 0.)
          ++expected;
      }
  deallog << "broken bonds: " << perideal::n_broken_bonds(particles) << " (expected " << expected
          << ")" << std::endl;
  const auto damage     = perideal::damage_index(particles);
  double     max_damage = 0.;
  for (unsigned int i = 0; i < particles.n_owned(); ++i)
    max_damage = std::max(max_damage, damage[i]);
  deallog << "largest damage index: " << Utilities::MPI::max(max_damage, MPI_COMM_WORLD)
          << std::endl;
}
