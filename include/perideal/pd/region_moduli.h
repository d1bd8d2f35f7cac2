// ---------------------------------------------------------------------
// PeriDeal: a modulus that changes from region to region, and the bond modulus of the series
// rule at the interfaces.
// ---------------------------------------------------------------------
#ifndef perideal_pd_region_moduli_h
#define perideal_pd_region_moduli_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <perideal/base/region.h>
#include <perideal/pd/particle_system.h>

#include <string>
#include <utility>
#include <vector>

namespace perideal
{
  /**
   * @brief A material modulus given per region of <Regions> (dissimilar materials in one
   * particle region): the model's own modulus mu_0 everywhere except in the listed regions,
   * where the last listed region that holds a point gives it.
   *
   * A bond acts as two springs in series across an interface (Oterkus & Madenci 2015, seed 000,
   * eq. 60; seed note 000, sec. 1.5): its modulus is the length-weighted harmonic mean
   *   mu_ij = |xi| / sum_s (l_s / mu_s),
   * l_s the lengths of the pieces of the bond in each material; (l_1 + l_2)/(l_1/mu_1 + l_2/mu_2)
   * for one crossing. The pieces are found by sampling the bond at 17 points and bisecting each
   * change of material to round-off (features thinner than |xi|/16 between two samples of the
   * same material are missed). A bond inside one material has that material's modulus.
   *
   * Parameter (in the model's subsection): the entry named by the caller (e.g. <Shear moduli by
   * region>), 'region: modulus' items separated by ';' (e.g. 'upper: 6e6'), empty for one
   * material. Every modulus must be positive (checked when read) and every region must exist
   * (checked by resolve()).
   */
  template <int dim>
  class RegionModuli
  {
  public:
    /**
     * @brief Declare the entry @p entry_name (empty default) in the current subsection; @p unit is
     * the modulus' unit for the documentation; @p of_bonds: the documentation states the bonds'
     * interface rule (bond_modulus()), else that the value is the particle's (at()).
     */
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const std::string        &entry_name,
                       const std::string        &unit,
                       const bool                of_bonds = true);

    /**
     * @brief Read the entry @p entry_name of the current subsection; @p path is the subsection's
     * path for messages (e.g. "Material/antiplane bond based"). Throws, naming the entry, for an
     * item that is not 'region: number' or a modulus that is not positive.
     */
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const std::string        &entry_name,
                     const std::string        &path);

    /**
     * @brief Look up the listed regions in @p regions (which must outlive this object); throws,
     * naming the entry, for a region that does not exist.
     */
    void
    resolve(const RegionCollection<dim> &regions);

    /**
     * @brief Whether no region has its own modulus (one material).
     */
    bool
    empty() const;

    /**
     * @brief The modulus at @p p: that of the last listed region holding it, otherwise
     * @p default_modulus.
     */
    double
    at(const dealii::Point<dim> &p, const double default_modulus) const;

    /**
     * @brief The modulus of the bond from @p a to @p b: the length-weighted harmonic mean of
     * the moduli along it (at() with @p default_modulus).
     */
    double
    bond_modulus(const dealii::Point<dim> &a,
                 const dealii::Point<dim> &b,
                 const double              default_modulus) const;

    /**
     * @brief Multiply the entry of each bond of the owned rows of @p particles in
     * @p coefficient (sized like the bond list) by bond_modulus() / @p default_modulus: a pair
     * coefficient of the modulus @p default_modulus becomes that of the bond's modulus. Nothing
     * for one material.
     */
    void
    scale_bonds(const ParticleSystem<dim> &particles,
                const double               default_modulus,
                std::vector<double>       &coefficient) const;

    /**
     * @brief The items for a log line ("upper: 6e+06"), empty for one material.
     */
    std::string
    summary() const;

  private:
    std::string                                         entry;
    std::vector<std::pair<std::string, double>>         items;
    std::vector<std::pair<const Region<dim> *, double>> resolved;
  };
} // namespace perideal

#endif
