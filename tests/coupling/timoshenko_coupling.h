// The Timoshenko-bond model (rotations) blended with linear elasticity (issue #14, sec. 2): the
// inputs and helpers of the static patch tests timoshenko_coupling_01 (2D), _02 and _03 (3D).
#ifndef perideal_tests_coupling_timoshenko_coupling_h
#define perideal_tests_coupling_timoshenko_coupling_h

#include <deal.II/base/mpi.h>

#include <perideal/coupling/coupled_problem.h>

#include "../tests.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  using dealii::deallog;
  const MPI_Comm comm = MPI_COMM_WORLD;

  const std::string input_2d = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Thickness       = 1e-3
  set Body            = plate
end
subsection Regions
  set Names = plate
  subsection plate
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.06, 0.06
  end
end
subsection Material
  set Model   = timoshenko bond based
  set Density = 7800
  subsection timoshenko bond based
    set Young's modulus = 200e9
    set Poisson's ratio = NU
  end
end
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 30, 30 : 0, 0 : 0.06, 0.06 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = NU
  end
  subsection Boundary conditions
    set Names = boundary
    subsection boundary
      set Boundary ids = 0, 1, 2, 3
      set Function     = UX; UY
    end
  end
end
subsection Coupling
  set Blending function  = min(1, max(0, min(min((x - 0.02 + WIDTH) / WIDTH, (0.04 + WIDTH - x) / WIDTH), min((y - 0.02 + WIDTH) / WIDTH, (0.04 + WIDTH - y) / WIDTH))))
  set Exact displacement = UX; UY; RZ
end
subsection Solver
  set Type          = static
  set Linear solver = direct
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  const std::string input_3d = R"(
set Dimension = 3
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Body            = cube
end
subsection Regions
  set Names = cube
  subsection cube
    set Shape        = box
    set Lower corner = 0, 0, 0
    set Upper corner = 0.024, 0.024, 0.024
  end
end
subsection Material
  set Model   = timoshenko bond based
  set Density = 7800
  subsection timoshenko bond based
    set Young's modulus = 200e9
    set Poisson's ratio = 0.2
  end
end
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 6, 6, 6 : 0, 0, 0 : 0.024, 0.024, 0.024 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.2
  end
  subsection Boundary conditions
    set Names = boundary
    subsection boundary
      set Boundary ids = 0, 1, 2, 3, 4, 5
      set Function     = FIELD3
    end
  end
end
subsection Coupling
  set Blending function  = min(1, max(0, min(min(min((x - 0.004) / 0.004, (0.020 - x) / 0.004), min((y - 0.004) / 0.004, (0.020 - y) / 0.004)), min((z - 0.004) / 0.004, (0.020 - z) / 0.004))))
  set Exact displacement = FIELD3; ROTATION3
end
subsection Solver
  set Type          = static
  set Linear solver = cg amg
  set Tolerance     = 1e-12
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)";

  template <int dim>
  std::string
  run(std::string text, const std::vector<std::pair<std::string, std::string>> &values)
  {
    for (const auto &[key, value] : values)
      while (text.find(key) != std::string::npos)
        text.replace(text.find(key), key.size(), value);
    std::ostringstream            log;
    perideal::CoupledProblem<dim> problem(comm, log);
    dealii::ParameterHandler      prm;
    perideal::CoupledProblem<dim>::declare_parameters(prm,
                                                      {dim == 2 ? "plate" : "cube"},
                                                      {},
                                                      {"boundary"});
    prm.parse_input_from_string(text);
    problem.parse_parameters(prm);
    problem.setup();
    problem.run();
    return dealii::Utilities::MPI::broadcast(comm, log.str(), 0);
  }

  double
  number_after(const std::string &log, const std::string &key)
  {
    const auto at = log.find(key);
    return at == std::string::npos ? std::nan("") : std::stod(log.substr(at + key.size()));
  }

  const char *
  ok(const bool condition)
  {
    return condition ? "ok" : "FAILED";
  }

  void
  report(const std::string &name, const std::string &log, const bool rigid)
  {
    const double fe =
      number_after(log,
                   "Displacement error (largest, relative to the largest exact value): FE nodes ");
    const double particles = number_after(log, ", particles ");
    const double ghost     = number_after(log, "relative to the FE internal-force scale: ");
    const double energy    = number_after(log, "(relative ");
    deallog << name << ": ";
    if (rigid)
      deallog << "errors of FE nodes and particles (u and theta) below 1e-10 "
              << ok(fe < 1e-10 && particles < 1e-10) << std::endl;
    else
      deallog << std::setprecision(2) << "ghost force " << ghost << ", largest error FE " << fe
              << ", particles (u and theta) " << particles << "; energy balance below 1e-10 "
              << ok(std::abs(energy) < 1e-10) << std::endl;
  }
} // namespace

#endif
