// ---------------------------------------------------------------------
// Every run goes through CoupledProblem. A problem with one region only (no mesh: particles
// only; no <Discretization/Body>: FE only) is the coupled problem with that region empty, and
// gives the same numbers as a coupled file whose blending function empties the region: 1
// everywhere on a mesh (no FE unknowns, all particles free) or 0 everywhere on a body (no
// particles). Compared, on 1 and 2 ranks:
//  - particles only, explicit: a plane-stress PMB plate pulled by two grips (velocity
//    conditions), every statistics column (energies, external work, reactions) and the final
//    displacements; without and with mass-proportional damping (<Time stepping/Damping> =
//    2e5 / s);
//  - particles only, adaptive dynamic relaxation at tolerance 1e-8 (the pre-cracked plate
//    below, no breaking) and static with bond breaking (the same plate, critical stretch, grips
//    moved apart in 3 load steps; the crack grows in the last): every statistics column (broken
//    bonds per step, reactions) and the final displacements;
//  - FE only, explicit: a bar clamped at one end and pulled at the other with a velocity ramp,
//    every statistics column;
//  - FE only, static: the bar with a displacement at its end, the displacements and reactions.
// The largest difference is printed relative to the largest value of each quantity; below
// 1e-10 it is printed as round-off, and more fails the test.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  const std::string pd_plate = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 2.5e-4
  set Horizon factor  = 4
  set Thickness       = 1e-4
  set Body            = plate, top grip, bottom grip
end
subsection Regions
  set Names = plate, top grip, bottom grip
  subsection plate
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.01, 0.01
  end
  subsection top grip
    set Shape        = box
    set Lower corner = 0, 0.01
    set Upper corner = 0.01, 0.011
  end
  subsection bottom grip
    set Shape        = box
    set Lower corner = 0, -0.001
    set Upper corner = 0.01, 0
  end
end
subsection Pre-cracks
  set Cracks = CRACKS
end
subsection Material
  set Model        = bond based
  set Density      = 7800
  set Damage model = DAMAGE
  subsection critical stretch
    set Critical stretch = 1.2e-3
  end
  subsection bond based
    set Young's modulus = 192e9
  end
end
subsection Boundary conditions
  set Names = pull top, pull bottom
  subsection pull top
    set Region     = top grip
    set Type       = TYPE
    set Components = x, y
    set Function   = 0; PULL
  end
  subsection pull bottom
    set Region     = bottom grip
    set Type       = TYPE
    set Components = x, y
    set Function   = 0; -PULL
  end
end
subsection Solver
  set Type          = SOLVER
  set Linear solver = direct
  set Load steps    = 3
  set Tolerance     = 1e-8
end
subsection Time stepping
  set End time = 4e-6
  set Damping  = DAMPING
end
subsection Output
  set Directory  = DIRECTORY
  set Write HDF5 = false
  set Progress   = false
end
)";

  // A mesh for the plate on which no cell carries FE unknowns.
  const std::string pd_plate_mesh = R"(
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 10, 12 : -0.001, -0.001 : 0.011, 0.011 : false
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 192e9
    set Poisson's ratio = 0.3333333333333333
  end
end
subsection Coupling
  set Blending function = 1
end
)";

  const std::string fe_bar = R"(
set Dimension = 2
subsection Discretization
  set Thickness = 0.001
end
subsection Material
  set Planar assumption = plane stress
end
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 40, 4 : 0, 0 : 0.1, 0.01 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3
  end
  subsection Boundary conditions
    set Names = clamp, pull
    subsection clamp
      set Boundary ids = 0
      set Components   = x, y
      set Function     = 0; 0
    end
    subsection pull
      set Boundary ids = 1
      set Type         = TYPE
      set Components   = x
      set Function     = PULL
    end
  end
end
subsection Solver
  set Type      = SOLVER
  set Tolerance = 1e-12
end
subsection Time stepping
  set End time = 3e-5
