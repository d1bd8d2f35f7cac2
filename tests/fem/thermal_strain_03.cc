// ---------------------------------------------------------------------
// FE thermal strain, constrained bodies (#39), uniform Delta T = 50 K, E = 200 GPa, nu = 0.3,
// alpha = 1.2e-5 /K, Q1. (a) A bar 0.1 m long along x (2D 0.1 x 0.02 m, 10 x 2 cells; 3D
// 0.1 x 0.02 x 0.02 m, 10 x 2 x 2 cells) whose ends are held in x and which is free laterally
// (held against rigid motions only: u_y (u_z) at the origin, u_z at (0, 0.02, 0)): the
// uniaxial stress sigma_xx = -E alpha Delta T of plane stress and 3D, and in plane strain
// (eps_zz = 0 too) sigma_xx = sigma_zz = -E alpha Delta T / (1 - nu); the other stresses 0.
// Energy per volume 1/2 E alpha^2 Delta T^2 (plane stress, 3D), E alpha^2 Delta T^2 / (1 - nu)
// (plane strain). (b) The same bodies held on every face (u = 0): sigma = -E alpha Delta T /
// (1 - nu) in the plane of plane stress, -E alpha Delta T / (1 - 2 nu) on every axis in plane
// strain and 3D, energy per volume E alpha^2 Delta T^2 / (1 - nu) (plane stress) and
// 3/2 E alpha^2 Delta T^2 / (1 - 2 nu). Printed: the largest stress error at the Gauss points
// relative to E alpha Delta T and the error of the energy 1/2 u.K.u - u.f_th + c_th relative to
// the exact one; for the bars also without the thermal load (u = 0), which then fail; and the
// quantities FERegion::write_output() writes for the plane-strain bar, with its free thermal
// strain (1 + nu) alpha Delta T against the output's thermal_strain_*.
// ---------------------------------------------------------------------
#include "thermal_strain_tests.h"

#include <fstream>

#include <tests.h>

using namespace dealii;
using namespace thermal_strain_tests;

namespace
{
  constexpr double E = 200e9, nu = 0.3, alpha = 1.2e-5, delta_T = 50.;

  // @p held: the ids of the faces held in @p components ("x" or "x, y(, z)").
  template <int dim>
  void
  run(const std::string                   &name,
      const perideal::PlanarAssumption     planar,
      const std::string                   &held,
      const std::string                   &components,
      const Supports<dim>                 &supports,
      const std::map<std::string, double> &stress,
      const double                         energy_density,
      const bool                           write = false)
  {
    const std::string mesh =
      dim == 2 ? "10, 2 : 0, 0 : 0.1, 0.02" : "10, 2, 2 : 0, 0, 0 : 0.1, 0.02, 0.02";
    auto fe = make_region<dim>("  set Generator = subdivided_hyper_rectangle\n"
                               "  set Generator arguments = " +
                                 mesh +
                                 " : true\n"
                                 "  subsection Elasticity\n"
                                 "    set Young's modulus = 200e9\n"
                                 "    set Poisson's ratio = 0.3\n"
                                 "    set Thermal expansion = 1.2e-5\n"
                                 "  end\n"
                                 "  subsection Boundary conditions\n"
                                 "    set Names = held\n"
                                 "    subsection held\n"
                                 "      set Boundary ids = " +
                                 held +
                                 "\n"
                                 "      set Components = " +
                                 components +
                                 "\n"
                                 "    end\n"
                                 "  end\n",
                               {"held"},
                               planar,
                               std::to_string(delta_T));
    if (!supports.empty())
      hold(*fe, supports, 0.02);
    FEVector f_th, zero;
    fe->initialize_vector(f_th);
    fe->initialize_vector(zero);
    fe->assemble_thermal_load(0., f_th);
    const double scale  = E * alpha * delta_T;
    const double volume = dim == 2 ? 0.1 * 0.02 : 0.1 * 0.02 * 0.02;
    const auto   u      = solve(*fe, f_th);
    deallog << name << ": stress error " << bounded(output_deviation(*fe, u, stress) / scale, 1e-10)
            << ", energy error "
            << bounded(mechanical_energy(*fe, u) / (energy_density * volume) - 1., 1e-10)
            << std::endl;
    if (write)
      {
        // The quantities FERegion::write_output() writes (their names in the XDMF file).
        std::vector<XDMFEntry> records;
        fe->write_output(".", "thermal_strain", 0, 0., u, records);
        std::ifstream file("thermal_strain.xdmf");
        std::string   line, names;
        while (std::getline(file, line))
          if (line.find("<Attribute") != std::string::npos)
            {
              const auto begin = line.find("Name=\"") + 6;
              names += " " + line.substr(begin, line.find('"', begin) - begin);
            }
        deallog << "  output:" << names << std::endl;
        // The free thermal strain of plane strain, alpha_2D Delta T = (1 + nu) alpha Delta T on
        // both in-plane axes (the 3D alpha would be off by nu).
        const double free_strain = (1. + nu) * alpha * delta_T;
        deallog << "  thermal strain error "
                << bounded(output_deviation(*fe,
                                            u,
                                            {{"thermal_strain_xx", free_strain},
                                             {"thermal_strain_yy", free_strain},
                                             {"thermal_strain_xy", 0.}}) /
                             (alpha * delta_T),
                           1e-12)
                << std::endl;
      }
    if (!supports.empty())
      deallog << "  without f_th: stress error "
              << bounded(output_deviation(*fe, solve(*fe, zero), stress) / scale, 1e-10)
              << std::endl;
  }

