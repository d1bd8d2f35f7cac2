// Helpers shared by the tests in tests/coupling.
#ifndef perideal_coupling_tests_h
#define perideal_coupling_tests_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/region.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/damage_model.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <tests.h>

namespace coupling_tests
{
  /**
   * @p text with every occurrence of each key of @p values replaced by its value.
   */
  inline std::string
  substitute(std::string text, const std::map<std::string, std::string> &values)
  {
    for (const auto &[key, value] : values)
      for (auto at = text.find(key); at != std::string::npos;
           at      = text.find(key, at + value.size()))
        text.replace(at, key.size(), value);
    return text;
  }

  /**
   * Write @p text to @p file on rank 0; every rank returns once the file is there.
   */
  inline void
  write_file(const std::string &file, const std::string &text)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(file) << text;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /// The whole text of @p file (empty if there is none).
  inline std::string
  read_text(const std::string &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /**
   * Declare and read the parameters of the coupled problem in @p file and hand them to
   * @p problem, as perideal-solid does: a first pass reads the names of the regions, of the
   * particle and FE boundary conditions and of the physics of <Physics/List> (with theirs),
   * which decide the subsections.
   */
  template <int dim>
  void
  parse(perideal::CoupledProblem<dim> &problem, const std::string &file)
  {
    dealii::ParameterHandler first;
    first.declare_entry("Dimension", "2", dealii::Patterns::Integer(2, 3), "");
    perideal::RegionCollection<dim>::declare_names(first);
    perideal::BoundaryConditions<dim>::declare_names(first);
    perideal::FERegion<dim>::declare_names(first);
    perideal::Physics<dim>::declare_names(first);
    perideal::ParameterUtilities::parse_partially(first, file);
    std::map<std::string, typename perideal::Physics<dim>::ConditionNames> physics;
    for (const auto &[name, conditions] : perideal::Physics<dim>::parse_names(first))
      physics[name] = conditions;
    dealii::ParameterHandler prm;
    perideal::CoupledProblem<dim>::declare_parameters(
      prm,
      perideal::RegionCollection<dim>::parse_names(first),
      perideal::BoundaryConditions<dim>::parse_names(first),
      perideal::FERegion<dim>::parse_names(first),
      physics);
    perideal::ParameterUtilities::parse_file(prm, file);
    problem.parse_parameters(prm);
  }
  /// What run() hands the problem to after the run (a non-deduced context: run<3>(...) with a
  /// generic lambda).
  template <int dim>
  using Inspect =
    typename std::common_type<std::function<void(const perideal::CoupledProblem<dim> &)>>::type;

  /**
   * Write @p text to @p file, run the coupled problem of dimension @p dim it describes and return
   * its log; @p inspect sees the problem after the run.
   */
  template <int dim = 2>
  std::string
  run(const std::string &file, const std::string &text, const Inspect<dim> &inspect = {})
  {
    write_file(file, text);
    std::ostringstream            log;
    perideal::CoupledProblem<dim> problem(MPI_COMM_WORLD, log);
    parse(problem, file);
    problem.setup();
    problem.run();
    if (inspect)
      inspect(problem);
    MPI_Barrier(MPI_COMM_WORLD);
    return log.str();
  }

  /// The torque and the strain energy per unit length of a torsion run (the last row of the
  /// section integrals: total_ of a coupled run, else fe_ or pd_).
  struct SectionIntegrals
  {
    /// Whether the run is FE only (T psi = 2E exactly).
    bool   fe;
    double torque;
    double energy;
  };

  /**
   * Run the benchmark file @p benchmark (a path below doc/benchmarks/) with @p overrides and the
   * output in results/ (no HDF5, no progress) and return its section integrals.
   */
  inline SectionIntegrals
  run_torsion(const std::string &benchmark, const std::string &overrides)
  {
    run("torsion.prm",
        "include " SOURCE_DIR "/../../doc/benchmarks/" + benchmark + "\n" + overrides +
          "subsection Output\n"
          "  set Directory  = results\n"
          "  set Write HDF5 = false\n"
          "  set Progress   = false\n"
          "end\n");
    const auto        columns = perideal_tests::read_statistics("results/statistics.csv");
    const std::string region  = columns.count("total_torque") > 0 ? "total" :
                                columns.count("fe_torque") > 0    ? "fe" :
                                                                    "pd";
    return {region == "fe",
            columns.at(region + "_torque").back(),
            columns.at(region + "_torsion_energy").back()};
  }

  /// The overrides of <Material> for the torsion benchmarks' files with the antiplane model
  /// @p model (mu = 1, twist 1 about the origin, as in the files).
  inline std::string
  torsion_material(const std::string &model)
  {
    // The state-based model as the seed has it (no stabilization), whose torque the
    // benchmarks' tables give.
    return "subsection Material\n  set Model = " + model + "\n  subsection " + model +
           "\n    set Shear modulus = 1\n    set Twist per unit length = 1\n"
           "    set Twist axis = 0, 0\n" +
           (model == "antiplane state based" ? "    set Stabilization = 0\n" : "") + "  end\nend\n";
  }

  /// The overrides of the torsion benchmarks' all-PD files for the lattice spacing @p dx and
  /// the antiplane model @p model: the region 'hold' shrunk to the particle (dx/2, dx/2).
  inline std::string
  torsion_pd_overrides(const double dx, const std::string &model)
  {
    const auto number = [](const double x) {
      std::ostringstream out;
      out << x;
      return out.str();
    };
    return "subsection Discretization\n  set Lattice spacing = " + number(dx) +
           "\nend\n"
           "subsection Regions\n  subsection hold\n    set Lower corner = " +
           number(0.1 * dx) + ", " + number(0.1 * dx) +
           "\n    set Upper corner = " + number(0.9 * dx) + ", " + number(0.9 * dx) +
           "\n  end\nend\n" + torsion_material(model);
  }

  /**
   * The strip of the tests of the adaptive PD region (adaptive_region_01, _02, the bad input):
   * 100 x 20 mm (2D, plane strain) or 100 x 20 x 10 mm (@p dim = 3), free, PMB at dx = 1 mm (2D)
   * or 2 mm (3D) with FE elasticity of the same material on @p cells ("nx, ny[, nz]") Q1 cells,
   * the blending function @p beta, <Coupling/Adaptive region> with @p criterion (5 % of the
   * critical stretch 0.01 for 'principal strain', checked every 5 steps; core radius 9 mm, ramp
   * 6 mm in 2D and 7 mm in 3D, at least a horizon) and the initial seeds @p seeds, a pulse of
   * velocity 20 exp(-((x - 20 mm) / 6 mm)^2) m/s along x, 120 steps of 0.1 us, no HDF5 output,
   * results in results/.
   */
  inline std::string
  adaptive_strip(const std::string &cells,
                 const std::string &beta,
                 const std::string &criterion,
                 const std::string &seeds,
                 const unsigned int dim = 2)
  {
    const bool three = dim == 3;
    return substitute(
      R"(
set Dimension = DIM
subsection Discretization
  set Lattice spacing = SPACING
  set Horizon factor  = 3.015
  set Thickness       = 1
  set Body            = strip
end
subsection Regions
  set Names = strip
  subsection strip
    set Shape        = box
    set Lower corner = LOWER
    set Upper corner = UPPER
  end
end
subsection Material
  set Model             = bond based
PLANAR  set Density           = 8000
  set Damage model      = critical stretch
  subsection bond based
    set Young's modulus = 191e9
  end
  subsection critical stretch
    set Critical stretch = 0.01
  end
end
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = CELLS : LOWER : UPPER : true
  set Density             = 8000
  subsection Elasticity
    set Young's modulus = 191e9
    set Poisson's ratio = 0.25
  end
end
subsection Coupling
  set Method            = blended
  set Blending function = BETA
  subsection Adaptive region
    set Criterion       = CRITERION
    set Strain fraction = 0.05
    set Check interval  = 5
    set Core radius     = 0.009
    set Ramp width      = RAMP
    set Damage distance = 0.0045
    set Initial seeds   = SEEDS
  end
end
subsection Initial conditions
  set Velocity = 20 * exp(-((x - 0.02) / 0.006)^2); 0ZERO
end
subsection Time stepping
  set End time  = 1.2e-5
  set Time step = 1e-7
end
subsection Output
  set Directory  = results
  set Write HDF5 = false
  set Progress   = false
end
)",
      {{"DIM", std::to_string(dim)},
       {"SPACING", three ? "2e-3" : "1e-3"},
       {"LOWER", three ? "0, 0, 0" : "0, 0"},
       {"UPPER", three ? "0.1, 0.02, 0.01" : "0.1, 0.02"},
       {"RAMP", three ? "0.007" : "0.006"},
       {"ZERO", three ? "; 0" : ""},
       {"PLANAR", three ? "" : "  set Planar assumption = plane strain\n"},
       {"CELLS", cells},
       {"BETA", beta},
       {"CRITERION", criterion},
       {"SEEDS", seeds}});
  }

