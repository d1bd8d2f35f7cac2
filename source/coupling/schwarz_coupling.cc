// ---------------------------------------------------------------------
// PeriDeal: overlapping (alternating) Schwarz coupling of the FE region and the particles.
// ---------------------------------------------------------------------
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>

#include <perideal/base/exact_sum.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/schwarz_coupling.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  SchwarzCoupling<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Converged when the change of the interface values (the FE dofs prescribed "
                      "by the PD field) in one Schwarz iteration, |G(x) - x|, is at most this "
                      "times |G(x)|.");
    prm.declare_entry("Maximum iterations",
                      "100",
                      Patterns::Integer(1),
                      "Schwarz iterations per solve; a solve that has not converged then stops "
                      "with its residual history and the state written.");
    prm.declare_entry("Relaxation",
                      "aitken",
                      Patterns::Selection("none|fixed factor|aitken"),
                      "The update of the interface values x <- x + omega (G(x) - x): omega = 1 "
                      "(none), <Relaxation factor> (fixed factor), or Aitken's dynamic factor "
                      "starting from <Relaxation factor> (aitken).");
    prm.declare_entry("Relaxation factor",
                      "0.5",
                      Patterns::Double(0.),
                      "omega of 'fixed factor' and the first omega of 'aitken', in (0, 1].");
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::parse_parameters(ParameterHandler &prm)
  {
    tolerance         = prm.get_double("Tolerance");
    max_iterations    = prm.get_integer("Maximum iterations");
    relaxation_name   = prm.get("Relaxation");
    relaxation        = relaxation_name == "none"         ? Relaxation::none :
                        relaxation_name == "fixed factor" ? Relaxation::fixed :
                                                            Relaxation::aitken;
    relaxation_factor = prm.get_double("Relaxation factor");
    AssertThrow(relaxation_factor > 0. && relaxation_factor <= 1.,
                ExcMessage("<Coupling/overlapping schwarz/Relaxation factor> = " +
                           ParameterUtilities::format_number(relaxation_factor) +
                           ": accepted values are in (0, 1]."));
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::check_solver(const SolverType type) const
  {
    AssertThrow(type != SolverType::explicit_dynamics && type != SolverType::implicit,
                ExcMessage("<Coupling/Method> = overlapping schwarz alternates equilibrium solves "
                           "of the FE and PD parts: <Solver/Type> = explicit or implicit is not "
                           "supported; accepted values: static, adaptive dynamic relaxation (or "
                           "use <Coupling/Method> = blended for explicit dynamics and implicit "
                           "time steps)."));
  }

  template <int dim>
  double
  SchwarzCoupling<dim>::fe_weight(const double beta) const
  {
    return beta < 1. ? 1. : 0.;
  }

  template <int dim>
  double
  SchwarzCoupling<dim>::particle_weight(const double beta) const
  {
    return beta > 0. ? 1. : 0.;
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::initialize(const CoupledRegions<dim> &coupled_regions)
  {
    regions = coupled_regions;
    AssertThrow(regions.layout == regions.fe->field_layout(),
                ExcMessage("<Coupling/Method> = overlapping schwarz needs the same unknowns on "
                           "both sides; the particles have " +
                           regions.layout.description() + ", <Finite elements/Physics> has " +
                           regions.fe->field_layout().description() +
                           ". Use <Coupling/Method> = blended for particles with rotations."));
    classify_particles();
    transfer.reinit(*regions.fe, *regions.particles, regions.layout);
    // The volume constraint takes the FE field: every constrained particle lies in an FE cell.
    std::uint64_t n_outside = 0;
    for (unsigned int i = 0; i < constrained.size(); ++i)
      n_outside += (constrained[i] && !transfer.is_slaved(i));
    n_outside = Utilities::MPI::sum(n_outside, regions.particles->get_communicator());
    AssertThrow(n_outside == 0,
                ExcMessage(regions.blending_entry + ": " + std::to_string(n_outside) +
                           " particles of the PD volume constraint (within a horizon of beta = "
                           "0) lie in cells without FE unknowns (beta = 1 at all their nodes). "
                           "Widen the overlap 0 < beta < 1."));
    setup_interface();
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::classify_particles()
  {
    const auto         &particles = *regions.particles;
    const auto         &x         = particles.positions();
    const auto         &bonds     = particles.bonds();
    const unsigned int  n_owned   = particles.n_owned();
    std::vector<double> beta(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      beta[i] = regions.blending(x[i]);
    // Free: beta > 0 and every bond to a particle with beta > 0 (the PD operator at full
    // weight); the others take their values from the FE field.
    constrained.assign(n_owned, false);
    pd_only.assign(n_owned, false);
    std::uint64_t n_short = 0;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        constrained[i] = constrained[i] || beta[i] <= 0.;
        pd_only[i]     = beta[i] >= 1.;
        for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
          {
            const unsigned int j = bonds.neighbor[b];
            constrained[i]       = constrained[i] || beta[j] <= 0.;
            if (j < n_owned)
              constrained[j] = constrained[j] || beta[i] <= 0.;
            n_short += (beta[i] >= 1. && beta[j] <= 0.) || (beta[i] <= 0. && beta[j] >= 1.);
          }
      }
    const MPI_Comm comm = particles.get_communicator();
    n_short             = Utilities::MPI::sum(n_short, comm);
    AssertThrow(n_short == 0,
                ExcMessage(regions.blending_entry +
                           ": the overlap (0 < beta < 1) is narrower than the horizon (" +
                           ParameterUtilities::format_number(particles.settings().horizon) +
                           " m): " + std::to_string(n_short) +
                           " bonds join a particle with beta = 1 to one with beta = 0, so the "
                           "PD volume constraint would reach where only PD is solved. Overlapping "
                           "Schwarz needs the ramp of the blending function wider than a horizon "
                           "(plus an FE cell)."));
    n_constrained = Utilities::MPI::sum<types::global_dof_index>(std::count(constrained.begin(),
                                                                            constrained.end(),
                                                                            true),
                                                                 comm);
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::setup_interface()
  {
    auto           &fe          = *regions.fe;
    const auto     &dof_handler = fe.get_dof_handler();
    const IndexSet &owned       = dof_handler.locally_owned_dofs();
    const auto     &held        = fe.prescribed_mask();

    // The interface: every dof of a cell with a vertex at beta = 1 (owned and ghost cells, so
    // that each owner sees all of its dofs), unless an FE condition holds it.
    std::map<types::global_dof_index, std::pair<unsigned int, Point<dim>>> interface;
    const MappingQ1<dim>                                                   mapping;
    std::vector<types::global_dof_index>                                   dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->get_fe().n_dofs_per_cell() > 0)
        {
          bool touches = false;
          for (const unsigned int v : cell->vertex_indices())
            touches = touches || regions.blending(cell->vertex(v)) >= 1.;
          if (!touches)
            continue;
          const auto &cell_fe = cell->get_fe();
          dofs.resize(cell_fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < dofs.size(); ++k)
            if (owned.is_element(dofs[k]) && !held[owned.index_within_set(dofs[k])])
              interface[dofs[k]] = {
                cell_fe.system_to_component_index(k).first,
                mapping.transform_unit_to_real_cell(cell, cell_fe.unit_support_point(k))};
        }
    std::vector<types::global_dof_index>          interface_global;
    std::vector<typename InterfaceFit<dim>::Node> nodes;
    interface_dofs.clear();
    for (const auto &[dof, point] : interface)
      {
        interface_global.push_back(dof);
        interface_dofs.push_back(owned.index_within_set(dof));
        nodes.push_back({dof, point.first, point.second});
      }
    fe.set_interior_values(interface_global, std::vector<double>(interface_global.size(), 0.));
    interface_values.assign(interface_dofs.size(), 0.);
    interface_fit.reinit(*regions.particles, constrained, nodes, owned, regions.blending_entry);
  }

  template <int dim>
  std::string
  SchwarzCoupling<dim>::summary() const
  {
    const types::global_dof_index n_interface =
      Utilities::MPI::sum<types::global_dof_index>(interface_dofs.size(),
                                                   regions.particles->get_communicator());
    return std::to_string(regions.particles->n_global() - n_constrained) + " particles free, " +
           std::to_string(n_constrained) + " in the volume constraint (from the FE field), " +
           std::to_string(n_interface) +
           " FE dofs from the PD field (quadratic least-squares fit); tolerance " +
           ParameterUtilities::format_number(tolerance) + ", relaxation " + relaxation_name;
  }

  template <int dim>
  const std::vector<bool> &
  SchwarzCoupling<dim>::slaved_particles() const
  {
    return constrained;
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::interpolate_to_particles(const FEVector &U, ParticleVector &u) const
  {
    // P U on the volume constraint only: the free particles of FE cells keep their values.
    const unsigned int nc = regions.layout.n_components();
    if (layer_values.size() != u.size())
      regions.particles->reinit_vector(layer_values, nc);
    transfer.interpolate(U, layer_values);
    for (unsigned int i = 0; i < constrained.size(); ++i)
      if (constrained[i])
        for (unsigned int c = 0; c < nc; ++c)
          u.local_element(i * nc + c) = layer_values.local_element(i * nc + c);
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::add_particle_forces(const ParticleVector &, FEVector &) const
  {
    AssertThrow(false, ExcMessage("overlapping schwarz: explicit dynamics is refused."));
  }

  template <int dim>
  CoupledEnergy
  SchwarzCoupling<dim>::strain_energy(const FEVector &U, const double particle_energy) const
  {
    return {regions.fe->strain_energy(U), particle_energy};
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::lumped_masses(FEVector &, std::vector<double> &) const
  {
    AssertThrow(false, ExcMessage("overlapping schwarz: explicit dynamics is refused."));
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::initialize_equilibrium(const ParticleVector           &particle_prescribed,
                                               const EquilibriumSettings<dim> &settings,
                                               const std::string              &condition_list)
  {
    conditions              = condition_list;
    const MPI_Comm     comm = regions.particles->get_communicator();
    const unsigned int nc   = regions.layout.n_components();
    // What a one-region problem has for its empty region: an FE region without a mesh, a
    // particle system without particles.
    no_fe = std::make_unique<FERegion<dim>>(comm);
    ParameterHandler prm;
    FERegion<dim>::declare_parameters(prm, {});
    no_fe->parse_parameters(prm, PlanarAssumption::plane_stress, 1.);
    no_fe->setup();
    no_particles = std::make_unique<ParticleSystem<dim>>(comm);
    no_particles->generate(regions.particles->settings(),
                           BoundingBox<dim>(),
                           [](const Point<dim> &) { return false; },
                           {});
    for (FEVector *vector : {&no_U, &no_fe_load, &no_fe_residual})
      no_fe->initialize_vector(*vector);
    for (ParticleVector *vector : {&no_u, &no_particle_load, &no_particle_force})
      no_particles->reinit_vector(*vector, nc);
    regions.particles->reinit_vector(force, nc);
    regions.particles->reinit_vector(nodal_force, nc);

    // The PD part holds its conditions and the volume constraint.
    ParticleVector pd_prescribed(particle_prescribed);
    for (unsigned int i = 0; i < constrained.size(); ++i)
      if (constrained[i])
        for (unsigned int c = 0; c < nc; ++c)
          pd_prescribed.local_element(i * nc + c) = 1.;
    fe_transfer.reinit(*regions.fe, *no_particles, regions.layout);
    pd_transfer.reinit(*no_fe, *regions.particles, regions.layout);
    fe_solver = std::make_unique<CoupledStaticSolver<dim>>(settings.linear);
    fe_solver->reinit(*regions.fe, *no_particles, fe_transfer, no_u);
    fe_solver->assemble(*regions.material, conditions);
    pd_solver = std::make_unique<CoupledStaticSolver<dim>>(settings.linear);
    pd_solver->reinit(*no_fe, *regions.particles, pd_transfer, pd_prescribed);
    pd_relaxation.reset();
    if (settings.type != SolverType::adaptive_dynamic_relaxation)
      return;

    // Adaptive dynamic relaxation of the PD part with the model's own forces (the FE part is
    // linear and keeps its static solve); its fictitious density is the Gershgorin bound of the
    // linearized PD stiffness.
    for (ParticleVector *vector : {&z, &z_prescribed, &z_force, &z_work})
      pd_solver->reinit_unknowns(*vector);
    regions.particles->reinit_vector(particle_state, nc);
    pd_residual = [this](ParticleVector &zz, ParticleVector &zforce) {
      pd_solver->from_unknowns(zz, no_U, particle_state);
      particle_nodal_forces(particle_state, *current_pd_load, nullptr);
      pd_solver->to_unknowns(no_fe_load, nodal_force, zforce);
    };
    pd_solver->assemble(*regions.material, conditions);
    pd_relaxation = pd_solver->relaxation(pd_residual,
                                          z_prescribed,
                                          settings.relaxation,
                                          settings.relaxation_safety);
  }

  template <int dim>
  std::array<double, 2>
  SchwarzCoupling<dim>::equilibrium_particle_energies(const ParticleVector &u_0,
                                                      const ParticleVector &u_1)
  {
    // The particles' energy of equilibrium_forces(): the model's own, where only PD is solved.
    auto &material = *regions.material;
    auto &ps       = *regions.particles;
    return {{model_strain_energy(material, ps, u_0, force, energy_density, pd_only),
             model_strain_energy(material, ps, u_1, force, energy_density, pd_only)}};
  }

  template <int dim>
  double
  SchwarzCoupling<dim>::particle_nodal_forces(const ParticleVector &u,
                                              const ParticleVector &f_pd,
                                              std::vector<double>  *energy)
  {
    // No bond breaks here: bonds break between solves, at the converged state (the load
    // stepping).
    auto &particles = *regions.particles;
    regions.material->compute_forces(particles,
                                     u,
                                     force,
                                     energy,
                                     std::numeric_limits<double>::infinity());
    const auto        &volume    = particles.volumes();
    const unsigned int nc        = regions.layout.n_components();
    double             pd_energy = 0.;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      {
        for (unsigned int k = i * nc; k < (i + 1) * nc; ++k)
          nodal_force.local_element(k) =
            (force.local_element(k) + f_pd.local_element(k)) * volume[i];
        if (energy != nullptr && pd_only[i])
          pd_energy += (*energy)[i] * volume[i];
      }
    return Utilities::MPI::sum(pd_energy, particles.get_communicator());
  }

  template <int dim>
  types::global_dof_index
  SchwarzCoupling<dim>::n_unknowns() const
  {
    return fe_solver->n_unknowns() + pd_solver->n_unknowns();
  }

  template <int dim>
  double
  SchwarzCoupling<dim>::solution_accuracy() const
  {
    return 100. * tolerance;
  }

  template <int dim>
  unsigned int
  SchwarzCoupling<dim>::solve_equilibrium(const FEVector       &f_fe,
                                          const ParticleVector &f_pd,
                                          FEVector             &U,
                                          ParticleVector       &u)
  {
    const MPI_Comm comm = regions.particles->get_communicator();
    // Bonds may have broken since the last solve: the PD stiffness once per solve (the
    // relaxation works with the model's forces).
    if (!pd_relaxation)
      pd_solver->assemble(*regions.material, conditions);
    // Exact sums (ExactSum): the norms decide the stop and Aitken's factor, which amplifies a
    // difference in their last bits, so they must not depend on the partition.
    const auto dot = [comm](const std::vector<double> &v, const std::vector<double> &w) {
      ExactSum sum;
      for (std::size_t k = 0; k < v.size(); ++k)
        sum.add(v[k] * w[k]);
      return ExactSum::global_sums({sum}, comm)[0];
    };
    pd_force_scale = 0.;
    std::vector<double> history;
    double              omega = relaxation == Relaxation::none ? 1. : relaxation_factor;
    for (unsigned int iteration = 1; iteration <= max_iterations; ++iteration)
      {
        // x -> FE solve -> volume constraint P U -> PD solve -> G(x), the fit of the PD field.
        for (std::size_t j = 0; j < interface_dofs.size(); ++j)
          U.local_element(interface_dofs[j]) = interface_values[j];
        fe_solver->solve_assembled(*regions.material, f_fe, no_particle_load, U, no_u, conditions);
        interpolate_to_particles(U, u);
        solve_pd_part(f_pd, u);
        interface_fit.evaluate(u, regions.layout.n_components(), interface_dofs, fitted_values);
        residual.resize(fitted_values.size());
        for (std::size_t j = 0; j < residual.size(); ++j)
          residual[j] = fitted_values[j] - interface_values[j];
        const double r = std::sqrt(dot(residual, residual)),
                     g = std::sqrt(dot(fitted_values, fitted_values));
        history.push_back(g > 0. ? r / g : r);
        const bool converged = r <= tolerance * g;
        const bool diverged  = !std::isfinite(r) || history.back() > 1e3 * history.front();
        if (converged || diverged || iteration == max_iterations)
          {
            // Converged: the count and the first and last residuals (the history between them
            // reaches the sub-solves' round-off, which differs with the partition; a failure
            // prints all of it).
            if (converged)
              {
                std::ostringstream summary;
                summary << "Overlapping Schwarz: " << iteration
                        << " iterations, |G(x) - x| / |G(x)| from " << std::scientific
                        << std::setprecision(1) << history.front() << " to " << history.back();
                if (regions.log != nullptr && Utilities::MPI::this_mpi_process(comm) == 0)
                  *regions.log << summary.str() << std::endl;
                return iteration;
              }
            std::ostringstream line;
            line << std::scientific << std::setprecision(1);
            for (const double h : history)
              line << " " << h;
            AssertThrow(false,
                        ExcNotConverged(
                          "The overlapping Schwarz iteration " +
                          std::string(diverged ? "diverged" : "did not converge") + " in " +
                          std::to_string(iteration) +
                          " iterations (<Coupling/overlapping "
                          "schwarz/Maximum iterations> = " +
                          std::to_string(max_iterations) +
                          ", <Tolerance> = " + ParameterUtilities::format_number(tolerance) +
                          ", <Relaxation> = " + relaxation_name +
                          "); |G(x) - x| / |G(x)| per iteration:" + line.str() +
                          ". Raise the maximum iterations, use Relaxation = aitken, or widen "
                          "the overlap of " +
                          regions.blending_entry + "."));
          }
        // Aitken's factor from the last two residuals.
        if (relaxation == Relaxation::aitken && iteration > 1)
          {
            for (std::size_t j = 0; j < residual.size(); ++j)
              previous_residual[j] = residual[j] - previous_residual[j];
            const double change = dot(previous_residual, previous_residual);
            if (change > 0.)
              omega *= -(dot(previous_residual, residual) - change) / change;
          }
        previous_residual = residual;
        for (std::size_t j = 0; j < residual.size(); ++j)
          interface_values[j] += omega * residual[j];
      }
    Assert(false, ExcInternalError());
    return max_iterations;
  }

  template <int dim>
  void
  SchwarzCoupling<dim>::solve_pd_part(const ParticleVector &f_pd, ParticleVector &u)
  {
    if (!pd_relaxation)
      {
        pd_solver->solve_assembled(*regions.material, no_fe_load, f_pd, no_U, u, conditions);
        return;
      }
    // ||F_ext|| over the free unknowns: the particle loads [N].
    const auto        &volume = regions.particles->volumes();
    const unsigned int nc     = regions.layout.n_components();
    for (std::size_t k = 0; k < nodal_force.locally_owned_size(); ++k)
      nodal_force.local_element(k) = f_pd.local_element(k) * volume[k / nc];
    pd_solver->to_unknowns(no_fe_load, nodal_force, z_force);
    pd_solver->clear_prescribed(z_force);
    pd_solver->to_unknowns(no_U, u, z);
    z_prescribed    = z;
    current_pd_load = &f_pd;
    // The tolerance is relative to the forces of the load step, the initial residual of its
    // first relaxation: the later ones start close to equilibrium, and relative to their own
    // initial residual would ask for round-off.
    if (pd_force_scale == 0.)
      {
        pd_residual(z, z_work);
        pd_solver->clear_prescribed(z_work);
        pd_force_scale = exact_l2_norm(z_work);
      }
    pd_relaxation->solve(z, std::max(exact_l2_norm(z_force), pd_force_scale));
    pd_solver->from_unknowns(z, no_U, u);
  }

  template <int dim>
  double
  SchwarzCoupling<dim>::equilibrium_forces(const FEVector       &U,
                                           const ParticleVector &u,
                                           const FEVector       &f_fe,
                                           const ParticleVector &f_pd,
                                           FEVector             &fe_residual,
                                           ParticleVector       &pd_force)
  {
    fe_solver->forces(U, no_u, f_fe, no_particle_load, fe_residual, no_particle_force);
    // The interface dofs are held by the PD field, not by supports: no reaction, no work.
    for (const unsigned int k : interface_dofs)
      fe_residual.local_element(k) = 0.;
    // The PD part's energy: the particles where only PD is solved (the model's own energy).
    const double energy = particle_nodal_forces(u, f_pd, &energy_density);
    if (pd_relaxation)
      pd_force = force;
    else
      pd_solver->forces(no_U, u, no_fe_load, f_pd, no_fe_residual, pd_force);
    return energy;
  }

  template class SchwarzCoupling<2>;
  template class SchwarzCoupling<3>;
} // namespace perideal

PERIDEAL_REGISTER_COUPLING_METHOD(perideal::SchwarzCoupling,
                                  "overlapping schwarz",
                                  "alternating (multiplicative) Schwarz: the FE part (beta < 1) "
                                  "and the PD part (beta > 0, its volume constraint from the FE "
                                  "field) solved in turn to a tolerance; static and adaptive "
                                  "dynamic relaxation (of the PD part).")
