// ---------------------------------------------------------------------
// <Coupling/Adaptive region/Seed shape>: a cylinder seed (3D, axis parallel to z) gives the
// same beta at every depth, 1 within the core radius R of the axis in the x-y plane, the linear
// ramp clamp((R + w - r) / w, 0, 1) of the in-plane distance r outside it; a ball seed at the
// same point falls off with the 3D distance. within_reach() and seed_distance() follow the
// shape. 'cylinder' in 2D is refused, naming the entry.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/adaptive_region.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <tests.h>

using namespace dealii;

namespace
{
  // R = 5 mm, w = 3 mm, horizon 1 mm, one seed at (50, 25, 4.5) mm.
  template <int dim>
  void
  parse(perideal::AdaptiveRegion<dim> &region, const std::string &shape, const std::string &seed)
  {
    ParameterHandler prm;
    perideal::AdaptiveRegion<dim>::declare_parameters(prm);
    prm.parse_input_from_string("subsection Adaptive region\n"
                                "  set Criterion       = damage\n"
                                "  set Seed shape      = " +
                                shape +
                                "\n"
                                "  set Damage distance = 0.002\n"
                                "  set Core radius     = 0.005\n"
                                "  set Ramp width      = 0.003\n"
                                "  set Initial seeds   = " +
                                seed + "\nend\n");
    region.parse_parameters(prm, 1e-3);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  perideal::AdaptiveRegion<3> cylinder, ball;
  parse(cylinder, "cylinder", "0.05, 0.025, 0.0045");
  parse(ball, "ball", "0.05, 0.025, 0.0045");
  deallog << "cylinder: shape is cylinder "
          << (cylinder.seed_shape() == perideal::AdaptiveRegion<3>::SeedShape::cylinder)
          << ", ball: shape is ball "
          << (ball.seed_shape() == perideal::AdaptiveRegion<3>::SeedShape::ball) << std::endl;

  // In-plane distances r from the axis (the 4 mm point inside the core, 6.5 mm half-way up the
  // ramp, 9.5 mm beyond it and beyond the reach R + w + 1 mm) at depths from one face to the other
  // and beyond the 9 mm plate.
  const double R = 0.005, w = 0.003;
  for (const double r : {0.004, 0.0065, 0.0095})
    for (const double z : {0., 0.0045, 0.009, 0.1})
      {
        const Point<3> x(0.05 + r * 0.6, 0.025 + r * 0.8, z);
        const double   expected = std::clamp((R + w - r) / w, 0., 1.);
        const double   d3       = std::hypot(r, z - 0.0045);
        deallog << "r = " << r * 1e3 << " mm, z = " << z * 1e3
                << " mm: cylinder beta = " << cylinder.blending(x) << " (expected " << expected
                << "), distance " << cylinder.seed_distance(x, cylinder.seed_points()[0]) * 1e3
                << " mm, within reach 1 mm " << cylinder.within_reach(x, 0.001)
                << "; ball beta = " << ball.blending(x) << " (expected "
                << std::clamp((R + w - d3) / w, 0., 1.) << "), distance "
                << ball.seed_distance(x, ball.seed_points()[0]) * 1e3 << " mm, within reach 1 mm "
                << ball.within_reach(x, 0.001) << std::endl;
        AssertThrow(std::abs(cylinder.blending(x) - expected) < 1e-12, ExcInternalError());
        AssertThrow(std::abs(ball.blending(x) - std::clamp((R + w - d3) / w, 0., 1.)) < 1e-12,
                    ExcInternalError());
        AssertThrow(cylinder.within_reach(x, 0.001) == (r < R + w + 0.001), ExcInternalError());
        AssertThrow(ball.within_reach(x, 0.001) == (d3 < R + w + 0.001), ExcInternalError());
      }

  // A seed given at another depth is the same cylinder.
  perideal::AdaptiveRegion<3> deep;
  parse(deep, "cylinder", "0.05, 0.025, 0.5");
  deallog << "seed at z = 0.5 m, point at (53, 28, 0) mm: beta "
          << deep.blending({0.053, 0.028, 0.}) << " = " << cylinder.blending({0.053, 0.028, 0.})
          << std::endl;

  // 2D refuses the cylinder.
  try
    {
      perideal::AdaptiveRegion<2> plane;
      parse(plane, "cylinder", "0.05, 0.025");
      deallog << "2D cylinder: accepted" << std::endl;
    }
  catch (const ExceptionBase &exc)
    {
      deallog << "2D cylinder: " << perideal_tests::exception_text(exc) << std::endl;
    }
}
