// ---------------------------------------------------------------------
// The coupling-method interface: methods defined outside the library (here, in the test) plug
// into CoupledProblem through the registry, with no change to its solvers or postprocessors.
//
// 1. A sharp interface derived from the blended method: the FE energy where beta < 1/2, the
//    particles' where beta >= 1/2 (bonds that cross the interface carry half their energy),
//    particles in cells with FE unknowns slaved as in the blended method, whose equilibrium
//    solve it reuses. On the plate of tests/app-solid/coupled_static_*_2d: a rigid translation
//    is exact for both methods; in tension both balance the load exactly, and the sharp
//    interface's ghost forces give a larger displacement error than the 10 mm blending ramp.
// 2. "separate regions", not derived from BlendedCoupling (no transfer operator, no particle
//    slaved to the FE field): the FE region and the particles occupy disjoint parts of the body
//    and do not interact. A PMB strip held at its left end and pulled by a traction at its
//    right, beside an FE strip clamped at its left end and pulled likewise, both under a body
//    force, run explicit and static through the unchanged solvers, against the PMB strip alone
//    (particles only) and the FE strip alone (FE only) run as separate problems. The coupled
//    run must give each region's final displacements bit for bit, every statistics column of
//    one region (reactions, broken bonds, largest displacements) as that region's run, and the
//    energies, the work and the applied loads as the sums of the two runs' to the 10 digits of
//    statistics.csv (2e-9 of the run's largest energy or of the column's largest load); a
//    solver that assumed the blended method (P, P^T, slaved particles, blended masses) would
//    change them.
// ---------------------------------------------------------------------
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/blended_coupling.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/coupling/coupled_static_solver.h>
#include <perideal/coupling/transfer_operator.h>

#include "coupling_tests.h"

