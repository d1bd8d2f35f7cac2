// ---------------------------------------------------------------------
// A coupled problem with one region empty is the other region's problem alone, through the
// coupled code path. Blending function 1 everywhere leaves no FE unknowns (all particles free);
// 0 everywhere leaves no particles. Each is run next to the same problem without the other
// region (PDProblem, FEProblem) and compared:
//  - PD alone, explicit: a plane-stress PMB plate pulled by two grips (velocity conditions),
//    every statistics column (energies, external work, reactions) and the final displacements;
//    without and with mass-proportional damping (<Time stepping/Damping> = 2e5 / s);
//  - PD alone, adaptive dynamic relaxation at tolerance 1e-8 (the pre-cracked plate below, no
//    breaking): the displacements agree to 10 x the tolerance (each run stops at its tolerance
//    on its own path);
//  - PD alone, static with bond breaking: the same plate with a central pre-crack, grips moved
//    apart in 3 load steps (the crack grows in the last); the broken bonds per step and the
//    final displacements (the reactions are not compared: the coupled solve reports those of
//    the linearized equilibrium it solves, PDProblem those of the full bond forces at that
//    solution, which differ by O(strain));
//  - FE alone, explicit: a bar clamped at one end and pulled at the other with a velocity ramp,
//    every statistics column;
//  - FE alone, static: the bar with a displacement at its end, the displacements.
// The largest difference is printed relative to the largest value of each quantity; below
// 1e-10 it is printed as round-off.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/fem/fe_problem.h>
#include <perideal/pd/pd_problem.h>

#include "coupling_tests.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
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

  // The FE region of the coupled version of the plate: no cell carries FE unknowns.
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
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 40, 4 : 0, 0 : 0.1, 0.01 : true
  FE_ONLY
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
  set Type = SOLVER
  COUPLED_ONLY
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

  // The PD part of the coupled version of the bar: no particle (beta = 0).
  const std::string fe_bar_particles = R"(
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Thickness       = 0.001
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
  set Model             = bond based
  set Planar assumption = plane stress
  set Density           = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Coupling
  set Blending function = 0
