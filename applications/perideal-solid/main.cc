// ---------------------------------------------------------------------
// perideal-solid: in-plane 2D and 3D solid mechanics from a parameter file.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_reference.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/base/version.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/boundary_conditions.h>

#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
  void
  print_usage()
  {
    std::cout
      << "Usage: perideal-solid [--restart] FILE.prm\n"
         "       perideal-solid --validate FILE.prm [FILE.prm ...]\n"
         "       perideal-solid --print-parameters [2|3]\n"
         "       perideal-solid --version | --help\n"
         "       perideal-solid --print-parameter-reference 2|3\n"
         "  FILE.prm              run the problem described in FILE.prm: particles "
         "(<Discretization/Body>),\n"
         "                        an FE mesh (<Finite elements>), or both joined through an "
         "overlap\n"
         "  --validate FILE.prm ...\n"
         "                        make every check of a run's set-up short of the solver's "
         "matrices\n"
         "                        (entries, mesh, particles, model, coupling) for each file "
         "in turn,\n"
         "                        print its verdict and exit (0: every file valid)\n"
         "  --restart FILE.prm    continue the run of FILE.prm from its newest checkpoint\n"
         "                        (<Output/Directory>/checkpoint, written by <Output/"
         "Checkpoint interval>\n"
         "                        or <Output/Checkpoint time interval>, and of the last "
         "converged load step\n"
         "                        by a quasi-static run that did not converge; its <Solver> "
         "tolerance and\n"
         "                        iteration settings may change)\n"
         "  --print-parameters    print a complete annotated parameter file that runs as "
         "printed:\n"
         "                        a bar clamped in its FE part and pulled at its PD end (regions "
         "'body'\n"
         "                        and 'edge', particle condition 'support', FE condition "
         "'clamp'),\n"
         "                        heated by a prescribed temperature (<Temperature>) with the "
         "thermal\n"
         "                        expansion of both regions,\n"
         "                        in 2 (default) or 3 dimensions\n"
         "  --version             print the PeriDeal version, its git revision and the deal.II,\n"
         "                        Trilinos and MPI versions (the first line of every run's "
         "log)\n"
         "  --print-parameter-reference 2|3\n"
         "                        print every entry with its default, pattern, unit and "
         "documentation\n"
         "                        as Markdown (doc/parameters/<dim>d.md)\n"
         "  --help, -h            print this text\n";
  }

  template <int dim>
  void
  run(const std::string &file, const bool validate_only, const bool restart)
  {
    using namespace perideal;
    // First pass: the lists of names that decide which subsections exist.
    dealii::ParameterHandler first_pass;
    first_pass.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3), "");
    RegionCollection<dim>::declare_names(first_pass);
    BoundaryConditions<dim>::declare_names(first_pass);
    FERegion<dim>::declare_names(first_pass);
    Physics<dim>::declare_names(first_pass);
    ParameterUtilities::parse_partially(first_pass, file);

    std::map<std::string, typename Physics<dim>::ConditionNames> physics_conditions;
    for (const auto &[name, conditions] : Physics<dim>::parse_names(first_pass))
      physics_conditions[name] = conditions;
    dealii::ParameterHandler prm;
    CoupledProblem<dim>::declare_parameters(prm,
                                            RegionCollection<dim>::parse_names(first_pass),
                                            BoundaryConditions<dim>::parse_names(first_pass),
                                            FERegion<dim>::parse_names(first_pass),
                                            physics_conditions);
    ParameterUtilities::parse_file(prm, file);

    CoupledProblem<dim> problem(MPI_COMM_WORLD, std::cout);
    problem.parse_parameters(prm);
    if (validate_only)
      {
        problem.check();
        if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << file << ": valid" << std::endl;
        return;
      }
    problem.setup();
    if (restart)
      problem.restart_from_checkpoint();
    problem.run();
  }

  /**
   * A small coupled problem that --print-parameters fills in, so that the template validates
   * and runs as printed: a bar 40 mm long, clamped at x = 0 in the FE region, particles where
   * x > 15 mm (beta ramps from 0 to 1 over 10 mm), pulled at its right end by a velocity of
   * 1 m/s and heated from 20 to 120 degrees C over the run (a prescribed temperature; the steel's
   * thermal expansion 1.2e-5 1/K in both regions), 2 us of explicit dynamics.
   */
  template <int dim>
  void
  set_example(dealii::ParameterHandler &prm)
  {
    const std::string z0 = dim == 3 ? ", 0" : "", z1 = dim == 3 ? ", 0.01" : "";
    const std::vector<std::pair<std::vector<std::string>, std::pair<std::string, std::string>>>
      values = {{{"Discretization"}, {"Lattice spacing", "1e-3"}},
                {{"Discretization"}, {"Thickness", dim == 2 ? "1e-3" : "1"}},
                {{"Discretization"}, {"Body", "body"}},
                {{"Regions"}, {"Names", "body, edge"}},
                {{"Regions", "body"}, {"Lower corner", "0, 0" + z0}},
                {{"Regions", "body"}, {"Upper corner", "0.04, 0.01" + z1}},
                {{"Regions", "edge"}, {"Lower corner", "0.037, 0" + z0}},
                {{"Regions", "edge"}, {"Upper corner", "0.04, 0.01" + z1}},
                {{"Material"}, {"Density", "7800"}},
                {{"Material", "bond based"}, {"Young's modulus", "200e9"}},
                {{"Material", "bond based"}, {"Thermal expansion", "1.2e-5"}},
                {{"Boundary conditions"}, {"Names", "support"}},
                {{"Boundary conditions", "support"}, {"Region", "edge"}},
                {{"Boundary conditions", "support"}, {"Type", "velocity"}},
                {{"Boundary conditions", "support"}, {"Components", "x"}},
                {{"Boundary conditions", "support"}, {"Function", "1"}},
                {{"Finite elements"}, {"Generator", "subdivided_hyper_rectangle"}},
                {{"Finite elements"},
                 {"Generator arguments",
                  dim == 2 ? "40, 10 : 0, 0 : 0.04, 0.01 : true" :
                             "40, 10, 10 : 0, 0, 0 : 0.04, 0.01, 0.01 : true"}},
                {{"Finite elements"}, {"Density", "7800"}},
                {{"Finite elements", "Elasticity"}, {"Young's modulus", "200e9"}},
                {{"Finite elements", "Elasticity"},
                 {"Poisson's ratio", dim == 2 ? "0.3333333333" : "0.25"}},
                {{"Finite elements", "Elasticity"}, {"Thermal expansion", "1.2e-5"}},
                {{"Finite elements", "Boundary conditions"}, {"Names", "clamp"}},
                {{"Finite elements", "Boundary conditions", "clamp"}, {"Boundary ids", "0"}},
                {{"Coupling"}, {"Blending function", "min(1, max(0, (x - 0.015) / 0.01))"}},
                {{"Temperature"}, {"Source", "function"}},
                {{"Temperature"}, {"Function", "20 + 100 * t / 2e-6"}},
                {{"Temperature"}, {"Reference temperature", "20"}},
                {{"Time stepping"}, {"End time", "2e-6"}}};
    for (const auto &[path, entry] : values)
      {
        for (const auto &section : path)
          prm.enter_subsection(section);
        prm.set(entry.first, entry.second);
        for (unsigned int k = 0; k < path.size(); ++k)
          prm.leave_subsection();
      }
  }

  template <int dim>
  void
  print_parameters()
  {
    dealii::ParameterHandler prm;
    perideal::CoupledProblem<dim>::declare_parameters(prm,
                                                      {"body", "edge"},
                                                      {"support"},
                                                      {"clamp"});
    set_example<dim>(prm);
    prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
  }

  /**
   * The parameter reference doc/parameters/<dim>d.md: every entry that a file of this
   * dimension may hold, with "<name>" for the names of regions and boundary conditions.
   */
  template <int dim>
  void
  print_parameter_reference()
  {
    dealii::ParameterHandler                                               prm;
    std::map<std::string, typename perideal::Physics<dim>::ConditionNames> physics_conditions;
    for (const auto &name : perideal::Physics<dim>::names())
      physics_conditions[name] = {{"<name>"}, {"<name>"}};
    perideal::CoupledProblem<dim>::declare_parameters(prm,
                                                      {"<name>"},
                                                      {"<name>"},
                                                      {"<name>"},
                                                      physics_conditions);
    perideal::write_parameter_reference(prm, dim, std::cout);
  }

  /// Validate or run @p file in the dimension its <Dimension> entry names.
  void
  run(const std::string &file, const bool validate_only, const bool restart)
  {
    dealii::ParameterHandler dimension_only;
    dimension_only.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3), "");
    perideal::ParameterUtilities::parse_partially(dimension_only, file);
    if (dimension_only.get_integer("Dimension") == 2)
      run<2>(file, validate_only, restart);
    else
      run<3>(file, validate_only, restart);
  }

  /**
   * --validate: check each of @p files in turn (one process start for all of them), print
   * "FILE: valid" or, on the error stream, "Error in FILE:" and what to fix; with more than one
   * file, a count at the end. Returns whether every file is valid. The checks run on every rank
   * alike, so a refusal leaves the ranks in step for the next file.
   */
  bool
  validate_files(const std::vector<std::string> &files)
  {
    const bool   is_root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    unsigned int refused = 0;
    for (const auto &file : files)
      {
        std::string error;
        try
          {
            run(file, true, false);
          }
        catch (const dealii::ExceptionBase &exc)
          {
            std::ostringstream message;
            exc.print_info(message);
            error = message.str();
          }
        catch (const std::exception &exc)
          {
            error = exc.what();
          }
        if (!error.empty())
          {
            ++refused;
            std::cerr << "\nError in " << file << ":\n" << error << std::endl;
          }
      }
    if (files.size() > 1 && is_root)
      std::cout << files.size() << " files: " << files.size() - refused << " valid, " << refused
                << " refused" << std::endl;
    return refused == 0;
  }
} // namespace

