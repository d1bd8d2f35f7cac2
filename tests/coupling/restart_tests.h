// ---------------------------------------------------------------------
// The harness of the restart tests (restart_01: runs without softening bonds, restart_03: with
// softening Timoshenko bonds). Checkpoint and restart (<Output/Checkpoint interval>,
// CoupledProblem::restart_from_checkpoint()): a run stopped after the checkpoint of step K and
// restarted from it ends with the numbers of the run that did not stop. Three runs, each with bonds
// or an FE region in its state:
//  - explicit dynamics with bond breaking: the PMB plate of app-solid/plate_2d_pmb pulled by its
//    grips, a pre-crack and a critical stretch of 1e-3 (the grips start at 10 m/s: 3570 bonds
//    are broken after step K = 5 of 80, 3726 at the end);
//  - a static run with load steps and bond breaking: app-solid/coupled_static_crack_2d (FE and
//    PD) with its grips moved twice as far in 10 load steps (the crack grows from step 5; K = 7);
//  - a coupled explicit run: app-solid/coupled_wave_2d (FE and PD, a wave through the overlap);
//  - the first run with softening Timoshenko bonds (nu = 0.25, Failure law = softening): the
//    state of a bond is then its histories (largest strain per mode, energy dissipated), which
//    the restart must restore; the dissipated energy at the stop and at the end is printed;
//  - coupled adaptive dynamic relaxation with softening Timoshenko bonds:
//    app-solid/coupled_adr_crack_2d (nu = 0.25 on both sides, the grips moved 2 x 6 um in 6
//    load steps, relative residual 1e-10): the bonds soften from step 5 on; stopped after step 5,
//    the last load step re-solved while the histories grow (until 2026-12-07 8 load steps to
//    2 x 8 um, stopped after step 6: a third more ADR iterations, the same checks). Restarted
//    on another number of ranks, ADR follows another round-off path to the same residual, so
//    the displacements agree to the solver's accuracy, not to round-off: measured 4e-9 of the
//    largest value (with the 8 load steps), checked against 1e-7 (1000 x the relative residual;
//    the other runs 1e-10).
// On the same number of ranks the final particle and FE displacements must be equal bit for bit,
// and statistics.csv and the XDMF records must be the same files (no row lost or repeated). On 2
// ranks each run is also stopped on 1 rank and restarted on 2, and stopped on 2 and restarted on
// 1: the displacements must then agree with the run on the ranks of the restart to 1e-10 of
// their largest value, and each statistics column to 1e-10 of its largest value plus 10 times
// the difference between the uninterrupted runs on 1 and 2 ranks (columns that vanish by
// symmetry, the x reactions and the force balance, are round-off themselves and differ by as
// much between the rank counts as they are large). With a second physics of <Physics/List>
// (restart_multiphysics_02) its particle and FE fields are checked the same way, and its XDMF
// records are files of the comparison too.
// ---------------------------------------------------------------------
#ifndef perideal_tests_restart_tests_h
#define perideal_tests_restart_tests_h

#include <deal.II/base/mpi.h>

#include <perideal/coupling/coupled_problem.h>

#include "coupling_tests.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <tests.h>

namespace restart_tests
{
  using namespace dealii;

  struct Case
  {
    std::string name;
    std::string text;
    // The stop step as a fraction of the steps of the run.
    double stop_fraction;
    // The largest difference of the displacements after a restart on another number of ranks,
    // relative to their largest value.
    double cross_rank_tolerance = 1e-10;
  };

  struct Result
  {
    // The first physics' particle and FE fields; those of a second physics of <Physics/List>
    // (particles, then FE dofs; empty without one).
    std::vector<double> u, U, T;
    unsigned int        n_steps = 0;
  };