end
subsection Output
  set Directory           = DIRECTORY
  set Statistics interval = 1
  set Progress   = false
end
)";

  // Particles for the bar on which beta = 0: none.
  const std::string fe_bar_particles = R"(
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Body            = bar
end
subsection Regions
  set Names = bar
  subsection bar
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.1, 0.01
  end
end
subsection Material
  set Model   = bond based
  set Density = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Coupling
  set Blending function = 0
end
)";

  // The largest difference between two sets of values relative to their largest magnitude,
  // over all ranks.
  template <typename VectorType>
  double
  relative_difference(const VectorType &a, const VectorType &b)
  {
    AssertThrow(a.locally_owned_size() == b.locally_owned_size(), ExcInternalError());
    double difference = 0., size = 0.;
    for (unsigned int k = 0; k < a.locally_owned_size(); ++k)
      {
        difference = std::max(difference, std::abs(a.local_element(k) - b.local_element(k)));
        size       = std::max(size, std::abs(a.local_element(k)));
      }
    difference = Utilities::MPI::max(difference, MPI_COMM_WORLD);
    size       = Utilities::MPI::max(size, MPI_COMM_WORLD);
    return size > 0. ? difference / size : difference;
  }

  std::string
  format(const double relative)
  {
    if (relative < 1e-10)
      return "round-off (< 1e-10)";
    std::ostringstream text;
    text << std::scientific << std::setprecision(2) << relative;
    return text.str();
  }

  // Every column, row by row; each difference above round-off fails.
  void
  compare_statistics(const std::string                                &what,
                     const std::map<std::string, std::vector<double>> &alone,
                     const std::map<std::string, std::vector<double>> &emptied)
  {
    AssertThrow(alone.size() == emptied.size(), ExcMessage(what + ": the columns differ."));
    double largest = 0.;
    for (const auto &[name, a] : alone)
      {
        const auto &c = emptied.at(name);
        AssertThrow(a.size() == c.size(),
                    ExcMessage(what + ": " + std::to_string(a.size()) + " rows against " +
                               std::to_string(c.size())));
        double difference = 0., size = 0.;
        for (unsigned int k = 0; k < a.size(); ++k)
          {
            difference = std::max(difference, std::abs(a[k] - c[k]));
            size       = std::max(size, std::abs(a[k]));
          }
        largest = std::max(largest, size > 0. ? difference / size : difference);
      }
    std::cout << what << ", " << alone.size() << " statistics columns, "
              << alone.begin()->second.size()
              << " rows: largest difference relative to the largest value of its column: "
              << format(largest) << std::endl;
    AssertThrow(largest < 1e-10, ExcMessage(what + ": the statistics differ."));
  }

  // The one-region problem and the coupled problem that empties the other region, both run
  // through CoupledProblem (as perideal-solid does) from <name>_alone.prm and
  // <name>_emptied.prm (output in the directories of the same names), with their statistics.
  struct Runs
  {
    std::unique_ptr<perideal::CoupledProblem<2>> alone, emptied;
    std::map<std::string, std::vector<double>>   alone_statistics, emptied_statistics;
  };

  Runs
  run_both(const std::string                  &name,
           const std::string                  &text,
           const std::string                  &emptying_text,
           std::map<std::string, std::string> &values)
  {
    Runs                                                runs;
    std::ostringstream                                  log;
    std::unique_ptr<perideal::CoupledProblem<2>> *const problems[] = {&runs.alone, &runs.emptied};
    const std::string                                   kinds[]    = {"alone", "emptied"};
    for (unsigned int k = 0; k < 2; ++k)
      {
        values["DIRECTORY"]    = name + "_" + kinds[k];
        const std::string file = values["DIRECTORY"] + ".prm";
        coupling_tests::write_file(file,
                                   coupling_tests::substitute(text, values) +
                                     (k == 1 ? emptying_text : ""));
        *problems[k] = std::make_unique<perideal::CoupledProblem<2>>(MPI_COMM_WORLD, log);
        coupling_tests::parse(**problems[k], file);
        (*problems[k])->setup();
        (*problems[k])->run();
      }
    MPI_Barrier(MPI_COMM_WORLD);
    runs.alone_statistics   = perideal_tests::read_statistics(name + "_alone/statistics.csv");
    runs.emptied_statistics = perideal_tests::read_statistics(name + "_emptied/statistics.csv");
    return runs;
  }

  // The final displacements (@p kind: "particle" or "FE") of both runs, to round-off.
  template <typename VectorType>
  void
  compare_displacements(const std::string &what,
                        const std::string &kind,
                        const VectorType  &alone,
                        const VectorType  &emptied)
  {
    const double du = relative_difference(alone, emptied);
    std::cout << what << ", final " << kind << " displacements: largest difference relative to "
              << "the largest displacement: " << format(du) << std::endl;
    AssertThrow(du < 1e-10, ExcMessage(what + ": the displacements differ."));
  }

  enum class Run
  {
    explicit_dynamics,
    explicit_damped,
    static_solve,
    relaxation
  };

  void
  pd_alone(const Run run_type)
  {
    const bool explicit_dynamics =
      run_type == Run::explicit_dynamics || run_type == Run::explicit_damped;
    const std::string what =
      std::string("Particles only, ") +
      (run_type == Run::explicit_dynamics ? "explicit" :
       run_type == Run::explicit_damped   ? "explicit with damping" :
       run_type == Run::static_solve      ? "static with bond breaking" :
                                            "adaptive dynamic relaxation (tolerance 1e-8)");
    std::map<std::string, std::string> values{{"CRACKS", ""},
                                              {"DAMAGE", "none"},
                                              {"TYPE", "velocity"},
                                              {"PULL", "10"},
                                              {"SOLVER", "explicit"},
                                              {"DAMPING",
                                               run_type == Run::explicit_damped ? "2e5" : "0"}};
    if (!explicit_dynamics)
      values = {{"CRACKS", "0.0035, 0.005 : 0.0065, 0.005"},
                {"DAMAGE", run_type == Run::static_solve ? "critical stretch" : "none"},
                {"TYPE", "displacement"},
                {"PULL", "2.25e-6"},
                {"SOLVER",
                 run_type == Run::static_solve ? "static" : "adaptive dynamic relaxation"},
                {"DAMPING", "0"}};

    const Runs runs = run_both("pd", pd_plate, pd_plate_mesh, values);
    if (run_type == Run::static_solve)
      {
        std::cout << what << ", broken bonds after load steps 0 (the pre-crack) to 3:";
        for (const double n : runs.alone_statistics.at("broken_bonds"))
          std::cout << " " << n;
        std::cout << std::endl;
      }
    compare_statistics(what, runs.alone_statistics, runs.emptied_statistics);
    compare_displacements(what,
                          "particle",
                          runs.alone->particle_displacement(),
                          runs.emptied->particle_displacement());
  }

  void
  fe_alone(const bool explicit_dynamics)
  {
    const std::string what = explicit_dynamics ? "FE only, explicit" : "FE only, static";
    std::map<std::string, std::string> values{{"TYPE", "velocity"},
                                              {"PULL", "if(t < 5e-6, t / 5e-6, 1)"},
                                              {"SOLVER", "explicit"}};
    if (!explicit_dynamics)
      values = {{"TYPE", "displacement"}, {"PULL", "1e-5"}, {"SOLVER", "static"}};

    const Runs runs = run_both("fe", fe_bar, fe_bar_particles, values);
    compare_statistics(what, runs.alone_statistics, runs.emptied_statistics);
    compare_displacements(what,
                          "FE",
                          runs.alone->fe_displacement(),
                          runs.emptied->fe_displacement());
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  pd_alone(Run::explicit_dynamics);
  pd_alone(Run::explicit_damped);
  pd_alone(Run::static_solve);
  pd_alone(Run::relaxation);
  fe_alone(true);
  fe_alone(false);
}