#include <algorithm>
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
  using perideal::FEVector;

  template <int dim>
  class SharpInterface : public perideal::BlendedCoupling<dim>
  {
  public:
    double
    fe_weight(const double beta) const override
    {
      return beta < 0.5 ? 1. : 0.;
    }
    double
    particle_weight(const double beta) const override
    {
      return beta < 0.5 ? 0. : 1.;
    }
  };

  /**
   * <Coupling/Method> = separate regions, not derived from BlendedCoupling: the FE region and
   * the particles occupy disjoint parts of the body (FE where beta < 1/2, particles elsewhere)
   * and do not interact. No particle is slaved to the FE field, so there is no P and no P^T; the
   * strain energy is the sum of the two regions'; a quasi-static step solves each region alone
   * with the library's static solve, as the one-region problems do (for the FE region with no
   * particles, for the particles with an FE region without unknowns).
   */
  template <int dim>
  class SeparateRegions : public perideal::CouplingMethod<dim>
  {
  public:
    /// No parameters.
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    check_solver(const perideal::SolverType type) const override
    {
      AssertThrow(type != perideal::SolverType::adaptive_dynamic_relaxation,
                  ExcMessage("<Coupling/Method> = separate regions runs <Solver/Type> = "
                             "explicit or static, not adaptive dynamic relaxation."));
    }

    double
    particle_weight(const double beta) const override
    {
      return beta < 0.5 ? 0. : 1.;
    }

    double
    fe_weight(const double beta) const override
    {
      return 1. - particle_weight(beta);
    }

    void
    initialize(const perideal::CoupledRegions<dim> &coupled_regions) override
    {
      regions = coupled_regions;
      slaved.assign(regions.particles->n_owned(), false);
    }

    std::string
    summary() const override
    {
      return "no particle slaved to the FE field, " +
             std::to_string(regions.particles->n_global()) + " free";
    }

    const std::vector<bool> &
    slaved_particles() const override
    {
      return slaved;
    }

    void
    interpolate_to_particles(const FEVector &, perideal::ParticleVector &) const override
    {}

    void
    add_particle_forces(const perideal::ParticleVector &, FEVector &) const override
    {}

    perideal::CoupledEnergy
    strain_energy(const FEVector &U, const double particle_energy) const override
    {
      return {regions.fe->strain_energy(U), particle_energy};
    }

    void
    lumped_masses(FEVector &fe_mass, std::vector<double> &particle_mass) const override
    {
      fe_mass            = regions.fe->lumped_mass();
      const auto &volume = regions.particles->volumes();
      particle_mass.resize(regions.particles->n_owned());
      for (unsigned int i = 0; i < particle_mass.size(); ++i)
        particle_mass[i] = regions.density * volume[i];
    }

    void
    initialize_equilibrium(const perideal::ParticleVector           &particle_prescribed,
                           const perideal::EquilibriumSettings<dim> &settings,
                           const std::string                        &condition_list) override
    {
      conditions              = condition_list;
      const MPI_Comm     comm = regions.particles->get_communicator();
      const unsigned int nc   = regions.material->field_layout().n_components();
      // What a one-region problem has for its empty region: an FE region without a mesh, a
      // particle system without particles.
      no_fe = std::make_unique<perideal::FERegion<dim>>(comm);
      ParameterHandler prm;
      perideal::FERegion<dim>::declare_parameters(prm, {});
      no_fe->parse_parameters(prm, perideal::PlanarAssumption::plane_stress, 1.);
      no_fe->setup();
      no_particles = std::make_unique<perideal::ParticleSystem<dim>>(comm);
      no_particles->generate(regions.particles->settings(),
                             BoundingBox<dim>(),
                             [](const Point<dim> &) { return false; },
                             {});
      for (FEVector *vector : {&no_U, &no_fe_load, &no_fe_residual})
        no_fe->initialize_vector(*vector);
      for (perideal::ParticleVector *vector : {&no_u, &no_particle_load, &no_particle_force})
        no_particles->reinit_vector(*vector, nc);

      fe_transfer.reinit(*regions.fe, *no_particles, regions.layout);
      pd_transfer.reinit(*no_fe, *regions.particles, regions.layout);
      fe_solver = std::make_unique<perideal::CoupledStaticSolver<dim>>(settings.linear);
      fe_solver->reinit(*regions.fe, *no_particles, fe_transfer, no_u);
      pd_solver = std::make_unique<perideal::CoupledStaticSolver<dim>>(settings.linear);
      pd_solver->reinit(*no_fe, *regions.particles, pd_transfer, particle_prescribed);
    }

    types::global_dof_index
    n_unknowns() const override
    {
      return fe_solver->n_unknowns() + pd_solver->n_unknowns();
    }

    unsigned int
    solve_equilibrium(const FEVector                 &f_fe,
                      const perideal::ParticleVector &f_pd,
                      FEVector                       &U,
                      perideal::ParticleVector       &u) override
    {
      const unsigned int fe_iterations =
        fe_solver->solve(*regions.material, f_fe, no_particle_load, U, no_u, conditions);
      return fe_iterations +
             pd_solver->solve(*regions.material, no_fe_load, f_pd, no_U, u, conditions);
    }

    double
    equilibrium_forces(const FEVector                 &U,
                       const perideal::ParticleVector &u,
                       const FEVector                 &f_fe,
                       const perideal::ParticleVector &f_pd,
                       FEVector                       &fe_residual,
                       perideal::ParticleVector       &pd_force) override
    {
      fe_solver->forces(U, no_u, f_fe, no_particle_load, fe_residual, no_particle_force);
      return pd_solver->forces(no_U, u, no_fe_load, f_pd, no_fe_residual, pd_force);
    }

  private:
    perideal::CoupledRegions<dim> regions;
    std::vector<bool>             slaved;
    std::string                   conditions;
    // The empty counterparts of the two regions, and the one-region static solves.
    std::unique_ptr<perideal::FERegion<dim>>            no_fe;
    std::unique_ptr<perideal::ParticleSystem<dim>>      no_particles;
    perideal::TransferOperator<dim>                     fe_transfer, pd_transfer;
    std::unique_ptr<perideal::CoupledStaticSolver<dim>> fe_solver, pd_solver;
    FEVector                                            no_U, no_fe_load, no_fe_residual;
    perideal::ParticleVector                            no_u, no_particle_load, no_particle_force;
  };

  const std::string base = R"(
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
    set Upper corner = 0.1, 0.1
  end
