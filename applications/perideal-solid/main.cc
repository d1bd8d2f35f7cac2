// ---------------------------------------------------------------------
// perideal-solid: in-plane 2D and 3D solid mechanics from a parameter file.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/fem/fe_problem.h>
#include <perideal/pd/boundary_conditions.h>
#include <perideal/pd/pd_problem.h>

#include <iostream>
#include <string>

namespace
{
  void
  print_usage()
  {
    std::cout
      << "Usage: perideal-solid [--validate] FILE.prm\n"
         "       perideal-solid --print-parameters [2|3] [pd|fe]\n"
         "  FILE.prm              run the problem described in FILE.prm\n"
         "  --validate FILE.prm   check every entry of FILE.prm and exit (0: valid)\n"
         "  --print-parameters    print a complete annotated parameter file of a particle (pd,\n"
         "                        default) or finite-element (fe) problem, with one example\n"
         "                        region 'body' and one boundary condition 'support'\n";
  }

  // Run (or only check) a problem of type Problem whose parameters are declared with
  // Problem::declare_parameters(prm, names...).
  template <typename Problem, typename... Names>
  void
  parse_and_run(const std::string &file, const bool validate_only, const Names &...names)
  {
    dealii::ParameterHandler prm;
    Problem::declare_parameters(prm, names...);
    perideal::ParameterUtilities::parse_file(prm, file);

    Problem problem(MPI_COMM_WORLD, std::cout);
    problem.parse_parameters(prm);
    if (validate_only)
      {
        if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
          std::cout << file << ": valid" << std::endl;
        return;
      }
    problem.setup();
    problem.run();
  }

  template <int dim>
  void
  run(const std::string &file, const bool validate_only)
  {
    using namespace perideal;
    // First pass: the lists of names that decide which subsections exist, and which regions
    // (particles, finite elements) the problem has.
    dealii::ParameterHandler first_pass;
    first_pass.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3), "");
    first_pass.enter_subsection("Discretization");
    first_pass.declare_entry("Body", "", dealii::Patterns::Anything(), "");
    first_pass.leave_subsection();
    RegionCollection<dim>::declare_names(first_pass);
    BoundaryConditions<dim>::declare_names(first_pass);
    FESolid<dim>::declare_names(first_pass);
    ParameterUtilities::parse_partially(first_pass, file);
    first_pass.enter_subsection("Discretization");
    const bool has_particles = !first_pass.get("Body").empty();
    first_pass.leave_subsection();
    const bool has_mesh = FESolid<dim>::is_enabled(first_pass);

    if (has_mesh && has_particles)
      parse_and_run<CoupledProblem<dim>>(file,
                                         validate_only,
                                         RegionCollection<dim>::parse_names(first_pass),
                                         BoundaryConditions<dim>::parse_names(first_pass),
                                         FESolid<dim>::parse_names(first_pass));
    else if (has_mesh)
      parse_and_run<FEProblem<dim>>(file, validate_only, FESolid<dim>::parse_names(first_pass));
    else
      parse_and_run<PDProblem<dim>>(file,
                                    validate_only,
                                    RegionCollection<dim>::parse_names(first_pass),
                                    BoundaryConditions<dim>::parse_names(first_pass));
  }

  template <int dim>
  void
  print_parameters(const bool finite_elements)
  {
    dealii::ParameterHandler prm;
    if (finite_elements)
      perideal::FEProblem<dim>::declare_parameters(prm, {"support"});
    else
      perideal::PDProblem<dim>::declare_parameters(prm, {"body"}, {"support"});
    prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
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
      if (args[0] == "--print-parameters")
        {
          const bool finite_elements = (args.size() > 2 && args[2] == "fe");
          if (args.size() > 1 && args[1] == "3")
            print_parameters<3>(finite_elements);
          else
            print_parameters<2>(finite_elements);
          return 0;
        }
      const bool validate = (args[0] == "--validate");
      AssertThrow(!validate || args.size() == 2,
                  dealii::ExcMessage("--validate takes exactly one parameter file."));
      const std::string file = validate ? args[1] : args[0];

      dealii::ParameterHandler dimension_only;
      dimension_only.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3), "");
      perideal::ParameterUtilities::parse_partially(dimension_only, file);
      if (dimension_only.get_integer("Dimension") == 2)
        run<2>(file, validate);
      else
        run<3>(file, validate);
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
