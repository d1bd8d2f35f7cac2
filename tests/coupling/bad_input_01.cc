// ---------------------------------------------------------------------
// Bad input of a coupled problem: a valid file is accepted; each bad case stops with a message
// naming the entry, before the time stepping starts: a blending function outside [0, 1], an overlap
// narrower than the horizon, particles outside the mesh, a PD condition on particles that follow
// the FE field, two FE conditions on the same component of a boundary, an FE condition on a
// boundary id the mesh does not have or on a boundary without FE unknowns, a body force in <Finite
// elements> (a coupled run takes the body force of <Body force> only), a PD condition on a
// component the field does not have, a moment condition on a model without rotations, an FE
// physics of another field than the material model's (found when the file is read, before any
// output: its output directory does not exist afterwards; the FE condition without a <Type>
// takes the default, valid for the scalar field too), a malformed expression in a condition's
// function (found when the file is read), an FE material shared with a particle model that has
// no elastic constants of its own or that is a polycrystal (grains). A state-based model is
// accepted (its energy is blended through the particles' weights). Quasi-static solves (run as
// well): a valid file is solved statically and by adaptive dynamic relaxation; an FE velocity
// condition, a component that no condition holds, and an exact-displacement tolerance without the
// exact field are refused.
// ---------------------------------------------------------------------
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include <tests.h>

using namespace dealii;