  // Run @p text with its output in @p directory on @p comm (nothing on ranks outside it):
  // stopped after step @p stop, or restarted from the checkpoint there.
  inline Result
  run(const MPI_Comm     comm,
      const std::string &text,
      const std::string &directory,
      const unsigned int stop,
      const bool         restart)
  {
    Result result;
    // No lines of the direct solver's solver control.
    const unsigned int depth = deallog.depth_file(0);
    if (comm != MPI_COMM_NULL)
      {
        const std::string file = directory + ".prm";
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          std::ofstream(file) << text << "subsection Output\n  set Directory = " << directory
                              << "\n  set Progress = false\nend\n";
        MPI_Barrier(comm);
        std::ostringstream          log;
        perideal::CoupledProblem<2> problem(comm, log);
        coupling_tests::parse(problem, file);
        problem.setup();
        if (restart)
          problem.restart_from_checkpoint();
        if (stop > 0)
          problem.stop_after_step(stop);
        problem.run();
        const auto &u = problem.particle_displacement();
        const auto &U = problem.fe_displacement();
        result.u.assign(u.begin(), u.begin() + u.locally_owned_size());
        result.U.assign(U.begin(), U.begin() + U.locally_owned_size());
        const auto &physics = problem.get_physics();
        if (physics.size() > 1)
          for (const auto *field : {&physics[1]->state().u, &physics[1]->state().U})
            result.T.insert(result.T.end(),
                            field->begin(),
                            field->begin() + field->locally_owned_size());
        // "Sequentially linear control: N events, ..." (the summary of a run that ended), "Time
        // step: dt s, steps: N", "Static solve: n unknowns (...), N load step(s)" or "Adaptive
        // dynamic relaxation: n unknowns (...), N load step(s)" (rank 0 prints).
        const std::string text = log.str();
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          for (const std::string key : {"Sequentially linear control:",
                                        "Time step:",
                                        "Static solve:",
                                        "Adaptive dynamic relaxation:"})
            if (text.find(key) != std::string::npos)
              {
                const auto numbers = coupling_tests::numbers_of(text, key);
                result.n_steps =
                  std::lround(key[0] == 'S' && key[1] == 'e' ? numbers.front() : numbers.back());
                break;
              }
      }
    deallog.depth_file(depth);
    result.n_steps = Utilities::MPI::broadcast(MPI_COMM_WORLD, result.n_steps, 0);
    return result;
  }

  // The largest difference of @p a and @p b over the ranks of @p comm, relative to the largest
  // value of @p a (0 if both vanish).
  inline double
  relative_difference(const std::vector<double> &a,
                      const std::vector<double> &b,
                      const MPI_Comm             comm)
  {
    AssertDimension(a.size(), b.size());
    double difference = 0., scale = 0.;
    for (std::size_t k = 0; k < a.size(); ++k)
      {
        difference = std::max(difference, std::abs(a[k] - b[k]));
        scale      = std::max(scale, std::abs(a[k]));
      }
    difference = Utilities::MPI::max(difference, comm);
    scale      = Utilities::MPI::max(scale, comm);
    return scale > 0. ? difference / scale : difference;
  }

  // The largest difference of the largest value of @p column over the rows of the same column
  // of @p other (infinite if the number of rows differs).
  inline double
  column_difference(const std::vector<double> &column, const std::vector<double> &other)
  {
    if (other.size() != column.size())
      return HUGE_VAL;
    double difference = 0.;
    for (std::size_t k = 0; k < column.size(); ++k)
      difference = std::max(difference, std::abs(column[k] - other[k]));
    return difference;
  }

  // Whether every column of the statistics file @p restarted differs from the same column of
  // @p reference by at most 1e-10 of the column's largest value plus 10 times the difference of
  // the runs that did not stop on 1 and on 2 ranks (@p one, @p two): columns that vanish by
  // symmetry (x reactions, force balance) are round-off themselves.
  inline bool
  statistics_agree(const std::string &reference,
                   const std::string &restarted,
                   const std::string &one,
                   const std::string &two)
  {
    const auto x = perideal_tests::read_statistics(reference),
               y = perideal_tests::read_statistics(restarted),
               a = perideal_tests::read_statistics(one), b = perideal_tests::read_statistics(two);
    if (x.size() != y.size())
      return false;
    for (const auto &[name, column] : x)
      {
        if (y.count(name) == 0)
          return false;
        double scale = 0.;
        for (const double value : column)
          scale = std::max(scale, std::abs(value));
        if (column_difference(column, y.at(name)) >
            1e-10 * scale + 10. * column_difference(a.at(name), b.at(name)))
          return false;
      }
    return true;
  }

