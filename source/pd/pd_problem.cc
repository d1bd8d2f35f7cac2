// ---------------------------------------------------------------------
// PeriDeal: a peridynamic problem driven by a parameter file.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/pd_problem.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    std::string
    zero_vector(const unsigned int dim)
    {
      return dim == 2 ? "0; 0" : "0; 0; 0";
    }

    template <int dim>
    std::vector<PreCrack<dim>>
    parse_pre_cracks(const std::string &text)
    {
      std::vector<PreCrack<dim>> cracks;
      for (const auto &item : Utilities::split_string_list(text, ';'))
        {
          if (item.empty())
            continue;
          const auto vertices = Utilities::split_string_list(item, ':');
          AssertThrow(vertices.size() == dim,
                      ExcMessage("Each crack in <Pre-cracks/Cracks> needs " + std::to_string(dim) +
                                 " points separated by ':' (2D: the two ends of a segment; 3D: a "
                                 "corner and its two neighbouring corners); found <" +
                                 item + ">."));
          PreCrack<dim> crack;
          for (unsigned int v = 0; v < dim; ++v)
            crack.vertices[v] =
              ParameterUtilities::parse_point<dim>(vertices[v], "Pre-cracks/Cracks");
          cracks.push_back(crack);
        }
      return cracks;
    }
  } // namespace

  SolverType
  solver_type_from_name(const std::string &name)
  {
    static const std::map<std::string, SolverType> types = {
      {"explicit", SolverType::explicit_dynamics},
      {"adaptive dynamic relaxation", SolverType::adaptive_dynamic_relaxation},
      {"static", SolverType::static_linear}};
    const auto found = types.find(name);
    AssertThrow(found != types.end(),
                ExcMessage("The parameter <Solver/Type> is <" + name +
                           ">; accepted: explicit, adaptive dynamic relaxation, static."));
    return found->second;
  }

  template <int dim>
  PDProblem<dim>::PDProblem(const MPI_Comm comm, std::ostream &log)
    : communicator(comm)
    , log(log)
    , is_root(Utilities::MPI::this_mpi_process(comm) == 0)
    , particle_system(comm)
  {}

  template <int dim>
  void
  PDProblem<dim>::declare_parameters(ParameterHandler               &prm,
                                     const std::vector<std::string> &region_names,
                                     const std::vector<std::string> &condition_names)
  {
    prm.declare_entry("Dimension",
                      std::to_string(dim),
                      Patterns::Integer(2, 3),
                      "2 (in-plane: plane stress or plane strain) or 3. Read first.");
    prm.enter_subsection("Discretization");
    {
      prm.declare_entry("Lattice spacing",
                        "0",
                        Patterns::Double(0.),
                        "Distance dx between neighbouring particles of the lattice [m].");
      prm.declare_entry("Horizon factor",
                        "3.015",
                        Patterns::Double(0.),
                        "Horizon delta as a multiple of the lattice spacing [-]; must exceed 1.");
      prm.declare_entry("Thickness",
                        "1",
                        Patterns::Double(0.),
                        "2D only: thickness h of the body [m]; particle volume dx^2 h.");
      prm.declare_entry("Partial volume correction",
                        "book",
                        Patterns::Selection("none|book|geometric"),
                        "How neighbours cut by the horizon count: 'none' (|xi| <= delta, full "
                        "volume); 'book' (|xi| <= delta, volume scaled by (delta + dx/2 - "
                        "|xi|)/dx beyond delta - dx/2, as in Madenci & Oterkus' codes and LAMMPS: "
                        "the family lacks 12-14 % of the horizon volume, which the surface "
                        "correction restores, so use it with 'Surface correction = true'); "
                        "'geometric' (the same factor with the family extended to delta + dx/2, "
                        "the cells the horizon cuts: right bulk stiffness without surface "
                        "correction, but an effective Poisson ratio 5 % low at delta = 3.015 dx). "
                        "See doc/architecture.md.");
      prm.declare_entry("Surface correction",
                        "true",
                        Patterns::Bool(),
                        "Correct the stiffness near free surfaces: energy method for 'bond "
                        "based', discrete weighted volume for 'linear peridynamic solid'.");
      prm.declare_entry("Body",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of the regions whose union is filled with "
                        "particles (fictitious boundary layers included).");
    }
    prm.leave_subsection();

    RegionCollection<dim>::declare_parameters(prm, region_names);

    prm.enter_subsection("Pre-cracks");
    prm.declare_entry("Cracks",
                      "",
                      Patterns::Anything(),
                      "Cracks separated by ';'. 2D: 'x0, y0 : x1, y1' (a segment); 3D: "
                      "'a : b : c' (the parallelogram with corner a and edges b - a, c - a) [m]. "
                      "Bonds that cross a crack start broken.");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      prm.declare_entry("Model",
                        "bond based",
                        Patterns::Selection(PluginRegistry<MaterialModel<dim>>::pattern_string()),
                        "The peridynamic material model. " +
                          PluginRegistry<MaterialModel<dim>>::documentation());
      prm.declare_entry("Planar assumption",
                        "plane stress",
                        Patterns::Selection("plane stress|plane strain"),
                        "2D only: the state of the third direction.");
      prm.declare_entry("Density", "0", Patterns::Double(0.), "Mass density rho [kg/m^3].");
      prm.declare_entry("No-fail regions",
                        "",
                        Patterns::Anything(),
                        "Comma-separated regions in which bonds never break (a bond with an end "
                        "there is kept), e.g. the layers that carry a traction.");
      prm.declare_entry("Damage model",
                        "none",
                        Patterns::Selection(PluginRegistry<DamageModel<dim>>::pattern_string()),
                        "When bonds break. " + PluginRegistry<DamageModel<dim>>::documentation());
      PluginRegistry<MaterialModel<dim>>::declare_parameters(prm);
      PluginRegistry<DamageModel<dim>>::declare_parameters(prm);
    }
    prm.leave_subsection();

    BoundaryConditions<dim>::declare_parameters(prm, condition_names);

    prm.enter_subsection("Initial conditions");
    prm.declare_entry("Displacement",
                      zero_vector(dim),
                      Patterns::Anything(),
                      "Initial displacement u(x) [m], one expression of x, y, (z) per component, "
                      "separated by ';'.");
    prm.declare_entry("Velocity",
                      zero_vector(dim),
                      Patterns::Anything(),
                      "Initial velocity v(x) [m/s], one expression per component.");
    prm.leave_subsection();

    prm.enter_subsection("Time stepping");
    ParameterUtilities::declare_time_stepping(prm);
    prm.declare_entry("Damping",
                      "0",
                      Patterns::Double(0.),
                      "Mass-proportional damping coefficient [1/s] to reach a steady state; 0 for "
                      "dynamics.");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    prm.declare_entry("Type",
                      "explicit",
                      Patterns::Selection("explicit|adaptive dynamic relaxation|static"),
                      "'explicit': velocity-Verlet dynamics to <Time stepping/End time>; "
                      "'adaptive dynamic relaxation': quasi-static equilibrium (Kilic & Madenci "
                      "2010) in load steps with bond breaking; 'static': the model linearized "
                      "about the reference configuration, a sparse linear solve per load step. "
                      "Quasi-static runs evaluate the boundary-condition functions at t = End "
                      "time and scale them by the load factor.");
    prm.declare_entry("Load steps",
                      "1",
                      Patterns::Integer(1),
                      "Quasi-static: number N of load steps; step k applies k/N of the prescribed "
                      "displacements and loads.");
    prm.declare_entry("Tolerance",
                      "1e-8",
                      Patterns::Double(0.),
                      "Quasi-static: relative residual at which a solve stops. Adaptive dynamic "
                      "relaxation: ||F|| / max(||F_ext||, ||F_0||) of the residual force density "
                      "on free components; static: ||K u - F|| / ||F|| of CG.");
    prm.declare_entry("Maximum iterations",
                      "100000",
                      Patterns::Integer(1),
                      "Quasi-static: largest number of iterations of one solve (relaxation "
                      "iterations or CG iterations).");
    prm.declare_entry("Density safety factor",
                      "1",
                      Patterns::Double(0.),
                      "Adaptive dynamic relaxation: the fictitious density is this factor times "
                      "1/4 of the model's Gershgorin stiffness bound; accepted: >= 1.");
    prm.declare_entry("Linear solver",
                      "cg amg",
                      Patterns::Selection("cg amg|direct"),
                      "Static: conjugate gradients with algebraic multigrid (Trilinos ML), or a "
                      "direct solver (Amesos KLU) for small problems.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", Patterns::Anything(), "Where results are written.");
    prm.declare_entry("Base name", "particles", Patterns::Anything(), "Prefix of particle files.");
    prm.declare_entry("Output interval",
                      "0",
                      Patterns::Integer(0),
                      "Explicit: write the particle and FE fields every this many steps (0: first "
                      "and last step only); quasi-static runs write them after the last load "
                      "step.");
    prm.declare_entry("Statistics interval",
                      "10",
                      Patterns::Integer(1),
                      "Write a row of statistics.csv every this many steps.");
    prm.declare_entry("Write HDF5", "true", Patterns::Bool(), "Particle fields as HDF5 + XDMF.");
    prm.declare_entry("Write VTU", "false", Patterns::Bool(), "Particle fields as VTU + PVD.");
    prm.declare_entry("Progress", "true", Patterns::Bool(), "Print progress and timing lines.");
    prm.declare_entry("Probe points",
                      "",
                      Patterns::Anything(),
                      "Points (coordinates separated by ',', points by ';') whose nearest "
                      "particle's displacement the final summary prints, in micrometres (um). "
                      "Each point needs a particle within one lattice spacing (coupled runs: in "
                      "the PD region or its overlap). Empty: none.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  PDProblem<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    // An empty <Body>: no particles (an FE-only problem); the PD entries are then not read,
    // except those the FE region shares (planar assumption, thickness).
    body_regions = ParameterUtilities::split_names(prm.get("Body"));
    if (has_body())
      {
        discretization.spacing = prm.get_double("Lattice spacing");
        ParameterUtilities::require_positive(discretization.spacing,
                                             "Discretization/Lattice spacing");
      }
    else
      discretization.spacing = 1.; // a lattice for no particles
    horizon_factor = prm.get_double("Horizon factor");
    AssertThrow(horizon_factor > 1.,
                ExcMessage("The parameter <Discretization/Horizon factor> is " +
                           ParameterUtilities::format_number(horizon_factor) +
                           ": the horizon must be larger than the lattice spacing (accepted: > 1; "
                           "3 to 4 is usual)."));
    discretization.horizon   = horizon_factor * discretization.spacing;
    discretization.thickness = (dim == 2 ? prm.get_double("Thickness") : 1.);
    ParameterUtilities::require_positive(discretization.thickness, "Discretization/Thickness");
    const std::string partial     = prm.get("Partial volume correction");
    discretization.partial_volume = (partial == "none" ? PartialVolume::none :
                                     partial == "book" ? PartialVolume::book :
                                                         PartialVolume::geometric);
    surface_correction            = prm.get_bool("Surface correction");
    prm.leave_subsection();

    regions.parse_parameters(prm);
    for (const auto &name : body_regions)
      regions.get(name, "Discretization/Body");

    prm.enter_subsection("Pre-cracks");
    pre_cracks = parse_pre_cracks<dim>(prm.get("Cracks"));
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      planar                       = planar_assumption_from_name(prm.get("Planar assumption"), dim);
      density                      = prm.get_double("Density");
      const std::string model_name = prm.get("Model");
      material = PluginRegistry<MaterialModel<dim>>::create(model_name, "Material/Model");
      if (has_body())
        {
          ParameterUtilities::require_positive(density, "Material/Density");
          prm.enter_subsection(model_name);
          material->parse_parameters(prm);
          prm.leave_subsection();
        }
      no_fail_regions = ParameterUtilities::split_names(prm.get("No-fail regions"));
      for (const auto &name : no_fail_regions)
        regions.get(name, "Material/No-fail regions");
      const std::string damage_name = prm.get("Damage model");
      damage = PluginRegistry<DamageModel<dim>>::create(damage_name, "Material/Damage model");
      if (has_body())
        {
          prm.enter_subsection(damage_name);
          damage->parse_parameters(prm);
          prm.leave_subsection();
        }
    }
    prm.leave_subsection();

    boundary_conditions.parse_parameters(prm, regions);

    prm.enter_subsection("Initial conditions");
    for (auto [function, entry] : {std::make_pair(&initial_displacement, "Displacement"),
                                   std::make_pair(&initial_velocity, "Velocity")})
      {
        const std::string expression = prm.get(entry);
        AssertThrow(Utilities::split_string_list(expression, ';').size() == dim,
                    ExcMessage("The parameter <Initial conditions/" + std::string(entry) +
                               "> needs " + std::to_string(dim) +
                               " expressions separated by ';'."));
        *function = std::make_unique<FunctionParser<dim>>(dim);
        (*function)->initialize(dim == 2 ? "x,y" : "x,y,z", expression, {{"pi", numbers::PI}});
      }
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    solver_type               = solver_type_from_name(prm.get("Type"));
    load_steps                = prm.get_integer("Load steps");
    relaxation_tolerance      = prm.get_double("Tolerance");
    relaxation_max_iterations = prm.get_integer("Maximum iterations");
    relaxation_safety         = prm.get_double("Density safety factor");
    AssertThrow(relaxation_safety >= 1.,
                ExcMessage("The parameter <Solver/Density safety factor> is " +
                           ParameterUtilities::format_number(relaxation_safety) +
                           "; accepted: >= 1 (below, the relaxation is not stable)."));
    ParameterUtilities::require_positive(relaxation_tolerance, "Solver/Tolerance");
    static_settings.tolerance      = relaxation_tolerance;
    static_settings.max_iterations = relaxation_max_iterations;
    static_settings.linear_solver  = prm.get("Linear solver") == "direct" ?
                                       StaticSolver<dim>::LinearSolver::direct :
                                       StaticSolver<dim>::LinearSolver::cg_amg;
    prm.leave_subsection();

    prm.enter_subsection("Time stepping");
    ParameterUtilities::parse_time_stepping(prm, end_time, requested_time_step, safety_factor);
    if (solver_type == SolverType::explicit_dynamics)
      ParameterUtilities::require_positive(end_time, "Time stepping/End time");
    damping = prm.get_double("Damping");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    output_directory    = prm.get("Directory");
    base_name           = prm.get("Base name");
    output_interval     = prm.get_integer("Output interval");
    statistics_interval = prm.get_integer("Statistics interval");
    write_hdf5          = prm.get_bool("Write HDF5");
    write_vtu           = prm.get_bool("Write VTU");
    show_progress       = prm.get_bool("Progress");
    probe_points.clear();
    for (const auto &item : Utilities::split_string_list(prm.get("Probe points"), ';'))
      if (!item.empty())
        probe_points.push_back(ParameterUtilities::parse_point<dim>(item, "Output/Probe points"));
    prm.leave_subsection();
  }

  template <int dim>
  void
  PDProblem<dim>::setup(const std::function<bool(const Point<dim> &)>   &keep,
                        const std::function<double(const Point<dim> &)> &energy_weight)
  {
    if (has_body())
      {
        const auto in_body = regions.union_of(body_regions, "Discretization/Body");
        particle_system.generate(discretization,
                                 regions.bounding_box_of(body_regions, "Discretization/Body"),
                                 keep ?
                                   std::function<bool(const Point<dim> &)>(
                                     [&](const Point<dim> &x) { return keep(x) && in_body(x); }) :
                                   std::function<bool(const Point<dim> &)>(in_body),
                                 pre_cracks,
                                 regions.union_of(no_fail_regions, "Material/No-fail regions"));
        // A coupled problem may leave the PD region empty (beta = 0 on the whole body).
        AssertThrow(keep || particle_system.n_global() > 0,
                    ExcMessage("The body (<Discretization/Body>) holds no particle: its regions "
                               "are smaller than the lattice spacing or empty."));
      }
    else
      particle_system.generate(discretization,
                               BoundingBox<dim>(),
                               [](const Point<dim> &) { return false; },
                               {});

    if (energy_weight)
      particle_system.set_energy_weights(energy_weight);

    ModelContext context;
    context.horizon            = discretization.horizon;
    context.thickness          = discretization.thickness;
    context.planar             = planar;
    context.surface_correction = surface_correction;
    material->initialize(particle_system, context);
    critical_stretch = damage->critical_stretch(*material);

    boundary_conditions.setup(particle_system);
    locate_probes();

    stable_dt = material->stable_time_step(particle_system, density);

    const auto n_bonds = particle_system.n_global_bonds();
    if (is_root && has_body())
      log << "Particles: " << particle_system.n_global() << "\n"
          << "Bonds: " << n_bonds << "\n"
          << "Material: " << material->summary() << "\n"
          << "Critical stretch: " << critical_stretch << std::endl;
  }

  template <int dim>
  bool
  PDProblem<dim>::has_body() const
  {
    return !body_regions.empty();
  }

  template <int dim>
  void
  PDProblem<dim>::open_output(std::unique_ptr<StatisticsFile> &statistics_file)
  {
    if (is_root)
      std::filesystem::create_directories(output_directory);
    statistics_file =
      std::make_unique<StatisticsFile>(communicator, output_directory + "/statistics.csv");
    particle_output = std::make_unique<ParticleOutput<dim>>(communicator,
                                                            output_directory,
                                                            base_name,
                                                            write_hdf5,
                                                            write_vtu);
  }

  template <int dim>
  void
  PDProblem<dim>::locate_probes()
  {
    // Per probe and rank: the distance to the nearest owned particle, then its coordinates.
    const unsigned int        n_probes = probe_points.size(), width = dim + 1;
    const unsigned int        n_owned = particle_system.n_owned();
    const auto               &x       = particle_system.positions();
    std::vector<double>       nearest(n_probes * width, std::numeric_limits<double>::max());
    std::vector<unsigned int> nearest_index(n_probes, numbers::invalid_unsigned_int);
    for (unsigned int p = 0; p < n_probes; ++p)
      for (unsigned int i = 0; i < n_owned; ++i)
        {
          std::array<double, dim + 1> candidate;
          candidate[0] = x[i].distance(probe_points[p]);
          for (unsigned int d = 0; d < dim; ++d)
            candidate[d + 1] = x[i][d];
          if (std::lexicographical_compare(candidate.begin(),
                                           candidate.end(),
                                           nearest.begin() + p * width,
                                           nearest.begin() + (p + 1) * width))
            {
              std::copy(candidate.begin(), candidate.end(), nearest.begin() + p * width);
              nearest_index[p] = i;
            }
        }
    const auto all = Utilities::MPI::all_gather(communicator, nearest);
    const auto me  = Utilities::MPI::this_mpi_process(communicator);

    probe_particles.resize(n_probes);
    probe_local_index.assign(n_probes, numbers::invalid_unsigned_int);
    for (unsigned int p = 0; p < n_probes; ++p)
      {
        unsigned int best = 0;
        for (unsigned int r = 1; r < all.size(); ++r)
          if (std::lexicographical_compare(all[r].begin() + p * width,
                                           all[r].begin() + (p + 1) * width,
                                           all[best].begin() + p * width,
                                           all[best].begin() + (p + 1) * width))
            best = r;
        const double       distance = all[best][p * width];
        std::ostringstream point;
        point << probe_points[p];
        AssertThrow(distance <= discretization.spacing,
                    ExcMessage(
                      "<Output/Probe points>: the point (" + point.str() +
                      ") has no particle within one lattice spacing (" +
                      ParameterUtilities::format_number(discretization.spacing) +
                      " m); the nearest is " + ParameterUtilities::format_number(distance) +
                      " m away. Put each probe on the particles of <Discretization/Body> (coupled "
                      "runs: the PD region and its overlap)."));
        for (unsigned int d = 0; d < dim; ++d)
          probe_particles[p][d] = all[best][p * width + d + 1];
        if (best == me)
          probe_local_index[p] = nearest_index[p];
      }
  }

  template <int dim>
  void
  PDProblem<dim>::log_probes() const
  {
    std::vector<double> values(probe_points.size() * dim, 0.);
    for (unsigned int p = 0; p < probe_points.size(); ++p)
      if (probe_local_index[p] != numbers::invalid_unsigned_int)
        for (unsigned int d = 0; d < dim; ++d)
          values[p * dim + d] = u.local_element(probe_local_index[p] * dim + d);
    Utilities::MPI::sum(values, communicator, values);
    if (!is_root)
      return;
    const auto flags = log.flags();
    for (unsigned int p = 0; p < probe_points.size(); ++p)
      {
        log << std::defaultfloat << "Probe " << p + 1 << " (" << probe_points[p]
            << "): particle at (" << probe_particles[p]
            << "), displacement [um]:" << std::scientific << std::setprecision(6);
        for (unsigned int d = 0; d < dim; ++d)
          log << ' ' << 1e6 * values[p * dim + d];
        log << '\n';
      }
    log << std::flush;
    log.flags(flags);
  }

  template <int dim>
  void
  PDProblem<dim>::write_particles(const unsigned int step, const double time)
  {
    ParticleOutput<dim> &output = *particle_output;
    if ((!write_hdf5 && !write_vtu) || !has_body())
      return;
    const unsigned int      n_owned = particle_system.n_owned();
    const auto             &x       = particle_system.positions();
    std::vector<Point<dim>> points(x.begin(), x.begin() + n_owned);
    const auto              owned_values = [&](const ParticleVector &vec) {
      return std::vector<double>(vec.begin(), vec.begin() + std::size_t(n_owned) * dim);
    };
    output.clear_fields();
    output.set_points(points);
    output.add_vector_field("displacement", dim, owned_values(u));
    output.add_vector_field("velocity", dim, owned_values(v));
    output.add_vector_field("force_density", dim, owned_values(internal_force));
    output.add_scalar_field("damage", damage_index(particle_system));
    if (energy_density.size() == n_owned)
      output.add_scalar_field("strain_energy_density", energy_density);
    output.write(step, time);
  }

  template class PDProblem<2>;
  template class PDProblem<3>;
} // namespace perideal
