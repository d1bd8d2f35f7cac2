// ---------------------------------------------------------------------
// A steady run of several physics (<Physics/List> = heat with <Heat/Solver/Type> = static;
// doc/architecture/16_multiphysics.md): the plate of multiphysics_01 (20 mm x 10 mm, plane
// stress, dx = 1 mm, 200 particles), its mechanics (PMB) pulled quasi-statically (the left end
// held, the right end moved by 1 um per load step, 2 static load steps), its heat (bond based
// conduction, k = 50 W/(m K)) held at 100 K on the left end and at 0 K on the right end, with a
// heat flux of 1e5 W/m^2 into a layer at the top edge; both scale with the load factor. Before
// each load step of the mechanics the heat solves its steady state at the same load factor
// (Lie order: the temperature the mechanics will read). Checked, on 1 and 2 ranks:
//  - the mechanics equal the mechanics run alone bit for bit;
//  - the temperatures equal those of the heat run alone (static, the same load steps) bit for
//    bit;
//  - the statistics row holds both physics' columns: the heat's (prefixed heat.) equal to
//    those of the heat run alone, its energy balance (heat.energy_error) closing to the direct
//    solver's accuracy (1e-10 of its work);
//  - the exchange publishes the steady temperature.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

using namespace dealii;

namespace
{
  enum class Fields
  {
    mechanics,
    heat,
    both
  };

  // The plate: the mechanics in the top-level sections, the heat in them (alone) or in
  // <Heat> (both).
  std::string
  input(const Fields fields)
  {
    const std::string solver    = R"(
subsection Solver
  set Type          = static
  set Load steps    = 2
  set Linear solver = direct
end
)";
    const std::string mechanics = R"(
subsection Material
  set Model   = bond based
  set Density = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Boundary conditions
  set Names = hold, pull
  subsection hold
    set Region = left
    set Type   = displacement
  end
  subsection pull
    set Region     = right
    set Type       = displacement
    set Components = x
    set Function   = 2e-6
  end
end
)";
    const std::string heat      = R"(
subsection Material
  set Model   = bond based conduction
  set Density = 1
  subsection bond based conduction
    set Conductivity  = 50
    set Specific heat = 1
  end
end
subsection Boundary conditions
  set Names = hot, cold, heater
  subsection hot
    set Region   = left
    set Function = 100
  end
  subsection cold
    set Region   = right
    set Function = 0
  end
  subsection heater
    set Region          = top
    set Type            = flux
    set Layer thickness = 1e-3
    set Function        = 1e5
  end
end
)";
    const std::string text      = R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Thickness       = 1e-3
  set Body            = plate
end
subsection Regions
  set Names = plate, left, right, top
  subsection plate
    set Lower corner = 0, 0
    set Upper corner = 0.02, 0.01
  end
  subsection left
    set Lower corner = 0, 0
    set Upper corner = 0.003, 0.01
  end
  subsection right
    set Lower corner = 0.017, 0
    set Upper corner = 0.02, 0.01
  end
  subsection top
    set Lower corner = 0.008, 0.009
    set Upper corner = 0.012, 0.01
  end
