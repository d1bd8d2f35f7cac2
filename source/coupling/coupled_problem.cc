// ---------------------------------------------------------------------
// PeriDeal: a problem with an FE region and particles joined through an overlap zone.
// ---------------------------------------------------------------------
#include <deal.II/fe/component_mask.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/base/progress_reporter.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/boundary_conditions.h>
#include <perideal/pd/damage_model.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <unordered_map>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    /// "x", "y" or "z".
    std::string
    axis_name(const unsigned int d)
    {
      return std::string(1, "xyz"[d]);
    }
  } // namespace

  template <int dim>
  CoupledProblem<dim>::CoupledProblem(const MPI_Comm comm, std::ostream &log)
    : comm(comm)
    , log(log)
    , is_root(Utilities::MPI::this_mpi_process(comm) == 0)
    , pd(comm, log)
    , fe(comm)
  {}

  template <int dim>
  void
  CoupledProblem<dim>::declare_parameters(ParameterHandler               &prm,
                                          const std::vector<std::string> &region_names,
                                          const std::vector<std::string> &condition_names,
                                          const std::vector<std::string> &fe_condition_names)
  {
    PDProblem<dim>::declare_parameters(prm, region_names, condition_names);
    FERegion<dim>::declare_parameters(prm, fe_condition_names);
    prm.enter_subsection("Coupling");
    using Methods = PluginRegistry<CouplingMethod<dim>>;
    prm.declare_entry("Method",
                      "blended",
                      Patterns::Selection(Methods::pattern_string()),
                      "How the FE region and the particles are joined: " +
                        Methods::documentation() + "Each method reads its own subsection.");
    Methods::declare_parameters(prm);
    prm.declare_entry("Blending function",
                      "0",
                      Patterns::Anything(),
                      "beta(x, y, (z)) in [0, 1]: 1 where only PD acts, 0 where only FE acts, in "
                      "between in the overlap, which must be at least a horizon wide (e.g. "
                      "'min(1, max(0, (x - 0.04) / 0.01))').");
    prm.declare_entry("Exact displacement",
                      "",
                      Patterns::Anything(),
                      "Static runs, for verification: the exact displacement (one expression per "
                      "component, separated by ';', in x, y(, z)); if given, the summary prints "
                      "the largest error at the FE nodes and at the particles relative to the "
                      "largest exact value. Empty: no comparison.");
    prm.declare_entry("Exact displacement tolerance",
                      "0",
                      Patterns::Double(0.),
                      "Static runs with <Exact displacement>: the summary states whether both "
                      "relative errors are below this value (0: no verdict).");
    prm.leave_subsection();
  }

  template <int dim>
  void
  CoupledProblem<dim>::parse_parameters(ParameterHandler &prm)
  {
    pd.parse_parameters(prm);
    fe.parse_parameters(prm, pd.planar, pd.discretization.thickness);
    AssertThrow(pd.has_body() || fe.has_mesh(),
                ExcMessage("The problem has neither particles nor an FE region: give "
                           "<Discretization/Body> (the regions filled with particles), "
                           "<Finite elements/Mesh file> or <Finite elements/Generator> (the FE "
                           "mesh), or both (a coupled problem)."));
    AssertThrow(pd.solver_type != SolverType::explicit_dynamics || !fe.has_mesh() ||
                  fe.get_density() > 0.,
                ExcMessage("The parameter <Finite elements/Density> is " +
                           ParameterUtilities::format_number(fe.get_density()) +
                           "; explicit dynamics (<Solver/Type> = explicit) needs the FE mass: "
                           "accepted values are > 0."));
    // One body force for the whole body: the particles take it with their weights beta_i
    // (BoundaryConditions::add_loads), the FE region with 1 - beta (FERegion's load).
    if (const auto body_force = pd.boundary_conditions.body_force_function())
      fe.set_body_force(body_force);
    AssertThrow(!pd.has_body() || !fe.has_mesh() ||
                  fe.field_layout() == pd.material->field_layout(),
                ExcMessage("<Finite elements/Physics> has the unknowns " +
                           fe.field_layout().description() + ", the particles' <Material/Model> " +
                           pd.material->field_layout().description() +
                           ": a coupled problem joins fields with the same unknowns."));
    prm.enter_subsection("Coupling");
    method_name = prm.get("Method");
    method      = PluginRegistry<CouplingMethod<dim>>::create(method_name, "Coupling/Method");
    prm.enter_subsection(method_name);
    method->parse_parameters(prm);
    prm.leave_subsection();
    method->check_solver(pd.solver_type);
    // With one region only, beta is fixed: 1 without a mesh, 0 without particles.
    blending_expression = prm.get("Blending function");
    AssertThrow((pd.has_body() && fe.has_mesh()) || blending_expression == "0",
                ExcMessage("<Coupling/Blending function> = <" + blending_expression +
                           "> is given, but the problem has " +
                           (fe.has_mesh() ? "no particles (<Discretization/Body> is empty)" :
                                            "no FE region (no <Finite elements/Mesh file> or "
                                            "<Finite elements/Generator>)") +
                           ": the blending function joins two regions; remove it."));
    if (!fe.has_mesh())
      blending_expression = "1";
    beta =
      ParameterUtilities::make_function<dim>(blending_expression, 1, "Coupling/Blending function");
    const std::string exact = prm.get("Exact displacement");
    exact_displacement.reset();
    if (!exact.empty())
      exact_displacement =
        ParameterUtilities::make_function<dim>(exact, dim, "Coupling/Exact displacement");
    exact_tolerance = prm.get_double("Exact displacement tolerance");
    AssertThrow(exact_tolerance == 0. || exact_displacement,
                ExcMessage("<Coupling/Exact displacement tolerance> is set, but <Coupling/Exact "
                           "displacement> is empty: give the exact field or remove the "
                           "tolerance."));
    AssertThrow(!exact_displacement || pd.solver_type != SolverType::explicit_dynamics,
                ExcMessage("<Coupling/Exact displacement> is compared in quasi-static runs only "
                           "(<Solver/Type> = static or adaptive dynamic relaxation); remove it or "
                           "change the solver type."));
    prm.leave_subsection();
  }

  template <int dim>
  const ParticleSystem<dim> &
  CoupledProblem<dim>::particles() const
  {
    return pd.particle_system;
  }

  template <int dim>
  const FERegion<dim> &
  CoupledProblem<dim>::fe_region() const
  {
    return fe;
  }

  template <int dim>
  double
  CoupledProblem<dim>::time_step() const
  {
    return dt;
  }

  template <int dim>
  const ParticleVector &
  CoupledProblem<dim>::particle_displacement() const
  {
    return pd.u;
  }

  template <int dim>
  const LinearAlgebra::distributed::Vector<double> &
  CoupledProblem<dim>::fe_displacement() const
  {
    return U;
  }

  template <int dim>
  double
  CoupledProblem<dim>::blending(const Point<dim> &x) const
  {
    // Values within round-off of 0 or 1 are 0 or 1: whether a cell carries FE unknowns and
    // whether a particle is free must not depend on the last bit of a coordinate (it broke the
    // mirror symmetry of the Kalthoff-Winkler case).
    const double b = beta->value(x);
    return std::abs(b) < 1e-10 ? 0. : std::abs(b - 1.) < 1e-10 ? 1. : b;
  }

  template <int dim>
  void
  CoupledProblem<dim>::check_blending() const
  {
    const std::string entry = "<Coupling/Blending function> = <" + blending_expression + ">";
    // beta in [0, 1] at the particles and the FE vertices.
    const auto         &x = pd.particle_system.positions();
    std::vector<double> beta_p(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      beta_p[i] = blending(x[i]);
    double lowest = 1., highest = 0.;
    for (const double b : beta_p)
      {
        lowest  = std::min(lowest, b);
        highest = std::max(highest, b);
      }
    for (const auto &cell : fe.get_triangulation().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const double b = blending(cell->vertex(v));
            lowest         = std::min(lowest, b);
            highest        = std::max(highest, b);
          }
    lowest  = Utilities::MPI::min(lowest, comm);
    highest = Utilities::MPI::max(highest, comm);
    AssertThrow(lowest >= 0. && highest <= 1.,
                ExcMessage(entry + " takes values in [" +
                           ParameterUtilities::format_number(lowest) + ", " +
                           ParameterUtilities::format_number(highest) +
                           "]; it must lie in [0, 1] (clamp it with min(1, max(0, ...)))."));
    // The transition must be at least a horizon wide: no bond from beta = 1 to beta = 0.
    const auto   &bonds   = pd.particle_system.bonds();
    std::uint64_t n_short = 0;
    for (unsigned int i = 0; i < pd.particle_system.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const double bi = beta_p[i], bj = beta_p[bonds.neighbor[b]];
          if ((bi >= 1. && bj <= 0.) || (bi <= 0. && bj >= 1.))
            ++n_short;
        }
    n_short = Utilities::MPI::sum(n_short, comm);
    AssertThrow(n_short == 0,
                ExcMessage(entry + ": the overlap (0 < beta < 1) is narrower than the horizon (" +
                           ParameterUtilities::format_number(pd.discretization.horizon) +
                           " m): " + std::to_string(n_short) +
                           " bonds join a particle with beta = 1 to one with beta = 0. Widen the "
                           "ramp of the blending function to at least a horizon."));
  }

  template <int dim>
  void
  CoupledProblem<dim>::setup()
  {
    const auto weight_fe = [this](const Point<dim> &x) { return method->fe_weight(blending(x)); };
    fe.setup(weight_fe);

    // Particles where the method's particle weight is positive and within a horizon of such
    // points (lattice offsets up to
    // delta + dx cover every bond).
    const double                dx = pd.discretization.spacing, delta = pd.discretization.horizon;
    const int                   reach = static_cast<int>(std::ceil(delta / dx)) + 1;
    std::vector<Tensor<1, dim>> offsets;
    {
      std::array<int, 3> k{{-reach, -reach, -reach}};
      while (true)
        {
          Tensor<1, dim> offset;
          for (unsigned int d = 0; d < dim; ++d)
            offset[d] = k[d] * dx;
          if (offset.norm() <= delta + dx)
            offsets.push_back(offset);
          unsigned int d = 0;
          while (d < dim && ++k[d] > reach)
            k[d++] = -reach;
          if (d == dim)
            break;
        }
    }
    // beta is evaluated once per lattice point (the offsets are lattice vectors, so x + offset
    // is a lattice point too); the key is the point's position in half spacings.
    struct KeyHash
    {
      std::size_t
      operator()(const std::array<long, dim> &key) const
      {
        std::size_t h = 0;
        for (const long k : key)
          h = h * 1000003u ^ std::hash<long>()(k);
        return h;
      }
    };
    std::unordered_map<std::array<long, dim>, double, KeyHash> beta_at;
    const auto lattice_beta = [&](const Point<dim> &y) {
      std::array<long, dim> key;
      for (unsigned int d = 0; d < dim; ++d)
        key[d] = std::lround(y[d] / dx * 2.);
      const auto found = beta_at.find(key);
      if (found != beta_at.end())
        return found->second;
      return beta_at[key] = method->particle_weight(blending(y));
    };
    const auto in_pd_region = [&](const Point<dim> &x) {
      for (const auto &offset : offsets)
        if (lattice_beta(x + offset) > 0.)
          return true;
      return false;
    };
    pd.setup(in_pd_region,
             [this](const Point<dim> &x) { return method->particle_weight(blending(x)); });

    transfer.reinit(fe, pd.particle_system);
    check_blending();
    CoupledRegions<dim> regions;
    regions.fe        = &fe;
    regions.particles = &pd.particle_system;
    regions.material  = pd.material.get();
    regions.transfer  = &transfer;
    regions.density   = pd.density;
    method->initialize(regions);

    // Free particles (in FE_Nothing cells) carry their own mass; PD boundary conditions may act
    // only on them.
    const unsigned int n_owned = pd.particle_system.n_owned();
    motion.assign(std::size_t(n_owned) * dim, Motion::follows_fe);
    std::uint64_t n_constrained_slaved = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const bool prescribed = pd.boundary_conditions.is_prescribed(i, d);
          if (transfer.is_slaved(i))
            n_constrained_slaved += prescribed;
          else
            motion[i * dim + d] = prescribed ? Motion::prescribed : Motion::moves;
        }
    n_constrained_slaved = Utilities::MPI::sum(n_constrained_slaved, comm);
    AssertThrow(n_constrained_slaved == 0,
                ExcMessage(
                  "A displacement or velocity condition of <Boundary conditions> acts on " +
                  std::to_string(n_constrained_slaved) +
                  " particle components that follow the FE field (they lie in cells "
                  "with FE unknowns); prescribe it there with <Finite elements/Boundary "
                  "conditions>, or move its region into the PD-only zone (beta = 1)."));

    const std::string fe_summary = fe.summary(), coupling_summary = method->summary();
    if (is_root && fe.has_mesh())
      log << fe_summary << std::endl;
    if (is_root && is_coupled())
      log << "Coupling: " << method_name << ", " << coupling_summary << std::endl;
    // Per particle component, the factors from the internal and the applied force density to
    // the load that does work: -V_i on prescribed components (the support balances the
    // internal force), V_i on the others (slaved particles too: they move with u = P U).
    const auto &volume = pd.particle_system.volumes();
    internal_work_factor.assign(motion.size(), 0.);
    applied_work_factor.assign(motion.size(), 0.);
    for (std::size_t k = 0; k < motion.size(); ++k)
      if (motion[k] == Motion::prescribed)
        internal_work_factor[k] = -volume[k / dim];
      else
        applied_work_factor[k] = volume[k / dim];
    if (pd.solver_type != SolverType::explicit_dynamics)
      return;

    fe.initialize_vector(mass);
    pd.particle_system.reinit_vector(nodal_force, dim);
    method->lumped_masses(mass, particle_mass);
    // The factor from force density to acceleration: V_i / m_i on the components that move by
    // their acceleration, 0 on the others.
    acceleration_factor.assign(motion.size(), 0.);
    for (std::size_t k = 0; k < motion.size(); ++k)
      if (motion[k] == Motion::moves)
        acceleration_factor[k] = volume[k / dim] / particle_mass[k / dim];

    // The time step: the smaller of the two regions' stable steps.
    const double fe_dt = fe.stable_time_step(&mass);
    stable_dt          = std::min(fe_dt, pd.stable_dt);
    dt = ParameterUtilities::choose_time_step(pd.requested_time_step, pd.safety_factor, stable_dt);

    if (is_root)
      {
        log << "Stable time step:";
        if (fe.n_dofs() > 0)
          log << " FE " << fe_dt << " s" << (pd.particle_system.n_global() > 0 ? "," : "");
        if (pd.particle_system.n_global() > 0)
          log << " PD " << pd.stable_dt << " s";
        log << std::endl;
      }
  }

  template <int dim>
  bool
  CoupledProblem<dim>::is_coupled() const
  {
    return pd.has_body() && fe.has_mesh();
  }

  template <int dim>
  void
  CoupledProblem<dim>::compute_acceleration(const double time, const bool with_energy)
  {
    auto &ps = pd.particle_system;
    transfer.interpolate(U, pd.u);
    pd.u.update_ghost_values();
    pd.material->compute_forces(ps,
                                pd.u,
                                pd.internal_force,
                                with_energy ? &pd.energy_density : nullptr,
                                pd.critical_stretch);
    // The applied forces (zero since the set-up if there are none).
    const bool loads = pd.boundary_conditions.has_loads();
    if (loads)
      {
        pd.external_force = 0.;
        pd.boundary_conditions.add_loads(time, pd.external_force);
      }
    // Particles: a = f V / m on the components that move by it (one pass, no branches); the
    // nodal forces f V only where P^T carries them to the FE dofs.
    const std::size_t n        = motion.size();
    const double     *internal = pd.internal_force.begin(), *applied = pd.external_force.begin();
    const double     *factor = acceleration_factor.data();
    double           *a      = pd.a.begin();
    if (loads)
      for (std::size_t k = 0; k < n; ++k)
        a[k] = (internal[k] + applied[k]) * factor[k];
    else
      for (std::size_t k = 0; k < n; ++k)
        a[k] = internal[k] * factor[k];
    if (fe.n_dofs() == 0)
      return;
    if (transfer.n_global_slaved() > 0)
      {
        const auto &volume = pd.particle_system.volumes();
        double     *nodal  = nodal_force.begin();
        for (std::size_t k = 0; k < n; ++k)
          nodal[k] = (internal[k] + applied[k]) * volume[k / dim];
      }

    // FE: R = f_ext - K U + P^T f; prescribed dofs do not move by it, and the work their
    // supports do is that of K U - P^T f (the part of R they balance).
    fe.assemble_load(time, f_ext);
    fe.stiffness_matrix().vmult(residual, U);
    residual.sadd(-1., 1., f_ext);
    transfer.add_transpose(nodal_force, residual);
    const auto &mask = fe.prescribed_mask();
    for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
      if (mask[k])
        {
          fe_load.local_element(k) = f_ext.local_element(k) - residual.local_element(k);
          A.local_element(k)       = 0.;
        }
      else
        {
          fe_load.local_element(k) = f_ext.local_element(k);
          A.local_element(k)       = residual.local_element(k) / mass.local_element(k);
        }
  }

  template <int dim>
  void
  CoupledProblem<dim>::start_work(const ParticleVector &applied)
  {
    local_work             = 0.;
    previous_U             = U;
    previous_fe_load       = fe_load;
    pd.previous_u          = pd.u;
    const double *internal = pd.internal_force.begin(), *applied_force = applied.begin();
    double       *load = pd.previous_load.begin();
    for (std::size_t k = 0; k < motion.size(); ++k)
      load[k] = internal_work_factor[k] * internal[k] + applied_work_factor[k] * applied_force[k];
  }

  template <int dim>
  void
  CoupledProblem<dim>::accumulate_work(const ParticleVector &applied)
  {
    // Trapezoidal rule in the loads over the step; one pass per region that also makes the
    // current state the previous one. (Local sums: one in the member could alias the arrays
    // and stay out of a register.)
    double work = local_work;
    {
      double       *load_before = previous_fe_load.begin(), *u_before = previous_U.begin();
      const double *load = fe_load.begin(), *u_now = U.begin();
      for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
        {
          work += 0.5 * (load_before[k] + load[k]) * (u_now[k] - u_before[k]);
          load_before[k] = load[k];
          u_before[k]    = u_now[k];
        }
    }
    {
      // The particles' load: internal_work_factor f_int + applied_work_factor f_applied.
      double       *load_before = pd.previous_load.begin(), *u_before = pd.previous_u.begin();
      const double *u_now = pd.u.begin(), *internal = pd.internal_force.begin();
      const double *applied_force = applied.begin(), *c_internal = internal_work_factor.data(),
                   *c_applied = applied_work_factor.data();
      for (std::size_t k = 0; k < motion.size(); ++k)
        {
          const double load = c_internal[k] * internal[k] + c_applied[k] * applied_force[k];
          work += 0.5 * (load_before[k] + load) * (u_now[k] - u_before[k]);
          load_before[k] = load;
          u_before[k]    = u_now[k];
        }
    }
    local_work = work;
  }

  template <int dim>
  void
  CoupledProblem<dim>::add_damping()
  {
    // a -= c v with the half-step velocity, as VelocityVerlet does, on the dofs and particle
    // components that move by their acceleration.
    const auto &mask = fe.prescribed_mask();
    for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
      if (!mask[k])
        A.local_element(k) -= pd.damping * V.local_element(k);
    for (std::size_t k = 0; k < motion.size(); ++k)
      if (motion[k] == Motion::moves)
        pd.a.local_element(k) -= pd.damping * pd.v.local_element(k);
  }

  template <int dim>
  void
  CoupledProblem<dim>::run()
  {
    if (pd.solver_type == SolverType::explicit_dynamics)
      run_explicit();
    else
      run_static();
  }

  template <int dim>
  void
  CoupledProblem<dim>::run_explicit()
  {
    const unsigned int n_steps = ParameterUtilities::equal_time_steps(pd.end_time, dt);
    if (is_root)
      log << "Time step: " << dt << " s, steps: " << n_steps << std::endl;

    // State and initial conditions (the same functions for both regions).
    auto &ps = pd.particle_system;
    for (ParticleVector *vec : {&pd.u,
                                &pd.v,
                                &pd.a,
                                &pd.internal_force,
                                &pd.external_force,
                                &pd.previous_u,
                                &pd.previous_load})
      ps.reinit_vector(*vec, dim);
    for (FEVector *vec : {&U, &V, &A, &f_ext, &residual, &fe_load, &previous_fe_load, &previous_U})
      fe.initialize_vector(*vec);
    const auto &x = ps.positions();
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        {
          pd.u.local_element(i * dim + d) = pd.initial_displacement->value(x[i], d);
          pd.v.local_element(i * dim + d) = pd.initial_velocity->value(x[i], d);
        }
    fe.interpolate(*pd.initial_displacement, U);
    fe.interpolate(*pd.initial_velocity, V);
    pd.energy_density.assign(ps.n_owned(), 0.);

    pd.open_output(statistics);

    fe.prescribe(0., U, V);
    pd.boundary_conditions.prescribe_displacement(0., pd.u);
    compute_acceleration(0., true);
    if (is_coupled())
      report_initial_residual();
    start_work(pd.external_force);
    write_statistics(0, 0., false);
    write_output(0, 0.);

    ProgressReporter progress(comm, log, n_steps, pd.end_time, pd.show_progress && is_root);
    unsigned int     output_step = 1;
    const auto       start       = std::chrono::steady_clock::now();
    for (unsigned int step = 1; step <= n_steps; ++step)
      {
        const double time = (step - 1) * dt;

        // Half step of the velocities, prescribed velocities over the step, positions.
        V.add(0.5 * dt, A);
        pd.v.add(0.5 * dt, pd.a);
        fe.prescribe(time + 0.5 * dt, U, V);
        pd.boundary_conditions.prescribe_step_velocity(time, dt, pd.v);
        U.add(dt, V);
        if (transfer.n_global_slaved() == 0)
          pd.u.add(dt, pd.v);
        else
          for (std::size_t k = 0; k < motion.size(); ++k)
            if (motion[k] != Motion::follows_fe)
              pd.u.local_element(k) += dt * pd.v.local_element(k);
        fe.prescribe(time + dt, U, V);
        pd.boundary_conditions.prescribe_displacement(time + dt, pd.u);
        U.update_ghost_values();

        const bool write_stats = (step % pd.statistics_interval == 0 || step == n_steps);
        const bool write_fields =
          (step == n_steps || (pd.output_interval > 0 && step % pd.output_interval == 0));
        compute_acceleration(time + dt, write_stats || write_fields);
        if (pd.damping > 0.)
          add_damping();
        V.add(0.5 * dt, A);
        pd.v.add(0.5 * dt, pd.a);
        fe.prescribe(time + dt, U, V);

        accumulate_work(pd.external_force);

        const double now = step * dt;
        if (write_stats)
          write_statistics(step, now, step == n_steps);
        if (write_fields)
          write_output(output_step++, now);
        progress.update(step, now);
      }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::uint64_t n_bonds = ps.n_global_bonds();
    if (is_root && pd.show_progress)
      {
        log << "Wall time of the time loop: " << seconds << " s" << std::endl;
        if (n_bonds > 0)
          log << "bond updates per second: " << double(n_bonds) * n_steps / seconds << std::endl;
      }
  }

  template <int dim>
  void
  CoupledProblem<dim>::run_static()
  {
    auto              &ps      = pd.particle_system;
    const unsigned int n_owned = ps.n_owned();

    // Conditions a static solve cannot apply, and components no condition holds.
    std::string condition_list;
    for (const auto &c : fe.conditions())
      condition_list += (condition_list.empty() ? "" : ", ") + c.name;
    for (const auto &name : pd.boundary_conditions.names())
      condition_list += (condition_list.empty() ? "" : ", ") + name;
    for (const auto &c : fe.conditions())
      AssertThrow(c.type != Quantity::rate,
                  ExcMessage("The FE boundary condition <" + c.name +
                             "> is of type 'velocity', which a quasi-static solve (<Solver/Type> "
                             "= static or adaptive dynamic relaxation) cannot apply; use "
                             "'displacement' (scaled by the load factor) instead."));
    const auto velocity_conditions =
      pd.boundary_conditions.names_of_type(BoundaryConditions<dim>::Type::velocity);
    AssertThrow(velocity_conditions.empty(),
                ExcMessage("The boundary condition <" + velocity_conditions.front() +
                           "> is of type 'velocity', which a quasi-static solve (<Solver/Type> = "
                           "static or adaptive dynamic relaxation) cannot apply; use "
                           "'displacement' (scaled by the load factor) instead."));
    const std::string solver_name =
      pd.solver_type == SolverType::static_linear ? "static" : "adaptive dynamic relaxation";
    const bool     relax = (pd.solver_type == SolverType::adaptive_dynamic_relaxation);
    ParticleVector prescribed, target, full_load;
    for (ParticleVector *vec : {&pd.u,
                                &pd.v,
                                &pd.a,
                                &pd.internal_force,
                                &pd.external_force,
                                &pd.previous_u,
                                &pd.previous_load,
                                &static_pd_load,
                                &prescribed,
                                &target,
                                &full_load})
      ps.reinit_vector(*vec, dim);
    // The components to hold: the FE field's, or the particles' displacement without a mesh.
    const FieldLayout layout = fe.has_mesh() ? fe.field_layout() : FieldLayout::displacement(dim);
    std::array<double, dim> constrained{};
    for (const auto &c : fe.conditions())
      if (c.type == Quantity::value)
        for (const unsigned int comp : c.components)
          constrained[comp] = 1.;
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        if (motion[i * dim + d] == Motion::prescribed)
          {
            prescribed.local_element(i * dim + d) = 1.;
            constrained[d] += 1.;
          }
    // A component no displacement condition holds leaves a rigid translation free: the static
    // system is singular; the relaxation leaves it at rest while it is not loaded, but needs at
    // least one condition.
    const std::string where = is_coupled()  ? "in <Finite elements/Boundary conditions> (type "
                                              "'displacement') or on free particles in "
                                              "<Boundary conditions>" :
                              fe.has_mesh() ? "in <Finite elements/Boundary conditions> (type "
                                              "'displacement')" :
                                              "on a region in <Boundary conditions> (type "
                                              "'displacement')";
    const std::string conditions_named =
      " (boundary conditions: " + (condition_list.empty() ? std::string("none") : condition_list) +
      ")";
    double n_constrained = 0.;
    for (unsigned int d = 0; d < layout.n_components(); ++d)
      {
        constrained[d] = Utilities::MPI::sum(constrained[d], comm);
        n_constrained += constrained[d];
        AssertThrow(constrained[d] > 0. || relax,
                    ExcMessage("No displacement condition prescribes the " + layout.name(d) +
                               " component anywhere" + conditions_named +
                               ", so a rigid translation in " + layout.name(d) +
                               " is free and the static system (<Solver/Type> = static) is "
                               "singular. Prescribe it " +
                               where +
                               ", or use 'adaptive dynamic relaxation', which leaves unloaded "
                               "rigid motions at rest."));
      }
    AssertThrow(n_constrained > 0.,
                ExcMessage("A quasi-static solve (<Solver/Type> = " + solver_name +
                           ") needs at least one displacement condition" + conditions_named +
                           ": without one every rigid motion is free. Prescribe one " + where +
                           "."));

    FEVector fe_target, fe_full_load;
    for (FEVector *vec : {&U,
                          &V,
                          &f_ext,
                          &residual,
                          &fe_load,
                          &previous_fe_load,
                          &previous_U,
                          &static_fe_load,
                          &fe_target,
                          &fe_full_load})
      fe.initialize_vector(*vec);
    {
      const auto modes = fe.component_masks();
      fe_dof_component.assign(U.locally_owned_size(), 0);
      for (unsigned int d = 0; d < modes.size(); ++d)
        for (unsigned int k = 0; k < fe_dof_component.size(); ++k)
          if (modes[d][k])
            fe_dof_component[k] = d;
    }
    pd.energy_density.assign(n_owned, 0.);

    pd.open_output(statistics);

    // The conditions at t = End time, scaled by the load factor.
    pd.boundary_conditions.prescribe_displacement(pd.end_time, target);
    pd.boundary_conditions.add_loads(pd.end_time, full_load);
    fe.prescribe(pd.end_time, fe_target, V);
    fe.assemble_load(pd.end_time, fe_full_load);

    EquilibriumSettings<dim> settings;
    settings.type                      = pd.solver_type;
    settings.linear                    = pd.static_settings;
    settings.relaxation.tolerance      = pd.relaxation_tolerance;
    settings.relaxation.max_iterations = pd.relaxation_max_iterations;
    settings.relaxation.length_scale   = pd.discretization.horizon;
    settings.relaxation_safety         = pd.relaxation_safety;
    method->initialize_equilibrium(prescribed, settings, condition_list);
    if (is_root)
      log << (relax ? "Adaptive dynamic relaxation: " : "Static solve: ") << method->n_unknowns()
          << " unknowns ("
          << (is_coupled()  ? "FE dofs and free particle components" :
              fe.has_mesh() ? "FE dofs" :
                              "particle components")
          << "), " << pd.load_steps << " load step(s)" << std::endl;

    start_work(static_pd_load);
    write_static_statistics(0, 0., 0, 0., false);
    const auto &mask   = fe.prescribed_mask();
    const auto &volume = ps.volumes();
    for (unsigned int step = 1; step <= pd.load_steps; ++step)
      {
        const double factor = double(step) / pd.load_steps;
        static_fe_load.equ(factor, fe_full_load);
        static_pd_load.equ(factor, full_load);

        unsigned int passes = 0, iterations = 0;
        for (;; ++passes)
          {
            const auto broken_before = n_broken_bonds(ps);
            for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
              if (mask[k])
                U.local_element(k) = factor * fe_target.local_element(k);
            for (unsigned int k = 0; k < n_owned * dim; ++k)
              if (prescribed.local_element(k) != 0.)
                pd.u.local_element(k) = factor * target.local_element(k);
            iterations += method->solve_equilibrium(static_fe_load, static_pd_load, U, pd.u);
            // The model's own forces and energy density at the solution (breaks bonds).
            pd.material->compute_forces(ps,
                                        pd.u,
                                        pd.internal_force,
                                        &pd.energy_density,
                                        pd.critical_stretch);
            if (breaking_settled(ps, broken_before, step, passes))
              break;
          }
        const double pd_energy = method->equilibrium_forces(U,
                                                            pd.u,
                                                            static_fe_load,
                                                            static_pd_load,
                                                            residual,
                                                            pd.internal_force);

        // The loads that do work: the applied ones, and on prescribed components the support
        // forces (the FE residual K z - F there; minus the internal force on particles).
        for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
          fe_load.local_element(k) =
            static_fe_load.local_element(k) + (mask[k] ? residual.local_element(k) : 0.);
        accumulate_work(static_pd_load);

        // Solves and broken bonds per step always (they are the same on every rank count);
        // iteration counts only with progress output.
        const auto broken = n_broken_bonds(ps);
        if (is_root)
          {
            log << "Load step " << step << "/" << pd.load_steps << ": " << passes + 1
                << " solve(s)";
            if (pd.has_body())
              log << ", " << broken << " broken bonds";
            if (pd.show_progress)
              log << ", " << iterations << (relax ? " relaxation" : " CG") << " iterations";
            log << std::endl;
          }
        write_static_statistics(step, factor, iterations, pd_energy, step == pd.load_steps);
      }

    if (exact_displacement)
      {
        // The residual K z - F of the exact field (FE nodes and particles set to it): for a
        // state the uncoupled models reproduce, the ghost force of the coupling, the number
        // explicit runs print at t = 0.
        FEVector       U_exact, fe_residual;
        ParticleVector u_exact, force;
        fe.initialize_vector(U_exact);
        fe.initialize_vector(fe_residual);
        ps.reinit_vector(u_exact, dim);
        ps.reinit_vector(force, dim);
        fe.interpolate(*exact_displacement, U_exact);
        U_exact.update_ghost_values();
        const auto &x = ps.positions();
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            u_exact.local_element(i * dim + d) = exact_displacement->value(x[i], d);
        transfer.interpolate(U_exact, u_exact);
        u_exact.update_ghost_values();
        method->equilibrium_forces(U_exact,
                                   u_exact,
                                   static_fe_load,
                                   static_pd_load,
                                   fe_residual,
                                   force);
        double largest = 0., scale = 0.;
        for (unsigned int k = 0; k < U_exact.locally_owned_size(); ++k)
          if (!mask[k])
            largest = std::max(largest, std::abs(fe_residual.local_element(k)));
        for (unsigned int i = 0; i < n_owned; ++i)
          for (unsigned int d = 0; d < dim; ++d)
            if (motion[i * dim + d] == Motion::moves)
              largest = std::max(largest,
                                 std::abs(force.local_element(i * dim + d) +
                                          static_pd_load.local_element(i * dim + d)) *
                                   volume[i]);
        for (const double sum : fe.absolute_row_sums(&U_exact))
          scale = std::max(scale, sum);
        log_residual("Force residual of the exact field", largest, scale);
      }

    pd.write_particles(pd.load_steps, 1.);
    if (pd.write_hdf5)
      fe.write_output(pd.output_directory, "solution", pd.load_steps, 1., U);
  }

  template <int dim>
  void
  CoupledProblem<dim>::write_static_statistics(const unsigned int step,
                                               const double       factor,
                                               const unsigned int iterations,
                                               const double       pd_energy,
                                               const bool         final_row)
  {
    const auto &ps      = pd.particle_system;
    const auto &volume  = ps.volumes();
    const auto &x       = ps.positions();
    const auto  n_owned = ps.n_owned();

    double max_u = 0.;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        double u2 = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          u2 += std::pow(pd.u.local_element(i * dim + d), 2);
        max_u = std::max(max_u, std::sqrt(u2));
      }
    max_u                     = Utilities::MPI::max(max_u, comm);
    const double max_fe_u     = U.linfty_norm();
    const double fe_energy    = fe.strain_energy(U);
    const double strain       = fe_energy + pd_energy;
    const double work         = Utilities::MPI::sum(local_work, comm);
    const double energy_error = work - strain;
    const auto   broken       = n_broken_bonds(ps);

    // Force balance: the applied loads against the reactions of the displacement conditions.
    Tensor<1, dim> applied, reaction_sum;
    for (unsigned int k = 0; k < static_fe_load.locally_owned_size(); ++k)
      applied[fe_dof_component[k]] += static_fe_load.local_element(k);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int d = 0; d < dim; ++d)
        applied[d] += static_pd_load.local_element(i * dim + d) * volume[i];
    applied                 = Utilities::MPI::sum(applied, comm);
    const auto fe_reactions = fe.reactions(residual);
    const auto pd_reactions = pd.boundary_conditions.reactions(pd.internal_force);
    const auto pd_types =
      pd.boundary_conditions.names_of_type(BoundaryConditions<dim>::Type::displacement);
    double largest = applied.norm();
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe.conditions()[k].type == Quantity::value)
        {
          reaction_sum += fe_reactions[k];
          largest = std::max(largest, fe_reactions[k].norm());
        }
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      if (std::find(pd_types.begin(), pd_types.end(), pd.boundary_conditions.names()[k]) !=
          pd_types.end())
        {
          reaction_sum += pd_reactions[k];
          largest = std::max(largest, pd_reactions[k].norm());
        }
    // Relative to the largest force involved; loads below 1e-10 of the internal-force scale
    // (a rigid motion) are round-off and give no ratio.
    double scale = 0.;
    U.update_ghost_values();
    for (const double sum : fe.absolute_row_sums(&U))
      scale = std::max(scale, sum);
    scale                  = Utilities::MPI::max(scale, comm);
    const double imbalance = (applied + reaction_sum).norm();
    const double balance   = largest > 1e-10 * scale ? imbalance / largest : 0.;
    // Likewise energies below 1e-10 of the force scale times the displacement.
    const double relative_energy_error =
      std::max(std::abs(work), strain) > 1e-10 * scale * max_u ? energy_error / work : 0.;

    StatisticsFile &file = *statistics;
    file.add_value("step", step);
    file.add_value("time", factor);
    file.add_value("strain_energy", strain);
    file.add_value("fe_strain_energy", fe_energy);
    file.add_value("pd_strain_energy", pd_energy);
    file.add_value("external_work", work);
    file.add_value("energy_error", energy_error);
    if (pd.particle_system.n_global() > 0)
      {
        file.add_value("broken_bonds", broken);
        file.add_value("max_particle_displacement", max_u);
      }
    if (fe.n_dofs() > 0)
      file.add_value("max_fe_displacement", max_fe_u);
    file.add_value("iterations", iterations);
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        file.add_value("reaction_" + pd.boundary_conditions.names()[k] + "_" + axis_name(d),
                       pd_reactions[k][d]);
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe.conditions()[k].type != Quantity::load)
        for (unsigned int d = 0; d < dim; ++d)
          file.add_value("reaction_" + fe.conditions()[k].name + "_" + axis_name(d),
                         fe_reactions[k][d]);
    for (unsigned int d = 0; d < dim; ++d)
      file.add_value(std::string("applied_load_") + axis_name(d), applied[d]);
    file.add_value("force_balance", balance);
    file.end_row();
    if (!final_row)
      return;

    // The error against the exact displacement: FE nodal values and particles.
    double fe_error = 0., fe_exact = 0., pd_error = 0., pd_exact = 0.;
    if (exact_displacement)
      {
        FEVector exact;
        fe.initialize_vector(exact);
        fe.interpolate(*exact_displacement, exact);
        for (unsigned int k = 0; k < exact.locally_owned_size(); ++k)
          {
            fe_error = std::max(fe_error, std::abs(U.local_element(k) - exact.local_element(k)));
            fe_exact = std::max(fe_exact, std::abs(exact.local_element(k)));
          }
        Vector<double> value(dim);
        for (unsigned int i = 0; i < n_owned; ++i)
          {
            exact_displacement->vector_value(x[i], value);
            double e2 = 0., v2 = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                e2 += std::pow(pd.u.local_element(i * dim + d) - value[d], 2);
                v2 += value[d] * value[d];
              }
            pd_error = std::max(pd_error, std::sqrt(e2));
            pd_exact = std::max(pd_exact, std::sqrt(v2));
          }
        fe_error = Utilities::MPI::max(fe_error, comm);
        fe_exact = Utilities::MPI::max(fe_exact, comm);
        pd_error = Utilities::MPI::max(pd_error, comm);
        pd_exact = Utilities::MPI::max(pd_exact, comm);
        fe_error = fe_exact > 0. ? fe_error / fe_exact : fe_error;
        pd_error = pd_exact > 0. ? pd_error / pd_exact : pd_error;
      }

    if (is_root)
      {
        const auto flags = log.flags();
        log << std::scientific << std::setprecision(6) << "Load factor: " << factor << "\n"
            << "Strain energy: " << strain << " J";
        if (is_coupled())
          log << " (FE " << fe_energy << " J, particles " << pd_energy << " J)";
        log << "\n"
            << "External work: " << work << " J\n"
            << "Energy error: " << energy_error << " J (relative " << relative_energy_error
            << ")\n";
        log_displacements(broken, max_u, max_fe_u);
        log_reactions(pd_reactions, fe_reactions);
        log << "Applied load: " << without_round_off(applied) << " N\n"
            << "Force balance: |applied + reactions| = " << imbalance
            << " N, relative to the largest force: " << balance << "\n";
        if (exact_displacement)
          {
            log << "Displacement error (largest, relative to the largest exact value): FE nodes "
                << fe_error << ", particles " << pd_error << "\n";
            if (exact_tolerance > 0.)
              log << "Displacement error below " << exact_tolerance << ": "
                  << (std::max(fe_error, pd_error) < exact_tolerance ? "yes" : "no") << "\n";
          }
        log << std::flush;
        log.flags(flags);
      }
    pd.log_probes();
  }

  template <int dim>
  void
  CoupledProblem<dim>::report_initial_residual()
  {
    // The largest force that is not balanced at t = 0, over the free FE dofs and the free
    // particle components, against the internal-force scale max_i sum_j |K_ij U_j| of the FE
    // rows (the nodal force without the cancellation between neighbours). For a deformation the
    // coupled model reproduces exactly (rigid motion; uniform strain away from free surfaces)
    // the residual is the ghost force of the coupling.
    const auto &mask         = fe.prescribed_mask();
    double      residual_max = 0., scale = 0.;
    U.update_ghost_values();
    for (unsigned int k = 0; k < U.locally_owned_size(); ++k)
      if (!mask[k])
        residual_max = std::max(residual_max, std::abs(residual.local_element(k)));
    for (const double sum : fe.absolute_row_sums(&U))
      scale = std::max(scale, sum);
    const auto &ps = pd.particle_system;
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      for (unsigned int d = 0; d < dim; ++d)
        if (motion[i * dim + d] == Motion::moves)
          residual_max = std::max(residual_max,
                                  std::abs(pd.internal_force.local_element(i * dim + d) +
                                           pd.external_force.local_element(i * dim + d)) *
                                    ps.volumes()[i]);
    log_residual("Force residual at t = 0", residual_max, scale);
  }

  template <int dim>
  void
  CoupledProblem<dim>::log_residual(const std::string &what,
                                    const double       local_largest,
                                    const double       local_scale) const
  {
    const double largest  = Utilities::MPI::max(local_largest, comm);
    const double scale    = Utilities::MPI::max(local_scale, comm);
    const double relative = scale > 0. ? largest / scale : 0.;
    // A residual below 1e-12 of the force scale is round-off: printed as 0 N (the ratio shows
    // it), so that it reads the same on every rank count and build.
    // Without FE unknowns (an empty FE region) there is no scale: the force itself.
    if (is_root && fe.n_dofs() == 0)
      log << what << ": " << largest
          << " N (largest unbalanced nodal force at free particles; no FE region)" << std::endl;
    else if (is_root)
      log << what << ": " << (relative < 1e-12 ? 0. : largest)
          << " N (largest unbalanced nodal force at free dofs and particles), relative to the FE "
             "internal-force scale: "
          << relative << std::endl;
  }

  template <int dim>
  void
  CoupledProblem<dim>::write_statistics(const unsigned int step,
                                        const double       time,
                                        const bool         final_row)
  {
    const auto &ps      = pd.particle_system;
    const auto &volume  = ps.volumes();
    const auto &mask    = fe.prescribed_mask();
    double      kinetic = 0., prescribed_kinetic = 0., strain = 0., max_u = 0.;
    for (unsigned int k = 0; k < V.locally_owned_size(); ++k)
      {
        const double e = 0.5 * mass.local_element(k) * V.local_element(k) * V.local_element(k);
        kinetic += e;
        if (mask[k])
          prescribed_kinetic += e;
      }
    for (unsigned int i = 0; i < ps.n_owned(); ++i)
      {
        double u2 = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double vv = pd.v.local_element(i * dim + d);
            if (motion[i * dim + d] != Motion::follows_fe)
              kinetic += 0.5 * particle_mass[i] * vv * vv;
            if (motion[i * dim + d] == Motion::prescribed)
              prescribed_kinetic += 0.5 * particle_mass[i] * vv * vv;
            u2 += std::pow(pd.u.local_element(i * dim + d), 2);
          }
        strain += pd.energy_density[i] * volume[i];
        max_u = std::max(max_u, std::sqrt(u2));
      }
    kinetic               = Utilities::MPI::sum(kinetic, comm);
    prescribed_kinetic    = Utilities::MPI::sum(prescribed_kinetic, comm);
    strain                = Utilities::MPI::sum(strain, comm) + fe.strain_energy(U);
    max_u                 = Utilities::MPI::max(max_u, comm);
    const double max_fe_u = U.linfty_norm();
    const double work_sum = Utilities::MPI::sum(local_work, comm);
    energy_balance.record(step, kinetic, strain, work_sum, prescribed_kinetic);
    energy_balance.check_stable(time, stable_dt);
    const double work         = energy_balance.work();
    const double energy_error = energy_balance.error();
    const auto   broken       = n_broken_bonds(ps);

    // Reactions: FE supports (the part of the residual they balance) and PD conditions.
    FEVector support;
    fe.initialize_vector(support);
    support = residual;
    support *= -1.;
    const auto fe_reactions = fe.reactions(support);
    const auto pd_reactions = pd.boundary_conditions.reactions(pd.internal_force);

    StatisticsFile &file = *statistics;
    file.add_value("step", step);
    file.add_value("time", time);
    file.add_value("kinetic_energy", kinetic);
    file.add_value("strain_energy", strain);
    file.add_value("external_work", work);
    file.add_value("energy_error", energy_error);
    if (pd.particle_system.n_global() > 0)
      {
        file.add_value("broken_bonds", broken);
        file.add_value("max_particle_displacement", max_u);
      }
    if (fe.n_dofs() > 0)
      file.add_value("max_fe_displacement", max_fe_u);
    const char axis[3] = {'x', 'y', 'z'};
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      for (unsigned int d = 0; d < dim; ++d)
        file.add_value("reaction_" + pd.boundary_conditions.names()[k] + "_" + axis[d],
                       pd_reactions[k][d]);
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe.conditions()[k].type != Quantity::load)
        for (unsigned int d = 0; d < dim; ++d)
          file.add_value("reaction_" + fe.conditions()[k].name + "_" + axis[d], fe_reactions[k][d]);
    file.end_row();

    if (is_root && final_row)
      {
        const auto flags = log.flags();
        log << std::scientific << std::setprecision(6) << "Final time: " << time << " s\n"
            << "Kinetic energy: " << kinetic << " J\n"
            << "Strain energy: " << strain << " J\n"
            << "External work: " << work << " J\n"
            << "Energy error: " << energy_error << " J\n";
        log_displacements(broken, max_u, max_fe_u);
        log_reactions(pd_reactions, fe_reactions);
        log << std::flush;
        log.flags(flags);
      }
    if (final_row)
      pd.log_probes();
  }

  template <int dim>
  void
  CoupledProblem<dim>::log_displacements(const std::uint64_t broken,
                                         const double        max_particle,
                                         const double        max_fe) const
  {
    if (pd.particle_system.n_global() > 0)
      log << "Broken bonds: " << broken << "\n"
          << "Max particle displacement: " << max_particle << " m\n";
    if (fe.n_dofs() > 0)
      log << "Max FE displacement: " << max_fe << " m (largest nodal component)\n";
  }

  template <int dim>
  void
  CoupledProblem<dim>::log_reactions(const std::vector<Tensor<1, dim>> &pd_reactions,
                                     const std::vector<Tensor<1, dim>> &fe_reactions) const
  {
    for (unsigned int k = 0; k < pd_reactions.size(); ++k)
      log << "Reaction " << pd.boundary_conditions.names()[k] << ": "
          << without_round_off(pd_reactions[k]) << " N\n";
    for (unsigned int k = 0; k < fe_reactions.size(); ++k)
      if (fe.conditions()[k].type != Quantity::load)
        log << "Reaction " << fe.conditions()[k].name << ": " << without_round_off(fe_reactions[k])
            << " N\n";
  }

  template <int dim>
  void
  CoupledProblem<dim>::write_output(const unsigned int step, const double time)
  {
    // The slaved particles move with the FE field: show their velocity too.
    transfer.interpolate(V, pd.v);
    pd.v.update_ghost_values();
    pd.write_particles(step, time);
    U.update_ghost_values();
    if (pd.write_hdf5)
      fe.write_output(pd.output_directory, "solution", step, time, U);
  }

  template class CoupledProblem<2>;
  template class CoupledProblem<3>;
} // namespace perideal