namespace
{
  const std::string base = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Thickness       = 1e-3
  set Body            = plate
end
subsection Regions
  set Names = plate, corner
  subsection plate
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = PLATE_X, 0.05
  end
  subsection corner
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.005, 0.005
  end
end
subsection Material
  set Model   = MODEL
  set Density = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
  subsection linear peridynamic solid
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3
  end
  subsection anisotropic bond based
    set Young's modulus = 200e9
    set Poisson's ratio = 0.25
    set Grains file     = GRAINS_FILE
  end
end
subsection Boundary conditions
  set Names = PD_CONDITIONS
PD_BLOCK
end
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 20, 10 : 0, 0 : 0.1, 0.05 : true
  set Density             = 7800
FE_EXTRA
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3333333333333333
  end
  subsection Boundary conditions
    set Names = FE_CONDITIONS
    subsection left
      set Boundary ids = 0
LEFT_EXTRA
    end
FE_BLOCK
  end
end
subsection Coupling
  set Blending function = BETA
COUPLING_EXTRA
end
subsection Solver
  set Type = SOLVER
end
subsection Time stepping
  set End time = 1e-7
end
subsection Output
  set Directory  = OUTPUT_DIRECTORY
  set Write HDF5 = false
  set Progress   = false
end
)";

  void
  run_case(const std::string &name, const std::vector<std::pair<std::string, std::string>> &changes)
  {
    std::map<std::string, std::string> values = {{"PLATE_X", "0.1"},
                                                 {"MODEL", "bond based"},
                                                 {"GRAINS_FILE", ""},
                                                 {"PD_CONDITIONS", ""},
                                                 {"PD_BLOCK", ""},
                                                 {"FE_CONDITIONS", "left"},
                                                 {"FE_BLOCK", ""},
                                                 {"FE_EXTRA", ""},
                                                 {"BETA", "min(1, max(0, (x - 0.04) / 0.01))"},
                                                 {"SOLVER", "explicit"},
                                                 {"LEFT_EXTRA", ""},
                                                 {"COUPLING_EXTRA", ""},
                                                 {"OUTPUT_DIRECTORY", "results"}};
    for (const auto &[key, value] : changes)
      values[key] = value;
    const std::string file = "bad_input.prm";
    coupling_tests::write_file(file, coupling_tests::substitute(base, values));
    try
      {
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        coupling_tests::parse(problem, file);
        problem.setup();
        if (values["SOLVER"] != "explicit")
          problem.run();
        std::cout << name << ": accepted" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        std::cout << name << ": " << perideal_tests::exception_text(exc) << std::endl;
      }
    // No rank may write the next case's file while another still reads this one (a rank that
    // stops early would otherwise hand the others the next case's input).
    MPI_Barrier(MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  run_case("valid input", {{"BETA", "min(1, max(0, (x - 0.04) / 0.01))"}});
  run_case("beta above 1", {{"BETA", "(x - 0.04) / 0.01"}});
  run_case("overlap narrower than the horizon", {{"BETA", "min(1, max(0, (x - 0.04) / 0.002))"}});
  run_case("particles outside the mesh", {{"PLATE_X", "0.12"}});
  run_case("PD condition on slaved particles",
           {{"PD_CONDITIONS", "hold"},
            {"PD_BLOCK", "  subsection hold\n    set Region = corner\n  end"},
            {"BETA", "min(1, max(0, (x - 0.003) / 0.01))"}});
  run_case("FE conditions on the same component",
           {{"FE_CONDITIONS", "left, left again"},
            {"FE_BLOCK",
             "    subsection left again\n      set Boundary ids = 0\n      set Components = y\n"
             "    end"}});
  run_case("FE condition on a boundary id the mesh does not have",
           {{"FE_CONDITIONS", "left, nowhere"},
            {"FE_BLOCK",
             "    subsection nowhere\n      set Boundary ids = 9\n      set Components = y\n"
             "    end"}});
  run_case("FE condition on a boundary without FE unknowns (beta = 1 there)",
           {{"FE_CONDITIONS", "left, right"},
            {"FE_BLOCK",
             "    subsection right\n      set Boundary ids = 1\n      set Components = y\n"
             "    end"}});
  run_case("PD condition on a component the field does not have",
           {{"PD_CONDITIONS", "hold"},
            {"PD_BLOCK",
             "  subsection hold\n    set Region = corner\n    set Components = x, z\n  end"}});
  run_case("moment condition on a model without rotations",
           {{"PD_CONDITIONS", "twist"},
            {"PD_BLOCK",
             "  subsection twist\n    set Region = corner\n    set Type = moment\n"
             "    set Layer thickness = 1e-3\n  end"}});
  const std::string field_directory = "results_field_mismatch";
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::remove_all(field_directory);
  run_case("FE physics of another field than the material model's",
           {{"FE_EXTRA", "  set Physics = scalar laplace"}, {"OUTPUT_DIRECTORY", field_directory}});
  std::cout << "  output directory created: "
            << (std::filesystem::exists(field_directory) ? "yes" : "no") << std::endl;
  run_case("malformed expression in a boundary-condition function",
           {{"PD_CONDITIONS", "hold"},
            {"PD_BLOCK",
             "  subsection hold\n    set Region = corner\n    set Components = y\n"
             "    set Function = 1e-3 * (t\n  end"}});
  run_case("FE material shared with a model that has no elastic constants",
           {{"FE_EXTRA",
             "  subsection Elasticity\n    set Same material as the particles = true\n  end"}});
  coupling_tests::write_file("grains.txt", "0.002 0.002 0\n0.004 0.002 30\n");
  run_case("FE material shared with a polycrystal",
           {{"MODEL", "anisotropic bond based"},
            {"GRAINS_FILE", "grains.txt"},
            {"FE_EXTRA",
             "  subsection Elasticity\n    set Same material as the particles = true\n  end"}});
  run_case("valid input, state-based model", {{"MODEL", "linear peridynamic solid"}});
  run_case("relaxation solver", {{"SOLVER", "adaptive dynamic relaxation"}});
  run_case("static solver", {{"SOLVER", "static"}});
  run_case("static solver, FE velocity condition",
           {{"SOLVER", "static"},
            {"FE_CONDITIONS", "left, push"},
            {"FE_BLOCK",
             "    subsection push\n      set Boundary ids = 3\n      set Type = velocity\n"
             "      set Components = y\n      set Function = 1\n    end"}});
  run_case("static solver, y held nowhere",
           {{"SOLVER", "static"}, {"LEFT_EXTRA", "      set Components = x"}});
  run_case("static solver, tolerance without the exact field",
           {{"SOLVER", "static"}, {"COUPLING_EXTRA", "  set Exact displacement tolerance = 1e-3"}});
}
