// Regions: particles fill exactly the lattice points of a gmsh mesh's material id, a disk, a box
// and a cylinder; counts compared with the lattice points counted by hand.
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/region.h>
#include <perideal/pd/particle_system.h>

#include "../tests.h"

using namespace dealii;

template <int dim>
perideal::Region<dim>
make_region(const std::vector<std::pair<std::string, std::string>> &entries)
{
  ParameterHandler prm;
  perideal::Region<dim>::declare_parameters(prm);
  for (const auto &e : entries)
    prm.set(e.first, e.second);
  perideal::Region<dim> region;
  region.parse_parameters(prm, "test");
  return region;
}

template <int dim>
unsigned long
count_particles(const perideal::Region<dim> &region, const double dx)
{
  perideal::ParticleSystem<dim>                    particles(MPI_COMM_WORLD);
  typename perideal::ParticleSystem<dim>::Settings settings;
  settings.spacing = dx;
  settings.horizon = 3.015 * dx;
  particles.generate(settings,
                     region.bounding_box(),
                     [&](const Point<dim> &p) { return region.contains(p); },
                     {});
  return particles.n_global();
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  const std::string mesh = std::string(SOURCE_DIR) + "/../../meshes/two_material_plate.msh";

  // Material 1 is x < 0.03 of a 0.05 x 0.02 plate: with dx = 1 mm, 30 x 20 cell centres.
  const auto left = make_region<2>({{"Shape", "mesh"}, {"Mesh file", mesh}, {"Material id", "1"}});
  deallog << "mesh material 1: " << count_particles(left, 1e-3) << " (expected 600)" << std::endl;
  const auto right = make_region<2>({{"Shape", "mesh"}, {"Mesh file", mesh}, {"Material id", "2"}});
  deallog << "mesh material 2: " << count_particles(right, 1e-3) << " (expected 400)" << std::endl;

  // A box of 7 x 5 spacings.
  const auto box =
    make_region<2>({{"Shape", "box"}, {"Lower corner", "0, 0"}, {"Upper corner", "0.7, 0.5"}});
  deallog << "box: " << count_particles(box, 0.1) << " (expected 35)" << std::endl;

  // A disk of radius 1 on a lattice of spacing 0.1: the cell centres (i + 1/2) 0.1 - 1 inside
  // the circle, counted directly.
  unsigned int expected_disk = 0;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      {
        const double x = (i + 0.5) * 0.1 - 1., y = (j + 0.5) * 0.1 - 1.;
        expected_disk += (x * x + y * y <= 1.);
      }
  const auto disk = make_region<2>({{"Shape", "ball"}, {"Center", "0, 0"}, {"Radius", "1"}});
  deallog << "disk: " << count_particles(disk, 0.1) << " (expected " << expected_disk << ")"
          << std::endl;

  // A cylinder of radius 0.5 and height 1 along z, spacing 0.1: 10 layers of the disk count.
  unsigned int expected_layer = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      {
        const double x = (i + 0.5) * 0.1 - 0.5, y = (j + 0.5) * 0.1 - 0.5;
        expected_layer += (x * x + y * y <= 0.25);
      }
  const auto cylinder = make_region<3>(
    {{"Shape", "cylinder"}, {"Center", "0, 0, 0"}, {"Axis", "0, 0, 1"}, {"Radius", "0.5"}});
  deallog << "cylinder: " << count_particles(cylinder, 0.1) << " (expected " << 10 * expected_layer
          << ")" << std::endl;
}