end
subsection Material
  set Model   = bond based
  set Density = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 25, 25 : 0, 0 : 0.1, 0.1 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3333333333333333
  end
  subsection Boundary conditions
CONDITIONS
  end
end
subsection Coupling
  set Method            = METHOD
  set Blending function = min(1, max(0, min(min((x - 0.03) / 0.01, (0.07 - x) / 0.01), min((y - 0.03) / 0.01, (0.07 - y) / 0.01))))
  set Exact displacement = EXACT
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

  const std::string translation = R"(
    set Names = all
    subsection all
      set Boundary ids = 0, 1, 2, 3
      set Function     = 1e-6; 2e-6
    end)";

  const std::string tension = R"(
    set Names = left, bottom, right
    subsection left
      set Boundary ids = 0
      set Components   = x
      set Function     = 0
    end
    subsection bottom
      set Boundary ids = 2
      set Components   = y
      set Function     = 0
    end
    subsection right
      set Boundary ids = 1
      set Type         = traction
      set Function     = 20e6; 0
    end)";

  void
  run_case(const std::string &method,
           const std::string &conditions,
           const std::string &exact,
           const std::string &name)
  {
    const std::string file = "coupling_method.prm";
    coupling_tests::write_file(file,
                               coupling_tests::substitute(base,
                                                          {{"CONDITIONS", conditions},
                                                           {"METHOD", method},
                                                           {"EXACT", exact}}));
    std::ostringstream          log;
    perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
    coupling_tests::parse(problem, file);
    problem.setup();
    problem.run();
    MPI_Barrier(MPI_COMM_WORLD);

    // The lines that state the method and the verification numbers.
    std::cout << name << std::endl;
    std::istringstream lines(log.str());
    for (std::string line; std::getline(lines, line);)
      for (const std::string key :
           {"Coupling: ", "Reaction ", "Force balance", "Energy error", "Displacement error ("})
        if (line.rfind(key, 0) == 0)
          std::cout << "  " << line << std::endl;
  }

  // The two strips: particles for x < 0.02 (held by a layer a horizon thick left of x = 0), an
  // FE mesh on 0.03 < x < 0.05; beta = 1 up to x = 0.025, 0 beyond x = 0.026.
  const std::string strips = R"(
set Dimension = 2
subsection Discretization
  set Thickness = 1e-3
PARTICLES
end
subsection Material
  set Planar assumption = plane stress
  set Model             = bond based
  set Density           = 7800
  subsection bond based
    set Young's modulus = 200e9
  end
end
MESH
COUPLING
subsection Body force
  set Function = 2e8; -1e8
end
subsection Solver
  set Type          = SOLVER
  set Linear solver = direct
  set Load steps    = 2
end
subsection Time stepping
  set End time  = 2e-6
  set Time step = 5e-8
end
subsection Output
  set Directory           = DIRECTORY
  set Statistics interval = 4
  set Write HDF5          = false
  set Progress            = false
end
)";

  const std::string strip_particles = R"(
  set Lattice spacing = 1e-3
  set Horizon factor  = 3.015
  set Body            = strip, holder
end
subsection Regions
  set Names = strip, holder, loaded end
  subsection strip
    set Shape        = box
    set Lower corner = 0, 0
    set Upper corner = 0.02, 0.005
  end
  subsection holder
    set Shape        = box
    set Lower corner = -0.004, 0
    set Upper corner = 0, 0.005
  end
  subsection loaded end
    set Shape        = box
    set Lower corner = 0.019, 0
    set Upper corner = 0.02, 0.005
  end
