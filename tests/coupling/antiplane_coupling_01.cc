// ---------------------------------------------------------------------
// The scalar field through the whole coupled driver: the bond-based antiplane PD model (one
// unknown w per particle) blended with the scalar Laplace FE physics (k = mu), 2D.
//  1. A constant field is an equilibrium: no force anywhere (round-off), static and explicit.
//  2. Antiplane simple shear w = gamma x (exact for both regions; the top and bottom faces are
//     free): the ghost force at t = 0 (largest unbalanced force of the exact field, against
//     the force scale mu gamma h dx) and the displacement error of the static solve, against
//     the overlap width; both fall as the overlap widens.
//  3. An antiplane shear pulse crossing the overlaps and the PD region (explicit): its speed
//     against sqrt(mu / rho), the reflected energy fraction and the energy drift.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  using coupling_tests::numbers_of;
  using coupling_tests::ok;

  const double mu = 26e9, rho = 2700.;

  const std::string base = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Thickness       = 1e-3
  set Body            = strip
end
subsection Regions
  set Names = strip
  subsection strip
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = LENGTH, 0.02
  end
end
subsection Material
  set Model   = antiplane bond based
  set Density = 2700
  subsection antiplane bond based
    set Shear modulus = 26e9
  end
end
subsection Finite elements
  set Physics             = scalar laplace
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = CELLS, 20 : 0, 0 : LENGTH, 0.02 : true
  set Density             = 2700
  subsection scalar laplace
    set Coefficient = 26e9
  end
  subsection Boundary conditions
CONDITIONS
  end
end
subsection Coupling
  set Blending function = min(1, max(0, min((x - (LOW - WIDTH)) / WIDTH, ((HIGH + WIDTH) - x) / WIDTH)))
  set Exact displacement = EXACT
end
subsection Initial conditions
  set Displacement = INITIAL_W
  set Velocity     = INITIAL_V
end
subsection Solver
  set Type          = SOLVER
  set Linear solver = direct