end
subsection Time stepping
  set End time = 1
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)" + solver;
    if (fields == Fields::mechanics)
      return text + mechanics;
    if (fields == Fields::heat)
      return text + heat;
    return text + mechanics + "subsection Physics\n  set List = heat\nend\nsubsection Heat\n" +
           heat + "  subsection Solver\n    set Type = static\n  end\nend\n";
  }

  struct Result
  {
    // Owned entries: the displacement, the temperature, the temperature as the exchange
    // publishes it.
    std::vector<double> u, T, published;
    // The last row of statistics.csv by column (rank 0).
    std::map<std::string, double> row;
  };

  std::map<std::string, double>
  last_row(const std::string &file)
  {
    std::map<std::string, double> row;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return row;
    std::ifstream            in(file);
    std::string              line, last;
    std::vector<std::string> names;
    std::getline(in, line);
    std::istringstream header(line);
    for (std::string name; std::getline(header, name, ',');)
      names.push_back(name);
    while (std::getline(in, line))
      if (!line.empty())
        last = line;
    std::istringstream values(last);
    std::string        value;
    for (unsigned int c = 0; c < names.size() && std::getline(values, value, ','); ++c)
      if (!value.empty())
        row[names[c]] = std::stod(value);
    return row;
  }

  Result
  run(const Fields fields)
  {
    std::ostringstream                   log;
    perideal::CoupledProblem<2>          problem(MPI_COMM_WORLD, log);
    ParameterHandler                     prm;
    perideal::Physics<2>::ConditionNames heat_conditions;
    heat_conditions.particles = {"hot", "cold", "heater"};
    perideal::CoupledProblem<2>::declare_parameters(
      prm,
      {"plate", "left", "right", "top"},
      fields == Fields::heat ? std::vector<std::string>{"hot", "cold", "heater"} :
                               std::vector<std::string>{"hold", "pull"},
      {},
      {{"heat", heat_conditions}});
    prm.parse_input_from_string(input(fields));
    problem.parse_parameters(prm);
    deallog.push("run");
    problem.setup();
    problem.run();
    deallog.pop();
    Result                          result;
    const auto                     &ps      = problem.particles();
    const auto                     &physics = problem.get_physics();
    const perideal::ParticleVector *temperature =
      fields == Fields::both ? &physics[1]->state().u :
      fields == Fields::heat ? &problem.particle_displacement() :
                               nullptr;
    if (fields != Fields::heat)
      for (unsigned int k = 0; k < ps.n_owned() * 2; ++k)
        result.u.push_back(problem.particle_displacement().local_element(k));
    if (temperature != nullptr)
      for (unsigned int i = 0; i < ps.n_owned(); ++i)
        {
          result.T.push_back(temperature->local_element(i));
          if (fields == Fields::both)
            result.published.push_back(problem.get_exchange().particle_value("temperature", i));
        }
    result.row = last_row("results/statistics.csv");
    return result;
  }

  // The largest difference of @p a and @p b over the ranks.
  double
  difference(const std::vector<double> &a, const std::vector<double> &b)
  {
    AssertThrow(a.size() == b.size(), ExcInternalError());
    double largest = 0.;
    for (std::size_t k = 0; k < a.size(); ++k)
      largest = std::max(largest, std::abs(a[k] - b[k]));
    return Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }

  void
  verdict(const std::string &what, const bool ok)
  {
    deallog << what << ": " << (ok ? "ok" : "FAILED") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_initlog();
  deallog.depth_file(1);

  const Result both      = run(Fields::both);
  const Result mechanics = run(Fields::mechanics);
  const Result heat      = run(Fields::heat);
  double       largest_T = 0.;
  for (const double T : both.T)
    largest_T = std::max(largest_T, std::abs(T));
  deallog << "largest temperature: " << Utilities::MPI::max(largest_T, MPI_COMM_WORLD) << " K"
          << std::endl;
  verdict("mechanics equal to the mechanics alone, bit for bit",
          difference(both.u, mechanics.u) == 0.);
  verdict("temperature equal to the heat alone, bit for bit", difference(both.T, heat.T) == 0.);
  verdict("the exchange publishes the temperature", difference(both.published, both.T) == 0.);

  // The statistics (rank 0 reads them and writes the log): both physics' columns in one row,
  // the heat's as alone.
  bool columns = true;
  for (const std::string name : {"strain_energy", "external_work", "energy_error"})
    {
      const auto mine = both.row.find(name), theirs = both.row.find("heat." + name);
      const auto alone = heat.row.find(name), alone_mechanics = mechanics.row.find(name);
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        continue;
      columns = columns && mine != both.row.end() && theirs != both.row.end() &&
                alone != heat.row.end() && alone_mechanics != mechanics.row.end() &&
                mine->second == alone_mechanics->second && theirs->second == alone->second;
    }
  verdict("statistics: both physics' columns, each as alone", columns);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      const double work  = both.row.at("heat.external_work");
      const double error = both.row.at("heat.energy_error");
      deallog << "heat: external work " << work << " J, energy error below 1e-10 of it: "
              << (std::abs(error) <= 1e-10 * std::abs(work) ? "yes" : "no") << std::endl;
    }
}