int
main(int argc, char **argv)
{
  try
    {
      dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
      const std::vector<std::string>           args(argv + 1, argv + argc);
      if (args.empty() || args[0] == "--help" || args[0] == "-h")
        {
          print_usage();
          return args.empty() ? 1 : 0;
        }
      const bool is_root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      if (args[0] == "--version")
        {
          AssertThrow(args.size() == 1, dealii::ExcMessage("--version takes no argument."));
          if (is_root)
            std::cout << perideal::version_line() << std::endl;
          return 0;
        }
      if (args[0] == "--print-parameter-reference")
        {
          AssertThrow(args.size() == 2 && (args[1] == "2" || args[1] == "3"),
                      dealii::ExcMessage(
                        "--print-parameter-reference takes the dimension: 2 or 3."));
          if (args[1] == "2")
            print_parameter_reference<2>();
          else
            print_parameter_reference<3>();
          return 0;
        }
      if (args[0] == "--print-parameters")
        {
          const std::string dimension = args.size() > 1 ? args[1] : "2";
          AssertThrow(args.size() <= 2 && (dimension == "2" || dimension == "3"),
                      dealii::ExcMessage("--print-parameters takes the dimension 2 or 3 "
                                         "(default 2), not <" +
                                         (args.size() > 2 ? args[1] + " " + args[2] : dimension) +
                                         ">."));
          if (dimension == "3")
            print_parameters<3>();
          else
            print_parameters<2>();
          return 0;
        }
      if (args[0] == "--validate")
        {
          AssertThrow(args.size() >= 2,
                      dealii::ExcMessage("--validate takes one or more parameter files."));
          return validate_files({args.begin() + 1, args.end()}) ? 0 : 1;
        }
      const bool restart = (args[0] == "--restart");
      AssertThrow(!restart || args.size() == 2,
                  dealii::ExcMessage("--restart takes exactly one parameter file."));
      AssertThrow(restart || (args.size() == 1 && args[0].rfind("-", 0) != 0),
                  dealii::ExcMessage("Unknown option or extra argument in <" + args[0] +
                                     (args.size() > 1 ? " " + args[1] : std::string()) +
                                     ">; perideal-solid --help lists the accepted ones."));
      // A run's log names the build first.
      if (is_root)
        std::cout << perideal::version_line() << std::endl;
      run(restart ? args[1] : args[0], false, restart);
    }
  catch (const dealii::ExceptionBase &exc)
    {
      std::cerr << "\nError: ";
      exc.print_info(std::cerr);
      std::cerr << std::endl;
      return 1;
    }
  catch (const std::exception &exc)
    {
      std::cerr << "\nError: " << exc.what() << std::endl;
      return 1;
    }
  return 0;
}