  // The stresses of the output named by their components: @p values for the listed ones, 0 for
  // the others.
  template <int dim>
  std::map<std::string, double>
  stresses(const std::map<std::string, double> &values)
  {
    std::map<std::string, double> result;
    for (const auto &component : dim == 2 ?
                                   std::vector<std::string>{"xx", "xy", "yy", "zz"} :
                                   std::vector<std::string>{"xx", "xy", "xz", "yy", "yz", "zz"})
      result["stress_" + component] = values.count(component) > 0 ? values.at(component) : 0.;
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  using perideal::PlanarAssumption;
  const double      s = E * alpha * delta_T, w = E * alpha * alpha * delta_T * delta_T;
  const Supports<2> bar_2d = {{Point<2>(), {1}}};
  const Supports<3> bar_3d = {{Point<3>(), {1, 2}}, {Point<3>(0., 0.02, 0.), {2}}};
  run<2>("bar, plane stress",
         PlanarAssumption::plane_stress,
         "0, 1",
         "x",
         bar_2d,
         stresses<2>({{"xx", -s}}),
         w / 2.);
  run<2>("bar, plane strain",
         PlanarAssumption::plane_strain,
         "0, 1",
         "x",
         bar_2d,
         stresses<2>({{"xx", -s / (1. - nu)}, {"zz", -s / (1. - nu)}}),
         w / (1. - nu),
         true);
  run<3>("bar, 3D",
         PlanarAssumption::three_dimensional,
         "0, 1",
         "x",
         bar_3d,
         stresses<3>({{"xx", -s}}),
         w / 2.);
  run<2>("held, plane stress",
         PlanarAssumption::plane_stress,
         "0, 1, 2, 3",
         "x, y",
         {},
         stresses<2>({{"xx", -s / (1. - nu)}, {"yy", -s / (1. - nu)}}),
         w / (1. - nu));
  const double hydrostatic = -s / (1. - 2. * nu);
  run<2>("held, plane strain",
         PlanarAssumption::plane_strain,
         "0, 1, 2, 3",
         "x, y",
         {},
         stresses<2>({{"xx", hydrostatic}, {"yy", hydrostatic}, {"zz", hydrostatic}}),
         1.5 * w / (1. - 2. * nu));
  run<3>("held, 3D",
         PlanarAssumption::three_dimensional,
         "0, 1, 2, 3, 4, 5",
         "x, y, z",
         {},
         stresses<3>({{"xx", hydrostatic}, {"yy", hydrostatic}, {"zz", hydrostatic}}),
         1.5 * w / (1. - 2. * nu));
}
