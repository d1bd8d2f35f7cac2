// ---------------------------------------------------------------------
// perideal-solid: in-plane 2D and 3D solid mechanics from a parameter file.
// ---------------------------------------------------------------------
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/boundary_conditions.h>

#include <iostream>
#include <string>

namespace
{
  void
  print_usage()
  {
    std::cout
      << "Usage: perideal-solid [--validate] FILE.prm\n"
         "       perideal-solid --print-parameters [2|3]\n"
         "  FILE.prm              run the problem described in FILE.prm: particles "
         "(<Discretization/Body>),\n"
         "                        an FE mesh (<Finite elements>), or both joined through an "
         "overlap\n"
         "  --validate FILE.prm   check every entry of FILE.prm and exit (0: valid)\n"
         "  --print-parameters    print a complete annotated parameter file, with one example "
         "region\n"
         "                        'body', one particle boundary condition 'support' and one FE\n"
         "                        boundary condition 'clamp'\n";
  }

  template <int dim>
  void
  run(const std::string &file, const bool validate_only)
  {
    using namespace perideal;
    // First pass: the lists of names that decide which subsections exist.
    dealii::ParameterHandler first_pass;
    first_pass.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3), "");
    RegionCollection<dim>::declare_names(first_pass);
    BoundaryConditions<dim>::declare_names(first_pass);
    FERegion<dim>::declare_names(first_pass);
    ParameterUtilities::parse_partially(first_pass, file);

    dealii::ParameterHandler prm;
    CoupledProblem<dim>::declare_parameters(prm,
                                            RegionCollection<dim>::parse_names(first_pass),
                                            BoundaryConditions<dim>::parse_names(first_pass),
                                            FERegion<dim>::parse_names(first_pass));
    ParameterUtilities::parse_file(prm, file);

    CoupledProblem<dim> problem(MPI_COMM_WORLD, std::cout);
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
  print_parameters()
  {
    dealii::ParameterHandler prm;
    perideal::CoupledProblem<dim>::declare_parameters(prm, {"body"}, {"support"}, {"clamp"});
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
          if (args.size() > 1 && args[1] == "3")
            print_parameters<3>();
          else
            print_parameters<2>();
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
