// ---------------------------------------------------------------------
// PeriDeal: a modulus that changes from region to region, and the bond modulus of the series
// rule at the interfaces.
// ---------------------------------------------------------------------
#include <deal.II/base/utilities.h>

#include <perideal/base/parameter_utilities.h>
#include <perideal/pd/region_moduli.h>

#include <sstream>

namespace perideal
{
  using namespace dealii;

  template <int dim>
  void
  RegionModuli<dim>::declare_parameters(ParameterHandler  &prm,
                                        const std::string &entry_name,
                                        const std::string &unit,
                                        const bool         of_bonds)
  {
    const std::string what = of_bonds ? "modulus" : "value";
    prm.declare_entry(entry_name,
                      "",
                      Patterns::Anything(),
                      "Dissimilar materials: 'region: " + what + "' items [" + unit +
                        "] separated by ';' (regions of <Regions>, e.g. 'upper: 6e6'); a point "
                        "takes the " +
                        what + " of the last listed region that holds it, else the model's own. " +
                        (of_bonds ? "A bond across an interface gets the length-weighted "
                                    "harmonic mean of the moduli along it (springs in series, "
                                    "Oterkus & Madenci 2015, eq. 60). " :
                                    "A property of the particle (at its position): no interface "
                                    "rule. ") +
                        "Empty: one material.");
  }

  template <int dim>
  void
  RegionModuli<dim>::parse_parameters(ParameterHandler  &prm,
                                      const std::string &entry_name,
                                      const std::string &path)
  {
    entry = path + "/" + entry_name;
    items.clear();
    resolved.clear();
    for (const auto &item : Utilities::split_string_list(prm.get(entry_name), ';'))
      {
        if (item.empty())
          continue;
        const auto parts = Utilities::split_string_list(item, ':');
        double     value = 0.;
        bool       valid = (parts.size() == 2 && !parts[0].empty());
        if (valid)
          try
            {
              std::size_t length = 0;
              value              = std::stod(parts[1], &length);
              valid              = (length == parts[1].size());
            }
          catch (const std::exception &)
            {
              valid = false;
            }
        AssertThrow(valid,
                    ExcMessage("The parameter <" + entry + "> has the item <" + item +
                               ">; accepted: 'region: modulus' items separated by ';'."));
        AssertThrow(value > 0.,
                    ExcMessage("The parameter <" + entry + "> gives the region <" + parts[0] +
                               "> the modulus " + ParameterUtilities::format_number(value) +
                               "; accepted: a positive modulus."));
        items.emplace_back(parts[0], value);
      }
  }

  template <int dim>
  void
  RegionModuli<dim>::resolve(const RegionCollection<dim> &regions)
  {
    resolved.clear();
    for (const auto &[name, value] : items)
      resolved.emplace_back(&regions.get(name, entry), value);
  }

  template <int dim>
  bool
  RegionModuli<dim>::empty() const
  {
    return items.empty();
  }

  template <int dim>
  double
  RegionModuli<dim>::at(const Point<dim> &p, const double default_modulus) const
  {
    Assert(resolved.size() == items.size(), ExcMessage("Call resolve() first."));
    double modulus = default_modulus;
    for (const auto &[region, value] : resolved)
      if (region->contains(p))
        modulus = value;
    return modulus;
  }

  template <int dim>
  double
  RegionModuli<dim>::bond_modulus(const Point<dim> &a,
                                  const Point<dim> &b,
                                  const double      default_modulus) const
  {
    const auto modulus = [&](const double t) { return at(a + t * (b - a), default_modulus); };
    constexpr unsigned int n_samples = 16;
    // sum_s l_s / mu_s over |xi|: the fraction of the bond in each material over its modulus.
    double compliance = 0., t0 = 0., mu0 = modulus(0.);
    for (unsigned int k = 1; k <= n_samples; ++k)
      {
        const double t1 = double(k) / n_samples, mu1 = modulus(t1);
        if (mu1 != mu0)
          {
            // Bisect the change of material in (t0, t1].
            double low = t0, high = t1;
            for (unsigned int step = 0; step < 60 && high - low > 1e-15; ++step)
              {
                const double middle                   = 0.5 * (low + high);
                (modulus(middle) == mu0 ? low : high) = middle;
              }
            compliance += (high - t0) / mu0;
            t0  = high;
            mu0 = mu1;
          }
      }
    compliance += (1. - t0) / mu0;
    return 1. / compliance;
  }

  template <int dim>
  void
  RegionModuli<dim>::scale_bonds(const ParticleSystem<dim> &particles,
                                 const double               default_modulus,
                                 std::vector<double>       &coefficient) const
  {
    if (empty())
      return;
    const BondList &bonds = particles.bonds();
    const auto     &x     = particles.positions();
    for (unsigned int i = 0; i < particles.n_owned(); ++i)
      for (unsigned int b = bonds.row_start[i]; b < bonds.row_start[i + 1]; ++b)
        coefficient[b] *=
          bond_modulus(x[i], x[bonds.neighbor[b]], default_modulus) / default_modulus;
  }

  template <int dim>
  std::string
  RegionModuli<dim>::summary() const
  {
    std::ostringstream out;
    for (const auto &[name, value] : items)
      out << (out.tellp() > 0 ? "; " : "") << name << ": " << value;
    return out.str();
  }

  template class RegionModuli<2>;
  template class RegionModuli<3>;
} // namespace perideal