end
subsection Boundary conditions
  set Names = hold, pull
  subsection hold
    set Region     = holder
    set Type       = displacement
    set Components = x, y
    set Function   = 0; 0
  end
  subsection pull
    set Region          = loaded end
    set Type            = traction
    set Function        = 1e6; 2e5
    set Layer thickness = 1e-3
  end)";

  const std::string strip_mesh = R"(
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 8, 2 : 0.03, 0 : 0.05, 0.005 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3
  end
  subsection Boundary conditions
    set Names = clamp, pull fe
    subsection clamp
      set Boundary ids = 0
      set Components   = x, y
      set Function     = 0; 0
    end
    subsection pull fe
      set Boundary ids = 1
      set Type         = traction
      set Function     = 1e6; 2e5
    end
  end
end)";

  const std::string separate_coupling = R"(
subsection Coupling
  set Method            = separate regions
  set Blending function = min(1, max(0, (0.026 - x) / 0.001))
end)";

  // The largest |a - b| over the owned entries of all ranks.
  template <typename VectorType>
  double
  largest_difference(const VectorType &a, const VectorType &b)
  {
    AssertThrow(a.locally_owned_size() == b.locally_owned_size(),
                ExcMessage("The runs distribute the unknowns differently."));
    double difference = 0.;
    for (unsigned int k = 0; k < a.locally_owned_size(); ++k)
      difference = std::max(difference, std::abs(a.local_element(k) - b.local_element(k)));
    return Utilities::MPI::max(difference, MPI_COMM_WORLD);
  }

  // The final displacements of one region in the coupled run and in that region's own run:
  // identical, bit for bit.
  template <typename VectorType>
  void
  compare_displacements(const std::string &what, const VectorType &coupled, const VectorType &alone)
  {
    const double difference = largest_difference(coupled, alone);
    std::cout << "  final " << what
              << " displacements: " << (difference == 0. ? "identical" : "differ") << " (largest "
              << std::scientific << std::setprecision(6) << coupled.linfty_norm() << " m)"
              << std::endl;
    AssertThrow(difference == 0.,
                ExcMessage("The " + what +
                           " displacements of the coupled run differ from "
                           "those of the region's own run."));
  }

  using Columns = std::map<std::string, std::vector<double>>;

  // Every column of the coupled run's statistics against the two one-region runs': a column of
  // one region only must be that region's; a column of both (energies, work, applied loads,
  // iterations) the sum of the two to the precision of statistics.csv (10 digits); step and
  // time the same. The force balance |applied + reactions| is a norm of the sum, not a sum:
  // its parts are compared as the reaction and applied-load columns.
  void
  compare_statistics(const Columns &coupled, const Columns &pd_alone, const Columns &fe_alone)
  {
    // The energy scale of the run: its largest energy or work, so that the energy error (a
    // small difference of large energies) is held to the energies' precision.
    double energy_scale = 0.;
    for (const auto &[name, values] : coupled)
      if (name.find("energy") != std::string::npos || name == "external_work")
        for (const double value : values)
          energy_scale = std::max(energy_scale, std::abs(value));
    unsigned int n_one = 0, n_sums = 0;
    for (const auto &[name, values] : pd_alone)
      AssertThrow(coupled.count(name), ExcMessage("Column " + name + " is missing."));
    for (const auto &[name, values] : fe_alone)
      AssertThrow(coupled.count(name), ExcMessage("Column " + name + " is missing."));
    for (const auto &[name, values] : coupled)
      {
        if (name == "force_balance")
          continue;
        const bool in_pd = pd_alone.count(name) > 0, in_fe = fe_alone.count(name) > 0;
        AssertThrow(in_pd || in_fe, ExcMessage("Column " + name + " belongs to neither run."));
        const auto &pd = in_pd ? pd_alone.at(name) : fe_alone.at(name);
        const auto &fe = in_fe ? fe_alone.at(name) : pd_alone.at(name);
        AssertThrow(values.size() == pd.size() && values.size() == fe.size(),
                    ExcMessage("Column " + name + " has other rows."));
        const bool additive = in_pd && in_fe && name != "step" && name != "time";
        double     scale    = 0.;
        if (additive && (name.find("energy") != std::string::npos || name == "external_work"))
          scale = energy_scale;
        else
          for (const double value : values)
            scale = std::max(scale, std::abs(value));
        for (unsigned int k = 0; k < values.size(); ++k)
          {
            const double expected = additive ? pd[k] + fe[k] : pd[k];
            AssertThrow(additive ? std::abs(values[k] - expected) <= 2e-9 * scale :
                                   values[k] == expected,
                        ExcMessage("Column " + name + ", row " + std::to_string(k) + ": " +
                                   std::to_string(values[k]) + " in the coupled run, " +
                                   std::to_string(expected) + " from the separate runs."));
          }
        ++(additive ? n_sums : n_one);
      }
    std::cout << "  statistics, " << coupled.at("step").size() << " rows: " << n_one
              << " columns as in one region's run, " << n_sums << " as the sum of both runs"
              << std::endl;
  }

  // The strips coupled by "separate regions" and each alone, with @p solver.
  void
  run_separate(const std::string &solver)
  {
    std::ostringstream log;
    const auto         run = [&](const std::string &name,
                         const std::string &particles,
                         const std::string &mesh,
                         const std::string &coupling) {
      const std::string directory = "separate_" + name;
      coupling_tests::write_file(directory + ".prm",
                                 coupling_tests::substitute(strips,
                                                            {{"PARTICLES", particles},
                                                             {"MESH", mesh},
                                                             {"COUPLING", coupling},
                                                             {"SOLVER", solver},
                                                             {"DIRECTORY", directory}}));
      auto problem = std::make_unique<perideal::CoupledProblem<2>>(MPI_COMM_WORLD, log);
      coupling_tests::parse(*problem, directory + ".prm");
      problem->setup();
      problem->run();
      MPI_Barrier(MPI_COMM_WORLD);
      return std::make_pair(std::move(problem),
                            perideal_tests::read_statistics(directory + "/statistics.csv"));
    };
    const auto coupled  = run("coupled", strip_particles, strip_mesh, separate_coupling);
    const auto pd_alone = run("particles", strip_particles, "", "");
    const auto fe_alone = run("fe", "", strip_mesh, "");

    std::cout << "separate regions, " << solver << std::endl;
    std::istringstream lines(log.str());
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("Coupling: ", 0) == 0)
        std::cout << "  " << line << std::endl;
    compare_displacements("particle",
                          coupled.first->particle_displacement(),
                          pd_alone.first->particle_displacement());
    compare_displacements("FE",
                          coupled.first->fe_displacement(),
                          fe_alone.first->fe_displacement());
    compare_statistics(coupled.second, pd_alone.second, fe_alone.second);
    const auto &energy = coupled.second.at("strain_energy");
    std::cout << "  strain energy at the end: " << std::scientific << std::setprecision(6)
              << energy.back() << " J" << std::endl;
  }
} // namespace

PERIDEAL_REGISTER_COUPLING_METHOD(SharpInterface,
                                  "sharp interface",
                                  "(test) FE energy where beta < 1/2, particles' elsewhere.")
PERIDEAL_REGISTER_COUPLING_METHOD(SeparateRegions,
                                  "separate regions",
                                  "(test) FE where beta < 1/2, particles elsewhere, no "
                                  "interaction.")

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    std::cout.setstate(std::ios::failbit);
  for (const std::string method : {"blended", "sharp interface"})
    {
      run_case(method, translation, "1e-6; 2e-6", method + ", rigid translation");
      run_case(method, tension, "1e-4*x; -1e-4*y/3", method + ", tension 20 MPa");
    }
  for (const std::string solver : {"explicit", "static"})
    run_separate(solver);
}