  inline std::size_t
  n_lines(const std::string &file)
  {
    const std::string text = coupling_tests::read_text(file);
    return std::count(text.begin(), text.end(), '\n');
  }

  inline void
  check(const Case &c)
  {
    const bool         root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const Result       full = run(MPI_COMM_WORLD, c.text, c.name + "_full", 0, false);
    const unsigned int stop = std::lround(c.stop_fraction * full.n_steps);
    run(MPI_COMM_WORLD, c.text, c.name + "_stopped", stop, false);
    const std::size_t rows_at_stop = n_lines(c.name + "_stopped/statistics.csv");
    const auto        broken_bonds = [&]() {
      return root ? perideal_tests::read_statistics(c.name + "_stopped/statistics.csv")
                      .at("broken_bonds")
                      .back() :
                           0.;
    };
    const double broken_at_stop = broken_bonds();
    const auto   dissipated     = [&]() {
      if (!root)
        return 0.;
      const auto statistics = perideal_tests::read_statistics(c.name + "_stopped/statistics.csv");
      return statistics.count("dissipated_energy") ? statistics.at("dissipated_energy").back() : 0.;
    };
    const double dissipated_at_stop = dissipated();
    const Result restarted          = run(MPI_COMM_WORLD, c.text, c.name + "_stopped", 0, true);
    const double du                 = relative_difference(full.u, restarted.u, MPI_COMM_WORLD);
    const double dU                 = relative_difference(full.U, restarted.U, MPI_COMM_WORLD);
    const double dT                 = relative_difference(full.T, restarted.T, MPI_COMM_WORLD);
    if (root)
      {
        const std::vector<std::string> files{"statistics.csv",
                                             "particles.xdmf",
                                             "solution.xdmf",
                                             "particles_heat.xdmf",
                                             "solution_heat.xdmf"};
        deallog << c.name << ": " << full.n_steps << " steps, stopped after " << stop
                << " (statistics.csv: " << rows_at_stop
                << " lines), restarted: " << n_lines(c.name + "_stopped/statistics.csv")
                << " lines; broken bonds: " << broken_at_stop << " at the stop, " << broken_bonds()
                << " at the end; dissipated energy: " << dissipated_at_stop << " J at the stop, "
                << dissipated() << " J at the end" << std::endl;
        deallog << "  largest difference of the particle displacements " << du
                << ", of the FE displacements " << dU << ": "
                << coupling_tests::ok(du == 0. && dU == 0.) << std::endl;
        if (!full.T.empty())
          deallog << "  largest difference of the heat's temperatures " << dT << ": "
                  << coupling_tests::ok(dT == 0. && restarted.T.size() == full.T.size())
                  << std::endl;
        for (const auto &file : files)
          if (std::filesystem::exists(c.name + "_full/" + file))
            {
              const bool same = coupling_tests::read_text(c.name + "_full/" + file) ==
                                coupling_tests::read_text(c.name + "_stopped/" + file);
              deallog << "  " << file << " the same file: " << coupling_tests::ok(same)
                      << std::endl;
            }
      }

    // On 2 ranks: stopped on 1 rank and restarted on 2, and the other way round.
    if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) != 2)
      return;
    MPI_Comm one;
    MPI_Comm_split(MPI_COMM_WORLD, root ? 0 : MPI_UNDEFINED, 0, &one);
    const Result full_one = run(one, c.text, c.name + "_full_one", 0, false);
    for (const bool from_one : {true, false})
      {
        const std::string directory = c.name + (from_one ? "_one_to_two" : "_two_to_one");
        run(from_one ? one : MPI_COMM_WORLD, c.text, directory, stop, false);
        const MPI_Comm on        = from_one ? MPI_COMM_WORLD : one;
        const Result   restarted = run(on, c.text, directory, 0, true);
        const Result  &reference = from_one ? full : full_one;
        double         du = 0., dU = 0., dT = 0.;
        if (on != MPI_COMM_NULL)
          {
            du = relative_difference(reference.u, restarted.u, on);
            dU = relative_difference(reference.U, restarted.U, on);
            dT = relative_difference(reference.T, restarted.T, on);
          }
        if (root)
          deallog << "  stopped on " << (from_one ? 1 : 2) << " rank(s), restarted on "
                  << (from_one ? 2 : 1) << ": particle and FE displacements within "
                  << c.cross_rank_tolerance << " of the largest value: "
                  << coupling_tests::ok(du < c.cross_rank_tolerance &&
                                        dU < c.cross_rank_tolerance && dT < c.cross_rank_tolerance)
                  << ", statistics columns within round-off: "
                  << coupling_tests::ok(statistics_agree(c.name +
                                                           (from_one ? "_full" : "_full_one") +
                                                           "/statistics.csv",
                                                         directory + "/statistics.csv",
                                                         c.name + "_full_one/statistics.csv",
                                                         c.name + "_full/statistics.csv"))
                  << std::endl;
      }
    if (one != MPI_COMM_NULL)
      MPI_Comm_free(&one);
  }

  // The five runs, in the order of the header comment (the application tests' files are read from
  // @p app).
  inline std::vector<Case>
  cases(const std::string &app)
  {
    const std::string statistics_every_step =
      "subsection Output\n  set Statistics interval = 1\n  set Output interval = 10\n"
      "  set Write HDF5 = true\nend\n";
    const auto softening = [](const std::string &youngs_modulus, const std::string &stretch) {
      return "subsection Material\n  set Model = timoshenko bond based\n"
             "  set Damage model = critical stretch\n"
             "  subsection critical stretch\n    set Critical stretch = " +
             stretch +
             "\n  end\n"
             "  subsection timoshenko bond based\n    set Young's modulus = " +
             youngs_modulus +
             "\n    set Poisson's ratio = 0.25\n    set Failure law = softening\n  end\nend\n";
    };
    return {
      {"explicit_breaking",
       "include " + app + "plate_2d_pmb.prm\n" + statistics_every_step +
         "subsection Output\n  set Probe points =\nend\n"
         "subsection Pre-cracks\n  set Cracks = 0.003, 0.005 : 0.007, 0.005\nend\n"
         "subsection Material\n  set Damage model = critical stretch\n"
         "  subsection critical stretch\n    set Critical stretch = 1e-3\n  end\nend\n",
       0.06},
      {"static_breaking",
       "include " + app + "coupled_static_crack_2d.prm\n" +
         "subsection Finite elements\n  subsection Boundary conditions\n"
         "    subsection bottom\n      set Function = 0; -1e-5\n    end\n"
         "    subsection top\n      set Function = 0; 1e-5\n    end\n  end\nend\n"
         "subsection Solver\n  set Load steps = 10\nend\n",
       0.7},
      {"coupled_explicit", "include " + app + "coupled_wave_2d.prm\n" + statistics_every_step, 0.5},
      {"explicit_softening",
       "include " + app + "plate_2d_pmb.prm\n" + statistics_every_step +
         "subsection Output\n  set Probe points =\nend\n"
         "subsection Pre-cracks\n  set Cracks = 0.003, 0.005 : 0.007, 0.005\nend\n" +
         softening("192e9", "1e-3"),
       0.3},
      {"coupled_adr_softening",
       "include " + app + "coupled_adr_crack_2d.prm\n" + softening("200e9", "2.5e-4") +
         "subsection Finite elements\n  subsection Elasticity\n    set Poisson's ratio = 0.25\n"
         "  end\n  subsection Boundary conditions\n    subsection bottom\n"
         "      set Function = 0; -6e-6\n    end\n    subsection top\n"
         "      set Function = 0; 6e-6\n    end\n  end\nend\n"
         "subsection Solver\n  set Load steps = 6\n  set Tolerance = 1e-10\nend\n",
       0.75,
       1e-7}};
  }
} // namespace restart_tests

#endif