  /// Rank 0: the reference position and damage index of every particle of @p problem (x, y,
  /// damage per particle; 2D), other ranks: empty. Collective.
  inline std::vector<double>
  gather_damage(const perideal::CoupledProblem<2> &problem)
  {
    const auto         &ps     = problem.particles();
    const auto          damage = perideal::damage_index(ps);
    std::vector<double> local, all;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (const double value : {ps.positions()[i][0], ps.positions()[i][1], damage[i]})
        local.push_back(value);
    for (const auto &part : dealii::Utilities::MPI::gather(MPI_COMM_WORLD, local))
      all.insert(all.end(), part.begin(), part.end());
    return all;
  }

  /// The crack particles of a Kalthoff-Winkler run on the side @p side (+1: y > 0) of the
  /// gathered particles @p points (gather_damage()): damage index >= 0.35, beyond the notch
  /// tips (x = 50 mm) by more than @p horizon (the pre-cracks damage particles within a horizon
  /// of their tips).
  inline std::vector<dealii::Point<2>>
  kalthoff_crack_particles(const std::vector<double> &points,
                           const double               side,
                           const double               horizon)
  {
    std::vector<dealii::Point<2>> result;
    for (std::size_t k = 0; k + 3 <= points.size(); k += 3)
      if (points[k + 2] >= 0.35 && points[k] > 0.05 + horizon && side * points[k + 1] > 0.)
        result.emplace_back(points[k], points[k + 1]);
    return result;
  }

