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
// Then the same plate coupled (blended): an FE part of both physics (an elasticity and a heat
// mesh of 2 mm cells over the plate), the particles blended out from x = 12 mm to 16 mm, the
// right end pulled, and held at 0 K, on the mesh's right edge (boundary id 1). The same checks,
// on the particles and the FE dofs of each physics.
// ---------------------------------------------------------------------

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

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
  // <Heat> (both); with an FE part of both physics if @p coupled.
  std::string
  input(const Fields fields, const bool coupled)
  {
    const std::string solver = R"(
subsection Solver
  set Type          = static
  set Load steps    = 2
  set Linear solver = direct
end
)";
    // The mesh and the overlap of the coupled plate; its heat mesh, held at 0 K at the right.
    const std::string mesh    = R"(
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 10, 5 : 0, 0 : 0.02, 0.01 : true
)";
    const std::string overlap = R"(
subsection Coupling
  set Blending function = min(1, max(0, (0.016 - x) / 0.004))
end
)";
    const std::string fe_heat = R"(
  set Physics = heat
  set Density = 1
  subsection heat
    set Conductivity  = 50
    set Specific heat = 1
  end
  subsection Boundary conditions
    set Names = cold
    subsection cold
      set Boundary ids = 1
      set Function     = 0
    end
  end
)";
    const std::string pull    = coupled ? R"(
  set Names = hold
  subsection hold
    set Region = left
    set Type   = displacement
  end
end
subsection Finite elements)" + mesh +
                                         R"(  set Density = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3333333333333333
  end
  subsection Boundary conditions
    set Names = pull
    subsection pull
      set Boundary ids = 1
      set Components   = x
      set Function     = 2e-6
    end
  end
end
)" :
                                          R"(
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
    const std::string mechanics =
      coupling_tests::multiphysics_mechanics(false) + "\nsubsection Boundary conditions" + pull;
    const std::string heat = coupling_tests::multiphysics_conduction() + R"(
subsection Boundary conditions
  set Names = hot, )" + (coupled ? "" : "cold, ") +
                             R"(heater
  subsection hot
    set Region   = left
    set Function = 100
  end)" + (coupled ? "" : R"(
  subsection cold
    set Region   = right
    set Function = 0
  end)") + R"(
  subsection heater
    set Region          = top
    set Type            = flux
    set Layer thickness = 1e-3
    set Function        = 1e5
  end
end
)";
    const std::string text = coupling_tests::multiphysics_plate(true) + R"(
subsection Time stepping
  set End time = 1
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)" + solver + (coupled ? overlap : "");
    if (fields == Fields::mechanics)
      return text + mechanics;
    if (fields == Fields::heat)
      return text + heat + (coupled ? "subsection Finite elements" + mesh + fe_heat + "end\n" : "");
    return text + mechanics +
           coupling_tests::with_heat(
             heat + "  subsection Solver\n    set Type = static\n  end\n" +
             (coupled ? "subsection Finite elements" + fe_heat + "end\n" : ""));
  }

  struct Result
  {
    // Owned entries: the displacement, the temperature, the temperature as the exchange
    // publishes it; the FE displacement and temperature.
    std::vector<double> u, T, published, U, FE_T;
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
  run(const Fields fields, const bool coupled)
  {
    std::ostringstream                   log;
    perideal::CoupledProblem<2>          problem(MPI_COMM_WORLD, log);
    ParameterHandler                     prm;
    perideal::Physics<2>::ConditionNames heat_conditions;
    const std::vector<std::string>       particle_heat =
      coupled ? std::vector<std::string>{"hot", "heater"} :
                      std::vector<std::string>{"hot", "cold", "heater"};
    heat_conditions.particles = particle_heat;
    if (coupled)
      heat_conditions.fe = {"cold"};
    perideal::CoupledProblem<2>::declare_parameters(prm,
                                                    {"plate", "left", "right", "top"},
                                                    fields == Fields::heat ? particle_heat :
                                                    coupled ? std::vector<std::string>{"hold"} :
                                                              std::vector<std::string>{"hold",
                                                                                       "pull"},
                                                    !coupled ? std::vector<std::string>{} :
                                                    fields == Fields::heat ?
                                                               std::vector<std::string>{"cold"} :
                                                               std::vector<std::string>{"pull"},
                                                    {{"heat", heat_conditions}});
    prm.parse_input_from_string(input(fields, coupled));
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
    const auto owned = [](const perideal::FEVector &v) {
      return std::vector<double>(v.begin(), v.begin() + v.locally_owned_size());
    };
    if (fields != Fields::heat)
      result.U = owned(physics[0]->state().U);
    if (fields != Fields::mechanics)
      result.FE_T = owned(physics.back()->state().U);
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

  for (const bool coupled : {false, true})
    {
      if (coupled)
        deallog << "coupled (blended):" << std::endl;
      const Result both      = run(Fields::both, coupled);
      const Result mechanics = run(Fields::mechanics, coupled);
      const Result heat      = run(Fields::heat, coupled);
      double       largest_T = 0.;
      for (const double T : both.T)
        largest_T = std::max(largest_T, std::abs(T));
      deallog << "largest temperature: " << Utilities::MPI::max(largest_T, MPI_COMM_WORLD) << " K"
              << std::endl;
      verdict("mechanics equal to the mechanics alone, bit for bit",
              difference(both.u, mechanics.u) == 0. && difference(both.U, mechanics.U) == 0.);
      verdict("temperature equal to the heat alone, bit for bit",
              difference(both.T, heat.T) == 0. && difference(both.FE_T, heat.FE_T) == 0.);
      verdict("the exchange publishes the temperature", difference(both.published, both.T) == 0.);

      // The statistics (rank 0 reads them and writes the log): both physics' columns in one
      // row, the heat's as alone.
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
}
