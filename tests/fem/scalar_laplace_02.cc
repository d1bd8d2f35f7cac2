// ---------------------------------------------------------------------
// Two materials in series, FE physics 'scalar laplace' through the problem's static path: a
// bar 0 <= x <= L = 1 m, height H = 0.1 m, thickness t = 0.01 m (a gmsh mesh written here:
// 10 x 2 cells, material id 1 (k1 = 8e10 Pa) for x < L/2, 2 (k2 = 4e10 Pa) beyond), w = 0 at
// x = 0 (boundary id 1) and at x = L (boundary id 2) either
//  (a) w = W = 1e-3 m: the flux q = k w' is the same in both materials,
//      q = W / (L/2 (1/k1 + 1/k2)) = 5.3333e7 Pa, w(L/2) = q L / (2 k1) = 3.3333e-4 m; or
//  (b) the flux k dw/dn = g = 1e7 Pa: q = g, w(L) = g L/2 (1/k1 + 1/k2) = 1.875e-4 m.
// w is piecewise linear, so Q1 holds it exactly (the interface is a mesh line). Printed: the
// largest nodal error relative to the largest value (round-off: below 1e-10), the flux
// k dw/dx of each material and its largest deviation from q relative to q (continuity of the
// flux across the interface; round-off), and the reactions of the supports, -q H t at x = 0
// (and +q H t at x = L in (a)).
// ---------------------------------------------------------------------
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <perideal/fem/physics/scalar_laplace.h>

