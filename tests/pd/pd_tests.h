// Helpers shared by the unit tests in tests/pd: lattices, model set-up and the bad-input harness.
#ifndef perideal_pd_tests_h
#define perideal_pd_tests_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <perideal/base/elasticity.h>
#include <perideal/coupling/coupled_problem.h>
#include <perideal/pd/material_model.h>
#include <perideal/pd/particle_system.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <tests.h>

namespace pd_tests
{
  // The name of a planar assumption as the tests print it.
  inline std::string
  planar_name(const perideal::PlanarAssumption planar)
  {
    switch (planar)
      {
        case perideal::PlanarAssumption::plane_stress:
          return "plane stress";
        case perideal::PlanarAssumption::plane_strain:
          return "plane strain";
        default:
          return "3D";
      }
  }

  // Deterministic pseudo-random number in [-1, 1] from an integer key (splitmix64), so that
  // a field built from it does not depend on the number of ranks.
  inline double
  random_number(std::uint64_t key)
  {
    key += 0x9e3779b97f4a7c15ULL;
    key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
    key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
    key = key ^ (key >> 31);
    return 2. * (key >> 11) * (1. / 9007199254740992.) - 1.;
  }

  // Fill ps with every lattice point of the box [lower, upper] (no in-body test).
  template <int dim>
  inline void
  generate_box(perideal::ParticleSystem<dim>                          &ps,
               const typename perideal::ParticleSystem<dim>::Settings &settings,
               const dealii::Point<dim>                               &lower,
               const dealii::Point<dim>                               &upper,
               const std::vector<perideal::PreCrack<dim>>             &cracks = {})
  {
    ps.generate(
      settings,
      dealii::BoundingBox<dim>(std::make_pair(lower, upper)),
      [](const dealii::Point<dim> &) { return true; },
      cracks);
  }

  // Call f(v) for every integer offset v in [-reach, reach]^dim, first component fastest.
  template <int dim, typename Function>
  inline void
  for_each_lattice_offset(const int reach, const Function &f)
  {
    std::array<int, dim> v;
    v.fill(-reach);
    while (true)
      {
        f(std::as_const(v));
        unsigned int d = 0;
        for (; d < dim; ++d)
          if (v[d] < reach)
            {
              ++v[d];
              break;
            }
          else
            v[d] = -reach;
        if (d == dim)
          break;
      }
  }

  // A cube lattice of n^dim particles of spacing dx starting at the origin.
  template <int dim>
  struct Body
  {
    Body(const int                     n,
         const double                  dx,
         const double                  horizon_factor,
         const perideal::PartialVolume partial_volume,
         const double                  thickness)
      : n(n)
      , dx(dx)
      , delta(horizon_factor * dx)
      , ps(MPI_COMM_WORLD)
    {
      typename perideal::ParticleSystem<dim>::Settings s;
      s.spacing        = dx;
      s.horizon        = delta;
      s.thickness      = thickness;
      s.partial_volume = partial_volume;
      dealii::Point<dim> upper;
      for (unsigned int d = 0; d < dim; ++d)
        upper[d] = n * dx;
      generate_box<dim>(ps, s, dealii::Point<dim>(), upper);
    }

    // Distance of particle i from the boundary in lattice layers (0 on the surface layer).
    int
    depth(const unsigned int i) const
    {
      int layers = n;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const int k = static_cast<int>(std::lround(ps.positions()[i][d] / dx - 0.5));
          layers      = std::min({layers, k, n - 1 - k});
        }
      return layers;
    }

    // Index of particle i in the lattice, first direction fastest.
    std::uint64_t
    lattice_index(const unsigned int i) const
    {
      std::uint64_t index = 0;
      for (unsigned int d = dim; d-- > 0;)
        index = index * n + std::lround(ps.positions()[i][d] / dx - 0.5);
      return index;
    }

    // u(x) for all local (owned and ghost) particles.
    void
    set_field(perideal::ParticleVector                                        &u,
              const std::function<dealii::Tensor<1, dim>(const unsigned int)> &field) const
    {
      ps.reinit_vector(u, dim);
      for (unsigned int i = 0; i < ps.n_local(); ++i)
        {
          const auto value = field(i);
          for (unsigned int d = 0; d < dim; ++d)
            u.local_element(i * dim + d) = value[d];
        }
    }