  /// The distance from @p point to the nearest of @p points (max double if there is none).
  inline double
  nearest_distance(const dealii::Point<2> &point, const std::vector<dealii::Point<2>> &points)
  {
    double nearest = std::numeric_limits<double>::max();
    for (const auto &q : points)
      nearest = std::min(nearest, point.distance(q));
    return nearest;
  }

  /// The largest distance from a point of one set to the nearest point of the other (the
  /// symmetric Hausdorff distance).
  inline double
  hausdorff(const std::vector<dealii::Point<2>> &a, const std::vector<dealii::Point<2>> &b)
  {
    double largest = 0.;
    for (const auto &p : a)
      largest = std::max(largest, nearest_distance(p, b));
    for (const auto &p : b)
      largest = std::max(largest, nearest_distance(p, a));
    return largest;
  }

  /// Link the repository's 'doc' and 'meshes' into the working directory, for parameter files
  /// that name their includes and meshes relative to the top directory. Collective.
  inline void
  link_top_directories()
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      for (const std::string directory : {"doc", "meshes"})
        if (!std::filesystem::exists(directory))
          std::filesystem::create_directory_symlink(SOURCE_DIR "/../../" + directory, directory);
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /// The number of occurrences of @p text in @p log.
  inline unsigned int
  count_lines(const std::string &log, const std::string &text)
  {
    unsigned int n = 0;
    for (auto at = log.find(text); at != std::string::npos; at = log.find(text, at + 1))
      ++n;
    return n;
  }

  /**
   * The conversions of an adaptive run (its @p log and results/statistics.csv) printed as one
   * line, with 3 digits: the conversions, the @p n_particles at the end against the
   * @p plate_points of the whole plate's lattice, and the energy change of the conversions
   * against the external work. Returns that change over the work.
   */
  inline double
  print_conversions(const std::string &log,
                    const unsigned int n_particles,
                    const double       plate_points)
  {
    const auto   stats  = perideal_tests::read_statistics("results/statistics.csv");
    const double change = stats.at("conversion_energy").back() / stats.at("external_work").back();
    std::cout << std::setprecision(3) << count_lines(log, "the PD region grew")
              << " conversions; particles at the end " << n_particles << ", "
              << n_particles / plate_points << " of the plate's lattice; energy change of the "
              << "conversions " << change << " of the external work" << std::endl;
    return change;
  }

  /// "ok" if @p condition holds, "FAILED" otherwise.
  inline const char *
  ok(const bool condition)
  {
    return condition ? "ok" : "FAILED";
  }