end
)";

  template <typename Problem>
  void
  parse_pd(Problem &problem, const std::string &file)
  {
    ParameterHandler first;
    first.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    perideal::RegionCollection<2>::declare_names(first);
    perideal::BoundaryConditions<2>::declare_names(first);
    perideal::ParameterUtilities::parse_partially(first, file);
    ParameterHandler prm;
    Problem::declare_parameters(prm,
                                perideal::RegionCollection<2>::parse_names(first),
                                perideal::BoundaryConditions<2>::parse_names(first));
    perideal::ParameterUtilities::parse_file(prm, file);
    problem.parse_parameters(prm);
  }

  void
  parse_fe(perideal::FEProblem<2> &problem, const std::string &file)
  {
    ParameterHandler first;
    perideal::FESolid<2>::declare_names(first);
    first.declare_entry("Dimension", "2", Patterns::Integer(2, 3), "");
    perideal::ParameterUtilities::parse_partially(first, file);
    ParameterHandler prm;
    perideal::FEProblem<2>::declare_parameters(prm, perideal::FESolid<2>::parse_names(first));
    perideal::ParameterUtilities::parse_file(prm, file);
    problem.parse_parameters(prm);
  }

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

  // Every column of @p alone that @p coupled has too (the coupled file has more), row by row.
  void
  compare_statistics(const std::string                                &what,
                     const std::map<std::string, std::vector<double>> &alone,
                     const std::map<std::string, std::vector<double>> &coupled,
                     const std::vector<std::string>                   &names)
  {
    for (const auto &name : names)
      {
        const auto &a = alone.at(name), &c = coupled.at(name);
        AssertThrow(a.size() == c.size(),
                    ExcMessage(what + ": " + std::to_string(a.size()) + " rows against " +
                               std::to_string(c.size())));
        double difference = 0., size = 0.;
        for (unsigned int k = 0; k < a.size(); ++k)
          {
            difference = std::max(difference, std::abs(a[k] - c[k]));
            size       = std::max(size, std::abs(a[k]));
          }
        std::cout << what << ", " << name << " (" << a.size()
                  << " rows): largest difference relative to the largest value: "
                  << format(size > 0. ? difference / size : difference) << std::endl;
      }
  }

  enum class Run
  {
    explicit_dynamics,
    explicit_damped,
    static_solve,
    relaxation
  };

  void
  pd_alone(const Run run)
  {
    const bool explicit_dynamics = run == Run::explicit_dynamics || run == Run::explicit_damped;
    const std::string what =
      std::string("FE region empty, ") +
      (run == Run::explicit_dynamics ? "explicit" :
       run == Run::explicit_damped   ? "explicit with damping" :
       run == Run::static_solve      ? "static with bond breaking" :
                                       "adaptive dynamic relaxation (tolerance 1e-8)");
    std::map<std::string, std::string> values{{"CRACKS", ""},
                                              {"DAMAGE", "none"},
                                              {"TYPE", "velocity"},
                                              {"PULL", "10"},
                                              {"SOLVER", "explicit"},
                                              {"DAMPING",
                                               run == Run::explicit_damped ? "2e5" : "0"}};
    if (!explicit_dynamics)
      values = {{"CRACKS", "0.0035, 0.005 : 0.0065, 0.005"},
                {"DAMAGE", run == Run::static_solve ? "critical stretch" : "none"},
                {"TYPE", "displacement"},
                {"PULL", "2.25e-6"},
                {"SOLVER", run == Run::static_solve ? "static" : "adaptive dynamic relaxation"},
                {"DAMPING", "0"}};

    std::ostringstream log_alone, log_coupled;
    values["DIRECTORY"] = "pd_alone";
    coupling_tests::write_file("pd_alone.prm", coupling_tests::substitute(pd_plate, values));
    perideal::PDProblem<2> alone(MPI_COMM_WORLD, log_alone);
    parse_pd(alone, "pd_alone.prm");
    alone.setup();
    alone.run();

    values["DIRECTORY"] = "pd_coupled";
    coupling_tests::write_file("pd_coupled.prm",
                               coupling_tests::substitute(pd_plate, values) + pd_plate_mesh);
    perideal::CoupledProblem<2> coupled(MPI_COMM_WORLD, log_coupled);
    coupling_tests::parse(coupled, "pd_coupled.prm");
    coupled.setup();
    coupled.run();

    MPI_Barrier(MPI_COMM_WORLD);
    const auto a = perideal_tests::read_statistics("pd_alone/statistics.csv");
    const auto c = perideal_tests::read_statistics("pd_coupled/statistics.csv");
    if (explicit_dynamics)
      compare_statistics(what,
                         a,
                         c,
                         {"time",
                          "kinetic_energy",
                          "strain_energy",
                          "external_work",
                          "reaction_pull top_y",
                          "reaction_pull bottom_y"});
    else if (run == Run::static_solve)
      {
        for (const auto &[name, table] :
             {std::make_pair("alone", &a), std::make_pair("coupled", &c)})
          {
            std::cout << what << ", broken bonds after load steps 0 (the pre-crack) to 3, " << name
                      << ":";
            for (const double n : table->at("broken_bonds"))
              std::cout << " " << n;
            std::cout << std::endl;
          }
        AssertThrow(a.at("broken_bonds") == c.at("broken_bonds"),
                    ExcMessage("The broken bonds differ."));
      }
    // Relaxation stops at its tolerance, each run on its own path: the displacements agree
    // to about the tolerance, not to round-off.
    const double du    = relative_difference(alone.displacement(), coupled.particle_displacement());
    const double bound = run == Run::relaxation ? 1e-7 : 1e-10;
    std::cout << what << ", final particle displacements: largest difference relative to the "
              << "largest displacement: "
              << (run == Run::relaxation ?
                    (du < bound ? "below 1e-7 (10 x the tolerance)" : format(du)) :
                    format(du))
              << std::endl;
    AssertThrow(du < bound, ExcMessage(what + ": the displacements differ."));
  }

  void
  fe_alone(const bool explicit_dynamics)
  {
    const std::string what =
      explicit_dynamics ? "PD region empty, explicit" : "PD region empty, static";
    std::map<std::string, std::string> values{{"TYPE", "velocity"},
                                              {"PULL", "if(t < 5e-6, t / 5e-6, 1)"},
                                              {"SOLVER", "explicit"}};
    if (!explicit_dynamics)
      values = {{"TYPE", "displacement"}, {"PULL", "1e-5"}, {"SOLVER", "static"}};

    std::ostringstream log_alone, log_coupled;
    values["DIRECTORY"] = "fe_alone";
    // The same CG tolerance: <Finite elements/Solver tolerance> alone, <Solver/Tolerance>
    // coupled; the planar assumption and thickness come from <Material> and <Discretization>
    // there.
    values["FE_ONLY"]      = "set Planar assumption = plane stress\n  set Thickness = 0.001\n"
                             "  set Solver tolerance = 1e-12";
    values["COUPLED_ONLY"] = "";
    coupling_tests::write_file("fe_alone.prm", coupling_tests::substitute(fe_bar, values));
    perideal::FEProblem<2> alone(MPI_COMM_WORLD, log_alone);
    parse_fe(alone, "fe_alone.prm");
    alone.setup();
    alone.run();

    values["DIRECTORY"]    = "fe_coupled";
    values["FE_ONLY"]      = "";
    values["COUPLED_ONLY"] = "set Tolerance = 1e-12";
    coupling_tests::write_file("fe_coupled.prm",
                               coupling_tests::substitute(fe_bar, values) + fe_bar_particles);
    perideal::CoupledProblem<2> coupled(MPI_COMM_WORLD, log_coupled);
    coupling_tests::parse(coupled, "fe_coupled.prm");
    coupled.setup();
    coupled.run();

    MPI_Barrier(MPI_COMM_WORLD);
    if (explicit_dynamics)
      compare_statistics(what,
                         perideal_tests::read_statistics("fe_alone/statistics.csv"),
                         perideal_tests::read_statistics("fe_coupled/statistics.csv"),
                         {"time",
                          "kinetic_energy",
                          "strain_energy",
                          "external_work",
                          "reaction_clamp_x",
                          "reaction_pull_x"});
    else
      {
        const double du = relative_difference(alone.solid().solution(), coupled.fe_displacement());
        std::cout << what << ", FE displacements: largest difference relative to the largest "
                  << "displacement: " << format(du) << std::endl;
        AssertThrow(du < 1e-10, ExcMessage(what + ": the displacements differ."));
      }
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