    const int                     n;
    const double                  dx, delta;
    perideal::ParticleSystem<dim> ps;
  };

  // The verdict printed after a check.
  inline const char *
  ok(const bool condition)
  {
    return condition ? "ok" : "FAILED";
  }

  // The nodal forces of a linearization divided by the volumes, f = -(1/V) G^T diag(w) G u, of
  // the owned particles into f (laid out like u), and its energy 1/2 sum_r w_r (G_r u)^2 summed
  // over the ranks.
  template <int dim>
  double
  linearized_forces(const perideal::ParticleSystem<dim> &ps,
                    const perideal::LinearizedModel     &linearized,
                    const perideal::ParticleVector      &u,
                    perideal::ParticleVector            &f)
  {
    const unsigned int nc = linearized.n_components();
    ps.reinit_vector(f, nc);
    double energy = 0.;
    for (std::size_t r = 0; r < linearized.n_rows(); ++r)
      {
        double e = 0.;
        for (auto entry = linearized.row_begin(r); entry != linearized.row_end(r); ++entry)
          e += entry->coefficient * u.local_element(nc * entry->particle + entry->component);
        energy += 0.5 * linearized.weight(r) * e * e;
        for (auto entry = linearized.row_begin(r); entry != linearized.row_end(r); ++entry)
          f.local_element(nc * entry->particle + entry->component) -=
            linearized.weight(r) * e * entry->coefficient / ps.volumes()[entry->particle];
      }
    f.compress(dealii::VectorOperation::add);
    return dealii::Utilities::MPI::sum(energy, ps.get_communicator());
  }

  // Example entries of the models that the tests over every model share (perturbed_kernels_01,
  // energy_balance_01): NaCl with its axes turned about three axes, NaCl turned about z only (the
  // plane-stress model needs z = 0 as a mirror plane), and Timoshenko bonds at nu = 0.1 with the
  // lattice calibration.
  inline const std::vector<std::pair<std::string, std::string>> nacl_entries = {
    {"Symmetry", "cubic"},
    {"Cubic constants", "49.1e9, 12.8e9, 12.8e9"},
    {"Orientation", "20, 30, 40"}};
  inline const std::vector<std::pair<std::string, std::string>> nacl_about_z_entries = {
    {"Symmetry", "cubic"},
    {"Cubic constants", "49.1e9, 12.8e9, 12.8e9"},
    {"Orientation", "20, 0, 0"}};
  inline const std::vector<std::pair<std::string, std::string>> timoshenko_entries = {
    {"Young's modulus", "2e11"},
    {"Poisson's ratio", "0.1"},
    {"Calibration", "lattice"},
    {"Bending stiffness ratio", "0.4"}};

  // Declare the parameters of a material model, set the given entries and parse them.
  template <typename Model>
  inline void
  parse_model(Model &model, const std::vector<std::pair<std::string, std::string>> &entries)
  {
    dealii::ParameterHandler prm;
    Model::declare_parameters(prm);
    for (const auto &entry : entries)
      prm.set(entry.first, entry.second);
    model.parse_parameters(prm);
  }

  // The FE side's 2D Voigt stiffness (pairs 11, 22, 12) of the material @p entries
  // (ElasticMaterial's) under @p planar.
  inline dealii::FullMatrix<double>
  fe_voigt_stiffness(const std::vector<std::pair<std::string, std::string>> &entries,
                     const perideal::PlanarAssumption                        planar)
  {
    dealii::ParameterHandler prm;
    perideal::ElasticMaterial::declare_parameters(prm);
    for (const auto &entry : entries)
      prm.set(entry.first, entry.second);
    perideal::ElasticMaterial material;
    material.parse_parameters(prm, "Finite elements/Elasticity");
    const auto                 C          = material.tensor<2>(planar);
    const unsigned int         pair[3][2] = {{0, 0}, {1, 1}, {0, 1}};
    dealii::FullMatrix<double> voigt(3, 3);
    for (unsigned int I = 0; I < 3; ++I)
      for (unsigned int J = 0; J < 3; ++J)
        voigt(I, J) = C[pair[I][0]][pair[I][1]][pair[J][0]][pair[J][1]];
    return voigt;
  }

  // A model context with all four entries given.
  inline perideal::ModelContext
  model_context(const double                     horizon,
                const double                     thickness,
                const perideal::PlanarAssumption planar,
                const bool                       surface_correction)
  {
    perideal::ModelContext context;
    context.horizon            = horizon;
    context.thickness          = thickness;
    context.planar             = planar;
    context.surface_correction = surface_correction;
    return context;
  }

  // Read @p input, a particles-only problem with the regions @p region_names and boundary
  // conditions @p condition_names, into @p problem (the driver, as perideal-solid runs it).
  template <int dim>
  void
  parse_problem(perideal::CoupledProblem<dim>  &problem,
                const std::string              &input,
                const std::vector<std::string> &region_names,
                const std::vector<std::string> &condition_names = {})
  {
    dealii::ParameterHandler prm;
    perideal::CoupledProblem<dim>::declare_parameters(prm, region_names, condition_names, {});
    prm.parse_input_from_string(input);
    problem.parse_parameters(prm);
  }

  // Parse input (a particles-only problem) into the driver, set it up (and run it if asked) and
  // print to deallog either "accepted (wrong)" or the message of the exception it throws.
  inline void
  check_bad_input(const std::string              &name,
                  const std::string              &input,
                  const std::vector<std::string> &region_names,
                  const std::vector<std::string> &condition_names,
                  const bool                      run)
  {
    std::ostringstream log;
    try
      {
        perideal::CoupledProblem<2> problem(MPI_COMM_WORLD, log);
        parse_problem(problem, input, region_names, condition_names);
        problem.setup();
        if (run)
          problem.run();
        dealii::deallog << name << ": accepted (wrong)" << std::endl;
      }
    catch (const dealii::ExceptionBase &exc)
      {
        dealii::deallog << name << ": " << perideal_tests::exception_text(exc) << std::endl;
      }
  }

  // Run @p set_up, which must throw: print "label: " and the message, or that it was accepted.
  inline void
  check_refused(const std::string &label, const std::function<void()> &set_up)
  {
    try
      {
        set_up();
        dealii::deallog << label << ": accepted (wrong)" << std::endl;
      }
    catch (const dealii::ExceptionBase &exc)
      {
        dealii::deallog << label << ": " << perideal_tests::exception_text(exc) << std::endl;
      }
  }
} // namespace pd_tests

#endif