  // The numbers in the line of @p log that starts with @p key (after the key).
  inline std::vector<double>
  numbers_of(const std::string &log, const std::string &key)
  {
    std::istringstream lines(log);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind(key, 0) == 0)
        {
          std::vector<double> numbers;
          const std::string   rest = line.substr(key.size());
          for (std::size_t at = 0; at < rest.size();)
            {
              const std::size_t start = rest.find_first_of("0123456789", at);
              if (start == std::string::npos)
                break;
              std::size_t length = 0;
              numbers.push_back(std::stod(rest.substr(start), &length));
              at = start + length;
            }
          return numbers;
        }
    std::cout << "line '" << key << "' missing (FAILED)" << std::endl;
    return {std::nan(""), std::nan(""), std::nan("")};
  }

  /**
   * The plate of the tests of several physics (multiphysics_*, restart_multiphysics_*): the
   * sections Dimension, Discretization and Regions of a 20 mm x 10 mm plane-stress plate, dx =
   * 1 mm (200 particles), with the regions plate, left (x < 3 mm), right (x > 17 mm) and, if
   * @p top, top (8 mm < x < 12 mm, y > 9 mm).
   */
  inline std::string
  multiphysics_plate(const bool top = false)
  {
    return R"(
set Dimension = 2
subsection Discretization
  set Lattice spacing = 1e-3
  set Thickness       = 1e-3
  set Body            = plate
end
subsection Regions
  set Names = plate, left, right)" +
           std::string(top ? ", top" : "") + R"(
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
  end)" +
           std::string(top ? R"(
  subsection top
    set Lower corner = 0.008, 0.009
    set Upper corner = 0.012, 0.01
  end)" :
                             "") +
           R"(
end
)";
  }

  /// The plate's mechanics: <Material> of PMB (E = 200 GPa, rho = 7800 kg/m^3), with a critical
  /// stretch of 1e-3 if @p damage.
  inline std::string
  multiphysics_mechanics(const bool damage)
  {
    return R"(
subsection Material
  set Model   = bond based
  set Density = 7800
  set Damage model = )" +
           std::string(damage ? "critical stretch" : "none") + R"(
  subsection bond based
    set Young's modulus = 200e9
  end
  subsection critical stretch
    set Critical stretch = 1e-3
  end
end
)";
  }

  /// The plate's heat: <Material> of the bond based conduction, k = 50 W/(m K), rho c = 1
  /// J/(m^3 K) (the heat diffuses across the plate in microseconds).
  inline std::string
  multiphysics_conduction()
  {
    return R"(
subsection Material
  set Model   = bond based conduction
  set Density = 1
  subsection bond based conduction
    set Conductivity  = 50
    set Specific heat = 1
  end
end
)";
  }

  /**
   * The plate's FE part (a mesh of 2 mm cells over the plate, the particles blended out from
   * x = 12 mm to 16 mm): for the mechanics (@p heat false) <Finite elements> with the mesh and
   * its elasticity, and <Coupling>; for the heat its <Finite elements> of the FE heat (k, rho c
   * as multiphysics_conduction()).
   */
  inline std::string
  multiphysics_fe(const bool heat)
  {
    if (heat)
      return R"(
subsection Finite elements
  set Physics = heat
  set Density = 1
  subsection heat
    set Conductivity  = 50
    set Specific heat = 1
  end
end
)";
    return R"(
subsection Finite elements
  set Generator           = subdivided_hyper_rectangle
  set Generator arguments = 10, 5 : 0, 0 : 0.02, 0.01 : true
  set Density             = 7800
  subsection Elasticity
    set Young's modulus = 200e9
    set Poisson's ratio = 0.3333333333333333
  end
end
subsection Coupling
  set Blending function = min(1, max(0, (0.016 - x) / 0.004))
end
)";
  }

  /// The plate's heat as the restart tests start it: 100 K in the left half and 0 in the
  /// right one, the left 3 mm held at 200 K (heat comes in).
  inline std::string
  multiphysics_heat_start()
  {
    return R"(
subsection Initial conditions
  set Displacement = if(x < 0.01, 100, 0)
end
subsection Boundary conditions
  set Names = hot
  subsection hot
    set Region   = left
    set Function = 200
  end
end
)";
  }

  /// The sections that add the physics @p heat (its entries, as the heat alone has them at
  /// the top level) as <Physics/List> = heat.
  inline std::string
  with_heat(const std::string &heat)
  {
    return "subsection Physics\n  set List = heat\nend\nsubsection Heat\n" + heat + "end\n";
  }

} // namespace coupling_tests

#endif
