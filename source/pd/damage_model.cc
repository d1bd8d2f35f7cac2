// ---------------------------------------------------------------------
// PeriDeal: damage models (when bonds break) and the damage index.
// ---------------------------------------------------------------------
#include <perideal/base/problem_settings.h>
#include <perideal/pd/damage_model.h>

#include <cmath>
#include <limits>
#include <string>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  bool
  DamageModel<dim>::calibrated_on_lattice() const
  {
    return false;
  }

  template <int dim>
  BondSoftening
  DamageModel<dim>::softening() const
  {
    return {};
  }

  template <int dim>
  double
  NoDamage<dim>::critical_stretch(const MaterialModel<dim> &) const
  {
    return std::numeric_limits<double>::infinity();
  }

  template <int dim>
  void
  CriticalStretch<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Fracture energy",
                      "0",
                      Patterns::Double(0.),
                      "Critical energy release rate G0 [J/m^2]; the critical stretch follows from "
                      "the material model's formula.");
    prm.declare_entry("Critical stretch",
                      "0",
                      Patterns::Double(0.),
                      "Critical stretch s0 [-]; when greater than zero it is used as given and "
                      "'Fracture energy' is ignored.");
    prm.declare_entry(
      "Fracture energy calibration",
      "continuum",
      Patterns::Selection("continuum|lattice"),
      "How the critical stretch (the critical slope of antiplane shear, each failure mode's "
      "limit of the Timoshenko bond) follows from the Fracture energy: continuum (the model's "
      "closed-form formula, the integral over the horizon's ball) or lattice (the bonds of the "
      "actual particles that a straight crack cuts, with their partial volumes and surface "
      "factors, on a regular or perturbed lattice, dissipate exactly the Fracture energy per "
      "unit crack area; measured on the interior particles, the crack normal along the "
      "coordinate axes; for the state-based models, whose energy is not a sum of bond "
      "energies, by a cleave of a box of the same lattice: mode III for antiplane state "
      "based, mode I for linear peridynamic solid). For bond based, antiplane bond based, "
      "antiplane state based, linear peridynamic solid and timoshenko bond based; not with a "
      "Critical stretch given.");
    prm.declare_entry(
      "Failure law",
      "brittle",
      Patterns::Selection("brittle|linear softening"),
      "How a bond fails: brittle (it breaks at the critical stretch s_G) or linear softening "
      "(elastic up to s_G / sqrt(n), then its force falls linearly to zero at s_G sqrt(n), n "
      "the Softening ratio: the brittle bond's work to break, so the same fracture energy; "
      "secant unloading; doc/theory/models.md, 'Softening PMB bonds'). Linear softening: for "
      "bond based, with <Solver/Control/Method> = sequentially linear, which follows the law "
      "in Softening teeth saw teeth of equal dissipated energy.");
    prm.declare_entry("Softening ratio",
                      "4",
                      Patterns::Double(1.),
                      "n [-] > 1 with <Failure law> = linear softening: the stretch at which a "
                      "bond's force has fallen to zero over its elastic limit.");
    prm.declare_entry("Softening teeth",
                      "8",
                      Patterns::Integer(1, 255),
                      "N [-] with <Failure law> = linear softening: the saw teeth by which the "
                      "sequentially linear control follows the softening of a bond (each one "
                      "event of the bond; each tooth's peak force is n^(1/(2N)) times the law's "
                      "at the start of its secant, its dissipated energy the law's exactly).");
  }

  template <int dim>
  void
  CriticalStretch<dim>::parse_parameters(ParameterHandler &prm)
  {
    fracture_energy = prm.get_double("Fracture energy");
    given_stretch   = prm.get_double("Critical stretch");
    on_lattice      = prm.get("Fracture energy calibration") == "lattice";
    law             = prm.get("Failure law") == "linear softening" ?
                        BondSoftening(prm.get_double("Softening ratio"), prm.get_integer("Softening teeth")) :
                        BondSoftening();
    AssertThrow(fracture_energy > 0. || given_stretch > 0.,
                ExcMessage("The damage model 'critical stretch' needs <Material/critical "
                           "stretch/Fracture energy> > 0 [J/m^2] or <Material/critical "
                           "stretch/Critical stretch> > 0."));
    AssertThrow(!(on_lattice && given_stretch > 0.),
                ExcMessage("<Material/critical stretch/Fracture energy calibration> = lattice "
                           "calibrates the critical stretch from the Fracture energy, but "
                           "<Material/critical stretch/Critical stretch> = " +
                           prm.get("Critical stretch") +
                           " gives it; accepted: Critical stretch = 0 with the lattice "
                           "calibration, or the continuum calibration."));
  }

  template <int dim>
  double
  CriticalStretch<dim>::critical_stretch(const MaterialModel<dim> &material) const
  {
    return given_stretch > 0. ? given_stretch : material.critical_stretch(fracture_energy);
  }

  template <int dim>
  bool
  CriticalStretch<dim>::calibrated_on_lattice() const
  {
    return on_lattice;
  }

  template <int dim>
  BondSoftening
  CriticalStretch<dim>::softening() const
  {
    return law;
  }

  template <int dim>
  std::vector<double>
  damage_index(const ParticleSystem<dim> &particles)
  {
    const BondList     &bonds   = particles.bonds();
    const auto         &volume  = particles.volumes();
    const unsigned int  n_owned = particles.n_owned();
    std::vector<double> total(n_owned, 0.), broken(n_owned, 0.);
    for (unsigned int i = 0; i < n_owned; ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        {
          const unsigned int j     = bonds.neighbor[b];
          const double       lost  = bonds.intact[b] ? 0. : 1.;
          const double       share = bonds.volume_factor(b);
          total[i] += share * volume[j];
          broken[i] += lost * share * volume[j];
          if (j < n_owned)
            {
              total[j] += share * volume[i];
              broken[j] += lost * share * volume[i];
            }
        }
    for (unsigned int i = 0; i < n_owned; ++i)
      broken[i] = (total[i] > 0. ? broken[i] / total[i] : 1.);
    return broken;
  }

  template <int dim>
  std::uint64_t
  n_broken_bonds(const ParticleSystem<dim> &particles)
  {
    const BondList &bonds = particles.bonds();
    double          local = 0.;
    for (std::size_t b = 0; b < bonds.size(); ++b)
      if (!bonds.intact[b])
        local += particles.bond_share(b);
    return static_cast<std::uint64_t>(
      std::llround(Utilities::MPI::sum(local, particles.get_communicator())));
  }

  template <int dim>
  bool
  breaking_settled(const ParticleSystem<dim> &particles,
                   const std::uint64_t        broken_before,
                   const bool                 damage_changed,
                   const unsigned int         step,
                   const unsigned int         pass)
  {
    if (n_broken_bonds(particles) == broken_before && !damage_changed)
      return true;
    const unsigned int max_passes = 100;
    // Not converged (not a plain error), so that the load stepping cuts the step if it may.
    AssertThrow(pass + 1 < max_passes,
                ExcNotConverged("Load step " + std::to_string(step) +
                                ": bonds kept breaking or softening through " +
                                std::to_string(max_passes) +
                                " re-solves (unstable crack growth); use more <Solver/Load "
                                "steps>, or let such steps be cut (<Solver/Control/Cut above "
                                "broken bonds>)."));
    return false;
  }

  template class DamageModel<2>;
  template class DamageModel<3>;
  template class NoDamage<2>;
  template class NoDamage<3>;
  template class CriticalStretch<2>;
  template class CriticalStretch<3>;
  template std::vector<double>
  damage_index<2>(const ParticleSystem<2> &);
  template std::vector<double>
  damage_index<3>(const ParticleSystem<3> &);
  template std::uint64_t
  n_broken_bonds<2>(const ParticleSystem<2> &);
  template std::uint64_t
  n_broken_bonds<3>(const ParticleSystem<3> &);
  template bool
  breaking_settled<2>(const ParticleSystem<2> &, std::uint64_t, bool, unsigned int, unsigned int);
  template bool
  breaking_settled<3>(const ParticleSystem<3> &, std::uint64_t, bool, unsigned int, unsigned int);
} // namespace perideal

PERIDEAL_REGISTER_DAMAGE_MODEL(perideal::NoDamage, "none", "bonds never break.")
PERIDEAL_REGISTER_DAMAGE_MODEL(perideal::CriticalStretch,
                               "critical stretch",
                               "a bond breaks for good when its stretch exceeds s0.")
