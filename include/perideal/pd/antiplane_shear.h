// ---------------------------------------------------------------------
// PeriDeal: what the antiplane shear models (one scalar w per particle) share.
// ---------------------------------------------------------------------
#ifndef perideal_pd_antiplane_shear_h
#define perideal_pd_antiplane_shear_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace perideal
{
  /**
   * @brief The parameter and the constants that the antiplane models (`antiplane bond based`,
   * `antiplane state based`; Oterkus & Madenci 2015, seed 000) share: the shear modulus mu, the
   * micromodulus of the bond-based energy and the critical slope of a fracture energy
   * (derivations in doc/theory/models.md).
   */
  namespace AntiplaneShear
  {
    /**
     * @brief Declare "Shear modulus" in the model's subsection.
     */
    void
    declare_shear_modulus(dealii::ParameterHandler &prm);

    /**
     * @brief The shear modulus mu [Pa] of the model's subsection; throws, naming
     * <Material/@p model_name/Shear modulus>, unless it is positive.
     */
    double
    parse_shear_modulus(dealii::ParameterHandler &prm, const std::string &model_name);

    /**
     * @brief The micromodulus c [N/m^6] of the bond-based energy W_i = 1/4 sum_j c r^2 |xi| V_j
     * that matches W = mu |grad w|^2 / 2 (seed eq. 40): 6 mu / (pi h delta^3) for @p dim = 2
     * (a cross-section of thickness @p thickness), 6 mu / (pi delta^4) for @p dim = 3.
     */
    double
    micromodulus(const unsigned int dim,
                 const double       shear_modulus,
                 const double       horizon,
                 const double       thickness);

    /**
     * @brief The critical bond slope r_c of the fracture energy @p fracture_energy (G_IIIc
     * [J/m^2]) for the bond-based energy: sqrt(2 pi G / (3 mu delta)) for @p dim = 2 (seed
     * eq. 78), sqrt(5 G / (3 mu delta)) for @p dim = 3.
     */
    double
    critical_slope(const unsigned int dim,
                   const double       fracture_energy,
                   const double       shear_modulus,
                   const double       horizon);
  } // namespace AntiplaneShear
} // namespace perideal

#endif