end
subsection Time stepping
  set End time = END_TIME
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  // The Dirichlet data w = @p value on the ends x = 0 and x = length (boundary ids 0, 1).
  std::string
  ends(const std::string &value)
  {
    return "    set Names = ends\n"
           "    subsection ends\n"
           "      set Boundary ids = 0, 1\n"
           "      set Type         = value\n"
           "      set Function     = " +
           value + "\n    end";
  }

  // The log of a run of the coupled problem of @p values; @p inspect sees the problem after it.
  std::string
  run(const std::map<std::string, std::string>                       &values,
      const std::function<void(const perideal::CoupledProblem<2> &)> &inspect = {})
  {
    return coupling_tests::run("antiplane_coupling.prm",
                               coupling_tests::substitute(base, values),
                               inspect);
  }

  // The largest relative displacement error of FE nodes and particles, and the ghost force of
  // the exact field relative to the FE force scale (ExactError's lines).
  std::pair<double, double>
  errors(const std::string &log)
  {
    const auto displacement =
      numbers_of(log, "Displacement error (largest, relative to the largest exact value): ");
    const auto residual = numbers_of(log, "Force residual of the exact field: ");
    return {std::max(displacement[0], displacement[1]), residual.back()};
  }

  std::map<std::string, std::string>
  strip(const double width)
  {
    return {{"LENGTH", "0.1"},
            {"CELLS", "50"},
            {"LOW", "0.04"},
            {"HIGH", "0.06"},
            {"WIDTH", std::to_string(width)},
            {"INITIAL_V", "0"},
            {"END_TIME", "0"}};
  }

  void
  constant_field()
  {
    for (const std::string solver : {"static", "explicit"})
      {
        auto values           = strip(0.008);
        values["CONDITIONS"]  = ends("1e-6");
        values["EXACT"]       = solver == "static" ? "1e-6" : "";
        values["INITIAL_W"]   = "1e-6";
        values["SOLVER"]      = solver;
        values["END_TIME"]    = solver == "explicit" ? "2e-6" : "0";
        const std::string log = run(values);
        std::cout << "constant field w = 1e-6, " << solver << ": ";
        if (solver == "static")
          {
            const auto [error, ghost] = errors(log);
            std::cout << "largest displacement error / w < 1e-12 " << ok(error < 1e-12)
                      << ", force of the exact field / force scale < 1e-12 " << ok(ghost < 1e-12);
          }
        else
          std::cout << "force at t = 0 / force scale < 1e-12 "
                    << ok(numbers_of(log, "Force residual at t = 0: ").back() < 1e-12)
                    << ", largest particle displacement after 2 us / w - 1 < 1e-12 "
                    << ok(std::abs(numbers_of(log, "Max particle displacement: ")[0] / 1e-6 - 1.) <
                          1e-12);
        std::cout << std::endl;
      }
  }

  // 2. w = gamma x: ghost force and displacement error against the overlap width.
  void
  simple_shear()
  {
    std::cout << "simple shear w = 1e-3 x, static: overlap width, largest displacement error "
                 "(relative), force of the exact field (relative to the FE force scale)"
              << std::endl;
    const std::vector<double> widths{0.004, 0.008, 0.012, 0.016};
    std::vector<double>       error, ghost;
    for (const double width : widths)
      {
        auto values          = strip(width);
        values["CONDITIONS"] = ends("1e-3 * x");
        values["EXACT"]      = "1e-3 * x";
        values["INITIAL_W"]  = "0";
        values["SOLVER"]     = "static";
        const auto [e, g]    = errors(run(values));
        error.push_back(e);
        ghost.push_back(g);
        std::cout << "  " << std::setw(5) << width * 1e3 << " mm: " << std::scientific
                  << std::setprecision(2) << e << ", " << g << std::defaultfloat
                  << std::setprecision(6) << std::endl;
      }
    // The blended method's ghost force comes from the gradient of beta in the overlap: it
    // falls as 1 / width.
    bool   falling = true;
    double spread  = 0.;
    for (std::size_t k = 1; k < error.size(); ++k)
      falling = falling && error[k] < error[k - 1] && ghost[k] < ghost[k - 1];
    for (std::size_t k = 0; k < widths.size(); ++k)
      spread = std::max(spread, std::abs(ghost[k] * widths[k] / (ghost[0] * widths[0]) - 1.));
    std::cout << "  both fall as the overlap widens " << ok(falling)
              << ", ghost force times width constant within 10 % " << ok(spread < 0.1) << std::endl;
  }

  // The nodal values (x, w) of the FE field on the line y = @p y, of all ranks, sorted by x.
  std::vector<std::pair<double, double>>
  line_values(const perideal::CoupledProblem<2> &problem, const double y)
  {
    const auto                            &dofs = problem.fe_region().get_dof_handler();
    const auto                            &U    = problem.fe_displacement();
    std::vector<std::pair<double, double>> local;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        for (const unsigned int v : cell->vertex_indices())
          if (std::abs(cell->vertex(v)[1] - y) < 1e-9)
            local.emplace_back(cell->vertex(v)[0],
                               U(cell->vertex_dof_index(v, 0, cell->active_fe_index())));
    std::vector<std::pair<double, double>> all;
    for (const auto &part : Utilities::MPI::all_gather(MPI_COMM_WORLD, local))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(),
                          all.end(),
                          [](const auto &a, const auto &b) {
                            return std::abs(a.first - b.first) < 1e-9;
                          }),
              all.end());
    return all;
  }

  // 3. A Gaussian shear pulse w = A exp(-((x - x0 - c t) / s)^2) from x0 = 50 mm to the right,
  // through the overlap ramps [70, 80] and [120, 130] mm and the PD region between.
  void
  shear_wave()
  {
    const double       c = std::sqrt(mu / rho), A = 1e-6, x0 = 0.05, s = 0.012, T = 35e-6;
    std::ostringstream pulse, velocity;
    pulse << std::setprecision(17) << A << " * exp(-((x - " << x0 << ") / " << s << ")^2)";
    velocity << std::setprecision(17) << c * A * 2. / (s * s) << " * (x - " << x0
             << ") * exp(-((x - " << x0 << ") / " << s << ")^2)";
    const std::map<std::string, std::string> values{{"LENGTH", "0.2"},
                                                    {"CELLS", "200"},
                                                    {"LOW", "0.08"},
                                                    {"HIGH", "0.12"},
                                                    {"WIDTH", "0.01"},
                                                    {"CONDITIONS", "    set Names ="},
                                                    {"EXACT", ""},
                                                    {"INITIAL_W", pulse.str()},
                                                    {"INITIAL_V", velocity.str()},
                                                    {"SOLVER", "explicit"},
                                                    {"END_TIME", std::to_string(T)}};
    std::vector<std::pair<double, double>>   line;
    const std::string log = run(values, [&](const perideal::CoupledProblem<2> &problem) {
      line = line_values(problem, 0.01);
    });

    // The peak: the largest nodal value and the parabola through it and its neighbours.
    const auto   top = std::max_element(line.begin(), line.end(), [](const auto &a, const auto &b) {
      return a.second < b.second;
    });
    const double w_m = (top - 1)->second, w_0 = top->second, w_p = (top + 1)->second;
    const double h      = top->first - (top - 1)->first;
    const double x_peak = top->first + 0.5 * h * (w_m - w_p) / (w_m - 2. * w_0 + w_p);
    const double speed  = (x_peak - x0) / T;
    // What is left behind the pulse (more than 4 s behind its peak): reflections and dispersion.
    double behind = 0.;
    for (const auto &[x, w] : line)
      if (x < x_peak - 4. * s)
        behind = std::max(behind, std::abs(w));
    const double energy =
      numbers_of(log, "Kinetic energy: ")[0] + numbers_of(log, "Strain energy: ")[0];
    const double drift = numbers_of(log, "Energy error: ")[0];
    std::cout << "antiplane shear pulse, explicit, " << T * 1e6
              << " us: speed / sqrt(mu / rho) = " << std::fixed << std::setprecision(4) << speed / c
              << " (within 2 % " << ok(std::abs(speed / c - 1.) < 0.02) << "), peak " << w_0 / A
              << " of the initial amplitude" << std::endl
              << std::scientific << std::setprecision(2)
              << "  largest amplitude left behind / initial amplitude " << behind / A
              << " (reflected energy fraction below its square, " << behind * behind / (A * A)
              << "), energy drift / energy " << std::abs(drift) / energy << " (< 1e-3 "
              << ok(std::abs(drift) < 1e-3 * energy) << ")" << std::defaultfloat
              << std::setprecision(6) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  constant_field();
  simple_shear();
  shear_wave();
}
