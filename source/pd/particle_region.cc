// ---------------------------------------------------------------------
// PeriDeal: the particle region of a problem.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/memory_estimate.h>
#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/particle_region.h>

#include <algorithm>

namespace perideal
{
  using namespace dealii;

  namespace
  {
    // The partial-volume rules by their names in <Discretization/Partial volume correction>.
    const ParameterUtilities::Choices<PartialVolume> &
    partial_volumes()
    {
      static const ParameterUtilities::Choices<PartialVolume> names = {
        {"none", PartialVolume::none},
        {"book", PartialVolume::book},
        {"geometric", PartialVolume::geometric}};
      return names;
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
          // A segment of zero length or a parallelogram of zero area has no plane to cut by.
          const Tensor<1, dim> e1   = crack.vertices[1] - crack.vertices[0];
          double               size = e1.norm();
          if constexpr (dim == 3)
            size = cross_product_3d(e1, crack.vertices[2] - crack.vertices[0]).norm();
          AssertThrow(size > 0.,
                      ExcMessage(
                        "The crack <" + item + "> in <Pre-cracks/Cracks> is degenerate (" +
                        (dim == 2 ? "its two ends coincide" : "its three corners lie on one line") +
                        "): give a segment of positive length (2D) or a "
                        "parallelogram of positive area (3D)."));
          cracks.push_back(crack);
        }
      return cracks;
    }
  } // namespace

  template <int dim>
  ParticleRegion<dim>::ParticleRegion(const MPI_Comm comm, std::ostream &log)
    : communicator(comm)
    , log(log)
    , is_root(Utilities::MPI::this_mpi_process(comm) == 0)
    , particle_system(std::make_shared<ParticleSystem<dim>>(comm))
  {}

  template <int dim>
  void
  ParticleRegion<dim>::declare_parameters(ParameterHandler               &prm,
                                          const std::vector<std::string> &region_names,
                                          const std::vector<std::string> &condition_names)
  {
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
      prm.declare_entry(
        "Thickness",
        "1",
        Patterns::Double(0.),
        "2D only: thickness h of the body [m]; particle volume dx^2 h. A 3D problem "
        "refuses any other value than 1.");
      prm.declare_entry("Partial volume correction",
                        "book",
                        Patterns::Selection(ParameterUtilities::selection(partial_volumes())),
                        "How neighbours cut by the horizon count: 'none' (|xi| <= delta, full "
                        "volume); 'book' (|xi| <= delta, volume scaled by (delta + dx/2 - "
                        "|xi|)/dx beyond delta - dx/2, as in Madenci & Oterkus' codes and LAMMPS: "
                        "the family lacks 12-14 % of the horizon volume, which the surface "
                        "correction restores, so use it with 'Surface correction = true'); "
                        "'geometric' (the same factor with the family extended to delta + dx/2, "
                        "the cells the horizon cuts: right bulk stiffness without surface "
                        "correction, but an effective Poisson ratio 5 % low at delta = 3.015 dx). "
                        "See doc/architecture/14_decisions.md.");
      prm.declare_entry("Lattice perturbation",
                        "0",
                        Patterns::Double(0., 0.5),
                        "epsilon in [0, 0.5]: each particle moves from the centre of its lattice "
                        "cell by a random offset, uniform in [-epsilon dx/2, epsilon dx/2] per "
                        "coordinate (the centre decides whether it is in the body; volumes stay "
                        "dx^dim). 0 is the regular lattice. A perturbed lattice has no preferred "
                        "bond directions, so cracks do not lock onto lattice rows; the offsets "
                        "depend on <Perturbation seed> and the lattice indices, not on the number "
                        "of ranks. See doc/theory/models.md, 'Perturbed lattices'.");
      prm.declare_entry("Perturbation seed",
                        "1",
                        Patterns::Integer(0),
                        "Seed of the <Lattice perturbation>'s offsets; runs with other seeds give "
                        "the scatter of a result over lattices.");
      prm.declare_entry("Surface correction",
                        "true",
                        Patterns::Bool(),
                        "Correct the stiffness near free surfaces: energy method for 'bond "
                        "based' (and the other models, each its own method). 'linear peridynamic "
                        "solid' always uses each particle's discrete weighted volume (its "
                        "correction, and what makes its forces the gradient of its energy), so "
                        "this entry does not change it.");
      prm.declare_entry(
        "Surface correction method",
        "energy",
        Patterns::Selection("energy|stiffness fit"),
        "With 'Surface correction = true', for 'bond based', 'timoshenko bond "
        "based' and 'anisotropic bond based' (one grain): 'energy' (each particle's moduli C_aaaa along the axes, one "
        "factor per particle and axis) or 'stiffness fit' (the bond factors "
        "closest to 1 that give every particle the interior's whole elasticity "
        "tensor, D_12 and the shear moduli too; bounded to [0.2, 5], least "
        "squares at corners; a linear solve at set-up). The other models have "
        "their own method and accept 'energy' only. See doc/theory/models.md, "
        "'Surface correction: the stiffness fit'.");
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
      prm.declare_entry("Planar assumption",
                        "plane stress",
                        Patterns::Selection(
                          ParameterUtilities::selection(planar_assumption_names())),
                        "2D only: the state of the third direction. A 3D problem refuses 'plane "
                        "strain'.");
      prm.declare_entry("No-fail regions",
                        "",
                        Patterns::Anything(),
                        "Comma-separated regions in which bonds never break (a bond with an end "
                        "there is kept), e.g. the layers that carry a traction.");
      prm.declare_entry("Damage model",
                        "none",
                        Patterns::Selection(PluginRegistry<DamageModel<dim>>::pattern_string()),
                        "When bonds break. " + PluginRegistry<DamageModel<dim>>::documentation());
      PluginRegistry<DamageModel<dim>>::declare_parameters(prm);
    }
    prm.leave_subsection();
    declare_physics_parameters(prm, condition_names);
  }

  template <int dim>
  void
  ParticleRegion<dim>::declare_physics_parameters(ParameterHandler               &prm,
                                                  const std::vector<std::string> &condition_names)
  {
    prm.enter_subsection("Material");
    {
      prm.declare_entry("Model",
                        "bond based",
                        Patterns::Selection(PluginRegistry<MaterialModel<dim>>::pattern_string()),
                        "The peridynamic material model. " +
                          PluginRegistry<MaterialModel<dim>>::documentation());
      prm.declare_entry("Density", "0", Patterns::Double(0.), "Mass density rho [kg/m^3].");
      PluginRegistry<MaterialModel<dim>>::declare_parameters(prm);
    }
    prm.leave_subsection();

    BoundaryConditions<dim>::declare_parameters(prm, condition_names);
  }

  template <int dim>
  void
  ParticleRegion<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    // An empty <Body>: no particles (an FE-only problem); the PD entries are then not read,
    // except those the FE region shares (planar assumption, thickness).
    body_regions = ParameterUtilities::split_names(prm.get("Body"));
    if (has_body())
      {
        settings.spacing = prm.get_double("Lattice spacing");
        ParameterUtilities::require_positive(settings.spacing, "Discretization/Lattice spacing");
      }
    else
      settings.spacing = 1.; // a lattice for no particles
    horizon_factor = prm.get_double("Horizon factor");
    AssertThrow(horizon_factor > 1.,
                ExcMessage("The parameter <Discretization/Horizon factor> is " +
                           ParameterUtilities::format_number(horizon_factor) +
                           ": the horizon must be larger than the lattice spacing (accepted: > 1; "
                           "3 to 4 is usual)."));
    settings.horizon   = horizon_factor * settings.spacing;
    settings.thickness = prm.get_double("Thickness");
    ParameterUtilities::require_positive(settings.thickness, "Discretization/Thickness");
    AssertThrow(dim == 2 || settings.thickness == 1.,
                ExcMessage("The parameter <Discretization/Thickness> is " +
                           ParameterUtilities::format_number(settings.thickness) +
                           ", an entry of 2D problems (a particle's volume dx^2 h); in 3D a "
                           "particle's volume is dx^3 and the body's thickness is the extent of "
                           "its regions (<Regions>): remove the entry (accepted in 3D: 1, its "
                           "default)."));
    if (dim == 3)
      settings.thickness = 1.;
    settings.partial_volume =
      ParameterUtilities::choice(partial_volumes(),
                                 prm.get("Partial volume correction"),
                                 "Discretization/Partial volume correction");
    settings.perturbation      = prm.get_double("Lattice perturbation");
    settings.perturbation_seed = prm.get_integer("Perturbation seed");
    surface_correction         = prm.get_bool("Surface correction");
    stiffness_fit              = prm.get("Surface correction method") == "stiffness fit";
    prm.leave_subsection();

    regions.parse_parameters(prm);
    for (const auto &name : body_regions)
      regions.get(name, "Discretization/Body");
    body = regions.union_of(body_regions, "Discretization/Body");

    prm.enter_subsection("Pre-cracks");
    pre_cracks = parse_pre_cracks<dim>(prm.get("Cracks"));
    prm.leave_subsection();

    parse_material(prm, "", true);
  }

  template <int dim>
  void
  ParticleRegion<dim>::parse_physics_parameters(ParameterHandler          &prm,
                                                const std::string         &section,
                                                const ParticleRegion<dim> &geometry)
  {
    settings           = geometry.settings;
    horizon_factor     = geometry.horizon_factor;
    surface_correction = geometry.surface_correction;
    stiffness_fit      = geometry.stiffness_fit;
    planar             = geometry.planar;
    regions            = geometry.regions;
    body_regions       = geometry.body_regions;
    body               = geometry.body;
    pre_cracks         = geometry.pre_cracks;
    no_fail_regions    = geometry.no_fail_regions;
    particle_system    = geometry.particle_system;
    owns_particles     = false;
    parse_material(prm, section + "/", false);
  }

  template <int dim>
  void
  ParticleRegion<dim>::parse_material(ParameterHandler  &prm,
                                      const std::string &section,
                                      const bool         with_geometry)
  {
    prm.enter_subsection("Material");
    {
      if (with_geometry)
        {
          const std::string planar_name = prm.get("Planar assumption");
          AssertThrow(dim == 2 || planar_name == "plane stress",
                      ExcMessage("The parameter <Material/Planar assumption> is '" + planar_name +
                                 "', an entry of 2D problems (the state of the third "
                                 "direction); a 3D body has none: remove the entry (accepted in "
                                 "3D: plane stress, its default, which 3D ignores)."));
          planar = planar_assumption_from_name(planar_name, dim);
        }
      rho                          = prm.get_double("Density");
      const std::string model_name = prm.get("Model");
      model = PluginRegistry<MaterialModel<dim>>::create(model_name, section + "Material/Model");
      if (has_body())
        {
          ParameterUtilities::require_positive(rho, section + "Material/Density");
          prm.enter_subsection(model_name);
          model->parse_parameters(prm);
          prm.leave_subsection();
          model->resolve_regions(regions);
          AssertThrow(!(surface_correction && stiffness_fit) || model->capabilities().stiffness_fit,
                      ExcMessage("<Discretization/Surface correction method> = stiffness fit is "
                                 "available for <" +
                                 section + "Material/Model> = " +
                                 material_models_with<dim>(&ModelCapabilities::stiffness_fit) +
                                 " (as their parameters allow), not '" + model_name +
                                 "' as set up here; accepted for it: energy (the model's own "
                                 "method)."));
        }
      const std::string damage_name = with_geometry ? prm.get("Damage model") : "none";
      if (with_geometry)
        {
          no_fail_regions = ParameterUtilities::split_names(prm.get("No-fail regions"));
          for (const auto &name : no_fail_regions)
            regions.get(name, "Material/No-fail regions");
        }
      damage = PluginRegistry<DamageModel<dim>>::create(damage_name, "Material/Damage model");
      if (has_body() && with_geometry)
        {
          prm.enter_subsection(damage_name);
          damage->parse_parameters(prm);
          prm.leave_subsection();
          AssertThrow(!damage->calibrated_on_lattice() || model->capabilities().lattice_fracture,
                      ExcMessage("<Material/" + damage_name +
                                 "/Fracture energy calibration> = lattice is available for "
                                 "<Material/Model> = " +
                                 material_models_with<dim>(&ModelCapabilities::lattice_fracture) +
                                 ", not '" + model_name + "'; accepted for it: continuum."));
          AssertThrow(damage->softening().law() == BondFailure::brittle ||
                        model->capabilities().bond_softening,
                      ExcMessage("<Material/" + damage_name +
                                 "/Failure law> = linear softening is available for "
                                 "<Material/Model> = " +
                                 material_models_with<dim>(&ModelCapabilities::bond_softening) +
                                 ", not '" + model_name + "'; accepted for it: brittle."));
        }
      prm.leave_subsection();
      conditions.parse_parameters(prm, regions, model->field_layout());
      if (has_body())
        conditions.check_layer_depths(settings.horizon,
                                      settings.spacing,
                                      model->force_reach(),
                                      model_name);
    }
  }

  template <int dim>
  void
  ParticleRegion<dim>::setup(const std::function<bool(const Point<dim> &)>   &keep,
                             const std::function<double(const Point<dim> &)> &energy_weight,
                             const bool                                       log_summary)
  {
    ParticleSystem<dim> &ps = *particle_system;
    // A region sharing another's particles finds them made by the owner's setup().
    if (owns_particles && has_body())
      {
        ps.generate(settings,
                    regions.bounding_box_of(body_regions, "Discretization/Body"),
                    keep ? std::function<bool(const Point<dim> &)>(
                             [&](const Point<dim> &x) { return keep(x) && body(x); }) :
                           body,
                    pre_cracks,
                    regions.union_of(no_fail_regions, "Material/No-fail regions"),
                    // At the first set-up only, not at each regeneration of a growing region.
                    log_summary ?
                      std::function<void(std::uint64_t)>([&](const std::uint64_t n_particles) {
                        warn_if_bonds_exceed_memory(n_particles);
                      }) :
                      std::function<void(std::uint64_t)>());
        // A coupled problem may leave the PD region empty (beta = 0 on the whole body).
        AssertThrow(keep || ps.n_global() > 0,
                    ExcMessage("The body (<Discretization/Body>) holds no particle: its regions "
                               "are smaller than the lattice spacing or empty."));
      }
    else if (owns_particles)
      ps.generate(settings, BoundingBox<dim>(), [](const Point<dim> &) { return false; }, {});

    if (energy_weight && owns_particles)
      ps.set_energy_weights(energy_weight);

    ModelContext context;
    context.horizon            = settings.horizon;
    context.thickness          = settings.thickness;
    context.planar             = planar;
    context.surface_correction = surface_correction;
    context.stiffness_fit      = stiffness_fit;
    context.lattice_fracture   = damage->calibrated_on_lattice();
    context.softening          = damage->softening();
    model->initialize(ps, context);
    s_critical = damage->critical_stretch(*model);

    conditions.setup(ps);

    stable_dt = model->stable_time_step(ps, rho);

    const auto n_bonds = ps.n_global_bonds();
    if (is_root && has_body() && log_summary)
      log << "Particles: " << ps.n_global() << "\n"
          << "Bonds: " << n_bonds << "\n"
          << "Material: " << model->summary() << "\n"
          << "Critical stretch: " << s_critical << std::endl;
  }

  template <int dim>
  void
  ParticleRegion<dim>::warn_if_bonds_exceed_memory(const std::uint64_t n_particles) const
  {
    std::vector<Tensor<1, dim>> xi;
    std::vector<double>         weight;
    particle_system->lattice_family(xi, weight);
    const std::string warning =
      MemoryEstimate::warning(0.5 * double(xi.size()) * double(n_particles),
                              MemoryEstimate::available_memory(communicator),
                              settings.spacing);
    if (is_root && !warning.empty())
      log << warning << std::endl;
  }

  template <int dim>
  bool
  ParticleRegion<dim>::in_body(const Point<dim> &x) const
  {
    return body && body(x);
  }

  template <int dim>
  bool
  ParticleRegion<dim>::has_body() const
  {
    return !body_regions.empty();
  }

  template <int dim>
  FieldLayout
  ParticleRegion<dim>::field_layout() const
  {
    return model->field_layout();
  }

  template <int dim>
  ParticleSystem<dim> &
  ParticleRegion<dim>::particles()
  {
    return *particle_system;
  }

  template <int dim>
  const ParticleSystem<dim> &
  ParticleRegion<dim>::particles() const
  {
    return *particle_system;
  }

  template <int dim>
  MaterialModel<dim> &
  ParticleRegion<dim>::material()
  {
    return *model;
  }

  template <int dim>
  const MaterialModel<dim> &
  ParticleRegion<dim>::material() const
  {
    return *model;
  }

  template <int dim>
  BoundaryConditions<dim> &
  ParticleRegion<dim>::boundary_conditions()
  {
    return conditions;
  }

  template <int dim>
  const BoundaryConditions<dim> &
  ParticleRegion<dim>::boundary_conditions() const
  {
    return conditions;
  }

  template <int dim>
  double
  ParticleRegion<dim>::density() const
  {
    return rho;
  }

  template <int dim>
  double
  ParticleRegion<dim>::critical_stretch() const
  {
    return s_critical;
  }

  template <int dim>
  double
  ParticleRegion<dim>::stable_time_step() const
  {
    return stable_dt;
  }

  template <int dim>
  const typename ParticleSystem<dim>::Settings &
  ParticleRegion<dim>::discretization() const
  {
    return settings;
  }

  template <int dim>
  PlanarAssumption
  ParticleRegion<dim>::planar_assumption() const
  {
    return planar;
  }

  template class ParticleRegion<2>;
  template class ParticleRegion<3>;
} // namespace perideal
