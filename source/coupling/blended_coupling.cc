// ---------------------------------------------------------------------
// PeriDeal: energy blending of the FE region and the particles in the overlap.
// ---------------------------------------------------------------------
#include <perideal/base/exact_sum.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/coupling/blended_coupling.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  BlendedCoupling<dim>::declare_parameters(ParameterHandler &)
  {}

  template <int dim>
  double
  BlendedCoupling<dim>::fe_weight(const double beta) const
  {
    return 1. - beta;
  }

  template <int dim>
  double
  BlendedCoupling<dim>::particle_weight(const double beta) const
  {
    return beta;
  }

  template <int dim>
  void
  BlendedCoupling<dim>::initialize(const CoupledRegions<dim> &coupled_regions)
  {
    regions = coupled_regions;
    check_overlap_width();
    transfer.reinit(*regions.fe, *regions.particles, regions.layout);
  }

  template <int dim>
  void
  BlendedCoupling<dim>::check_overlap_width() const
  {
    // No bond from beta = 1 to beta = 0: a particle whose neighbours are all slaved to the FE field
    // but which carries the whole energy of its bonds, or the reverse, is a ghost force the
    // overlap cannot spread.
    const auto         &particles = *regions.particles;
    const auto         &x         = particles.positions();
    std::vector<double> beta(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      beta[i] = regions.blending(x[i]);
    const auto   &bonds   = particles.bonds();
    std::uint64_t n_short = 0;
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const double bi = beta[i], bj = beta[bonds.neighbor[b]];
          if ((bi >= 1. && bj <= 0.) || (bi <= 0. && bj >= 1.))
            ++n_short;
        }
    n_short = Utilities::MPI::sum(n_short, particles.get_communicator());
    AssertThrow(n_short == 0,
                ExcMessage(regions.blending_entry +
                           ": the overlap (0 < beta < 1) is narrower than the horizon (" +
                           ParameterUtilities::format_number(particles.settings().horizon) +
                           " m): " + std::to_string(n_short) +
                           " bonds join a particle with beta = 1 to one with beta = 0. Widen the "
                           "ramp of the blending function to at least a horizon."));
  }

  template <int dim>
  std::string
  BlendedCoupling<dim>::summary() const
  {
    const auto n_slaved = transfer.n_global_slaved();
    return std::to_string(n_slaved) + " particles slaved to the FE field, " +
           std::to_string(regions.particles->n_global() - n_slaved) + " free";
  }

  template <int dim>
  std::vector<ExchangeVolume>
  BlendedCoupling<dim>::transfer_exchanges() const
  {
    // TransferOperator::interpolate() and add_transpose() do nothing without slaved particles.
    if (transfer.n_global_slaved() == 0)
      return {};
    return {matrix_exchange("P U (FE dofs to slaved particles)", transfer.matrix(), false),
            matrix_exchange("P^T f (forces back to the FE dofs)", transfer.matrix(), true)};
  }

  template <int dim>
  const std::vector<bool> &
  BlendedCoupling<dim>::slaved_particles() const
  {
    return transfer.slaved_particles();
  }

  template <int dim>
  void
  BlendedCoupling<dim>::interpolate_to_particles(const FEVector &U, ParticleVector &u) const
  {
    transfer.interpolate(U, u);
  }

  template <int dim>
  void
  BlendedCoupling<dim>::add_particle_forces(const ParticleVector &f, FEVector &F) const
  {
    transfer.add_transpose(f, F);
  }

  template <int dim>
  CoupledEnergy
  BlendedCoupling<dim>::strain_energy(const FEVector &U, const double particle_energy) const
  {
    return {regions.fe->strain_energy(U), particle_energy};
  }

  template <int dim>
  void
  BlendedCoupling<dim>::lumped_masses(FEVector &fe_mass, std::vector<double> &particle_mass) const
  {
    // Particles: beta_i rho V_i (times the model's inertia scale). FE: the lumped (1 - beta) rho
    // plus P^T of the slaved particles' masses.
    const auto        &particles = *regions.particles;
    const auto        &volume    = particles.volumes();
    const auto        &weights   = particles.energy_weights();
    const unsigned int n_owned   = particles.n_owned();
    const unsigned int nc        = regions.layout.n_components();
    particle_mass.assign(n_owned, 0.);
    ParticleVector slaved_mass;
    particles.reinit_vector(slaved_mass, nc);
    // What a slaved component carries to the FE dofs per unit mass (MaterialModel::
    // inertia_ratios(): 1 for translations and scalars, the specific heat c for a temperature,
    // as the FE heat physics' lumped capacity rho c).
    const std::vector<double> inertia_ratio = regions.material->inertia_ratios(regions.density);
    // Materials by region: the particle's inertia relative to the uniform one.
    const std::vector<double> scales = regions.material->inertia_scales(particles, regions.density);
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        particle_mass[i] =
          weights[i] * regions.density * volume[i] * (scales.empty() ? 1. : scales[i]);
        // Rotations of slaved particles follow 1/2 curl U: their (second-order) rotational
        // inertia is not carried over to the FE translations.
        if (transfer.is_slaved(i))
          for (unsigned int c = 0; c < nc; ++c)
            if (regions.layout.kind(c) != ComponentKind::rotation)
              slaved_mass.local_element(i * nc + c) = particle_mass[i] * inertia_ratio[c];
      }
    fe_mass = regions.fe->lumped_mass();
    transfer.add_transpose(slaved_mass, fe_mass);
    std::uint64_t n_massless = 0;
    for (unsigned int k = 0; k < fe_mass.locally_owned_size(); ++k)
      n_massless += (fe_mass.local_element(k) <= 0.);
    n_massless = Utilities::MPI::sum(n_massless, particles.get_communicator());
    AssertThrow(n_massless == 0,
                ExcMessage(std::to_string(n_massless) +
                           " FE dofs carry no mass: their cells have 1 - beta = 0 at the nodes and "
                           "no particles. Check <Coupling/Blending function> against "
                           "<Discretization/Body>."));
  }

  template <int dim>
  void
  BlendedCoupling<dim>::initialize_equilibrium(const ParticleVector           &particle_prescribed,
                                               const EquilibriumSettings<dim> &settings,
                                               const std::string              &condition_list)
  {
    conditions    = condition_list;
    static_solver = std::make_unique<CoupledStaticSolver<dim>>(settings.linear);
    static_solver->reinit(*regions.fe, *regions.particles, transfer, particle_prescribed);
    relaxation.reset();
    if (settings.type != SolverType::adaptive_dynamic_relaxation)
      return;

    // Adaptive dynamic relaxation of the unknowns z of the static solve with the model's own
    // forces; its fictitious density is the Gershgorin bound of the linearized K.
    for (ParticleVector *vec : {&z, &z_prescribed, &z_force})
      static_solver->reinit_unknowns(*vec);
    const unsigned int nc = regions.layout.n_components();
    regions.particles->reinit_vector(nodal_force, nc);
    regions.particles->reinit_vector(pd_work, nc);
    regions.particles->reinit_vector(particle_state, nc);
    regions.fe->initialize_vector(fe_work);
    regions.fe->initialize_vector(fe_state);
    static_solver->assemble(*regions.material, conditions);
    relaxation = static_solver->relaxation(
      [this](ParticleVector &zz, ParticleVector &force) {
        static_solver->from_unknowns(zz, fe_state, particle_state);
        model_forces(fe_state,
                     particle_state,
                     *current_fe_load,
                     *current_pd_load,
                     fe_work,
                     pd_work,
                     false);
        fe_work *= -1.;
        static_solver->to_unknowns(fe_work, nodal_force, force);
      },
      z_prescribed,
      settings.relaxation,
      settings.relaxation_safety);
  }

  template <int dim>
  types::global_dof_index
  BlendedCoupling<dim>::n_unknowns() const
  {
    return static_solver->n_unknowns();
  }

  template <int dim>
  void
  BlendedCoupling<dim>::set_equilibrium_diagonal(const FEVector       &fe_diagonal,
                                                 const ParticleVector &particle_diagonal)
  {
    Assert(static_solver, ExcMessage("Call initialize_equilibrium() first."));
    static_solver->set_diagonal(fe_diagonal, particle_diagonal);
  }

  template <int dim>
  unsigned int
  BlendedCoupling<dim>::solve_equilibrium(const FEVector       &f_fe,
                                          const ParticleVector &f_pd,
                                          FEVector             &U,
                                          ParticleVector       &u)
  {
    if (!relaxation)
      return static_solver->solve(*regions.material, f_fe, f_pd, U, u, conditions);

    // ||F_ext|| over the free unknowns: the FE loads and the particle loads [N].
    const auto        &volume = regions.particles->volumes();
    const unsigned int nc     = regions.layout.n_components();
    for (std::size_t k = 0; k < nodal_force.locally_owned_size(); ++k)
      nodal_force.local_element(k) = f_pd.local_element(k) * volume[k / nc];
    static_solver->to_unknowns(f_fe, nodal_force, z_force);
    static_solver->clear_prescribed(z_force);
    static_solver->to_unknowns(U, u, z);
    z_prescribed      = z;
    current_fe_load   = &f_fe;
    current_pd_load   = &f_pd;
    const auto result = relaxation->solve(z, exact_l2_norm(z_force));
    static_solver->from_unknowns(z, U, u);
    return result.iterations;
  }

  template <int dim>
  double
  BlendedCoupling<dim>::equilibrium_forces(const FEVector       &U,
                                           const ParticleVector &u,
                                           const FEVector       &f_fe,
                                           const ParticleVector &f_pd,
                                           FEVector             &fe_residual,
                                           ParticleVector       &pd_force)
  {
    if (relaxation)
      return model_forces(U, u, f_fe, f_pd, fe_residual, pd_force, true);
    return static_solver->forces(U, u, f_fe, f_pd, fe_residual, pd_force);
  }

  template <int dim>
  std::array<double, 2>
  BlendedCoupling<dim>::equilibrium_particle_energies(const ParticleVector &u_0,
                                                      const ParticleVector &u_1)
  {
    if (!relaxation)
      return static_solver->particle_energies(*regions.material, u_0, u_1);
    // The model's own energy.
    auto &material = *regions.material;
    auto &ps       = *regions.particles;
    return {{model_strain_energy(material, ps, u_0, pd_work, energy_density),
             model_strain_energy(material, ps, u_1, pd_work, energy_density)}};
  }

  template <int dim>
  double
  BlendedCoupling<dim>::model_forces(const FEVector       &U,
                                     const ParticleVector &u,
                                     const FEVector       &f_fe,
                                     const ParticleVector &f_pd,
                                     FEVector             &fe_residual,
                                     ParticleVector       &pd_force,
                                     const bool            with_energy)
  {
    auto &particles = *regions.particles;
    // No bond breaks here: the relaxation's transients overshoot the equilibrium; bonds break
    // between solves, at the converged state (CoupledProblem's load stepping).
    regions.material->compute_forces(particles,
                                     u,
                                     pd_force,
                                     with_energy ? &energy_density : nullptr,
                                     std::numeric_limits<double>::infinity());
    const auto        &volume  = particles.volumes();
    const unsigned int n_owned = particles.n_owned();
    const unsigned int nc      = regions.layout.n_components();
    double             energy  = 0.;
    for (unsigned int i = 0; i < n_owned; ++i)
      {
        for (unsigned int k = i * nc; k < (i + 1) * nc; ++k)
          nodal_force.local_element(k) =
            (pd_force.local_element(k) + f_pd.local_element(k)) * volume[i];
        if (with_energy)
          energy += energy_density[i] * volume[i];
      }
    static_solver->fe_forces(U, f_fe, nodal_force, fe_residual);
    return Utilities::MPI::sum(energy, particles.get_communicator());
  }

  template class BlendedCoupling<2>;
  template class BlendedCoupling<3>;
} // namespace perideal

PERIDEAL_REGISTER_COUPLING_METHOD(perideal::BlendedCoupling,
                                  "blended",
                                  "energy blending in the overlap, particles there slaved to the "
                                  "FE field; explicit, static and adaptive dynamic relaxation.")
