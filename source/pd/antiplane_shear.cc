// ---------------------------------------------------------------------
// PeriDeal: what the antiplane shear models (one scalar w per particle) share.
// ---------------------------------------------------------------------
#include <deal.II/base/numbers.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/antiplane_shear.h>
#include <perideal/pd/antiplane_torsion.h>

#include <cmath>
#include <sstream>

namespace perideal
{
  namespace AntiplaneShear
  {
    double
    micromodulus(const unsigned int dim,
                 const double       shear_modulus,
                 const double       horizon,
                 const double       thickness)
    {
      const double pi = dealii::numbers::PI;
      return (dim == 2) ? 6. * shear_modulus / (pi * thickness * std::pow(horizon, 3)) :
                          6. * shear_modulus / (pi * std::pow(horizon, 4));
    }

    double
    critical_slope(const unsigned int dim,
                   const double       fracture_energy,
                   const double       shear_modulus,
                   const double       horizon)
    {
      const double G = fracture_energy, mu = shear_modulus, pi = dealii::numbers::PI;
      return (dim == 2) ? std::sqrt(2. * pi * G / (3. * mu * horizon)) :
                          std::sqrt(5. * G / (3. * mu * horizon));
    }
  } // namespace AntiplaneShear

  template <int dim>
  FieldLayout
  AntiplaneModel<dim>::field_layout() const
  {
    return FieldLayout::scalar("w");
  }

  template <int dim>
  double
  AntiplaneModel<dim>::critical_stretch(const double fracture_energy) const
  {
    return fracture_factor *
           AntiplaneShear::critical_slope(dim, fracture_energy, mu, context.horizon);
  }

  template <int dim>
  ModelCapabilities
  AntiplaneModel<dim>::capabilities() const
  {
    ModelCapabilities capabilities;
    capabilities.lattice_fracture = true;
    return capabilities;
  }

  template <int dim>
  bool
  AntiplaneModel<dim>::has_prestrain() const
  {
    return twist.active();
  }

  template <int dim>
  const Torsion *
  AntiplaneModel<dim>::torsion() const
  {
    return twist.active() ? &twist : nullptr;
  }

  template <int dim>
  std::vector<std::string>
  AntiplaneModel<dim>::integral_names() const
  {
    return twist.active() ? AntiplaneTorsion::integral_names() : std::vector<std::string>();
  }

  template <int dim>
  std::vector<double>
  AntiplaneModel<dim>::section_integrals(const ParticleSystem<dim> &particles,
                                         const ParticleVector      &u,
                                         const double               strain_energy) const
  {
    if (!twist.active())
      return {};
    return AntiplaneTorsion::section_integrals(particles, u, twist, mu, strain_energy);
  }

  template <int dim>
  std::vector<DerivedParticleField>
  AntiplaneModel<dim>::derived_fields(const ParticleSystem<dim> &particles,
                                      const ParticleVector      &u) const
  {
    std::vector<dealii::Tensor<1, dim>> tau;
    AntiplaneTorsion::shear_stresses(particles, u, twist, mu, tau);
    const auto          &x = particles.positions();
    DerivedParticleField field{"shear_stress", dim, {}};
    for (unsigned int i = 0; i < tau.size(); ++i)
      {
        // tau = mu_i grad w with the modulus of the particle's region (no twist with regions).
        const double factor = region_moduli.empty() ? 1. : region_moduli.at(x[i], mu) / mu;
        for (unsigned int d = 0; d < dim; ++d)
          field.values.push_back(factor * tau[i][d]);
      }
    return {field};
  }

  template <int dim>
  double
  AntiplaneModel<dim>::shear_modulus() const
  {
    return mu;
  }

  template <int dim>
  void
  AntiplaneModel<dim>::resolve_regions(const RegionCollection<dim> &regions)
  {
    region_moduli.resolve(regions);
  }

  template <int dim>
  void
  AntiplaneModel<dim>::declare_antiplane_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Shear modulus",
                      "0",
                      dealii::Patterns::Double(0.),
                      "Shear modulus mu [Pa] of antiplane shear (the field w is the "
                      "out-of-plane displacement, its stresses tau_xz, tau_yz = mu grad w).");
    RegionModuli<dim>::declare_parameters(prm, "Shear moduli by region", "Pa");
    Torsion::declare_parameters(prm);
  }

  template <int dim>
  void
  AntiplaneModel<dim>::parse_antiplane_parameters(dealii::ParameterHandler &prm,
                                                  const std::string        &model_name)
  {
    mu = prm.get_double("Shear modulus");
    ParameterUtilities::require_positive(mu, "Material/" + model_name + "/Shear modulus");
    region_moduli.parse_parameters(prm, "Shear moduli by region", "Material/" + model_name);
    twist.parse_parameters(prm, "Material/" + model_name, dim);
    AssertThrow(!(twist.active() && !region_moduli.empty()),
                dealii::ExcMessage("The parameter <Material/" + model_name +
                                   "/Shear moduli by region> is set together with a twist "
                                   "(<Twist per unit length>): torsion takes one shear modulus; "
                                   "accepted: an empty list with a twist."));
  }

  template <int dim>
  std::string
  AntiplaneModel<dim>::antiplane_summary() const
  {
    std::ostringstream out;
    if (!region_moduli.empty())
      out << "; by region: " << region_moduli.summary();
    if (twist.active())
      out << "; torsion: twist " << twist.twist() << " rad/m about (" << twist.axis() << ")";
    if (context.lattice_fracture)
      out << "; lattice calibration of the fracture energy: critical slope " << fracture_factor
          << " times the continuum's";
    return out.str();
  }

  template <int dim>
  std::vector<double>
  AntiplaneModel<dim>::twist_fields(const ParticleSystem<dim> &particles) const
  {
    if (!twist.active())
      return {};
    AntiplaneTorsion::check_section(particles);
    return AntiplaneTorsion::twist_fields(particles, twist);
  }

  template class AntiplaneModel<2>;
  template class AntiplaneModel<3>;
} // namespace perideal