#include "fem_tests.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  const double       L = 1., H = 0.1, t = 0.01, k1 = 8e10, k2 = 4e10;
  const unsigned int nx = 10, ny = 2;

  // A gmsh 2.2 mesh of the bar: quadrilaterals with physical ids 1 | 2, the end lines 1 and 2.
  void
  write_mesh(const std::string &file)
  {
    std::ostringstream out;
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << (nx + 1) * (ny + 1) << "\n";
    const auto node = [](const unsigned int i, const unsigned int j) {
      return j * (nx + 1) + i + 1;
    };
    for (unsigned int j = 0; j <= ny; ++j)
      for (unsigned int i = 0; i <= nx; ++i)
        out << node(i, j) << " " << L * i / nx << " " << H * j / ny << " 0\n";
    out << "$EndNodes\n$Elements\n" << 2 * ny + nx * ny << "\n";
    unsigned int id = 1;
    for (unsigned int j = 0; j < ny; ++j)
      {
        out << id++ << " 1 2 1 1 " << node(0, j) << " " << node(0, j + 1) << "\n";
        out << id++ << " 1 2 2 2 " << node(nx, j) << " " << node(nx, j + 1) << "\n";
      }
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          const unsigned int material = (i < nx / 2 ? 1 : 2);
          out << id++ << " 3 2 " << material << " " << material << " " << node(i, j) << " "
              << node(i + 1, j) << " " << node(i + 1, j + 1) << " " << node(i, j + 1) << "\n";
        }
    out << "$EndElements\n";
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(file) << out.str();
    MPI_Barrier(MPI_COMM_WORLD);
  }

  void
  run(const bool flux_at_end)
  {
    const double q = flux_at_end ? 1e7 : 1e-3 / (0.5 * L * (1. / k1 + 1. / k2));
    deallog << (flux_at_end ? "(b) flux g = 1e7 Pa at x = L" : "(a) w = 1e-3 m at x = L")
            << ": q = " << q << " Pa, w(L/2) = " << q * L / (2. * k1)
            << " m, w(L) = " << q * 0.5 * L * (1. / k1 + 1. / k2) << " m" << std::endl;
    const std::string end_condition = flux_at_end ? "      set Type = flux\n"
                                                    "      set Function = 1e7\n" :
                                                    "      set Type = value\n"
                                                    "      set Function = 1e-3\n";
    const std::string text          = fem_tests::static_problem(2, "plane stress", "0", "1e-12") +
                             "subsection Discretization\n"
                             "  set Thickness = 0.01\n"
                             "end\n"
                             "subsection Finite elements\n"
                             "  set Physics = scalar laplace\n"
                             "  set Mesh file = bar.msh\n"
                             "  subsection scalar laplace\n"
                             "    set Coefficients by material id = 1: 8e10, 2: 4e10\n"
                             "  end\n"
                             "  subsection Boundary conditions\n"
                             "    set Names = left, right\n"
                             "    subsection left\n"
                             "      set Boundary ids = 1\n"
                             "      set Type = value\n"
                             "    end\n"
                             "    subsection right\n"
                             "      set Boundary ids = 2\n" +
                             end_condition +
                             "    end\n"
                             "  end\n"
                             "end\n";
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    const auto                  w  = fem_tests::solve(problem, text);
    const auto                 &fe = problem.fe_region();
    const auto &physics            = dynamic_cast<const perideal::ScalarLaplace<2> &>(fe.physics());

    // Nodal errors, and the flux k dw/dx at the cell centres.
    const auto exact = [&](const Point<2> &x) {
      return x[0] <= 0.5 * L ? q * x[0] / k1 : q * (0.5 * L / k1 + (x[0] - 0.5 * L) / k2);
    };
    FEValues<2>               nodal(fe.get_fe_collection()[0],
                      Quadrature<2>(fe.get_fe_collection()[0].get_unit_support_points()),
                      update_values | update_quadrature_points);
    FEValues<2>               centre(fe.get_fe_collection()[0], QMidpoint<2>(), update_gradients);
    std::vector<double>       values(nodal.n_quadrature_points);
    std::vector<Tensor<1, 2>> gradient(1);
    double                    error = 0., largest = 0., flux_deviation = 0., flux[3] = {0., 0., 0.};
    for (const auto &cell : fe.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          nodal.reinit(cell);
          nodal.get_function_values(w, values);
          for (const unsigned int p : nodal.quadrature_point_indices())
            {
              error   = std::max(error, std::abs(values[p] - exact(nodal.quadrature_point(p))));
              largest = std::max(largest, std::abs(exact(nodal.quadrature_point(p))));
            }
          centre.reinit(cell);
          centre.get_function_gradients(w, gradient);
          const double k            = physics.coefficient(cell->material_id());
          flux[cell->material_id()] = k * gradient[0][0];
          flux_deviation =
            std::max(flux_deviation,
                     (std::abs(k * gradient[0][0] - q) + std::abs(k * gradient[0][1])) / q);
        }
    error          = Utilities::MPI::max(error, MPI_COMM_WORLD);
    largest        = Utilities::MPI::max(largest, MPI_COMM_WORLD);
    flux_deviation = Utilities::MPI::max(flux_deviation, MPI_COMM_WORLD);
    for (double &f : flux)
      f = Utilities::MPI::max(f, MPI_COMM_WORLD);
    const auto round_off = [](const double x) {
      return x < 1e-10 ? std::string("below 1e-10") : std::to_string(x);
    };
    deallog << "nodal error / largest value: " << round_off(error / largest) << std::endl;
    deallog << "flux k dw/dx: material 1 " << flux[1] << " Pa, material 2 " << flux[2]
            << " Pa; largest |k grad w - (q, 0)| / q: " << round_off(flux_deviation) << std::endl;

    MPI_Barrier(MPI_COMM_WORLD);
    const auto statistics = perideal_tests::read_statistics("results/statistics.csv");
    deallog << "reaction left: " << statistics.at("reaction_left_w").back()
            << " N (exact -q H t = " << -q * H * t << " N)";
    if (!flux_at_end)
      deallog << ", right: " << statistics.at("reaction_right_w").back() << " N (exact "
              << q * H * t << " N)";
    deallog << std::endl;
    const bool right_ok = flux_at_end || std::abs(statistics.at("reaction_right_w").back() -
                                                  q * H * t) < 1e-10 * q * H * t;
    deallog << "all within round-off of the exact values: "
            << (error < 1e-10 * largest && flux_deviation < 1e-10 &&
                    std::abs(statistics.at("reaction_left_w").back() + q * H * t) <
                      1e-10 * q * H * t &&
                    right_ok ?
                  "yes" :
                  "NO")
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1); // no CG iteration lines
  write_mesh("bar.msh");
  run(false);
  run(true);
}
