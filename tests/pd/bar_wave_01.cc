// Validation: a long smooth pulse in a free 2D plane-stress strip travels at the bar speed
// sqrt(E/rho) within 2 %, for bond-based PMB (nu = 1/3) and the LPS (nu = 0.3), both with surface
// correction. Full study and the width dependence: doc/benchmarks/bar_wave/README.md.
//
// Initial state: the right-going bar wave u_x = A g(x - x0), v_x = -c0 A g'(x - x0), with the
// Poisson contraction u_y = -nu du_x/dx (y - W/2), v_y = -nu dv_x/dx (y - W/2), g Gaussian of
// width w. For any linear dispersion relation omega(k), the centroid of the (cross-section
// summed) displacement of a one-directional wave moves at d omega/dk at k = 0, the long-wave
// speed, so the lattice and horizon dispersion do not bias the measurement. If the PD bar speed c
// differs from c0, the initial state also sends a small left-going pulse of relative size
// (1 - c0/c)/2, which the measurement window x > x0 + c0 T/2 leaves out; the displacement
// carried by the right-going part, (1 + c0/c)/2, gives a second, independent estimate of c.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <perideal/coupling/coupled_problem.h>

#include "../tests.h"
#include "pd_tests.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace
{
  struct Strip
  {
    std::string model;     // "bond based" or "linear peridynamic solid"
    double      nu;        // Poisson's ratio of the model
    double      dx;        // lattice spacing [m]
    double      width;     // W [m]
    std::string directory; // output directory
    double      tolerance; // accepted |speed / sqrt(E/rho) - 1|
  };

  constexpr double E = 200e9, rho = 8000., amplitude = 1e-6;
  constexpr double horizon_factor = 3.015;
  constexpr double pulse_width = 0.06, x0 = 3 * pulse_width, end_time = 6e-5;

  std::string
  number(const double x)
  {
    std::ostringstream s;
    s << std::setprecision(17) << x;
    return s.str();
  }

  void
  run_strip(const Strip &strip)
  {
    using namespace dealii;
    const double c0     = std::sqrt(E / rho);
    const double length = x0 + c0 * end_time + 3.5 * pulse_width;
    const double yc     = 0.5 * strip.width;

    // g = exp(-((x - x0)/w)^2); g' = -2 (x - x0)/w^2 g; g'' = -(2/w^2)(1 - 2((x - x0)/w)^2) g.
    const std::string xi = "((x-" + number(x0) + ")/" + number(pulse_width) + ")";
    const std::string g  = "exp(-" + xi + "^2)";
    const std::string w2 = number(pulse_width * pulse_width);
    const std::string A = number(amplitude), C = number(c0), NU = number(strip.nu);
    const std::string dg      = "(-2*(x-" + number(x0) + ")/" + w2 + "*" + g + ")";
    const std::string ddg     = "(-(2/" + w2 + ")*(1-2*" + xi + "^2)*" + g + ")";
    const std::string lateral = "(y-" + number(yc) + ")";

    std::ostringstream text;
    text << "subsection Discretization\n"
         << "  set Lattice spacing = " << number(strip.dx) << "\n"
         << "  set Horizon factor = " << horizon_factor << "\n"
         << "  set Thickness = 1e-3\n"
         << "  set Body = bar\n"
         << "end\n"
         << "subsection Regions\n"
         << "  set Names = bar\n"
         << "  subsection bar\n"
         << "    set Lower corner = 0, 0\n"
         << "    set Upper corner = " << number(length) << ", " << number(strip.width) << "\n"
         << "  end\n"
         << "end\n"
         << "subsection Material\n"
         << "  set Model = " << strip.model << "\n"
         << "  set Density = " << rho << "\n"
         << "  subsection bond based\n"
         << "    set Young's modulus = " << E << "\n"
         << "  end\n"
         << "  subsection linear peridynamic solid\n"
         << "    set Young's modulus = " << E << "\n"
         << "    set Poisson's ratio = " << number(strip.nu) << "\n"
         << "  end\n"
         << "end\n"
         << "subsection Initial conditions\n"
         << "  set Displacement = " << A << "*" << g << "; -" << NU << "*" << A << "*" << dg << "*"
         << lateral << "\n"
         << "  set Velocity = -" << C << "*" << A << "*" << dg << "; " << NU << "*" << C << "*" << A
         << "*" << ddg << "*" << lateral << "\n"
         << "end\n"
         << "subsection Time stepping\n"
         << "  set End time = " << number(end_time) << "\n"
         << "end\n"
         << "subsection Output\n"
         << "  set Directory = " << strip.directory << "\n"
         << "  set Statistics interval = 1000\n"
         << "  set Write HDF5 = false\n"
         << "  set Progress = false\n"
         << "end\n";

    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    pd_tests::parse_problem(problem, text.str(), {"bar"});
    problem.setup();
    problem.run();

    const auto  &particles = problem.particles();
    const auto  &x         = particles.positions();
    const auto  &u         = problem.particle_displacement();
    const double cut       = x0 + 0.5 * c0 * end_time;
    double       sums[3]   = {0., 0., 0.}; // sum u_x (window), sum x u_x (window), sum u_x(0)
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      {
        const double ux = u.local_element(2 * i);
        const double s  = (x[i][0] - x0) / pulse_width;
        sums[2] += amplitude * std::exp(-s * s);
        if (x[i][0] > cut)
          {
            sums[0] += ux;
            sums[1] += x[i][0] * ux;
          }
      }
    Utilities::MPI::sum(ArrayView<const double>(sums, 3),
                        MPI_COMM_WORLD,
                        ArrayView<double>(sums, 3));
    const double centroid        = sums[1] / sums[0];
    const double speed_ratio     = (centroid - x0) / end_time / c0;
    const double right_part      = sums[0] / sums[2];
    const double amplitude_ratio = 1. / (2. * right_part - 1.);

    const bool pass = std::abs(speed_ratio - 1.) < strip.tolerance &&
                      std::abs(amplitude_ratio - 1.) < strip.tolerance;
    std::ostringstream line;
    line << strip.model << ", nu = " << std::setprecision(3) << strip.nu << ", strip "
         << std::llround(length / strip.dx) << " x " << std::llround(strip.width / strip.dx)
         << " particles, W/delta = " << strip.width / (horizon_factor * strip.dx)
         << ", pulse width w/delta = " << pulse_width / (horizon_factor * strip.dx) << "\n"
         << std::fixed << "  centroid speed / sqrt(E/rho) = " << speed_ratio << "\n"
         << "  right-going part " << right_part << " -> speed / sqrt(E/rho) = " << amplitude_ratio
         << "\n"
         << "  within " << std::setprecision(0) << 100. * strip.tolerance
         << " %: " << (pass ? "yes" : "NO");
    std::istringstream lines(line.str());
    for (std::string text; std::getline(lines, text);)
      deallog << text << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();

  // Both models with the default partial volume ('book') and surface correction. The LPS strip
  // is stiffer near its free edges (the dilatation of particles within delta of an edge is
  // overestimated; the excess grows like delta/W), so it is twice as wide in horizons.
  run_strip({"bond based", 1. / 3., 1e-3, 0.02, "output_pmb", 0.02});
  run_strip({"linear peridynamic solid", 0.3, 0.5e-3, 0.02, "output_lps", 0.02});
}
